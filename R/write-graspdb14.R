# Writer for the GraspDB14 motion-file format (report section 4.2.2): one
# row per frame, blank-separated, `YYYY MM DD hh mm ss.sssss switch` then the
# 23 sensor values (radians with five decimals, or raw integer counts), in the
# layout the original files use (each value followed by one blank).

#' Write recordings as GraspDB14 motion files
#'
#' Writes each recording of a 23-sensor [grasps()] object (DoFs as in
#' [cyberglove_sensors], unit `"rad"` or `"raw"`) to one GraspDB14 motion
#' file, named after the report's pattern for its scenario. Files written here
#' read back with [read_graspdb14()] to the same values, to the written
#' precision (5 decimals for radians, as in the original files).
#'
#' @param x A `grasps` object whose DoFs are the 23 CyberGlove sensor names
#'   (any order; they are written in the file order).
#' @param dir Directory to write to (created if needed).
#' @param file_names Optional file names, one per recording. By default they
#'   are built from the metadata: `scenario` (`"1"`, `"2"`, `"3"`, `"calib"`;
#'   by default `"3"` when the grasp type is known, else `"1"`), `object_id`
#'   (or the `object` name looked up in [graspdb14_objects]), `grasp`,
#'   `action_code` (scenario 2), `variant`, `trial` (or the recording's
#'   position) and `subject_id` (or the digits of `subject`).
#' @param start_time Time stamp of the first frame (POSIXct or a string
#'   `"YYYY-MM-DD hh:mm:ss"`, UTC) for recordings without a `start_time`
#'   metadata column.
#' @param digits Decimals written for radians (the format uses 5).
#' @param overwrite Replace existing files? By default an existing file is
#'   an error of class `handmotion_error_file_exists` naming it, and nothing
#'   is written.
#' @return The paths written, invisibly.
#' @details Time stamps are the recording's `"time"` attribute (elapsed
#'   seconds, as read) when present, otherwise frames spaced `1 / x$rate`
#'   apart. The switch column is the recording's `"switch"` attribute, or 1
#'   (ON) throughout.
#' @seealso [read_graspdb14()]
#' @export
#' @examples
#' g <- read_graspdb14(system.file("extdata", "graspdb14", package = "handmotion"))
#' out <- write_graspdb14(g[1:2], tempfile("graspdb14-"))
#' basename(out)
#' readLines(out[1], n = 1)
write_graspdb14 <- function(x, dir, file_names = NULL, start_time = "2014-01-01 00:00:00",
                            digits = 5L, overwrite = FALSE) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  sensors <- handmotion::cyberglove_sensors$name
  if (length(x$dofs) != length(sensors) || !setequal(x$dofs, sensors)) {
    hm_abort(c("{.arg x} must have the 23 GraspDB14 sensors as DoFs to be written as GraspDB14.",
               i = "Its DoFs: {.val {utils::head(x$dofs, 6)}}{if (length(x$dofs) > 6) '...' else ''}.",
               i = "See {.code cyberglove_sensors$name}."),
             "bad_input", argument = "x", call = call)
  }
  if (!x$unit %in% c("rad", "raw")) {
    hm_abort(c("GraspDB14 files hold radians or raw counts, not {.val {x$unit}}.",
               i = "Convert the angles to radians first (unit {.val rad})."),
             "bad_input", argument = "x", call = call)
  }
  # decimals of radians: fewer than 3 round by up to 0.05 degrees and more
  digits <- check_whole(digits, "digits", min = 3, max = 10, call = call)
  start <- as_utc_time(start_time, call = call)
  if (is.null(file_names)) file_names <- graspdb14_file_names(x, call = call)
  if (length(file_names) != length(x) || anyDuplicated(file_names)) {
    hm_abort("{.arg file_names} must be {length(x)} distinct name{?s}.", "bad_input",
             argument = "file_names", call = call)
  }
  dir <- create_output_dir(dir, call = call)
  paths <- file.path(dir, file_names)
  check_overwrite(paths, overwrite, call = call)
  starts <- if ("start_time" %in% names(x$meta) && inherits(x$meta$start_time, "POSIXct"))
    as.numeric(x$meta$start_time) else rep(NA_real_, length(x))
  starts[is.na(starts)] <- as.numeric(start)
  for (i in seq_along(x$recordings)) {
    rec <- x$recordings[[i]]
    # column subsetting drops the per-frame attributes, so pass them along
    lines <- graspdb14_lines(rec[, sensors, drop = FALSE], start = starts[i], rate = x$rate,
                             unit = x$unit, digits = digits, id = x$meta$id[i],
                             time = attr(rec, "time", exact = TRUE),
                             switch = attr(rec, "switch", exact = TRUE), call = call)
    write_text_file(lines, paths[i], use_bytes = TRUE, call = call)
  }
  invisible(paths)
}

# Format one recording's rows.
graspdb14_lines <- function(rec, start, rate, unit, digits, id, time = NULL, switch = NULL,
                            call = rlang::caller_env()) {
  n <- nrow(rec)
  if (is.null(time) || length(time) != n) time <- (seq_len(n) - 1) / rate
  # what read_graspdb14() would refuse is refused here, naming the recording
  if (anyNA(time) || any(!is.finite(time)) || (n > 1L && any(diff(time) <= 0))) {
    hm_abort(c("Recording {.val {id}} has time stamps that are missing or do not increase.",
               i = "Its {.code time} attribute must be finite and strictly increasing (seconds from the start)."),
             "bad_recording", recording = id, call = call)
  }
  sw <- switch
  if (is.null(sw) || length(sw) != n) sw <- rep(1L, n)
  if (anyNA(sw) || any(!sw %in% c(0, 1))) {
    hm_abort("Recording {.val {id}} has a {.code switch} attribute with values other than 0 and 1.",
             "bad_recording", recording = id, call = call)
  }
  # round the absolute time to the written precision before splitting it,
  # so that 59.999996 s becomes the next minute rather than "60.00000"
  t <- round(start + time, 5)
  whole <- floor(t)
  stamp <- format(as.POSIXct(whole, origin = "1970-01-01", tz = "UTC"), "%Y %m %d %H %M", tz = "UTC")
  sec <- sprintf("%08.5f", whole %% 60 + (t - whole))
  if (unit == "raw") {
    if (any(abs(rec - round(rec)) > 1e-8)) {
      hm_abort("Recording {.val {id}} is in raw counts but has non-integer values.",
               "bad_recording", recording = id, call = call)
    }
    vals <- sprintf("%d ", as.integer(round(rec)))
  } else {
    vals <- sprintf(paste0("%", digits + 3L, ".", digits, "f "), rec)
  }
  dim(vals) <- dim(rec)
  body <- do.call(paste0, as.data.frame(vals, stringsAsFactors = FALSE))
  paste(stamp, sec, as.integer(sw), body)
}

as_utc_time <- function(x, call = rlang::caller_env()) {
  t <- if (inherits(x, "POSIXct")) x else
    tryCatch(as.POSIXct(x, tz = "UTC", tryFormats = c("%Y-%m-%d %H:%M:%OS", "%Y-%m-%d")),
             error = function(e) NA)
  if (length(t) != 1L || is.na(t)) {
    hm_abort("{.arg start_time} must be one date-time such as {.val 2014-09-15 08:02:09}.",
             "bad_input", argument = "start_time", call = call)
  }
  t
}

# File names following the report's patterns, from the metadata.
graspdb14_file_names <- function(x, call = rlang::caller_env()) {
  m <- x$meta
  n <- nrow(m)
  get <- function(name, default = rep(NA, n)) if (name %in% names(m)) m[[name]] else default
  grasp_id <- as.integer(m$grasp)
  scenario <- as.character(get("scenario"))
  scenario[is.na(scenario)] <- ifelse(is.na(grasp_id), "1", "3")[is.na(scenario)]
  object_id <- as.integer(get("object_id"))
  from_name <- match(tolower(m$object), tolower(handmotion::graspdb14_objects$name))
  object_id[is.na(object_id)] <- handmotion::graspdb14_objects$id[from_name][is.na(object_id)]
  object_id[scenario == "calib" & is.na(object_id)] <- 0L
  subject_id <- as.integer(get("subject_id"))
  from_subject <- suppressWarnings(as.integer(gsub("\\D", "", m$subject)))
  subject_id[is.na(subject_id)] <- from_subject[is.na(subject_id)]
  trial <- m$trial
  trial[is.na(trial)] <- seq_len(n)[is.na(trial)]
  action <- as.character(get("action_code"))
  variant <- as.character(get("variant"))
  datatype <- x$unit
  missing <- is.na(object_id) | is.na(subject_id) | (scenario == "3" & is.na(grasp_id)) |
    (scenario == "2" & is.na(action)) | !scenario %in% c("1", "2", "3", "calib")
  if (any(missing)) {
    hm_abort(c("Cannot build a GraspDB14 file name for recording{?s} {.val {m$id[missing]}}.",
               i = "Needs an object ({.field object_id} or a {.field object} of {.code graspdb14_objects}),
                    a subject number, a grasp for scenario 3 and an {.field action_code} for scenario 2.",
               i = "Or pass {.arg file_names}."),
             "bad_input", argument = "x", recording = m$id[missing], call = call)
  }
  ex <- sprintf("ex%02d%s", suppressWarnings(as.integer(scenario)),
                ifelse(is.na(variant), "", paste0("-", variant)))
  prefix <- sprintf("%02d", object_id)
  prefix <- ifelse(scenario == "3", sprintf("%s_%02d", prefix, grasp_id), prefix)
  prefix <- ifelse(scenario == "2", paste0(prefix, "_", action), prefix)
  out <- sprintf("%s_%s-%s-%03d-grasp-su%02d.txt", prefix, ex, datatype, trial, subject_id)
  calib <- scenario == "calib"
  out[calib] <- sprintf("%02d_calib-%s-su%02d.txt", object_id[calib], datatype, subject_id[calib])
  out
}
