# The grasps class: a set of joint-angle recordings with their metadata.
# Every reader, the simulator and every generator returns one; every model,
# plot and exporter takes one. Stored as a list with five fields:
#   recordings  list of numeric matrices, frames x DoF, colnames = dofs
#   meta        data.frame, one row per recording (id, grasp, subject, object,
#               trial, n_frames, source, and any extra columns)
#   dofs        character, the DoF names
#   rate        sampling rate in Hz
#   unit        angle unit: "deg", "rad" or "raw" (raw sensor counts)
#   glove       the glove_profile of the channels (R/glove.R): joints driven,
#               units, ranges, stuck channels

grasp_units <- c("deg", "rad", "raw")

#' Create a set of grasp recordings
#'
#' `grasps()` is the package's one data class: a set of recordings, each a
#' frames x DoF numeric matrix of joint angles, with one row of metadata per
#' recording and set-level attributes (DoF names, sampling rate, angle unit).
#' Readers ([read_hust()], [read_graspdb14()]), the simulator
#' ([simulate_grasps()]) and generators ([generate()]) all return this class.
#'
#' @param recordings A list of numeric matrices (frames x DoF), or a single
#'   matrix for a set of one. Every matrix must have `length(dofs)` columns,
#'   at least one row and only finite values.
#' @param meta A data frame with one row per recording. Recognised columns:
#'   `id` (character, unique), `grasp` (the recording's class label: any
#'   string or factor level, such as an object, a gesture or a Feix grasp
#'   type; `NA` for unlabelled motion; see Labels), `subject`, `object`,
#'   `trial`, `source`. Missing
#'   columns are filled in (ids `"r1"`, `"r2"`, ...; others `NA`); extra
#'   columns are kept. `n_frames` is always recomputed.
#' @param dofs DoF names. Defaults to the column names of the first recording,
#'   or to the 16 HUST DoFs ([hust_dofs]) when those are absent and the
#'   recordings have 16 columns.
#' @param rate Sampling rate in Hz (positive number).
#' @param unit Angle unit: `"deg"`, `"rad"` or `"raw"` (raw sensor counts).
#'   `NULL` (default): the unit of the `glove`'s channels, else `"deg"`.
#' @param glove The glove that recorded the data: a [glove_profile()] or the
#'   name of a shipped one. `NULL` (default) recognises the HUST and
#'   GraspDB14 channel names and otherwise describes the channels as not
#'   drawn. Channels that are constant over every recording are flagged as
#'   stuck (a warning of class `handmotion_warning_stuck_channels`); models
#'   hold them at their value instead of fitting them.
#' @section Labels:
#' A recording's class is whatever you call it. When every label names a
#' Feix grasp type (by name in any case, with spaces, hyphens or
#' underscores, or by id 1-33) the labels become a factor over the 33 Feix
#' types in id order, which the thesis' tables and [reproduce_thesis()]
#' need. Otherwise the labels are kept as your own classes: a factor keeps
#' its levels, strings are sorted. When only some labels look like Feix
#' types a warning of class `handmotion_warning_mixed_labels` says so (a
#' misspelt type would otherwise become a class of its own). Every verb
#' (fits, [generate()], classifiers, evaluation, plots) works on the labels
#' as they are.
#' @return An object of class `grasps`.
#' @seealso [simulate_grasps()], [as.data.frame.grasps()], [autoplot.grasps()]
#' @export
#' @examples
#' set.seed(1)
#' recs <- replicate(3, matrix(rnorm(40 * 16), 40, 16), simplify = FALSE)
#' g <- grasps(recs, meta = data.frame(grasp = c("Tripod", "Tripod", "Ring"),
#'                                     subject = c("s1", "s2", "s1")))
#' g
#' g[g$meta$grasp == "Tripod"]
#' # your own labels: objects, gestures, ...
#' h <- grasps(recs, meta = data.frame(grasp = c("bottle", "mug", "bottle")))
#' levels(h$meta$grasp)
grasps <- function(recordings, meta = NULL, dofs = NULL, rate = 50, unit = NULL, glove = NULL) {
  call <- rlang::caller_env()
  if (!is.null(glove)) glove <- glove_profile(glove)
  if (is.null(unit)) {
    u <- unique(glove$channels$unit)
    unit <- if (length(u) == 1L) u else if (length(u) > 1L) "raw" else "deg"
  }
  if (is.matrix(recordings) || is.data.frame(recordings)) recordings <- list(recordings)
  if (!is.list(recordings)) {
    hm_abort("{.arg recordings} must be a list of numeric matrices, not {.obj_type_friendly {recordings}}.",
             "bad_input", argument = "recordings", call = call)
  }
  if (length(recordings) == 0L) {
    hm_abort("{.arg recordings} is empty: a grasps set needs at least one recording.",
             "bad_input", argument = "recordings", call = call)
  }
  check_rate(rate, call = call)
  unit <- check_unit(unit, call = call)
  # ids: meta$id, else the names of `recordings`, else r1, r2, ...; a missing
  # or empty id among given ones is an error (renaming them all would lose
  # the ids that were there)
  from <- if (!is.null(meta) && "id" %in% names(meta)) "meta$id" else if (!is.null(names(recordings))) "names(recordings)" else NULL
  ids <- switch(from %||% "none", "meta$id" = as.character(meta$id),
                "names(recordings)" = names(recordings), NULL)
  if (!is.null(ids) && length(ids) == length(recordings) && (anyNA(ids) || any(ids == ""))) {
    if (from == "names(recordings)" && all(is.na(ids) | ids == "")) {
      ids <- NULL
    } else {
      bad <- which(is.na(ids) | ids == "")
      hm_abort(c("Recording id{?s} {from} must not be missing or empty.",
                 x = "Missing at position{cli::qty(length(bad))}{?s} {bad}."),
               "bad_input", argument = if (from == "meta$id") "meta" else "recordings", call = call)
    }
  }
  if (is.null(ids)) ids <- paste0("r", seq_along(recordings))
  recordings <- lapply(seq_along(recordings), function(i) {
    as_recording_matrix(recordings[[i]], ids[i], call = call)
  })
  dofs <- resolve_dofs(dofs, recordings, call = call)
  for (i in seq_along(recordings)) {
    if (ncol(recordings[[i]]) != length(dofs)) {
      hm_abort(c("Recording {.val {ids[i]}} has {ncol(recordings[[i]])} DoF column{?s}, expected {length(dofs)}.",
                 i = "Every recording must have one column per DoF ({.val {dofs}})."),
               "bad_recording", recording = ids[i], call = call)
    }
    colnames(recordings[[i]]) <- dofs
  }
  meta <- build_meta(meta, recordings, ids, call = call)
  names(recordings) <- meta$id
  angle_profile <- !is.null(glove) && !any(glove$channels$unit == "raw")
  if (unit == "raw" && (is.null(glove) || angle_profile)) {
    guessed <- guess_raw_glove(dofs, recordings, template = if (angle_profile) glove)
    if (!is.null(guessed) || is.null(glove)) glove <- guessed
    if (!is.null(guessed)) {
      hm_warn(c("Raw counts without a map to degrees: channels {.val {utils::head(glove$channels$channel[!is.na(glove$channels$axis)], 4)}}... are drawn through a guessed map.",
                i = "Each channel's recorded range is mapped onto a typical range of its joint; give {.arg glove} ({.fn glove_profile}) or {.fn calibrate} the data for true angles."),
              "guessed_glove")
    }
  }
  glove <- match_glove(glove, dofs, unit, call = call)
  flag_stuck(new_grasps(recordings, meta, dofs, rate, unit, glove = glove), call = call)
}

# Low-level constructor: no validation, for internal use by code that already
# guarantees the invariants (subsetting, generators). A generator that
# already knows the frame counts passes `n_frames` (saves a per-recording R
# call, which dominates large generated batches).
new_grasps <- function(recordings, meta, dofs, rate, unit, n_frames = NULL, glove = NULL) {
  meta$n_frames <- if (is.null(n_frames)) vapply(recordings, nrow, integer(1)) else as.integer(n_frames)
  rownames(meta) <- NULL
  structure(list(recordings = recordings, meta = meta, dofs = dofs,
                 rate = rate, unit = unit, glove = glove %||% guess_glove(dofs, unit)), class = "grasps")
}

check_rate <- function(rate, call = rlang::caller_env()) {
  invisible(check_number(rate, "rate", min = 0, min_open = TRUE, unit = "frames per second", call = call))
}

# A grasps set a verb reads recordings from, with at least one recording:
# an empty selection gave an empty result (predict(), project()), a base R
# error deep inside ggplot2 (plots) or a page with nothing on it, without
# saying why. `what` the verb does with them.
check_some_recordings <- function(x, arg = "x", what = "draw", call = rlang::caller_env()) {
  if (inherits(x, "grasps") && length(x) == 0L) {
    hm_abort("{.arg {arg}} holds no recordings (an empty selection?): there is nothing to {what}.",
             "bad_recording", argument = arg, call = call)
  }
  invisible(x)
}

# Recordings a fitted model is applied to (`verb` "project" or "classify"):
# a valid grasps set (`finite = FALSE` where a recording with non-finite
# values gets NA instead), not empty, its too-short recordings named.
check_new_recordings <- function(x, arg, verb, finite = TRUE, call = rlang::caller_env()) {
  check_grasps(x, arg, call = call, finite = finite)
  check_some_recordings(x, arg, verb, call = call)
  warn_short_recordings(x, arg, action = c(project = "projected", classify = "classified")[[verb]])
}

check_unit <- function(unit, call = rlang::caller_env()) {
  check_choice(unit, grasp_units, "unit", call = call)
}

as_recording_matrix <- function(x, id, call = rlang::caller_env()) {
  if (is.data.frame(x)) {
    num <- vapply(x, is.numeric, logical(1))
    if (!all(num)) {
      hm_abort("Recording {.val {id}} has non-numeric column{?s} {.val {names(x)[!num]}}.",
               "bad_recording", recording = id, call = call)
    }
    x <- as.matrix(x)
  }
  if (is.numeric(x) && is.null(dim(x))) {
    hm_abort("Recording {.val {id}} is a vector; it must be a frames x DoF matrix.",
             "bad_recording", recording = id, call = call)
  }
  if (!is.matrix(x) || !is.numeric(x)) {
    hm_abort("Recording {.val {id}} must be a numeric matrix, not {.obj_type_friendly {x}}.",
             "bad_recording", recording = id, call = call)
  }
  if (nrow(x) == 0L || ncol(x) == 0L) {
    hm_abort("Recording {.val {id}} has zero length ({nrow(x)} frame{?s} x {ncol(x)} DoF{?s}).",
             "bad_recording", recording = id, call = call)
  }
  # the sum of finite doubles is finite (and integers are finite unless NA):
  # the values are searched only when it is not, not once per recording
  # (which(!is.finite()) was a tenth of reading 5,000 GraspDB14 files)
  suspect <- if (is.double(x)) !is.finite(sum(x)) else anyNA(x)
  bad <- if (suspect) which(!is.finite(x), arr.ind = TRUE) else matrix(0L, 0L, 2L)
  if (nrow(bad) > 0L) {
    col <- if (is.null(colnames(x))) bad[1, 2] else colnames(x)[bad[1, 2]]
    frames <- unique(bad[, 1])
    hm_abort(c("Recording {.val {id}} has {nrow(bad)} missing or infinite value{?s} in {length(frames)} frame{?s}.",
               i = "First at frame {bad[1, 1]}, DoF {.val {col}}."),
             "bad_recording", recording = id, call = call)
  }
  storage.mode(x) <- "double"
  x
}

resolve_dofs <- function(dofs, recordings, call = rlang::caller_env()) {
  if (is.null(dofs)) dofs <- colnames(recordings[[1]])
  if (is.null(dofs)) {
    p <- ncol(recordings[[1]])
    dofs <- if (p == nrow(handmotion::hust_dofs)) handmotion::hust_dofs$name else paste0("dof", seq_len(p))
  }
  if (!is.character(dofs) || anyNA(dofs) || anyDuplicated(dofs)) {
    hm_abort("{.arg dofs} must be unique, non-missing names, not {describe_value(dofs)}.", "bad_input",
             argument = "dofs", call = call)
  }
  dofs
}

build_meta <- function(meta, recordings, ids, call = rlang::caller_env()) {
  n <- length(recordings)
  if (is.null(meta)) meta <- data.frame(row.names = seq_len(n))
  if (!is.data.frame(meta)) {
    hm_abort("{.arg meta} must be a data frame, not {.obj_type_friendly {meta}}.",
             "bad_input", argument = "meta", call = call)
  }
  if (nrow(meta) != n) {
    hm_abort("{.arg meta} has {nrow(meta)} row{?s} but there {?is/are} {n} recording{?s}.",
             "bad_input", argument = "meta", call = call)
  }
  meta <- as.data.frame(meta, stringsAsFactors = FALSE)
  meta$id <- ids
  if (anyDuplicated(ids)) {
    hm_abort("Recording ids must be unique; duplicated: {.val {unique(ids[duplicated(ids)])}}.",
             "bad_input", argument = "meta", call = call)
  }
  meta$grasp <- as_grasp_label(if ("grasp" %in% names(meta)) meta$grasp else rep(NA, n),
                               ids = ids, call = call)
  meta$subject <- if ("subject" %in% names(meta)) as.character(meta$subject) else NA_character_
  meta$object <- if ("object" %in% names(meta)) as.character(meta$object) else NA_character_
  meta$trial <- if ("trial" %in% names(meta)) as.integer(meta$trial) else NA_integer_
  meta$source <- if ("source" %in% names(meta)) as.character(meta$source) else NA_character_
  meta$n_frames <- vapply(recordings, nrow, integer(1))
  core <- c("id", "grasp", "subject", "object", "trial", "n_frames", "source")
  meta[c(core, setdiff(names(meta), core))]
}

#' Access the recordings of a grasps set
#'
#' @param x A [grasps()] object.
#' @return The list of frames x DoF matrices, named by recording id (the
#'   metadata are `x$meta`).
#' @noRd
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:2, objects = 1, trials = 1)
#' dim(recordings(g)[[1]])
recordings <- function(x) {
  check_grasps(x)
  x$recordings
}

# A grasps set where a verb uses it: the class, then the invariants grasps()
# established (validate_grasps()), since a set edited after construction
# (x$recordings[[2]][3, 4] <- NaN, a meta row dropped, x$rate <- 0) would
# otherwise reach a fit as a NaN, a recycled vector or a base R error.
# `finite = FALSE` lets non-finite values through, for the verbs that handle
# them recording by recording (predict() gives such a recording NA).
check_grasps <- function(x, arg = "x", call = rlang::caller_env(), finite = TRUE) {
  if (!inherits(x, "grasps")) {
    # recordings held in a shape as_grasps() takes: say the call that turns them
    hint <- if (is.matrix(x) || is.data.frame(x) || is.list(x)) {
      c(i = "Turn a matrix, a list of matrices (frames x DoFs) or a long data frame into one with {.code as_grasps({arg})}.")
    } else {
      c(i = "Make one with {.fn grasps}, {.fn as_grasps} or a reader ({.fn read_hust}, {.fn read_glove}).")
    }
    hm_abort(c("{.arg {arg}} must be a {.cls grasps} object, not {.obj_type_friendly {x}}.", hint),
             "bad_input", argument = arg, call = call)
  }
  validate_grasps(x, arg, call, finite = finite)
}

# The invariants of a grasps set, each fault a classed error naming the
# argument and, for a recording's fault, the recording. One sum per
# recording reads the values; the rest is per-recording metadata. On the
# default data (8910 recordings, 6.1 M values) about 40 ms
# (bench/bench-validation.R), small next to any verb that reads them.
validate_grasps <- function(x, arg = "x", call = rlang::caller_env(), finite = TRUE) {
  fault <- function(what, class = "bad_input", recording = NULL) {
    hm_abort(c(paste("{.arg {arg}} is not a valid {.cls grasps} set:", what),
               i = "Was it changed after it was built? Rebuild it with {.fn grasps}."),
             class, argument = arg, recording = recording, call = call, .envir = parent.frame())
  }
  lost <- setdiff(c("recordings", "meta", "dofs", "rate", "unit"), names(x))
  if (length(lost)) fault("it has no {.field {lost}}.")
  recs <- x$recordings
  meta <- x$meta
  dofs <- x$dofs
  if (!is.list(recs) || is.object(recs)) fault("{.field recordings} is not a list of matrices.")
  if (!is.character(dofs) || length(dofs) == 0L || anyNA(dofs) || anyDuplicated(dofs)) {
    fault("{.field dofs} must be unique, non-missing names, not {describe_value(dofs)}.")
  }
  if (!is.numeric(x$rate) || length(x$rate) != 1L || !is.finite(x$rate) || x$rate <= 0) {
    fault("{.field rate} must be one positive number, not {describe_value(x$rate)}.")
  }
  if (!is.character(x$unit) || length(x$unit) != 1L || !x$unit %in% grasp_units) {
    fault("{.field unit} must be one of {.val {grasp_units}}, not {describe_value(x$unit)}.")
  }
  if (!is.data.frame(meta) || nrow(meta) != length(recs)) {
    rows <- if (is.data.frame(meta)) nrow(meta) else 0L
    fault("{.field meta} has {rows} row{?s} for {length(recs)} recording{?s}.")
  }
  lost <- setdiff(c("id", "grasp"), names(meta))
  if (length(lost)) fault("{.field meta} has no {.field {lost}} column.")
  ids <- meta$id
  if (!is.character(ids) || anyNA(ids) || anyDuplicated(ids)) {
    dup <- if (is.character(ids)) unique(ids[duplicated(ids) | is.na(ids)]) else character()
    fault(paste0("recording ids ({.field meta$id}) must be unique strings", if (length(dup)) "; repeated or missing: {.val {dup}}." else "."))
  }
  # every recording's first failed check, in one compiled pass
  # (src/recording-checks.c; R-level vapply()s of is.matrix, dim, dimnames
  # and sum took 0.39 s at ten times the default data)
  n_frames <- meta$n_frames
  if (!is.null(n_frames) && !is.numeric(n_frames)) n_frames <- suppressWarnings(as.numeric(n_frames))
  codes <- .Call(hm_recording_faults, recs, dofs, n_frames, finite)
  shape <- function(code, what) {
    i <- which(codes == code)
    first <- ids[i[1]]
    more <- if (length(i) > 1L) sprintf(" (and %d more)", length(i) - 1L) else ""
    if (length(i)) fault(paste0("recording {.val {first}}", more, " ", what, "."), "bad_recording", recording = first)
  }
  shape(1L, "is not a numeric matrix")
  shape(2L, "has no frames")
  shape(3L, "does not have one column per DoF ({length(dofs)})")
  shape(4L, "has columns other than {.field dofs}")
  shape(5L, "has a {.field meta$n_frames} other than its frame count")
  if (any(codes == 6L)) {
    i <- which(codes == 6L)[1]
    bad <- which(!is.finite(recs[[i]]), arr.ind = TRUE)
    hm_abort(c("{.arg {arg}} has {sum(codes == 6L)} recording{?s} with missing or infinite values.",
               x = "First: recording {.val {ids[i]}}, frame {bad[1, 1]}, DoF {.val {dofs[bad[1, 2]]}}.",
               i = "Was it changed after it was built? {.fn grasps} refuses such values."),
             "bad_recording", argument = arg, recording = ids[i], call = call)
  }
  invisible(x)
}

# Which recordings (a list of numeric matrices) hold only finite values
# (src/recording-checks.c: each read until its first missing or infinite
# value).
recordings_finite <- function(recs) {
  .Call(hm_recording_faults, recs, NULL, NULL, TRUE) != 6L
}

#' @export
length.grasps <- function(x) length(x$recordings)

#' Subset a grasps set
#'
#' @param x A [grasps()] object.
#' @param i Recording indices, logical vector, or recording ids.
#' @param ... Unused.
#' @return A `grasps` object with the selected recordings.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:3, objects = 1, trials = 1)
#' g[1:2]
#' g[g$meta$grasp == "Medium Wrap"]
`[.grasps` <- function(x, i, ...) {
  if (missing(i)) return(x)
  n <- length(x)
  if (is.character(i)) {
    idx <- match(i, x$meta$id)
    if (anyNA(idx)) {
      hm_abort("Unknown recording id{?s} {.val {i[is.na(idx)]}}.", "bad_input", argument = "i")
    }
  } else if (is.logical(i)) {
    if (length(i) != n) {
      hm_abort("A logical index must have length {n}, not {length(i)}.", "bad_input", argument = "i")
    }
    idx <- which(i & !is.na(i))
  } else {
    idx <- check_positions(i, n, "recording")
  }
  meta <- x$meta[idx, , drop = FALSE]
  new_grasps(x$recordings[idx], meta, x$dofs, x$rate, x$unit, glove = x$glove)
}

#' @export
print.grasps <- function(x, ...) {
  m <- x$meta
  rate <- sprintf("%g", x$rate)
  cli::cat_line(cli::pluralize("<grasps> {length(x)} recording{?s} of {length(x$dofs)} DoF{?s} at {rate} Hz, in {x$unit}"))
  if (length(x) > 0) {
    nf <- m$n_frames
    cli::cat_line(sprintf("  frames: %d to %d (mean %.1f)", min(nf), max(nf), mean(nf)))
    ntypes <- length(unique(stats::na.omit(m$grasp)))
    unlabelled <- if (anyNA(m$grasp)) sprintf(" (+%d unlabelled)", sum(is.na(m$grasp))) else ""
    cli::cat_line("  grasp types: ", ntypes, unlabelled, "; ", origin_line(m))
    cli::cat_line("  DoFs: ", paste(utils::head(x$dofs, 16), collapse = " "), if (length(x$dofs) > 16) " ...")
    note <- resampled_note(m, x$rate)
    if (!is.null(note)) cli::cat_line("  ", note)
  }
  print_glove_line(x)
  invisible(x)
}

# Where a set's recordings come from, for print(): recorded ones by their
# subjects and objects; generated ones (generate(), which has neither) by how
# many per type, so a generated set does not read "subjects: 0; objects: 0".
origin_line <- function(m) {
  gen <- !is.na(m[["source"]] %||% NA) & (m[["source"]] %||% "") == "generated"
  gen <- rep_len(gen, nrow(m))
  rec <- m[!gen, , drop = FALSE]
  recorded <- sprintf("subjects: %d; objects: %d", length(unique(stats::na.omit(rec$subject))),
                      length(unique(stats::na.omit(rec$object))))
  if (!any(gen)) return(recorded)
  per <- range(table(as.character(m$grasp[gen]), useNA = "ifany"))
  generated <- sprintf("generated by fitted models: %s per type", if (per[1] == per[2]) per[1] else paste(per, collapse = " to "))
  if (all(gen)) generated else paste0(recorded, " (recorded); ", sum(gen), " ", generated)
}

#' Summarise a grasps set by grasp type
#'
#' @param object A [grasps()] object.
#' @param ... Unused.
#' @return A data frame with one row per grasp type present: number of
#'   recordings, subjects, objects, and frame-count statistics.
#' @export
#' @examples
#' summary(simulate_grasps(subjects = 3, grasps = 1:4, seed = 1))
summary.grasps <- function(object, ...) {
  check_grasps(object, "object")
  m <- object$meta
  g <- addNA(droplevels(m$grasp), ifany = TRUE)
  rows <- lapply(split(m, g, drop = TRUE), function(d) {
    data.frame(grasp = as.character(d$grasp[1]), recordings = nrow(d),
               subjects = length(unique(d$subject)), objects = length(unique(d$object)),
               min_frames = min(d$n_frames), mean_frames = mean(d$n_frames),
               max_frames = max(d$n_frames), stringsAsFactors = FALSE)
  })
  out <- do.call(rbind, rows)
  rownames(out) <- NULL
  structure(out, class = c("summary_grasps", "data.frame"),
            rate = object$rate, unit = object$unit, dofs = object$dofs,
            glove = object$glove$name %||% NA_character_, stuck = stuck_channels(object),
            resampled = resampled_note(m, object$rate))
}

#' @export
print.summary_grasps <- function(x, ...) {
  rate <- sprintf("%g", attr(x, "rate"))
  cli::cat_line(cli::pluralize("Grasps by type ({length(attr(x, 'dofs'))} DoF{?s} at {rate} Hz, {attr(x, 'unit')})"))
  print(as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE), digits = 4, row.names = FALSE)
  stuck <- attr(x, "stuck")
  if (length(stuck)) cli::cat_line("Stuck channels (constant, left out of models): ", paste(stuck, collapse = " "))
  if (!is.null(attr(x, "resampled"))) cli::cat_line("Recordings ", attr(x, "resampled"))
  invisible(x)
}

#' Long-form data frame of a grasps set
#'
#' One row per recording, frame and DoF: columns `id`, `frame`, `time`
#' (seconds), `dof`, `angle`, and the metadata columns `grasp`, `subject`,
#' `object`, `trial`.
#'
#' @param x A [grasps()] object.
#' @param row.names,optional Unused, for compatibility with the generic.
#' @param ... Unused.
#' @return A data frame in long form.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 1)
#' head(as.data.frame(g))
as.data.frame.grasps <- function(x, row.names = NULL, optional = FALSE, ...) {
  check_grasps(x)
  nf <- x$meta$n_frames
  p <- length(x$dofs)
  rec <- rep(seq_along(nf), nf * p)
  frame <- unlist(lapply(nf, function(n) rep(seq_len(n), p)), use.names = FALSE)
  dof <- unlist(lapply(nf, function(n) rep(seq_len(p), each = n)), use.names = FALSE)
  m <- x$meta
  data.frame(
    id = m$id[rec], frame = frame, time = (frame - 1) / x$rate,
    dof = factor(x$dofs[dof], levels = x$dofs),
    angle = unlist(lapply(x$recordings, as.vector), use.names = FALSE),
    grasp = m$grasp[rec], subject = m$subject[rec], object = m$object[rec],
    trial = m$trial[rec], stringsAsFactors = FALSE
  )
}

# The glove line of print.grasps(): the profile, channels not drawn, stuck ones.
print_glove_line <- function(x) {
  g <- x$glove
  if (is.null(g)) return(invisible())
  ch <- g$channels
  undrawn <- ch$channel[is.na(ch$axis)]
  cli::cat_line("  glove: ", g$name, if (length(undrawn)) paste("; not drawn:", paste(utils::head(undrawn, 6), collapse = " ")))
  if (any(ch$stuck)) cli::cat_line("  stuck channels (constant, left out of models): ", paste(ch$channel[ch$stuck], collapse = " "))
  invisible()
}
