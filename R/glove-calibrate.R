# Calibration: raw sensor counts to joint angles in degrees, one linear map
# per channel (angle = offset + gain * count), as data-glove software does.
# The map comes from calibration poses whose angles are known (the flat
# hand, a fist, or the user's own), fitted by least squares per channel, or
# from given ranges (count range <-> angle range), or else from the glove
# profile's nominal ranges.

#' Calibrate raw glove counts to degrees
#'
#' Converts the raw channels of a [grasps()] set to joint angles in degrees,
#' one linear map per channel, `angle = offset + gain * count`:
#'
#' * **From calibration poses** (`poses`): recordings of the hand held in
#'   known postures, as a named list (`flat`, `fist`, or your own names) of
#'   [grasps()] sets or count matrices with the glove's channels; `angles`
#'   gives each pose's angles (a named list of numbers per channel, or one
#'   number for all). The built-in poses are `flat` (every joint at 0
#'   degrees) and `fist` (finger flexion 90 degrees at the knuckles, 100 at
#'   the middle and 70 at the end joints, the thumb 50 and 60, spread and
#'   other channels 0). Per channel, the mean count of each pose is matched
#'   to its angle by least squares; a channel whose poses share one angle
#'   keeps the nominal gain and gets its offset from them.
#' * **From ranges** (`ranges`): a data frame with columns `channel`,
#'   `min`, `max` (counts) and optionally `angle_min`, `angle_max` (degrees;
#'   the profile's nominal angles otherwise).
#' * **Nominal**: otherwise the profile's own `min`/`max` and
#'   `angle_min`/`angle_max`.
#'
#' Channels that are not raw are kept as they are; raw channels without any
#' map (a pressure pad) stay in counts, and the set's unit is then `"raw"`.
#' The profile of the result describes the calibrated channels (unit
#' `"deg"`, their sensor range in degrees) and channels constant over every
#' recording are flagged as stuck again (classed warning
#' `handmotion_warning_stuck_channels`).
#'
#' @param x A [grasps()] set with a glove profile whose channels report raw
#'   counts.
#' @param poses `NULL` or a named list of calibration recordings (see
#'   above).
#' @param angles Known angles of the poses, named like `poses`; the built-in
#'   `flat` and `fist` need none.
#' @param ranges `NULL` or a data frame of count and angle ranges per channel.
#' @return The recordings in degrees, a [grasps()] set with attribute
#'   `"calibration"`: a data frame with one row per channel (`channel`,
#'   `gain`, `offset`, `source`: `"poses"`, `"ranges"`, `"nominal"` or
#'   `"none"`).
#' @seealso [glove_profile()], [trim_motion()]
#' @export
#' @examples
#' raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 3, pen = 20), objects = 1,
#'                        trials = 2, glove = "resistive", rest = 1, hold = 1, seed = 1)
#' deg <- calibrate(raw)              # the profile's nominal ranges
#' deg
#' head(attr(deg, "calibration"))
#' # from poses: the counts of a flat hand and a fist (here made up)
#' ch <- raw$glove$channels
#' counts <- function(a) matrix(ch$min + (a - ch$angle_min) / (ch$angle_max - ch$angle_min) *
#'                                (ch$max - ch$min), 5, nrow(ch), byrow = TRUE,
#'                              dimnames = list(NULL, ch$channel))
#' fist <- calibration_pose_angles(raw$glove, "fist")
#' deg2 <- calibrate(raw, poses = list(flat = counts(rep(0, nrow(ch))), fist = counts(fist)))
calibrate <- function(x, poses = NULL, angles = NULL, ranges = NULL) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  if (!is.null(poses) && !is.null(ranges)) {
    hm_abort("Give {.arg poses} or {.arg ranges}, not both.", "bad_input", argument = "poses", call = call)
  }
  glove <- match_glove(x$glove, x$dofs, x$unit, call = call)
  ch <- glove$channels
  raw <- ch$unit == "raw"
  if (!any(raw)) {
    hm_abort(c("{.arg x} has no raw channels to calibrate (its glove {.val {glove$name}} reports {.val {unique(ch$unit)}}).",
               i = "Give the recordings a profile whose channels have {.code unit = \"raw\"}."),
             "bad_input", argument = "x", call = call)
  }
  map <- nominal_map(ch)
  if (!is.null(ranges)) map <- ranges_map(ch, map, ranges, call)
  if (!is.null(poses)) map <- poses_map(ch, map, poses, angles, glove, call)
  map$source[!raw] <- "none"
  conv <- raw & !is.na(map$gain)
  recs <- lapply(x$recordings, function(r) {
    r[, conv] <- sweep(sweep(r[, conv, drop = FALSE], 2, map$gain[conv], "*"), 2, map$offset[conv], "+")
    r
  })
  # the calibrated channels' sensor range, in degrees
  lo <- map$offset + map$gain * ch$min
  hi <- map$offset + map$gain * ch$max
  ch$min[conv] <- pmin(lo, hi)[conv]
  ch$max[conv] <- pmax(lo, hi)[conv]
  ch$unit[conv] <- "deg"
  ch$angle_min[conv] <- NA_real_
  ch$angle_max[conv] <- NA_real_
  unit <- if (all(ch$unit == "deg")) "deg" else if (all(ch$unit %in% c("deg", "raw"))) "raw" else x$unit
  out <- new_grasps(recs, x$meta, x$dofs, x$rate, unit, glove = new_glove_profile(glove$name, ch))
  out <- flag_stuck(out, call = call)
  attr(out, "calibration") <- data.frame(channel = ch$channel, gain = map$gain, offset = map$offset,
                                         source = map$source, stringsAsFactors = FALSE)
  out
}

#' @rdname calibrate
#' @param glove A [glove_profile()].
#' @param pose `"flat"` or `"fist"`.
#' @export
calibration_pose_angles <- function(glove, pose = c("flat", "fist")) {
  pose <- check_choice(pose, c("flat", "fist"), arg = "pose", call = rlang::caller_env())
  ch <- glove_profile(glove)$channels
  out <- stats::setNames(rep(0, nrow(ch)), ch$channel)
  if (pose == "flat") return(out)
  flex <- !is.na(ch$axis) & ch$axis == "x"
  j <- ch$joint
  out[flex & grepl("mcp$", j) & !grepl("^th", j)] <- 90
  out[flex & grepl("pip$", j)] <- 100
  out[flex & grepl("dip$", j)] <- 70
  out[flex & j == "th-mcp"] <- 50
  out[flex & j == "th-ip"] <- 60
  # the profile's sign: a channel that reads flexion negated sees the fist negated
  out * ifelse(ch$sign < 0 & flex, -1, 1)
}

# The profile's nominal map: counts min..max to angles angle_min..angle_max.
nominal_map <- function(ch) {
  ok <- ch$unit == "raw" & !is.na(ch$min) & !is.na(ch$max) & !is.na(ch$angle_min) & !is.na(ch$angle_max)
  gain <- ifelse(ok, (ch$angle_max - ch$angle_min) / (ch$max - ch$min), NA_real_)
  data.frame(gain = gain, offset = ifelse(ok, ch$angle_min - gain * ch$min, NA_real_),
             source = ifelse(ok, "nominal", "none"), stringsAsFactors = FALSE)
}

ranges_map <- function(ch, map, ranges, call) {
  if (!is.data.frame(ranges) || !all(c("channel", "min", "max") %in% names(ranges))) {
    hm_abort("{.arg ranges} must be a data frame with columns {.field channel}, {.field min} and {.field max}.",
             "bad_input", argument = "ranges", call = call)
  }
  i <- match(ranges$channel, ch$channel)
  if (anyNA(i)) {
    hm_abort("{.arg ranges} names channel{?s} {.val {ranges$channel[is.na(i)]}} that the glove does not have.",
             "bad_input", argument = "ranges", call = call)
  }
  a0 <- if ("angle_min" %in% names(ranges)) ranges$angle_min else ch$angle_min[i]
  a1 <- if ("angle_max" %in% names(ranges)) ranges$angle_max else ch$angle_max[i]
  bad <- is.na(a0) | is.na(a1) | !is.finite(ranges$min) | !is.finite(ranges$max) | ranges$min == ranges$max
  if (any(bad)) {
    hm_abort("{.arg ranges} for channel{?s} {.val {ranges$channel[bad]}} need{?s/} distinct finite counts and angles.",
             "bad_input", argument = "ranges", call = call)
  }
  map$gain[i] <- (a1 - a0) / (ranges$max - ranges$min)
  map$offset[i] <- a0 - map$gain[i] * ranges$min
  map$source[i] <- "ranges"
  map
}

poses_map <- function(ch, map, poses, angles, glove, call) {
  if (!is.list(poses) || inherits(poses, "grasps") || is.null(names(poses)) || any(!nzchar(names(poses)))) {
    hm_abort("{.arg poses} must be a named list of calibration recordings (e.g. {.code list(flat = , fist = )}).",
             "bad_input", argument = "poses", call = call)
  }
  p <- nrow(ch)
  # mean count per pose and channel, and the pose's target angles
  means <- t(vapply(names(poses), function(nm) {
    v <- poses[[nm]]
    M <- if (inherits(v, "grasps")) do.call(rbind, v$recordings) else as.matrix(v)
    if (!is.numeric(M) || ncol(M) != p || anyNA(M)) {
      hm_abort("Calibration pose {.val {nm}} must hold finite counts of the {p} glove channel{?s}.",
               "bad_input", argument = "poses", call = call)
    }
    if (!is.null(colnames(M)) && !identical(colnames(M), ch$channel)) M <- M[, ch$channel, drop = FALSE]
    colMeans(M)
  }, numeric(p)))
  target <- t(vapply(names(poses), function(nm) {
    a <- angles[[nm]]
    if (is.null(a)) {
      if (!nm %in% c("flat", "fist")) {
        hm_abort("Give the angles of calibration pose {.val {nm}} in {.arg angles}.", "bad_input",
                 argument = "angles", call = call)
      }
      return(unname(calibration_pose_angles(glove, nm)))
    }
    if (length(a) == 1L) return(rep(as.numeric(a), p))
    if (!is.null(names(a))) a <- a[ch$channel]
    if (length(a) != p || anyNA(a)) {
      hm_abort("The angles of pose {.val {nm}} must be one number or one per channel.", "bad_input",
               argument = "angles", call = call)
    }
    as.numeric(a)
  }, numeric(p)))
  for (k in which(ch$unit == "raw")) {
    y <- target[, k]
    u <- means[, k]
    if (length(unique(y)) >= 2L && length(unique(u)) >= 2L) {
      b <- stats::cov(u, y) / stats::var(u)
      map$gain[k] <- b
      map$offset[k] <- mean(y) - b * mean(u)
      map$source[k] <- "poses"
    } else if (!is.na(map$gain[k])) {
      map$offset[k] <- mean(y - map$gain[k] * u)
      map$source[k] <- "poses"
    }
  }
  map
}
