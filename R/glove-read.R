# read_glove(): the glove-first entry to the readers (the rows and columns
# of any data glove through a glove profile); the reading is read_hust()'s.

#' Read recordings of any data glove
#'
#' Reads delimited text files of a data glove's channels, one file per
#' recording and one row per frame, with labels from the file names or
#' folders (`pattern`) or a manifest: [read_hust()] with the columns and
#' units of the `glove` profile. Every file that cannot be read is reported
#' (attribute `"failures"`, see [read_failures()]), never dropped silently.
#'
#' Files as labs keep them: a folder per label (`pattern` with a `/` is
#' matched against the path below `path`, e.g. `"^(?<grasp>[^/]+)/"` for
#' "the label is the first folder"; sub-folders are then read), the same
#' file name in several folders (ids become the relative paths), and time
#' stamps in a column (`time`) when frames are unevenly spaced: every
#' recording is resampled to one constant rate by linear interpolation
#' (`rate`, by default one over the median interval between frames), each
#' file's own rate kept in `meta$recorded_rate` and the resampling shown by
#' `print()` and `summary()`. Details in [read_hust()].
#'
#' The package ships 626 real recordings of a six-flex-sensor glove in this
#' layout (`system.file("extdata", "flexglove", package = "handmotion")`:
#' folders per grasp type, files `<P1|P2>_<object>_<trial>.csv` with columns
#' `time_ms,flex1,...,flex6`; source Oooorca/AML_LAB_Project, MIT licence;
#' see the README.md there): the first example reads them all.
#'
#' @param path A directory, or one or more files.
#' @param glove The [glove_profile()] of the glove (or a shipped profile's
#'   name).
#' @param rate Sampling rate in Hz. `NULL` (default): with `time`, one over
#'   the median interval between frames; else the manifest's, else 50.
#' @param ... Further arguments of [read_hust()]: `manifest`, `pattern`,
#'   `time`, `time_unit`, `timestamps`, `header`, `sep`, `unit`, `file_pattern`,
#'   `recursive`, `truncated`.
#' @return A [grasps()] object carrying `glove`.
#' @seealso [glove_profile()], [calibrate()], [trim_motion()]
#' @export
#' @examples
#' # the shipped real recordings: 626 files, 8 grasp folders, 2 participants
#' g <- read_glove(system.file("extdata", "flexglove", package = "handmotion"), glove = "flexglove", time = "time_ms", pattern = "^(?<grasp>[^/]+)/(?<subject>P\\d)_(?<object>[a-z]+)_(?<trial>\\d+)$")
#' g
#' table(g$meta$grasp, g$meta$subject)
#'
#' # your own files: labels from the file names
#' raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 3, pen = 20), objects = 1,
#'                        trials = 2, glove = "resistive", rest = 1, hold = 1, seed = 1)
#' dir <- tempfile("glove")
#' dir.create(dir)
#' for (i in seq_along(raw)) {
#'   f <- file.path(dir, sprintf("%s_%d.csv", raw$meta$grasp[i], i))
#'   write.csv(raw$recordings[[i]], f, row.names = FALSE)
#' }
#' g <- read_glove(dir, glove = "resistive", rate = 50,
#'                 pattern = "^(?<grasp>[a-z]+)_(?<trial>\\d+)$")
#' g
read_glove <- function(path, glove, rate = NULL, ...) {
  call <- rlang::caller_env()
  if (missing(glove)) {
    hm_abort("{.arg glove} is needed: the profile that says what each column measures.",
             "bad_input", argument = "glove", call = call)
  }
  check_dots_for(list(...), read_hust, "read_glove", exclude = c("glove", "rate", "path"), call = call)
  read_hust(path, glove = glove, rate = rate, ...)
}
