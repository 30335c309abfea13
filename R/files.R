# File helpers shared by the readers and writers: listing input files,
# checking and reading text files, creating output folders.

# List the files to read from `path` (files and/or directories). Returns the
# files, and whether the read is a "many files" read (any directory, or more
# than one path) that collects failures rather than stopping.
list_input_files <- function(path, pattern, recursive, call = rlang::caller_env()) {
  if (!is.character(path) || length(path) == 0L || anyNA(path)) {
    hm_abort("{.arg path} must be file or directory paths, not {.obj_type_friendly {path}}.",
             "bad_input", argument = "path", call = call)
  }
  missing <- !file.exists(path)
  if (any(missing)) {
    hm_abort("{.arg path} does not exist: {.file {path[missing]}}.",
             "file_not_found", argument = "path", file = path[missing], call = call)
  }
  is_dir <- dir.exists(path)
  files <- unlist(lapply(seq_along(path), function(i) {
    if (!is_dir[i]) return(path[i])
    sort(list.files(path[i], pattern = pattern, full.names = TRUE,
                    recursive = recursive, ignore.case = TRUE))
  }), use.names = FALSE)
  # a folder named like a data file (matching `pattern`) is kept, so that the
  # reader reports it as unreadable instead of skipping it without a word
  sub_dirs <- dir.exists(files)
  if (!is.null(pattern)) {
    sub_dirs <- sub_dirs & !grepl(pattern, basename(files), ignore.case = TRUE)
  }
  files <- files[!sub_dirs]
  list(files = files, many = any(is_dir) || length(path) > 1L)
}

# ---- shared text-parsing helpers (GraspDB14 and HUST readers) ----

# The output folder of a writer, created if need be, or a classed error when
# it cannot be (a file of that name, no permission).
create_output_dir <- function(dir, call = rlang::caller_env()) {
  dir <- check_string(dir, "dir", call = call)
  if (file.exists(dir) && !dir.exists(dir)) {
    abort_bad_file("{.file {dir}} is a file, not a folder to write into.", "unwritable_file",
                   file = dir, argument = "dir", call = call)
  }
  dir.create(dir, showWarnings = FALSE, recursive = TRUE)
  if (!dir.exists(dir)) {
    abort_bad_file("Cannot create the folder {.file {dir}}.", "unwritable_file", file = dir,
                   argument = "dir", call = call)
  }
  dir
}

# Every writer refuses to replace files unless told to: a classed error
# (file_exists, with the files in `file`) naming them, before anything is
# written.
check_overwrite <- function(paths, overwrite, call = rlang::caller_env()) {
  overwrite <- check_flag(overwrite, "overwrite", call = call)
  exists <- file.exists(paths) & !dir.exists(paths)
  if (!overwrite && any(exists)) {
    hm_abort(c("{sum(exists)} file{?s} already exist{?s/}: {.file {utils::head(paths[exists], 3)}}.",
               i = "Use {.code overwrite = TRUE} to replace existing files."),
             "file_exists", file = paths[exists], argument = "overwrite", call = call)
  }
  invisible(paths)
}

# Write lines to `file`, or a classed error naming the file when it cannot be
# written (a folder, a missing folder, no permission): R's own is "cannot
# open the connection".
write_text_file <- function(lines, file, use_bytes = FALSE, call = rlang::caller_env()) {
  if (dir.exists(file)) {
    abort_bad_file("{.file {file}} cannot be written: it is a folder.", "unwritable_file",
                   file = file, argument = "file", call = call)
  }
  ok <- tryCatch({
    writeLines(lines, file, useBytes = use_bytes)
    TRUE
  }, error = function(e) conditionMessage(e), warning = function(w) conditionMessage(w))
  if (!isTRUE(ok)) {
    abort_bad_file("{.file {file}} cannot be written: {ok}", "unwritable_file", file = file,
                   argument = "file", call = call)
  }
  invisible(file)
}

# Is `file` a symbolic link (broken or not)? (Sys.readlink() gives "" for
# other files and NA where links do not exist.)
is_symlink <- function(file) {
  l <- Sys.readlink(file)
  !is.na(l) & nzchar(l)
}

# A path that names a readable regular file, or a classed error saying why
# not (R's own "cannot open the connection" names neither class nor reason).
check_readable_file <- function(file, call = rlang::caller_env()) {
  why <- if (dir.exists(file)) "it is a folder, not a file"
    else if (!file.exists(file)) {
      if (is_symlink(file)) "it is a broken symbolic link" else "it does not exist"
    } else if (file.access(file, 4L) != 0L) "no read permission"
  if (!is.null(why)) {
    abort_bad_file("{.file {file}} cannot be read: {why}.", "unreadable_file", file = file,
                   line = NA_integer_, call = call)
  }
  invisible(file)
}

# Read a text file as lines: accepts LF, CRLF and CR line endings, trims
# blanks, records whether the last line was complete.
read_text_lines <- function(file, call = rlang::caller_env()) {
  check_readable_file(file, call = call)
  size <- file.size(file)
  if (is.na(size) || size == 0) {
    abort_bad_file("{.file {file}} is empty.", "empty_file", file = file, line = NA_integer_, call = call)
  }
  bytes <- tryCatch(readBin(file, "raw", size), error = function(e) {
    abort_bad_file("{.file {file}} cannot be read: {conditionMessage(e)}", "unreadable_file",
                   file = file, line = NA_integer_, call = call)
  })
  # NUL and the other C0 control bytes (tab, line ends and form feed aside)
  # do not occur in text files
  ctrl <- bytes < as.raw(32) & !(bytes %in% as.raw(c(9, 10, 12, 13))) | bytes == as.raw(127)
  if (any(ctrl)) {
    abort_bad_file("{.file {file}} is not a text file (control byte 0x{as.character(bytes[which(ctrl)[1]])} at byte {which(ctrl)[1]}).",
                   "not_text", file = file, line = NA_integer_, call = call)
  }
  txt <- rawToChar(bytes)
  # stray non-UTF-8 bytes (e.g. a Latin-1 header) must not break the regexes
  if (!validUTF8(txt)) txt <- iconv(txt, "latin1", "UTF-8")
  # normalise CRLF and CR endings, then split with a fixed pattern (fast)
  if (grepl("\r", txt, fixed = TRUE)) txt <- gsub("\r\n?", "\n", txt, perl = TRUE)
  lines <- strsplit(txt, "\n", fixed = TRUE)[[1]]
  list(text = trimws(lines), complete = bytes[length(bytes)] %in% as.raw(c(10, 13)))
}

# Check that every data line has `expected` fields. A short last line is a
# recording cut off mid-write: an error, or with truncated = "drop" dropped
# with a warning (and reported back as `dropped`). Any other wrong count is an
# error naming the first bad line.
check_field_counts <- function(tokens, line_no, expected, file, truncated = "error",
                               what = NULL, call = rlang::caller_env()) {
  nf <- lengths(tokens)
  bad <- which(nf != expected)
  last <- length(tokens)
  dropped <- FALSE
  if (length(bad) && bad[1] == last && nf[last] < expected) {
    if (truncated == "drop" && last > 1L) {
      hm_warn("Dropped the truncated last line {line_no[last]} of {.file {file}} ({nf[last]} of {expected} fields).",
              "truncated_line", file = file, line = line_no[last])
      return(list(tokens = tokens[-last], line_no = line_no[-last], dropped = TRUE))
    }
    abort_bad_file(c("Truncated last line in {.file {file}}, line {line_no[last]}: {nf[last]} of {expected} fields.",
                     i = "Use {.code truncated = \"drop\"} to read the file without that line."),
                   "truncated_line", file = file, line = line_no[last], call = call)
  }
  if (length(bad)) {
    b <- bad[1]
    abort_bad_file(c("Wrong field count in {.file {file}}, line {line_no[b]}: {nf[b]} field{?s}, expected {expected}.",
                     i = "{length(bad)} line{?s} with the wrong count in total.",
                     i = what),
                   "bad_field_count", file = file, line = line_no[b], call = call)
  }
  list(tokens = tokens, line_no = line_no, dropped = dropped)
}

# Convert the tokens of `ncol`-field rows to numbers; the first token that is
# not a finite number is an error naming its line and field.
parse_numeric_fields <- function(tok, line_no, ncol, file, call = rlang::caller_env()) {
  v <- suppressWarnings(as.numeric(tok))
  bad <- which(!is.finite(v))
  if (length(bad)) {
    i <- bad[1]
    row <- (i - 1L) %/% ncol + 1L
    field <- (i - 1L) %% ncol + 1L
    abort_bad_file("Non-numeric field in {.file {file}}, line {line_no[row]}, field {field}: {.val {tok[i]}}.",
                   "non_numeric", file = file, line = line_no[row], field = field, call = call)
  }
  v
}

# A file's name without folder and extension (the recording id of a file).
file_stem <- function(path) sub("\\.[[:alnum:]]+$", "", trimws(basename(path)))
