# Recordings too short, and grasp types with too few recordings, to model:
# a fit used to take them (a two-frame recording stretched to the template
# is a straight line, not a grasp; a class mean from two recordings is a
# guess) or drop them without a word. The result stays usable, as before,
# and one classed warning names the recordings or types.

# Fewer frames than this show no motion to align, model or classify: a
# straight line between two postures at best.
min_motion_frames <- 3L

# Fewer recordings of a type than this give a class mean and spread from a
# pair at most.
min_type_recordings <- 3L

# Warn (class short_recordings, degenerate family) naming the recordings of
# `x` with fewer than min_motion_frames frames; `action` says what is done
# with them ("fitted", "classified").
warn_short_recordings <- function(x, arg = "x", action = "used") {
  nf <- x$meta$n_frames
  short <- which(nf < min_motion_frames)
  if (!length(short)) return(invisible(character()))
  ids <- x$meta$id[short]
  hm_warn(c("{.arg {arg}} has {length(ids)} recording{?s} of fewer than {min_motion_frames} frames, {action} all the same: {.val {ids}}.",
            i = "So short a recording shows no motion; check how it was cut."),
          "short_recordings", recording = ids, argument = arg)
  invisible(ids)
}

# Warn (class few_recordings) naming the labelled types of `x` (of `types`
# only, when given: counted in the set's meta, not in a subset of it, which
# at ten times the default data cost a copy of the set after every fit) with
# fewer than min_type_recordings recordings.
warn_few_recordings <- function(x, arg = "x", types = NULL) {
  n <- table(droplevels(as.factor(x$meta$grasp)))
  if (!is.null(types)) n <- n[names(n) %in% types]
  few <- names(n)[n < min_type_recordings]
  if (!length(few)) return(invisible(character()))
  hm_warn(c("{.arg {arg}} has {length(few)} grasp type{?s} with fewer than {min_type_recordings} recordings, fitted all the same: {.val {few}}.",
            i = "Their means and spreads rest on one or two recordings each."),
          "few_recordings", grasp = few, argument = arg)
  invisible(few)
}
