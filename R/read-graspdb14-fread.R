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
  size <- graspdb14_readable_size(files)
  chunk <- cumsum(size) %/% graspdb14_fread_chunk
  for (idx in split(seq_along(files), chunk)) {
    plain <- graspdb14_plain_text(files[idx], size[idx])
    ok <- !is.na(plain$n_lines)
    if (any(ok)) out[idx[ok]] <- graspdb14_fread_group(files[idx][ok], size[idx][ok], plain$n_lines[ok], plain$text)
  }
  out
}

# The size of each file, 0 for one the per-file reader must see: a folder,
# broken link or unreadable file is left to it, which reports it
# (unreadable_file) without R's connection warnings.
graspdb14_readable_size <- function(files) {
  size <- file.size(files)
  size[is.na(size) | dir.exists(files) | file.access(files, 4L) != 0L] <- 0
  size
}

# The plain files among `files` (only the characters of numbers, blanks and
# line ends), concatenated into one string (`text`, each file's last line
# ended), and each file's line count (`n_lines`, NA for a file left out: not
# plain, empty or unreadable). Compiled (src/plain-text.c): the bytes are
# read into the string once.
graspdb14_plain_text <- function(files, size) {
  .Call(hm_plain_text, files, as.numeric(size))
}

# Read a group of plain files with one fread (of `text`, when the caller has
# it); when the group does not parse as 30 finite numbers on every line,
# halve it until the files that do not are alone (they get NULL), so one bad
# file costs a few extra freads.
graspdb14_fread_group <- function(files, size, n_lines, text = NULL) {
  text <- text %||% graspdb14_plain_text(files, size)$text
  values <- graspdb14_fread_text(text, sum(n_lines))
  if (!is.null(values)) {
    file_of_row <- rep.int(seq_along(files), n_lines)
    # a row of finite values has a finite sum (a sum that overflows only
    # sends its file to the text parser, which reads it the same): one pass,
    # where !is.finite() of every value cost as much as the fread
    finite <- is.finite(rowSums(values))
    good <- vapply(split(finite, factor(file_of_row, seq_along(files))), all, logical(1))
    rows <- split(seq_len(nrow(values)), factor(file_of_row, seq_along(files)))
    return(lapply(seq_along(files), function(i) {
      if (!good[i]) return(NULL)
      list(values = values[rows[[i]], , drop = FALSE], line_no = seq_len(n_lines[i]), dropped = FALSE)
    }))
  }
  if (length(files) == 1L) return(list(NULL))
  half <- seq_len(length(files) %/% 2L)
  c(graspdb14_fread_group(files[half], size[half], n_lines[half]),
    graspdb14_fread_group(files[-half], size[-half], n_lines[-half]))
}

# One fread of the concatenated contents of plain files: the 30-column
# matrix, or NULL when fread warns, fails, or does not find 30 fields on each
# of `n_lines` lines. The text is one string in memory (plain bytes hold no
# NUL): fread parses it in place, where a temporary file would cost a disk
# write of the whole directory.
graspdb14_fread_text <- function(text, n_lines) {
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
