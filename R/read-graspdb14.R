# Reader for GraspDB14 motion files (Stollenwerk, Hinkenjann and Klein 2018,
# sections 4.1.2 and 4.2.2). One whitespace-separated row per frame, 30 fields:
#   YYYY MM DD hh mm ss.sssss switch s0 ... s22
# The file name carries the metadata (object, scenario, action/hand or Feix
# grasp, data type rad/raw, trial counter, subject). A file becomes a grasps
# object of one recording; a directory becomes one grasps object of every
# readable file plus a report of the files that failed (see read-failures.R).

graspdb14_n_fields <- 30L
graspdb14_nominal_rate <- 60

#' Read GraspDB14 motion files
#'
#' Reads one GraspDB14 motion file, several files, or whole directories into a
#' [grasps()] object whose DoFs are the 23 CyberGlove sensors
#' ([cyberglove_sensors]), in radians (`-rad-` files) or raw 8-bit sensor
#' counts (`-raw-` files).
#'
#' File names follow the report's patterns (case-insensitive):
#' * scenario 1, uncontrolled transport: `<obj>_ex01-<rad|raw>-<trial>-grasp-su<subject>.txt`
#' * scenario 2, object use: `<obj>_<action>_<hand>_ex02-...` (actions of
#'   [graspdb14_actions])
#' * scenario 3, controlled transport: `<obj>_<grasp>_ex03-...`, also the
#'   `ex03-1` variant; the Feix grasp id becomes the `grasp` factor
#' * calibration streams: `00_calib-<rad|raw>-su<subject>.txt`
#' * phase annotations `<motion file>_annot-.txt` (intervals and labels) are
#'   not recordings: they are read into the `"annotations"` attribute.
#'
#' Each row must have 30 whitespace-separated fields (spaces, tabs, trailing
#' blanks and CRLF line endings are all fine). The elapsed time comes from the
#' time stamps and the sampling rate of a file is (frames - 1) / elapsed time
#' (about 60 Hz). A file with a single frame or without time progress gets the
#' nominal 60 Hz, recorded in `rate_source`.
#'
#' Files that hold nothing but the 30 numbers of each line are parsed by
#' [data.table::fread()], many files per call (about 1.5 million lines, 5,000
#' files, in a few seconds); any other layout is read line by line, and the
#' error reports name the file, line and field either way.
#'
#' @param path A motion file, several files, or directories.
#' @param recursive Look into sub-directories of directories.
#' @param pattern Regular expression selecting the files of a directory.
#' @param datatype Which files to read from a directory: `"rad"` or `"raw"`.
#'   `NULL` (default) reads the type present; when a directory holds both,
#'   the `rad` files are read and the `raw` files are listed in the failure
#'   report with class `"skipped_datatype"` (a grasps set has one unit).
#' @param truncated What to do with a truncated last line (fewer than 30
#'   fields, typically a recording cut off mid-write): `"error"` (default)
#'   treats the file as bad; `"drop"` drops that line, warns, and records it
#'   in the metadata column `dropped_last_line`.
#' @return A `grasps` object. Metadata columns: `id` (file stem), `grasp`
#'   (Feix type for scenario 3, `NA` otherwise), `subject` (actor number as
#'   text, e.g. `"4"` for `su04`), `object` (name from [graspdb14_objects]),
#'   `trial` (the running number), `source` (file path), `scenario` (`"1"`,
#'   `"2"`, `"3"` or `"calib"`), `variant` (the `-1` of `ex03-1`),
#'   `object_id`, `grasp_id`, `subject_id`, `action`, `hand`, `action_code`
#'   (scenario 2), `datatype`, `file_rate` (the file's own rate in Hz),
#'   `start_time` (POSIXct of the first frame, in UTC as written),
#'   `duration` (seconds), `rate_source`, `dropped_last_line`. The set's
#'   `rate` is the file's rate, or for several files the median, rounded to
#'   0.01 Hz. Each recording matrix carries attributes `switch` (integer 0/1
#'   per frame, see [segment_by_switch()]) and `time` (elapsed seconds).
#'   Attribute `"failures"` holds the report of unreadable files (see
#'   [read_failures()]); attribute `"annotations"` the phase annotations found.
#'
#'   A single file that cannot be read raises a classed error (all inherit
#'   from `"handmotion_error_bad_file"` and carry `file` and `line`):
#'   `handmotion_error_empty_file`, `handmotion_error_bad_field_count`,
#'   `handmotion_error_truncated_line`, `handmotion_error_non_numeric`,
#'   `handmotion_error_bad_value` (switch not 0/1, impossible date),
#'   `handmotion_error_unknown_file_name`. A read of several files or a
#'   directory carries on, and warns (class
#'   `handmotion_warning_read_failures`) naming the files it skipped.
#' @seealso [write_graspdb14()], [segment_by_switch()], [graspdb14_to_hust()],
#'   [read_failures()]
#' @export
#' @examples
#' dir <- system.file("extdata", "graspdb14", package = "handmotion")
#' g <- read_graspdb14(dir)
#' g
#' g$meta[, c("id", "grasp", "object", "scenario", "file_rate")]
#' one <- read_graspdb14(file.path(dir, "01_11_ex03-rad-001-grasp-su01.txt"))
#' one$rate
read_graspdb14 <- function(path, recursive = FALSE, pattern = "\\.txt$", datatype = NULL,
                           truncated = c("error", "drop")) {
  call <- rlang::caller_env()
  truncated <- check_choice(truncated, arg = "truncated", call = call)
  if (!is.null(datatype)) datatype <- check_choice(datatype, c("rad", "raw"), arg = "datatype", call = call)
  pattern <- check_regex(pattern, "pattern", allow_null = TRUE, call = call)
  input <- list_input_files(path, pattern, recursive, call = call)
  files <- input$files
  is_annot <- grepl("_annot[^/\\\\]*$", file_stem(files), ignore.case = TRUE)
  annot_files <- files[is_annot]
  files <- files[!is_annot]
  if (!input$many) {
    if (length(files) == 0L) {
      hm_abort(c("{.file {path}} is a phase annotation file, not a motion file.",
                 i = "Read the motion file it belongs to."),
               c("unknown_file_name", "bad_file"), file = path, line = NA_integer_, call = call)
    }
    rec <- read_graspdb14_file(files, truncated = truncated, call = call)
    out <- graspdb14_as_grasps(list(rec), call = call)
    attr(out, "failures") <- empty_read_failures()
    return(out)
  }
  if (length(files) == 0L) {
    hm_abort("No GraspDB14 motion files matching {.val {pattern}} in {.file {path}}.",
             "no_files", file = path, argument = "path", call = call)
  }
  # the numbers of the well-formed files, read in a few large freads
  fields <- graspdb14_fread_many(files)
  names(fields) <- files
  read <- read_each_file(files, function(f) {
    read_graspdb14_file(f, truncated = truncated, fields = fields[[f]], call = call)
  })
  failures <- read$failures
  recs <- read$results
  types <- vapply(recs, function(r) r$info$datatype, character(1))
  explicit <- !is.null(datatype)
  if (is.null(datatype)) datatype <- if (any(types == "rad") || length(types) == 0L) "rad" else "raw"
  skip <- types != datatype
  if (any(skip)) {
    failures <- rbind(failures, data.frame(
      file = read$files[skip], line = NA_integer_, class = "skipped_datatype",
      message = sprintf("A %s file in a %s read: one grasps set has one unit; read with datatype = \"%s\".",
                        types[skip], datatype, types[skip]),
      stringsAsFactors = FALSE))
    recs <- recs[!skip]
  }
  annotations <- read_annotation_files(annot_files)
  failures <- rbind(failures, annotations$failures)
  # files left out because the caller asked for the other data type are in
  # the report but are no reason to warn
  asked <- explicit & failures$class == "skipped_datatype"
  warn_read_failures(failures[!asked, , drop = FALSE], total = length(files) + length(annot_files))
  if (length(recs) == 0L) {
    hm_abort(c("None of the {length(files)} file{?s} in {.file {path}} could be read.",
               i = "First failure: {failures$message[1]}"),
             "no_files", file = path, failures = failures, call = call)
  }
  out <- graspdb14_as_grasps(recs, call = call)
  attr(out, "failures") <- failures
  if (nrow(annotations$table) > 0L) attr(out, "annotations") <- annotations$table
  out
}

# Read one motion file: metadata from its name, then the content (`fields`:
# its numbers when already read by graspdb14_fread_many()).
read_graspdb14_file <- function(file, truncated = "error", fields = NULL, call = rlang::caller_env()) {
  info <- parse_graspdb14_name(file, call = call)
  content <- parse_graspdb14_content(file, truncated = truncated, fields = fields, call = call)
  # raw CyberGlove counts are whole numbers: a "raw" file with fractional
  # values holds something else (radians under the wrong name)
  if (identical(info$datatype, "raw")) {
    frac <- which(abs(content$angles - round(content$angles)) > 1e-8, arr.ind = TRUE)
    if (nrow(frac)) {
      abort_bad_file(c("{.file {file}} is named as raw sensor counts but holds fractional values.",
                       i = "First at data row {frac[1, 1]}, sensor {colnames(content$angles)[frac[1, 2]]}: {.val {content$angles[frac[1, 1], frac[1, 2]]}}.",
                       i = "Radians belong in a file named {.val -rad-}."),
                     "bad_value", file = file, call = call)
    }
  }
  list(info = info, content = content, file = file)
}

# Metadata from a GraspDB14 file name. Liberal in case and surrounding
# blanks; anything that is not one of the documented patterns is an error.
parse_graspdb14_name <- function(file, call = rlang::caller_env()) {
  stem <- trimws(file_stem(file))
  s <- tolower(stem)
  motion_re <- paste0("^(?<obj>\\d+)(?:_(?<grasp>\\d+)|_(?<act>[a-z]+)_(?<hand>[a-z]+))?",
                      "_ex(?<ex>\\d+)(?:-(?<var>\\d+))?-(?<dt>rad|raw)-(?<trial>\\d+)",
                      "(?:-grasp)?-su(?<su>\\d+)$")
  calib_re <- "^(?<obj>\\d+)_calib-(?<dt>rad|raw)-su(?<su>\\d+)$"
  m <- regex_groups(s, motion_re)
  if (is.null(m)) {
    m <- regex_groups(s, calib_re)
    if (!is.null(m)) m[c("ex", "grasp", "act", "hand", "var", "trial")] <- ""
  }
  bad_name <- function(why) {
    abort_bad_file(c("Unknown GraspDB14 file name {.file {basename(file)}}: {why}",
                     i = "Expected {.code <obj>_ex01-rad-<trial>-grasp-su<subject>.txt},
                          {.code <obj>_<action>_<hand>_ex02-...}, {.code <obj>_<grasp>_ex03[-1]-...}
                          or {.code 00_calib-rad-su<subject>.txt}."),
                   "unknown_file_name", file = file, line = NA_integer_, call = call)
  }
  if (is.null(m)) bad_name("it matches none of the documented patterns.")
  scenario <- if (m[["ex"]] == "") "calib" else as.character(as.integer(m[["ex"]]))
  has_grasp <- m[["grasp"]] != ""
  has_action <- m[["act"]] != ""
  if (scenario == "3" && !has_grasp) bad_name("a scenario 3 name must carry the grasp id (<obj>_<grasp>_ex03).")
  if (scenario == "2" && !has_action) bad_name("a scenario 2 name must carry action and hand (<obj>_<action>_<hand>_ex02).")
  if (scenario %in% c("1", "calib") && (has_grasp || has_action)) {
    bad_name("only scenario 2 names carry an action and only scenario 3 names a grasp id.")
  }
  if (!scenario %in% c("1", "2", "3", "calib")) bad_name("GraspDB14 has scenarios ex01, ex02 and ex03 only.")
  grasp_id <- if (has_grasp) as.integer(m[["grasp"]]) else NA_integer_
  if (!is.na(grasp_id) && !grasp_id %in% seq_along(feix_levels())) {
    bad_name(sprintf("grasp id %d is not a Feix grasp type (1-33).", grasp_id))
  }
  object_id <- as.integer(m[["obj"]])
  objects <- handmotion::graspdb14_objects
  code <- if (has_action) paste0(m[["act"]], "_", m[["hand"]]) else NA_character_
  actions <- handmotion::graspdb14_actions
  hand_names <- c(l = "left", r = "right")
  list(
    id = stem, scenario = scenario,
    variant = if (m[["var"]] == "") NA_character_ else m[["var"]],
    object_id = if (scenario == "calib") NA_integer_ else object_id,
    object = if (scenario == "calib") NA_character_ else objects$name[match(object_id, objects$id)],
    grasp_id = grasp_id,
    action_code = code,
    action = actions$action[match(code, actions$code)],
    hand = if (has_action) unname(hand_names[m[["hand"]]]) else NA_character_,
    datatype = m[["dt"]],
    trial = if (m[["trial"]] == "") NA_integer_ else as.integer(m[["trial"]]),
    subject_id = as.integer(m[["su"]])
  )
}

# Named capture groups of one regular-expression match, or NULL.
regex_groups <- function(x, re) {
  r <- regexpr(re, x, perl = TRUE)
  if (r == -1L) return(NULL)
  st <- attr(r, "capture.start")[1, ]
  len <- attr(r, "capture.length")[1, ]
  out <- substring(x, st, st + len - 1L)
  out[len <= 0L] <- ""
  stats::setNames(as.list(out), attr(r, "capture.names"))
}

# Parse the content of a motion file: the numbers of a well-formed file come
# from data.table::fread() (read-graspdb14-fread.R); any other file is split
# into lines and fields in R (graspdb14_text_fields()), which reads the
# liberal layouts (comments, blank lines, tabs, CR line ends) and names the
# first bad line and field. The checks of the values below are the same for both.
parse_graspdb14_content <- function(file, truncated = "error", fields = NULL, call = rlang::caller_env()) {
  fields <- fields %||% graspdb14_fread_many(file)[[1]] %||%
    graspdb14_text_fields(file, truncated = truncated, call = call)
  m <- fields$values
  line_no <- fields$line_no
  dropped <- fields$dropped
  switch_state <- m[, 7]
  bad_sw <- which(!switch_state %in% c(0, 1))
  if (length(bad_sw)) {
    abort_bad_file("Switch state must be 0 or 1 in {.file {file}}, line {line_no[bad_sw[1]]}: {.val {switch_state[bad_sw[1]]}}.",
                   c("bad_value"), file = file, line = line_no[bad_sw[1]], field = 7L, call = call)
  }
  stamp <- graspdb14_time(m[, 1:6, drop = FALSE])
  bad_t <- which(is.na(stamp))
  if (length(bad_t)) {
    abort_bad_file("Impossible date or time in {.file {file}}, line {line_no[bad_t[1]]}: {.val {paste(m[bad_t[1], 1:6], collapse = ' ')}}.",
                   "bad_value", file = file, line = line_no[bad_t[1]], call = call)
  }
  # time must move forward: a stamp at or before its predecessor would give a
  # negative or zero duration and a wrong sampling rate
  back <- which(diff(stamp) <= 0)
  if (length(back)) {
    k <- back[1] + 1L
    abort_bad_file(c("Time stamps do not increase in {.file {file}}: line {line_no[k]} is {if (stamp[k] == stamp[k - 1L]) 'the same time as' else 'earlier than'} line {line_no[k - 1L]}.",
                     i = "{length(back)} such line{?s} in the file."),
                   "bad_value", file = file, line = line_no[k], call = call)
  }
  elapsed <- stamp - stamp[1]
  n <- nrow(m)
  duration <- elapsed[n]
  rate <- if (n > 1L && duration > 0) (n - 1) / duration else NA_real_
  angles <- m[, 8:30, drop = FALSE]
  colnames(angles) <- handmotion::cyberglove_sensors$name
  list(angles = angles, switch = as.integer(switch_state), time = elapsed,
       start = .POSIXct(stamp[1], tz = "UTC"),
       rate = rate, duration = duration, dropped_last_line = dropped)
}

# The numbers of a file of any layout the format allows, split into lines and
# fields in R; a wrong field count, a truncated last line or a non-numeric
# field is an error naming the line (and field).
graspdb14_text_fields <- function(file, truncated = "error", call = rlang::caller_env()) {
  lines <- read_text_lines(file, call = call)
  text <- lines$text
  keep <- nzchar(text) & !startsWith(text, "#")
  if (!any(keep)) {
    abort_bad_file("{.file {file}} is empty: it has no data rows.", "empty_file",
                   file = file, line = if (length(text)) length(text) else NA_integer_, call = call)
  }
  line_no <- which(keep)
  tokens <- strsplit(text[keep], "[ \t\f\v]+", perl = TRUE)
  checked <- check_field_counts(tokens, line_no, graspdb14_n_fields, file, truncated,
                                what = "A row is date (3), time (3), switch and 23 sensor values.",
                                call = call)
  tok <- unlist(checked$tokens, use.names = FALSE)
  v <- parse_numeric_fields(tok, checked$line_no, graspdb14_n_fields, file, call = call)
  list(values = matrix(v, ncol = graspdb14_n_fields, byrow = TRUE), line_no = checked$line_no,
       dropped = checked$dropped)
}

# Seconds since 1970 (UTC, as written) from year, month, day, hour, minute,
# seconds columns; NA for impossible dates or times (years 0-9999, the days of
# each month, leap years). Calendar arithmetic (days from the civil date), not
# strptime: this runs once per file, thousands of times in a directory read.
graspdb14_time <- function(d) {
  y <- d[, 1]
  mo <- d[, 2]
  leap <- (y %% 4 == 0 & y %% 100 != 0) | y %% 400 == 0
  month_days <- c(31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31)
  whole_in <- function(v, lo, hi) v >= lo & v <= hi & v == floor(v)
  ok <- whole_in(y, 0, 9999) & whole_in(mo, 1, 12) & whole_in(d[, 3], 1, 31) &
    whole_in(d[, 4], 0, 23) & whole_in(d[, 5], 0, 59) & d[, 6] >= 0 & d[, 6] < 61
  ok[is.na(ok)] <- FALSE
  ok[ok] <- d[ok, 3] <= month_days[mo[ok]] + (mo[ok] == 2 & leap[ok])
  # days since 1970-01-01 of the proleptic Gregorian date (H. Hinnant's
  # days_from_civil): years start in March so that leap days come last
  ys <- y - (mo <= 2)
  era <- ys %/% 400
  yoe <- ys - era * 400
  doy <- (153 * (mo + 9 - 12 * (mo > 2)) + 2) %/% 5 + d[, 3] - 1
  doe <- yoe * 365 + yoe %/% 4 - yoe %/% 100 + doy
  days <- era * 146097 + doe - 719468
  out <- days * 86400 + d[, 4] * 3600 + d[, 5] * 60 + d[, 6]
  out[!ok] <- NA_real_
  out
}

# Assemble parsed files into one grasps object.
graspdb14_as_grasps <- function(recs, call = rlang::caller_env()) {
  info <- lapply(recs, `[[`, "info")
  col <- function(name, type) vapply(info, function(i) i[[name]], type)
  cont <- lapply(recs, `[[`, "content")
  file_rate <- vapply(cont, `[[`, numeric(1), "rate")
  rate_source <- ifelse(is.na(file_rate), "nominal 60 Hz (no time progress)", "time stamps")
  file_rate[is.na(file_rate)] <- graspdb14_nominal_rate
  meta <- data.frame(
    id = col("id", character(1)),
    grasp = col("grasp_id", integer(1)),
    subject = as.character(col("subject_id", integer(1))),
    object = col("object", character(1)),
    trial = col("trial", integer(1)),
    source = vapply(recs, `[[`, character(1), "file"),
    scenario = col("scenario", character(1)),
    variant = col("variant", character(1)),
    object_id = col("object_id", integer(1)),
    grasp_id = col("grasp_id", integer(1)),
    subject_id = col("subject_id", integer(1)),
    action = col("action", character(1)),
    hand = col("hand", character(1)),
    action_code = col("action_code", character(1)),
    datatype = col("datatype", character(1)),
    file_rate = file_rate,
    start_time = .POSIXct(vapply(cont, function(x) as.numeric(x$start), numeric(1)), tz = "UTC"),
    duration = vapply(cont, `[[`, numeric(1), "duration"),
    rate_source = rate_source,
    dropped_last_line = vapply(cont, `[[`, logical(1), "dropped_last_line"),
    stringsAsFactors = FALSE
  )
  recordings <- lapply(cont, function(x) {
    a <- x$angles
    attr(a, "switch") <- x$switch
    attr(a, "time") <- x$time
    a
  })
  units <- unique(meta$datatype)
  grasps(recordings, meta = meta, dofs = handmotion::cyberglove_sensors$name,
         rate = round(stats::median(file_rate), 2), unit = units[1])
}

# Phase annotation files ("# interval annotation" then "start end label"
# rows): a table of id, start, end, label; unreadable ones become failures.
read_annotation_files <- function(files) {
  table <- data.frame(id = character(), start = integer(), end = integer(),
                      label = character(), stringsAsFactors = FALSE)
  if (length(files) == 0L) return(list(table = table, failures = empty_read_failures()))
  read <- read_each_file(files, read_annotation_file)
  list(table = do.call(rbind, c(list(table), read$results)), failures = read$failures)
}

read_annotation_file <- function(file) {
  lines <- read_text_lines(file)
  text <- lines$text
  keep <- which(nzchar(text) & !startsWith(text, "#"))
  if (!length(keep)) abort_bad_file("Annotation file {.file {file}} has no intervals.", "empty_file",
                                    file = file, line = NA_integer_)
  tok <- strsplit(text[keep], "[[:space:]]+")
  bad <- which(lengths(tok) < 3L | !vapply(tok, function(t) all(grepl("^[0-9]+$", t[1:2])), logical(1)))
  if (length(bad)) {
    abort_bad_file("Bad annotation row in {.file {file}}, line {keep[bad[1]]}: expected {.code start end label}.",
                   "bad_field_count", file = file, line = keep[bad[1]])
  }
  stem <- file_stem(file)
  data.frame(id = sub("_annot.*$", "", stem, ignore.case = TRUE),
             start = as.integer(vapply(tok, `[`, "", 1L)), end = as.integer(vapply(tok, `[`, "", 2L)),
             label = vapply(tok, function(t) paste(t[-(1:2)], collapse = " "), ""),
             stringsAsFactors = FALSE)
}
