# Reader for the HUST grasp data layout (Jeppsson 2017, section 4.1.1): one
# delimited text file per grasp, 16 columns (the DoFs of Figure 4.1, in the
# order of `hust_dofs`), one row per 1/50 s. The thesis does not document the
# file names, so the grasp, subject, object and trial of each file come from a
# manifest or from a regular expression with named groups.

hust_manifest_name <- "manifest.csv"

#' Read HUST-layout grasp recordings
#'
#' Reads delimited text files with one row per frame and the 16 HUST DoFs as
#' columns (see [hust_dofs]) into a [grasps()] object. Each file is one grasp.
#'
#' Where the metadata comes from, in order:
#' 1. `manifest`: a data frame, or the path of a CSV file, with a column
#'    `file` (file name or path, relative to the manifest's folder or to
#'    `path`) and any of `grasp` (the label: any string, e.g. a Feix type or
#'    an object), `subject`, `object`,
#'    `trial`, `id`, `rate`, `unit` and further columns (kept as metadata).
#' 2. `pattern`: a Perl regular expression with named groups (`grasp`,
#'    `subject`, `object`, `trial`, `id`) matched against each file name
#'    without its extension, e.g.
#'    `"^s(?<subject>\\d+)_g(?<grasp>\\d+)_o(?<object>\\d+)_t(?<trial>\\d+)$"`.
#'    A pattern that contains a `/` is matched against the file's path
#'    below `path` instead (folders separated by `/`, no extension), so
#'    labels can come from folders: `"^(?<grasp>[^/]+)/"` takes the label
#'    from the first folder (a folder per label), and
#'    `"^(?<grasp>[^/]+)/(?<subject>P\\d)_"` the subject from the file name
#'    as well. Such a pattern looks into sub-folders (`recursive = NA`).
#' 3. A `manifest.csv` in a directory given as `path` (what [write_hust()]
#'    writes).
#' 4. Otherwise ids are the file names and grasp, subject, object and trial
#'    are unknown (`NA`).
#'
#' Recording ids are the file names without extension; when a name
#' repeats (the same `P1_pen_1.csv` in two label folders) every id is the
#' file's path below `path` instead (`"Ventral/P1_pen_1"`), so ids are
#' always unique.
#'
#' **Time stamps.** Files whose frames are not evenly spaced (an Arduino
#' glove writes a line about every 30 ms, unevenly) carry a time column:
#' name it with `time` (its unit from `time_unit`, or from the name's
#' suffix: `"time_ms"` is milliseconds, `"t_s"` seconds, `"t_us"`
#' microseconds). Files with a header must have that column (anywhere);
#' files without one have it first. Times must increase from frame to
#' frame. Time stamps kept in files of their own (one per data file, at the
#' same path below a folder) are read with `timestamps`. Every recording is
#' then resampled onto a constant grid from its
#' first time by linear interpolation, at `rate`, or by default at one over
#' the median interval between frames over the whole set. The metadata
#' column `recorded_rate` keeps each file's own rate (one over its median
#' interval) and `print()` and `summary()` say the set was resampled.
#'
#' Files may have a header row or none (detected by default: a first row
#' that is not all numbers is a header; header names matching the HUST DoF
#' names, in any order and case, put the columns in the standard order), and
#' be separated by commas, semicolons (then a decimal comma is accepted),
#' tabs or blanks (detected per file by default). Blank lines, surrounding
#' blanks, quotes, a trailing separator and CRLF line endings are accepted.
#'
#' @param path A directory, or one or more files.
#' @param manifest `NULL`, a data frame or the path of a manifest CSV (see
#'   Details).
#' @param pattern `NULL` or a regular expression with named groups, matched
#'   against file names, or against paths below `path` when it holds a `/`
#'   (see Details).
#' @param header `NA` (detect), `TRUE` or `FALSE`.
#' @param sep `NA` (detect per file) or the separator, e.g. `","` or `";"`.
#' @param rate Sampling rate in Hz; `NULL` takes it from the manifest's
#'   `rate` column, else, with `time`, one over the median interval between
#'   frames, else 50 Hz (the HUST rate). With `time`, the rate the
#'   recordings are resampled to.
#' @param unit Angle unit; `NULL` takes it from the manifest's `unit`
#'   column, else `"deg"`.
#' @param file_pattern Regular expression selecting data files in a directory.
#' @param recursive Look into sub-directories: `TRUE`, `FALSE`, or `NA`
#'   (default) for "when `pattern` holds a `/`".
#' @param truncated `"error"` or `"drop"` a truncated last line (fewer
#'   fields than DoFs); see [read_graspdb14()].
#' @param glove `NULL` for the 16 HUST DoFs, or the [glove_profile()] (or a
#'   shipped profile's name) of the glove that wrote the files: its channels
#'   are the columns (matched to a header by name, else in the profile's
#'   order), and `unit` defaults to the profile's. See [read_glove()].
#' @param time `NULL` (frames evenly spaced at `rate`), or the name of the
#'   files' time column (see Details): the recordings are resampled to a
#'   constant rate.
#' @param time_unit Unit of the time column: `"ms"`, `"s"` or `"us"`;
#'   `NULL` reads it from the column name's suffix (`"time_ms"`).
#' @param timestamps `NULL` (the time column is in the data files), or a
#'   folder (below `path`, or a path) holding the `time` column of each data
#'   file in a file at the same relative path, e.g. `"timestamps"` for
#'   `timestamps/Ventral/P1_pen_1.csv` beside `Ventral/P1_pen_1.csv`; its
#'   files are not read as recordings.
#' @return A `grasps` object with the 16 HUST DoFs (or the glove's
#'   channels). Attribute `"failures"`
#'   lists every file that could not be read (see [read_failures()]): bad
#'   content (classed errors as in [read_graspdb14()]), a file name the
#'   `pattern` does not match (`handmotion_error_unknown_file_name`), a
#'   manifest row whose file is missing (`handmotion_error_file_not_found`)
#'   or whose grasp is unknown (`handmotion_error_unknown_grasp`), and files
#'   of the directory the manifest does not list
#'   (`handmotion_error_not_in_manifest`), a file without the `time`
#'   column (`handmotion_error_missing_column`) or whose times do not
#'   increase (`handmotion_error_bad_time`). Reading a single file raises
#'   these errors instead.
#' @seealso [write_hust()], [simulate_grasps()]
#' @export
#' @examples
#' dir <- system.file("extdata", "hust", package = "handmotion")
#' g <- read_hust(dir)
#' g
#' g$meta
read_hust <- function(path, manifest = NULL, pattern = NULL, header = NA, sep = NA,
                      rate = NULL, unit = NULL, file_pattern = "\\.(csv|txt)$",
                      recursive = NA, truncated = c("error", "drop"), glove = NULL,
                      time = NULL, time_unit = NULL, timestamps = NULL) {
  call <- rlang::caller_env()
  truncated <- check_choice(truncated, arg = "truncated", call = call)
  pattern <- check_regex(pattern, "pattern", perl = TRUE, allow_null = TRUE, call = call)
  time <- check_time_arg(time, time_unit, call = call)
  check_flag(recursive, "recursive", allow_na = TRUE, call = call)
  # a pattern about folders means the files are in folders
  if (is.na(recursive)) recursive <- is_path_pattern(pattern)
  if (!is.null(rate)) check_rate(rate, call = call)
  file_pattern <- check_regex(file_pattern, "file_pattern", allow_null = TRUE, call = call)
  sep <- check_sep(sep, call = call)
  if (!is.null(manifest) && !is.null(pattern)) {
    hm_abort("Give {.arg manifest} or {.arg pattern}, not both.", "bad_input",
             argument = "manifest", call = call)
  }
  input <- list_input_files(path, file_pattern, recursive, call = call)
  base_dir <- if (length(path) == 1L && dir.exists(path)) path else dirname(path[1])
  ts_dir <- timestamps_dir(timestamps, time, base_dir, call = call)
  if (!is.null(ts_dir)) input$files <- input$files[!under_dir(input$files, ts_dir)]
  if (is.null(manifest) && is.null(pattern) && length(path) == 1L && dir.exists(path) &&
      file.exists(file.path(path, hust_manifest_name))) {
    manifest <- file.path(path, hust_manifest_name)
  }
  plan <- hust_read_plan(input$files, manifest, pattern, base_dir,
                         from_dir = any(dir.exists(path)), call = call)
  if (!is.null(glove)) glove <- glove_profile(glove)
  dofs <- if (is.null(glove)) handmotion::hust_dofs$name else glove$channels$channel
  columns <- c(time$column, dofs)
  reader <- function(k) {
    pre <- plan$errors[[k]]
    if (!is.null(pre)) stop(pre)
    if (is.null(ts_dir)) {
      rec <- parse_hust_content(plan$files[k], dofs = columns, header = header, sep = sep,
                                truncated = truncated, time = time$column, call = call)
    } else {
      rec <- parse_hust_content(plan$files[k], dofs = dofs, header = header, sep = sep,
                                truncated = truncated, call = call)
      rec <- add_time_file(rec, plan$files[k], base_dir, ts_dir, time, header, sep, truncated, call = call)
    }
    if (!is.null(time)) rec <- split_time_column(rec, time, rec$time_file %||% plan$files[k], call = call)
    rec
  }
  if (!input$many) {
    rec <- reader(1L)
    keep <- 1L
    failures <- empty_read_failures()
    recs <- list(rec)
  } else {
    read <- read_each_file(seq_along(plan$files), reader)
    read$failures$file <- plan$files[as.integer(read$failures$file)]
    failures <- rbind(read$failures, plan$unlisted)
    keep <- as.integer(read$files)
    recs <- read$results
    warn_read_failures(failures, total = length(plan$files) + nrow(plan$unlisted))
    if (length(recs) == 0L) {
      hm_abort(c("None of the {length(plan$files)} HUST file{?s} could be read.",
                 i = if (nrow(failures)) "First failure: {failures$message[1]}" else NULL),
               "no_files", file = path, failures = failures, call = call)
    }
  }
  meta <- plan$meta[keep, , drop = FALSE]
  # only a "drop" read can drop lines; record which files lost one
  if (truncated == "drop") meta$dropped_last_line <- vapply(recs, `[[`, logical(1), "dropped")
  if (is.null(rate)) rate <- manifest_single(meta, "rate", if (is.null(time)) 50, call = call)
  if (is.null(unit)) unit <- manifest_single(meta, "unit", NA, call = call)
  if (is.na(unit)) unit <- NULL   # the glove's unit, else degrees
  meta$rate <- NULL
  meta$unit <- NULL
  values <- lapply(recs, `[[`, "values")
  if (!is.null(time)) {
    # uneven frames onto one constant grid, recorded in the metadata
    res <- resample_read(recs, rate)
    values <- res$values
    rate <- res$rate
    meta$recorded_rate <- res$recorded_rate
  }
  out <- grasps(values, meta = meta, dofs = dofs, rate = as.numeric(rate),
                unit = unit, glove = glove)
  attr(out, "failures") <- failures
  out
}

# The one value of a manifest column (rate, unit), or the default.
manifest_single <- function(meta, column, default, call = rlang::caller_env()) {
  v <- unique(stats::na.omit(meta[[column]]))
  if (length(v) == 0L) return(default)
  if (length(v) > 1L) {
    hm_abort("The manifest gives several values of {.field {column}} ({.val {v}}); one grasps set has one.",
             "bad_manifest", argument = "manifest", call = call)
  }
  v
}

# Decide, before reading any content, which files to read and with what
# metadata. Problems found here (unknown name, missing file, unknown grasp)
# are stored per file and raised when that file is "read", so they land in
# the failure report like content errors.
hust_read_plan <- function(files, manifest, pattern, base_dir, from_dir, call = rlang::caller_env()) {
  unlisted <- empty_read_failures()
  if (!is.null(manifest)) {
    man <- read_hust_manifest(manifest, call = call)
    man_dir <- if (is.character(manifest)) dirname(manifest) else base_dir
    # manifest paths are relative to the manifest's folder; absolute ones are kept
    rel <- file.path(man_dir, man$file)
    listed <- ifelse(file.exists(rel) | !file.exists(man$file), rel, man$file)
    norm <- function(p) normalizePath(p, mustWork = FALSE)
    files <- files[basename(files) != hust_manifest_name]
    if (from_dir) {
      # data files next to the manifest that it does not mention are reported
      extra <- files[!norm(files) %in% norm(listed)]
    } else {
      # files named explicitly: read only their manifest rows
      rows <- match(norm(files), norm(listed))
      by_name <- match(basename(files), basename(listed))
      rows[is.na(rows)] <- by_name[is.na(rows)]
      extra <- files[is.na(rows)]
      man <- man[stats::na.omit(rows), , drop = FALSE]
      listed <- files[!is.na(rows)]
    }
    if (length(extra)) {
      unlisted <- data.frame(file = extra, line = NA_integer_, class = "handmotion_error_not_in_manifest",
                             message = "File is not listed in the manifest; not read.",
                             stringsAsFactors = FALSE)
      if (!from_dir && length(listed) == 0L) {
        abort_bad_file("File{?s} {.file {extra}} {?is/are} not listed in the manifest.",
                       "not_in_manifest", file = extra, call = call)
      }
    }
    meta <- man
    meta$file <- NULL
    if (!"id" %in% names(meta)) meta$id <- unique_ids(file_stem(listed), file_stem_path(man$file), listed)
    meta$source <- listed
    errors <- lapply(seq_along(listed), function(k) {
      if (!file.exists(listed[k])) {
        return(hm_condition("Manifest row {k}: file {.file {listed[k]}} does not exist.",
                            c("file_not_found", "bad_file"), file = listed[k], line = NA_integer_))
      }
      NULL
    })
    return(list(files = listed, meta = meta, errors = errors, unlisted = unlisted))
  }
  files <- files[basename(files) != hust_manifest_name]
  rel <- relative_stems(files, base_dir)
  meta <- data.frame(id = unique_ids(file_stem(files), rel, files), source = files, stringsAsFactors = FALSE)
  errors <- vector("list", length(files))
  if (!is.null(pattern)) {
    # a pattern with a "/" is about the folders too: matched against the
    # path below `path`, without extension
    target <- if (is_path_pattern(pattern)) rel else file_stem(files)
    groups <- lapply(target, function(s) regex_groups(s, pattern))
    known <- c("grasp", "subject", "object", "trial", "id")
    names_found <- unique(unlist(lapply(groups, names)))
    if (length(groups) && !length(intersect(names_found, known)) && all(!vapply(groups, is.null, logical(1)))) {
      hm_abort(c("{.arg pattern} has no named group among {.val {known}}.",
                 i = "Write e.g. {.code (?<grasp>\\\\d+)} for a group named grasp."),
               "bad_input", argument = "pattern", call = call)
    }
    for (col in intersect(known, names_found)) {
      meta[[col]] <- vapply(groups, function(g) if (is.null(g) || g[[col]] == "") NA_character_ else g[[col]],
                            character(1))
    }
    for (k in which(vapply(groups, is.null, logical(1)))) {
      errors[[k]] <- hm_condition("File name {.file {target[k]}} does not match {.arg pattern} ({.code {pattern}}).",
                                  c("unknown_file_name", "bad_file"), file = files[k], line = NA_integer_)
    }
    if ("trial" %in% names(meta)) meta$trial <- suppressWarnings(as.integer(meta$trial))
  }
  list(files = files, meta = meta, errors = errors, unlisted = unlisted)
}

# Whether a file-name pattern is about folders too (it holds a "/").
is_path_pattern <- function(pattern) !is.null(pattern) && grepl("/", pattern, fixed = TRUE)

# A path without its extension (a file_stem() that keeps the folders).
file_stem_path <- function(path) sub("\\.[[:alnum:]]+$", "", trimws(path))

# Each file's path below `base_dir`, "/"-separated ("Ventral/P1_pen_1.csv");
# a file outside `base_dir` keeps only its name.
relative_paths <- function(files, base_dir) {
  f <- normalizePath(files, winslash = "/", mustWork = FALSE)
  b <- sub("/+$", "", normalizePath(base_dir, winslash = "/", mustWork = FALSE))
  inside <- startsWith(f, paste0(b, "/"))
  ifelse(inside, substring(f, nchar(b) + 2L), basename(f))
}

# The same without extension ("Ventral/P1_pen_1").
relative_stems <- function(files, base_dir) file_stem_path(relative_paths(files, base_dir))

# Recording ids: the file names, or, when a name repeats (the same
# "P1_pen_1.csv" in two label folders), every file's relative path, or when
# even those repeat (files named one by one from different folders), the
# full paths.
unique_ids <- function(stems, rel, full) {
  if (!anyDuplicated(stems)) return(stems)
  if (!anyDuplicated(rel)) return(rel)
  file_stem_path(normalizePath(full, winslash = "/", mustWork = FALSE))
}

# A classed condition object built like hm_abort() would, without raising it.
hm_condition <- function(message, class, ..., .envir = parent.frame()) {
  tryCatch(hm_abort(message, class, ..., call = NULL, .envir = .envir),
           handmotion_error = function(e) e)
}

# Read and check a manifest (data frame or CSV path).
read_hust_manifest <- function(manifest, call = rlang::caller_env()) {
  if (is.character(manifest) && length(manifest) == 1L) {
    if (!file.exists(manifest)) {
      hm_abort("Manifest {.file {manifest}} does not exist.", "file_not_found",
               file = manifest, argument = "manifest", call = call)
    }
    # through the shared text reader: an unreadable or binary manifest is a
    # classed error, and stray Latin-1 bytes are converted (read.csv() on the
    # file stopped with "invalid multibyte string")
    lines <- read_text_lines(manifest, call = call)$text
    # all text first: ids like "007" must not become numbers
    man <- tryCatch(utils::read.csv(text = lines, colClasses = "character", strip.white = TRUE,
                                    check.names = FALSE, na.strings = c("NA", "")),
                    error = function(e) {
                      hm_abort("Cannot read manifest {.file {manifest}}: {conditionMessage(e)}",
                               c("bad_manifest", "bad_file"), file = manifest, line = NA_integer_,
                               argument = "manifest", call = call)
                    })
  } else if (is.data.frame(manifest)) {
    man <- as.data.frame(manifest, stringsAsFactors = FALSE)
  } else {
    hm_abort("{.arg manifest} must be a data frame or the path of a CSV file.", "bad_input",
             argument = "manifest", call = call)
  }
  names(man) <- trimws(tolower(names(man)))
  if (!"file" %in% names(man) || nrow(man) == 0L || anyNA(man$file)) {
    hm_abort(c("The manifest needs a {.field file} column naming every data file.",
               i = "Its columns: {.val {names(man)}}."),
             "bad_manifest", argument = "manifest", call = call)
  }
  man$file <- trimws(as.character(man$file))
  text_cols <- c("file", "id", "grasp", "subject", "object")
  for (v in setdiff(names(man), text_cols)) {
    if (is.character(man[[v]])) man[[v]] <- utils::type.convert(man[[v]], as.is = TRUE)
  }
  if ("trial" %in% names(man)) man$trial <- suppressWarnings(as.integer(man$trial))
  man
}

# Parse one HUST file into a frames x DoF matrix (columns in `dofs` order).
parse_hust_content <- function(file, dofs, header = NA, sep = NA, truncated = "error",
                               time = NULL, call = rlang::caller_env()) {
  text <- read_text_lines(file, call = call)$text
  keep <- nzchar(text) & !startsWith(text, "#")
  if (!any(keep)) {
    abort_bad_file("{.file {file}} is empty: it has no data rows.", "empty_file",
                   file = file, line = if (length(text)) length(text) else NA_integer_, call = call)
  }
  line_no <- which(keep)
  text <- text[keep]
  if (is.na(sep)) sep <- detect_separator(text[min(2L, length(text))])
  tokens <- if (sep == " ") strsplit(text, "[ \t]+", perl = TRUE) else strsplit(text, sep, fixed = TRUE)
  # cleaned in one pass over all fields (per line, this was most of the
  # time of reading a folder of small files)
  n <- lengths(tokens)
  u <- gsub("^[\"' ]+|[\"' ]+$", "", trimws(unlist(tokens, use.names = FALSE)))
  # a trailing separator leaves one empty last field
  ends <- cumsum(n)
  empty_last <- n > 0L & u[pmax(ends, 1L)] == ""
  if (any(empty_last)) {
    u <- u[-ends[empty_last]]
    n[empty_last] <- n[empty_last] - 1L
  }
  if (sep == ";") u <- sub("^([-+]?[0-9]*),([0-9]+([eE][-+]?[0-9]+)?)$", "\\1.\\2", u)
  tokens <- unname(split(u, factor(rep.int(seq_along(n), n), levels = seq_along(n))))
  first <- tokens[[1]]
  has_header <- if (is.na(header)) any(is.na(suppressWarnings(as.numeric(first)))) else isTRUE(header)
  order <- seq_along(dofs)
  if (has_header) {
    hdr <- first
    tokens <- tokens[-1]
    hdr_line <- line_no[1]
    line_no <- line_no[-1]
    if (length(tokens) == 0L) {
      abort_bad_file("{.file {file}} has a header but no data rows.", "empty_file",
                     file = file, line = hdr_line, call = call)
    }
    m <- match(toupper(hdr), toupper(dofs))
    # a named time column must be in the header: taking another column as
    # the time would resample the recording on its values
    if (!is.null(time) && !toupper(time) %in% toupper(hdr)) {
      abort_bad_file(c("{.file {file}}, line {hdr_line}: no time column {.val {time}} in the header.",
                       i = "Its columns: {.val {hdr}}."),
                     "missing_column", file = file, line = hdr_line, call = call)
    }
    if (length(hdr) == length(dofs) && !anyNA(m) && !anyDuplicated(m)) {
      order <- match(seq_along(dofs), m)
    } else if (length(hdr) == length(dofs) && !is.null(time)) {
      # the time column where the header says, the channels in file order
      tp <- match(toupper(time), toupper(hdr))
      order <- c(tp, setdiff(seq_along(hdr), tp))
      hm_warn("Header of {.file {file}} does not name the glove's channels; they are taken in file order.",
              "unknown_header", file = file, line = hdr_line)
    } else if (length(hdr) == length(dofs)) {
      hm_warn("Header of {.file {file}} does not name the HUST DoFs; columns taken in the standard order.",
              "unknown_header", file = file, line = hdr_line)
    } else {
      # (a first line of text with another field count was dropped without a word)
      hm_warn("The first line of {.file {file}} has {length(hdr)} field{?s}, not one name per DoF ({length(dofs)}); read as a header and ignored.",
              "unknown_header", file = file, line = hdr_line)
    }
  }
  checked <- check_field_counts(tokens, line_no, length(dofs), file, truncated,
                                what = sprintf("A HUST row has one value per DoF (%s).",
                                               paste(dofs, collapse = " ")),
                                call = call)
  v <- parse_numeric_fields(unlist(checked$tokens, use.names = FALSE), checked$line_no,
                            length(dofs), file, call = call)
  values <- matrix(v, ncol = length(dofs), byrow = TRUE)[, order, drop = FALSE]
  colnames(values) <- dofs
  list(values = values, dropped = checked$dropped, line_no = checked$line_no)
}

# The separator of a data line: semicolon, comma, tab, else blanks.
detect_separator <- function(line) {
  if (grepl(";", line, fixed = TRUE)) return(";")
  if (grepl(",", line, fixed = TRUE)) return(",")
  if (grepl("\t", line, fixed = TRUE)) return("\t")
  " "
}
