# The numbers of well-formed GraspDB14 files, read by data.table::fread().
#
# Splitting text into fields in R costs about 25 microseconds a line; fread
# parses the same lines some ten times faster, and per call its set-up costs
# about as much as a 300-line file, so the files of a directory are read in a
# few calls: their bytes are concatenated, in chunks of about
# `graspdb14_fread_chunk` bytes, and each chunk is one fread of that text.
#
# A file is "well formed" when it holds only digits, signs, points, exponent
# letters, blanks and line ends and fread finds exactly 30 fields on each of
# its lines (as many rows as the file has lines: nothing skipped) with every
# value finite. Such a file has exactly one reading, and fread and the text
# parser give the same numbers (tested on the real samples and on 1.5 million
# simulated lines). Every other file (comments, blank lines, CR line ends, a
# bad field, a truncated line, ...) gets NULL here and goes to the text parser
# (graspdb14_text_fields()), which reads what the format allows and names the
# file, line and field of what it does not: error reports are the text
# parser's, whichever files are read here.

graspdb14_fread_chunk <- 32 * 1024^2

# Values of each file (a list parallel to `files`: list(values, line_no,
# dropped) or NULL for a file the text parser must read).
graspdb14_fread_many <- function(files) {
  out <- vector("list", length(files))
  size <- file.size(files)
  size[is.na(size)] <- 0
  chunk <- cumsum(size) %/% graspdb14_fread_chunk
  for (idx in split(seq_along(files), chunk)) {
    plain <- lapply(files[idx], graspdb14_plain_bytes)
    ok <- !vapply(plain, is.null, logical(1))
    if (any(ok)) out[idx[ok]] <- graspdb14_fread_group(plain[ok])
  }
  out
}

# A file's bytes and line count when it holds only the characters of numbers,
# blanks and line ends; NULL otherwise (or when it is empty or unreadable).
graspdb14_plain_bytes <- function(file) {
  size <- file.size(file)
  # a folder, broken link or unreadable file is left to the per-file reader,
  # which reports it (unreadable_file) without R's connection warnings
  if (is.na(size) || size == 0 || dir.exists(file) || file.access(file, 4L) != 0L) return(NULL)
  bytes <- tryCatch(suppressWarnings(readBin(file, "raw", size)), error = function(e) NULL)
  if (length(bytes) != size) return(NULL)
  counts <- .Call(hm_byte_counts, bytes)
  if (sum(counts[graspdb14_plain_codes]) != size) return(NULL)
  last_open <- bytes[size] != as.raw(10L)
  # a last line without its line end gets one, so files can be concatenated
  if (last_open) bytes <- c(bytes, as.raw(10L))
  list(bytes = bytes, n_lines = counts[11L] + last_open)
}

graspdb14_plain_codes <- utf8ToInt("0123456789.+-eE \t\r\n") + 1L

# Read a group of plain files with one fread; when the group does not parse
# as 30 finite numbers on every line, halve it until the files that do not
# are alone (they get NULL), so one bad file costs a few extra freads.
graspdb14_fread_group <- function(plain) {
  n_lines <- vapply(plain, `[[`, numeric(1), "n_lines")
  values <- graspdb14_fread_bytes(lapply(plain, `[[`, "bytes"), sum(n_lines))
  if (!is.null(values)) {
    file_of_row <- rep.int(seq_along(plain), n_lines)
    # a row of finite values has a finite sum (a sum that overflows only
    # sends its file to the text parser, which reads it the same): one pass,
    # where !is.finite() of every value cost as much as the fread
    finite <- is.finite(rowSums(values))
    good <- vapply(split(finite, factor(file_of_row, seq_along(plain))), all, logical(1))
    rows <- split(seq_len(nrow(values)), factor(file_of_row, seq_along(plain)))
    return(lapply(seq_along(plain), function(i) {
      if (!good[i]) return(NULL)
      list(values = values[rows[[i]], , drop = FALSE], line_no = seq_len(n_lines[i]), dropped = FALSE)
    }))
  }
  if (length(plain) == 1L) return(list(NULL))
  half <- seq_len(length(plain) %/% 2L)
  c(graspdb14_fread_group(plain[half]), graspdb14_fread_group(plain[-half]))
}

# One fread of concatenated file contents: the 30-column matrix, or NULL when
# fread warns, fails, or does not find 30 fields on each of `n_lines` lines.
graspdb14_fread_bytes <- function(bytes, n_lines) {
  # one string in memory (plain bytes hold no NUL): fread parses it in place,
  # where a temporary file would cost a disk write of the whole directory
  text <- rawToChar(unlist(bytes, use.names = FALSE))
  # a warning is noted and muffled, not caught: unwinding out of fread's C
  # code mid-read leaves it unable to read the next file
  warned <- FALSE
  dt <- withCallingHandlers(
    tryCatch(
      data.table::fread(text = text, sep = " ", header = FALSE, skip = 0L, quote = "", dec = ".",
                        colClasses = "numeric", fill = FALSE, blank.lines.skip = FALSE,
                        na.strings = NULL, strip.white = TRUE, showProgress = FALSE,
                        data.table = FALSE),
      error = function(e) NULL),
    warning = function(w) {
      warned <<- TRUE
      invokeRestart("muffleWarning")
    })
  if (warned || is.null(dt) || ncol(dt) != graspdb14_n_fields || nrow(dt) != n_lines) return(NULL)
  values <- do.call(cbind, unname(as.list(dt)))
  if (!is.double(values)) return(NULL)
  values
}
