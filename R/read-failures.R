# What failed when reading many files. Readers of whole directories
# (read_hust(), read_graspdb14()) never stop at the first bad file and never
# drop one silently: every file that could not be read becomes one row of a
# "failures" data frame (file, line, class, message) attached to the result as
# attribute "failures", and a classed warning says how many there were.

# An empty failure report, so callers can always rbind onto it.
empty_read_failures <- function() {
  data.frame(file = character(), line = integer(), class = character(),
             message = character(), stringsAsFactors = FALSE)
}

# One failure row from a condition raised while reading `file`.
read_failure_row <- function(file, cnd) {
  cls <- class(cnd)
  specific <- cls[startsWith(cls, "handmotion_error_")][1]
  if (is.na(specific)) specific <- cls[1]
  line <- cnd$line
  line <- if (is.null(line) || length(line) != 1L) NA_integer_ else as.integer(line)
  msg <- tryCatch(cli::ansi_strip(conditionMessage(cnd)), error = function(e) "<unprintable message>")
  data.frame(file = file, line = line, class = specific,
             message = gsub("\\s+", " ", msg), stringsAsFactors = FALSE)
}

# Apply `reader(file)` to every file. Files whose reading raises an error of
# class `catch` are collected in the failure report; any other error (a bug)
# propagates. Only errors are caught: a warning of one file (e.g. a dropped
# truncated line) is a warning, not a failure, and must not stop the others.
# Returns list(results = named list of successes, failures = data frame).
read_each_file <- function(files, reader, catch = "handmotion_error") {
  results <- vector("list", length(files))
  failures <- vector("list", length(files))
  for (i in seq_along(files)) {
    results[i] <- list(tryCatch(reader(files[i]), error = function(cnd) {
      if (!inherits(cnd, catch)) stop(cnd)
      failures[[i]] <<- read_failure_row(files[i], cnd)
      NULL
    }))
  }
  ok <- !vapply(results, is.null, logical(1))
  fail <- do.call(rbind, c(list(empty_read_failures()), failures[!ok]))
  rownames(fail) <- NULL
  list(results = results[ok], files = files[ok], failures = fail)
}

# Warn (classed) about the files that could not be read, naming them.
warn_read_failures <- function(failures, total) {
  n <- nrow(failures)
  if (n == 0L) return(invisible(failures))
  # file names go into a cli template, so braces are escaped
  shown <- utils::head(sprintf("%s%s: %s", gsub("([{}])", "\\1\\1", basename(failures$file)),
                               ifelse(is.na(failures$line), "", paste0(":", failures$line)),
                               failures$class), 5)
  hm_warn(c("{n} of {total} file{?s} could not be read and {cli::qty(n)}{?was/were} skipped.",
            stats::setNames(shown, rep("x", length(shown))),
            i = if (n > 5) "... and {n - 5} more." else NULL,
            i = "See {.code read_failures()} on the result for every file, line and reason."),
          "read_failures", failures = failures)
  invisible(failures)
}

#' Files a reader could not read
#'
#' Directory reads ([read_graspdb14()], [read_hust()]) read every file they
#' can and record each file they could not, with the line and the reason.
#' `read_failures()` returns that report.
#'
#' @param x The result of a reader.
#' @return A data frame with one row per failed file: `file`, `line` (`NA`
#'   when the failure is not tied to a line, e.g. an unknown file name),
#'   `class` (the condition class, e.g. `"handmotion_error_bad_field_count"`)
#'   and `message`. Zero rows when everything was read.
#' @export
#' @examples
#' dir <- tempfile("graspdb14-")
#' dir.create(dir)
#' file.copy(system.file("extdata", "graspdb14", package = "handmotion"), dir,
#'           recursive = TRUE)
#' writeLines("not a motion file", file.path(dir, "graspdb14", "junk.txt"))
#' g <- suppressWarnings(read_graspdb14(file.path(dir, "graspdb14")))
#' read_failures(g)
read_failures <- function(x) {
  # (a list or data frame that no reader returned has no failures to report,
  # not an empty report)
  if (!is.list(x) || !inherits(x, "grasps") && is.null(attr(x, "failures", exact = TRUE))) {
    hm_abort("{.arg x} must be the result of a reader such as {.fn read_graspdb14}, not {describe_value(x)}.",
             "bad_input", argument = "x", call = rlang::caller_env())
  }
  f <- attr(x, "failures", exact = TRUE)
  if (is.null(f)) empty_read_failures() else f
}

# Raise a classed error about a file's content or name. `class` is the
# specific problem; every such error is also in the "handmotion_error_bad_file" family,
# and carries the fields `file` and `line`.
abort_bad_file <- function(message, class, file, line = NA_integer_, ...,
                           call = rlang::caller_env(), .envir = parent.frame()) {
  hm_abort(message, class = unique(c(class, "bad_file")), file = file,
           line = as.integer(line), ..., call = call, .envir = .envir)
}
