# Classed errors. Every error the package raises inherits from
# "handmotion_error" and from one of three families, so callers (and the
# Python front end) can tell a bad file from a bad argument from a failed fit
# without parsing text. The family of each specific class lives in one table
# below; hm_abort() adds it, so no call site has to remember it.

#' Errors raised by handmotion
#'
#' Every error handmotion raises is a condition of class `handmotion_error`,
#' with one family class and, below it, a specific class naming what went
#' wrong. Catch a family with `tryCatch(..., handmotion_error_bad_file = ...)`
#' or a specific class with `handmotion_error_truncated_line`. Each condition
#' carries the offending argument, file, line, recording or joint as fields
#' (`cnd$argument`, `cnd$file`, `cnd$line`, `cnd$recording`, ...).
#'
#' * `handmotion_error_bad_input`: a bad argument or recording. Specific
#'   classes: `bad_recording`, `unknown_grasp`, `no_labels`, `bad_markers`,
#'   `occluded`, `bad_mapping`, `dof_mismatch`, `multiple_grasps`,
#'   `bad_params`, `bad_skeleton` (a skeleton that does not fit the data),
#'   `too_few_subjects`, `bad_glove` (a glove profile that cannot be used;
#'   with `bad_file` when read from a file) and `not_feix_labels` (a thesis
#'   table asked of labels that are not Feix types).
#' * `handmotion_error_bad_file`: a file that cannot be read in its format.
#'   Specific classes: `empty_file`, `bad_field_count`, `truncated_line`,
#'   `non_numeric`, `bad_value`, `unknown_header`, `unknown_file_name`,
#'   `file_not_found`, `missing_file`, `not_in_manifest`, `bad_manifest`,
#'   `no_files`, `file_exists`, `no_switch`, `no_segments`, `unreadable_file`
#'   (a folder, a broken link or no read permission), `not_text` (a binary
#'   file), `unwritable_file` (a path a writer cannot write),
#'   `missing_column` (a file without the named time column), `bad_time`
#'   (time stamps that do not increase), and
#'   `bad_skeleton`
#'   raised while reading an `.xmlskel` file.
#' * `handmotion_error_fit_failed`: data that cannot be fitted, or a fitted
#'   object that cannot be used.
#'   Specific classes: `too_few_recordings`, `reference_too_small`,
#'   `model_failed` (a grasp type whose model could not be fitted, asked for
#'   by name), `alignment_failed` (dynamic time warping failed),
#'   `engine_failed` (a reference engine such as fda.usc failed) and
#'   `bad_model` (a fitted model whose parts were changed after fitting, or
#'   that lacks what was asked of it, e.g. a temperature for probabilities).
#' * `handmotion_error_missing_dependency`: a suggested package that a
#'   function needs is not installed (no family).
#'
#' All specific classes are prefixed with `handmotion_error_`.
#'
#' **Warnings** follow the same scheme under `handmotion_warning`. The family
#' `handmotion_warning_degenerate` marks data a function accepted with a
#' fallback (the result is usable and its `print()` says what happened) but
#' that is almost certainly not what was meant; its specific classes are
#' `one_frame` (recordings of a single frame), `identical_recordings` (the
#' recordings do not vary), `constant_dofs` (some DoFs do not vary),
#' `rank_deficient` (more components than the rank of the data),
#' `small_mixture` (too few recordings for the mixture's `k` components),
#' `linear_fallback` (dynamic time warping failed and linear warping was
#' used), `non_finite` (recordings holding `NaN` or infinite values),
#' `short_recordings` (recordings of fewer than three frames, fitted or
#' classified all the same) and
#' `zero_window` (a DTW window that leaves only the diagonal path). One
#' warning carries every class that applies, and the rows in its field
#' `degenerate_data` (`class`, `message`). Other warnings: `read_failures`
#' (files a directory read skipped), `truncated_line` and `unknown_header`
#' (a file read with a fallback), `few_recordings` (a grasp type with
#' fewer than three recordings, or a last-frame type with fewer recordings
#' than PCs), `model_failed` (types whose model failed: skipped, or left out
#' of a fitted set), `projection_failed` (models that could not score the
#' recordings), `fold_failed` (an evaluation fold that could not be
#' fitted), `skeleton_default_unit` (a skeleton file without a unit),
#' `constant_channels` (channels constant in every recording, left out of
#' the correlation measures), `no_limits` (no joint limits to keep
#' generated grasps within), `stuck_channels` (glove channels that never
#' change), `mixed_labels` (labels of which only some are Feix types),
#' `guessed_glove` (raw counts with recognised channel names but no
#' profile, drawn through a guessed map), `switch_unchanged` (a recording
#' [segment_by_switch()] could not cut: its switch never changes), `note`
#' and `deprecated`.
#'
#' From Python the error families are `BadInputError`, `BadFileError` and
#' `FitFailedError`, all subclasses of `HandmotionError`; warnings arrive as
#' `HandmotionWarning` (`DegenerateDataWarning` for the degenerate family),
#' carrying the R class vector in `r_class`.
#'
#' @name handmotion_errors
#' @examples
#' cnd <- tryCatch(simulate_grasps(grasps = "No Such Grasp"),
#'                 handmotion_error = function(e) e)
#' class(cnd)
#' inherits(cnd, "handmotion_error_bad_input")
NULL

# Specific class -> family: every class the package raises is listed (a
# test scans R/ for them). A class given with "bad_file" or "fit_failed"
# (abort_bad_file() adds "bad_file") takes that family over "bad_input"; a
# class not listed would fall back to "bad_input".
error_families <- c(
  bad_input = "bad_input", bad_recording = "bad_input", unknown_grasp = "bad_input",
  no_labels = "bad_input", bad_markers = "bad_input", occluded = "bad_input",
  bad_mapping = "bad_input", dof_mismatch = "bad_input", multiple_grasps = "bad_input",
  bad_params = "bad_input", bad_skeleton = "bad_input", too_few_subjects = "bad_input",
  bad_glove = "bad_input", not_feix_labels = "bad_input",
  bad_file = "bad_file", empty_file = "bad_file", bad_field_count = "bad_file",
  truncated_line = "bad_file", non_numeric = "bad_file", bad_value = "bad_file",
  unknown_header = "bad_file", unknown_file_name = "bad_file",
  file_not_found = "bad_file", missing_file = "bad_file",
  not_in_manifest = "bad_file", bad_manifest = "bad_file", no_files = "bad_file",
  file_exists = "bad_file", no_switch = "bad_file", no_segments = "bad_file",
  unreadable_file = "bad_file", not_text = "bad_file", unwritable_file = "bad_file",
  missing_column = "bad_file", bad_time = "bad_file",
  fit_failed = "fit_failed", too_few_recordings = "fit_failed",
  reference_too_small = "fit_failed", model_failed = "fit_failed",
  alignment_failed = "fit_failed", engine_failed = "fit_failed", bad_model = "fit_failed",
  missing_dependency = NA_character_
)

# The class vector of a handmotion condition: specific classes first, then the
# family, then the root.
error_classes <- function(class) {
  listed <- class %in% names(error_families)
  family <- if (any(listed)) unique(unname(error_families[class[listed]])) else "bad_input"
  if (length(family) > 1L) family <- setdiff(family, "bad_input")
  family <- family[!is.na(family)]
  c(paste0("handmotion_error_", unique(c(class, family))), "handmotion_error")
}

#' Raise a classed handmotion error
#'
#' @param message A cli-formatted message (character vector; names give bullets).
#' @param class Specific class name(s); the condition gets
#'   `handmotion_error_<class>`, its family (see [handmotion_errors]) and
#'   `handmotion_error`.
#' @param ... Extra fields stored in the condition (e.g. `file`, `line`,
#'   `argument`, `recording`).
#' @param call The user-facing call to report, passed down from the exported
#'   function with `call = rlang::caller_env()`.
#' @param .envir Environment in which the cli message is interpolated.
#' @noRd
hm_abort <- function(message, class = "bad_input", ..., call = rlang::caller_env(),
                     .envir = parent.frame()) {
  cli::cli_abort(message, class = error_classes(class), ..., call = call, .envir = .envir)
}

# Specific warning class -> family, as error_families does for errors
# (NA: no family). Every warning class the package raises is listed.
warning_families <- c(
  one_frame = "degenerate", identical_recordings = "degenerate", constant_dofs = "degenerate",
  rank_deficient = "degenerate", small_mixture = "degenerate", linear_fallback = "degenerate",
  non_finite = "degenerate", zero_window = "degenerate", short_recordings = "degenerate",
  read_failures = NA, truncated_line = NA, unknown_header = NA, few_recordings = NA,
  model_failed = NA, projection_failed = NA, fold_failed = NA, skeleton_default_unit = NA,
  constant_channels = NA, no_limits = NA, stuck_channels = NA, mixed_labels = NA, guessed_glove = NA,
  switch_unchanged = NA,
  note = NA, deprecated = NA
)

# The class vector of a handmotion warning: specific classes, family, root.
warning_classes <- function(class) {
  family <- unname(warning_families[class[class %in% names(warning_families)]])
  family <- family[!is.na(family)]
  c(paste0("handmotion_warning_", unique(c(class, family))), "handmotion_warning")
}

#' Warn with a classed handmotion warning
#' @noRd
hm_warn <- function(message, class = "note", ..., .envir = parent.frame()) {
  cli::cli_warn(message, class = warning_classes(class), ..., .envir = .envir)
}
