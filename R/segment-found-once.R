# Every recording's motion found once per fit. A fit of trimmed recordings
# looked at each recording three times: to decide whether the set is
# trimmed (resolve_motion()), to trim the temperature sample, and to trim
# each type for its model. find_motion() is most of such a fit: on the wide
# glove's stand-in (168 recordings of 23 channels, about 380 frames; its
# fit's goal is 3 s) it took 1.8 s of the fit's 2.4. Each recording's motion
# depends on that recording alone, so the set's table is found once and
# find_motion() reads it, within the fit, for any of its recordings.

motion_found <- new.env(parent = emptyenv())

# Evaluate `expr` with the find_motion() table `found` (found with the
# default settings) known to find_motion(); NULL keeps what is known.
with_motion_found <- function(found, expr) {
  if (is.null(found)) return(expr)
  old <- motion_found$table
  motion_found$table <- found
  on.exit(motion_found$table <- old, add = TRUE)
  expr
}

# Per recording of `x`, its row in the known table (matched by id, with
# the same number of frames), NA where it has none or the settings are not
# the defaults the table was found with.
known_motion <- function(x, min_move, min_still) {
  tab <- motion_found$table
  none <- rep(NA_integer_, length(x))
  defaults <- formals(find_motion)
  if (is.null(tab) || min_move != defaults$min_move || min_still != defaults$min_still) return(none)
  i <- match(x$meta$id, tab$id)
  i[!is.na(i) & tab$n_frames[i] != x$meta$n_frames] <- NA_integer_
  i
}

# The set's motion decision (resolve_motion()) and, with `find_all` when it
# trims, the find_motion() table of every recording (the decision's sample
# found once, as part of it). list(motion, found).
resolve_motion_found <- function(x, motion, call = rlang::caller_env(), find_all = TRUE) {
  motion <- check_choice(motion, c("auto", "trim", "as_recorded"), arg = "motion", call = call)
  sample <- NULL
  if (motion == "auto") {
    if (length(x) == 0L) return(list(motion = "as_recorded", found = NULL))
    idx <- evenly_spread(length(x), motion_auto_sample)
    sample <- find_motion(x[idx])
    motion <- auto_motion(sample)
  }
  if (!find_all || motion != "trim" || length(x) == 0L) return(list(motion = motion, found = NULL))
  found <- with_motion_found(sample, find_motion(x))
  list(motion = motion, found = found)
}
