# Recordings whose frames carry their own time stamps (an Arduino glove
# writes a line whenever it gets round to it: ~30 ms apart, often 10 ms for
# the first). Models assume one constant rate per set, so such recordings are
# resampled onto a constant grid by linear interpolation, once, when read;
# the rate each file was recorded at is kept in the metadata
# (`recorded_rate`) and print()/summary() say the set was resampled.

time_units <- c(ms = 1e-3, s = 1, us = 1e-6)

# The `time` and `time_unit` arguments of read_hust(): NULL (no time column),
# or the column's name and the factor from its unit to seconds. Without a
# unit, the column name's suffix ("time_ms", "t_s") says it.
check_time_arg <- function(time, time_unit, call = rlang::caller_env()) {
  if (is.null(time)) {
    if (!is.null(time_unit)) {
      hm_abort("{.arg time_unit} is given but {.arg time} (the time column) is not.", "bad_input",
               argument = "time_unit", call = call)
    }
    return(NULL)
  }
  if (!is.character(time) || length(time) != 1L || is.na(time) || !nzchar(trimws(time))) {
    hm_abort("{.arg time} must be the name of the time column, not {describe_value(time)}.",
             "bad_input", argument = "time", call = call)
  }
  if (is.null(time_unit)) {
    suffix <- regmatches(tolower(time), regexpr("(?<=[_.])(ms|s|us)$", tolower(time), perl = TRUE))
    if (!length(suffix)) {
      hm_abort(c("The unit of time column {.val {time}} is not known.",
                 i = "Give {.arg time_unit} ({.val {names(time_units)}}) or name the column with its unit, e.g. {.val time_ms}."),
               "bad_input", argument = "time_unit", call = call)
    }
    time_unit <- suffix
  }
  time_unit <- check_choice(time_unit, names(time_units), arg = "time_unit", call = call)
  list(column = trimws(time), unit = time_unit, to_seconds = time_units[[time_unit]])
}

# Take the time column out of a parsed file (its first column): times in
# seconds, which must increase from frame to frame (the line of the first
# that does not is named).
split_time_column <- function(rec, time, file, call = rlang::caller_env()) {
  t <- rec$values[, 1] * time$to_seconds
  bad <- which(diff(t) <= 0)
  if (length(bad)) {
    b <- bad[1] + 1L
    abort_bad_file(c("{.file {file}}, line {rec$line_no[b]}: time {rec$values[b, 1]} {time$unit} is not after the previous frame's {rec$values[b - 1L, 1]}.",
                     i = "Times in {.val {time$column}} must increase from frame to frame ({length(bad)} frame{?s} do{?es/} not)."),
                   "bad_time", file = file, line = rec$line_no[b], call = call)
  }
  rec$time <- t
  rec$values <- rec$values[, -1, drop = FALSE]
  rec
}

# The rate of a set of time-stamped recordings: one over the median interval
# between frames, over every interval of every recording (a set shares one
# rate; pooling weights long recordings as they weigh in the data).
rate_from_times <- function(times) {
  dt <- unlist(lapply(times, diff), use.names = FALSE)
  if (!length(dt)) return(NULL)
  1 / stats::median(dt)
}

# One recording's values at times `t` resampled onto the grid t[1], t[1] +
# 1/rate, ... up to its last time, by linear interpolation per channel.
resample_linear <- function(values, t, rate) {
  n <- length(t)
  if (n < 2L) return(values)
  # (the tolerance keeps the last time on the grid despite rounding)
  grid <- t[1] + seq(0, floor((t[n] - t[1]) * rate + 1e-9)) / rate
  i <- pmin(findInterval(grid, t, rightmost.closed = TRUE), n - 1L)
  w <- (grid - t[i]) / (t[i + 1L] - t[i])
  out <- values[i, , drop = FALSE] * (1 - w) + values[i + 1L, , drop = FALSE] * w
  dimnames(out) <- list(NULL, colnames(values))
  out
}

# Resample every recording of a read onto a constant grid at `rate` (NULL:
# the set's median interval). Returns the recordings, the rate and each
# file's own rate (1 / its median interval).
resample_read <- function(recs, rate) {
  times <- lapply(recs, `[[`, "time")
  rate <- rate %||% rate_from_times(times) %||% 50
  recorded <- vapply(times, function(t) if (length(t) > 1L) 1 / stats::median(diff(t)) else NA_real_,
                     numeric(1))
  values <- lapply(recs, function(r) resample_linear(r$values, r$time, rate))
  list(values = values, rate = rate, recorded_rate = recorded)
}

# The line print() and summary() show for a resampled set (NULL if not).
resampled_note <- function(meta, rate) {
  r <- meta$recorded_rate
  if (is.null(r) || all(is.na(r))) return(NULL)
  sprintf("resampled to %.4g Hz from time stamps (recorded at %.4g to %.4g Hz, median %.4g)",
          rate, min(r, na.rm = TRUE), max(r, na.rm = TRUE), stats::median(r, na.rm = TRUE))
}

# Time stamps kept apart from the channels: a folder (`timestamps`, below
# `path` or anywhere) holding, for each data file, a file at the same
# relative path with the `time` column (what the flexglove source's copy in
# /work/shared keeps: <label>/<name>.csv and timestamps/<label>/<name>.csv).
# Returns the folder's normalised path, or NULL.
timestamps_dir <- function(timestamps, time, base_dir, call = rlang::caller_env()) {
  if (is.null(timestamps)) return(NULL)
  check_string(timestamps, "timestamps", what = "the folder of the time stamp files", call = call)
  if (is.null(time)) {
    hm_abort("{.arg timestamps} needs {.arg time}: the name of the time column in its files.",
             "bad_input", argument = "time", call = call)
  }
  dir <- c(file.path(base_dir, timestamps), timestamps)
  dir <- dir[dir.exists(dir)]
  if (!length(dir)) {
    hm_abort("{.arg timestamps} folder {.file {timestamps}} does not exist (in {.file {base_dir}} or as given).",
             "file_not_found", argument = "timestamps", file = timestamps, call = call)
  }
  normalizePath(dir[1], winslash = "/")
}

# Whether each file lies inside `dir` (the time stamp files are not data).
under_dir <- function(files, dir) {
  startsWith(normalizePath(files, winslash = "/", mustWork = FALSE), paste0(dir, "/"))
}

# A parsed data file with the times of its time stamp file put first (as if
# the file had the column), for split_time_column(). Its frames and times
# must pair up one to one.
add_time_file <- function(rec, file, base_dir, ts_dir, time, header, sep, truncated,
                          call = rlang::caller_env()) {
  rel <- relative_paths(file, base_dir)
  tfile <- file.path(ts_dir, rel)
  if (!file.exists(tfile)) {
    abort_bad_file("No time stamp file {.file {tfile}} for {.file {file}}.", "file_not_found",
                   file = file, call = call)
  }
  t <- parse_hust_content(tfile, dofs = time$column, header = header, sep = sep, truncated = truncated,
                          time = time$column, call = call)
  if (nrow(t$values) != nrow(rec$values)) {
    abort_bad_file("{.file {tfile}} has {nrow(t$values)} time{?s} for the {nrow(rec$values)} frame{?s} of {.file {file}}.",
                   "bad_time", file = file, line = NA_integer_, call = call)
  }
  rec$values <- cbind(t$values, rec$values)
  rec$line_no <- t$line_no
  rec$time_file <- tfile
  rec
}
