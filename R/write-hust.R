# Writer for the HUST layout: one delimited file per recording, 16 columns in
# the order of `hust_dofs`, plus a manifest CSV that carries the metadata the
# HUST file names do not (see read_hust()).

#' Write recordings in the HUST layout
#'
#' Writes each recording of a [grasps()] object with the 16 HUST DoFs to one
#' delimited text file (one row per frame, columns in the order of
#' [hust_dofs]) and a manifest CSV mapping each file to its metadata, so that
#' [read_hust()] on the directory returns the same set.
#'
#' @param x A `grasps` object whose DoFs are the 16 HUST DoF names (any
#'   order). For GraspDB14 recordings use [graspdb14_to_hust()] first.
#' @param dir Directory to write to (created if needed).
#' @param file_names File names, one per recording; by default the recording
#'   id (characters other than letters, digits, `-`, `_` and `.` replaced by
#'   `_`) with extension `.csv`.
#' @param sep Field separator, `","` (default) or `";"`.
#' @param header Write a header row with the DoF names?
#' @param digits Significant digits written (15 keeps doubles to about
#'   1e-15 relative precision).
#' @param manifest Name of the manifest file written into `dir`, or `NULL`
#'   for none. Columns: `file`, `id`, `grasp` (Feix name),
#'   `subject`, `object`, `trial`, `rate`, `unit`, then every other atomic
#'   metadata column except `n_frames` and `source`.
#' @param overwrite Replace existing files? By default an existing file is
#'   an error of class `handmotion_error_file_exists` naming it, and nothing
#'   is written.
#' @return The paths of the data files, invisibly (the manifest path is
#'   attribute `"manifest"`).
#' @seealso [read_hust()]
#' @export
#' @examples
#' g <- read_hust(system.file("extdata", "hust", package = "handmotion"))
#' dir <- tempfile("hust-")
#' write_hust(g, dir)
#' list.files(dir)
#' all.equal(read_hust(dir)$recordings, g$recordings)
write_hust <- function(x, dir, file_names = NULL, sep = ",", header = FALSE, digits = 15L,
                       manifest = "manifest.csv", overwrite = FALSE) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  check_some_recordings(x, what = "write", call = call)
  dofs <- handmotion::hust_dofs$name
  if (length(x$dofs) != length(dofs) || !setequal(x$dofs, dofs)) {
    hm_abort(c("{.arg x} must have the 16 HUST DoFs to be written in the HUST layout.",
               i = "Its DoFs: {.val {utils::head(x$dofs, 6)}}{if (length(x$dofs) > 6) '...' else ''}.",
               i = if (all(handmotion::cyberglove_sensors$name %in% x$dofs))
                 "Convert GraspDB14 recordings with {.fn graspdb14_to_hust} first." else NULL),
             "bad_input", argument = "x", call = call)
  }
  # fewer significant digits would round angles by whole degrees (the file
  # would read back as other grasps); more than 17 add nothing to a double
  digits <- check_whole(digits, "digits", min = 6, max = 17, call = call)
  sep <- check_choice(sep, c(",", ";"), "sep", whole = FALSE, call = call)
  if (is.null(file_names)) file_names <- paste0(gsub("[^A-Za-z0-9._-]", "_", x$meta$id), ".csv")
  if (length(file_names) != length(x) || anyDuplicated(tolower(file_names))) {
    hm_abort("{.arg file_names} must be {length(x)} distinct name{?s} (case-insensitively).",
             "bad_input", argument = "file_names", call = call)
  }
  if (!is.null(manifest) && tolower(manifest) %in% tolower(file_names)) {
    hm_abort("A data file cannot be named like the manifest {.val {manifest}}.", "bad_input",
             argument = "file_names", call = call)
  }
  dir <- create_output_dir(dir, call = call)
  paths <- file.path(dir, file_names)
  targets <- c(paths, if (!is.null(manifest)) file.path(dir, manifest))
  check_overwrite(targets, overwrite, call = call)
  fmt <- paste0("%.", digits, "g")
  for (i in seq_along(paths)) {
    rec <- x$recordings[[i]][, dofs, drop = FALSE]
    vals <- sprintf(fmt, rec)
    # a semicolon file is the European CSV: decimal commas
    if (sep == ";") vals <- sub(".", ",", vals, fixed = TRUE)
    dim(vals) <- dim(rec)
    body <- do.call(paste, c(as.data.frame(vals, stringsAsFactors = FALSE), sep = sep))
    write_text_file(c(if (header) paste(dofs, collapse = sep), body), paths[i], use_bytes = TRUE, call = call)
  }
  if (!is.null(manifest)) {
    m <- x$meta
    man <- data.frame(file = file_names, id = m$id, grasp = as.character(m$grasp), subject = m$subject, object = m$object,
                      trial = m$trial, rate = x$rate, unit = x$unit, stringsAsFactors = FALSE)
    extra <- setdiff(names(m), c(names(man), "n_frames", "source"))
    extra <- extra[vapply(m[extra], function(v) is.atomic(v) && is.null(dim(v)), logical(1))]
    for (v in extra) man[[v]] <- m[[v]]
    utils::write.csv(man, file.path(dir, manifest), row.names = FALSE, na = "")
    attr(paths, "manifest") <- file.path(dir, manifest)
  }
  invisible(paths)
}
