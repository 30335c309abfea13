# Glove profiles: what each channel of a data glove measures. A profile is
# the one place a glove is described: which joint of the hand skeleton a
# channel drives (axis, sign, scale, as in joint_map()), the unit it reports
# (degrees, radians or raw sensor counts), its physical range, and for raw
# channels the nominal map from counts to degrees. A grasps object carries its
# glove's profile, so forward kinematics, pictures, BVH, joint limits,
# calibration and generation all read the same description.

glove_channel_cols <- c("channel", "joint", "axis", "sign", "scale", "frame", "unit",
                        "min", "max", "angle_min", "angle_max", "stuck")

#' Glove profiles: what each channel of a data glove measures
#'
#' A glove profile describes a data glove once, per channel:
#' * `channel`: the column name in the recordings;
#' * `joint`, `axis`, `sign`, `scale`, `frame`: the skeleton joint the channel
#'   drives, as in [joint_map()] (`joint`/`axis` `NA` for a channel that
#'   drives no joint: pressure pads, wrist or unnamed channels are kept for
#'   modelling and listed as not drawn);
#' * `unit`: what the channel reports, `"deg"`, `"rad"` or `"raw"` (sensor
#'   counts);
#' * `min`, `max`: its physical range in that unit (`NA` when unknown; for a
#'   raw channel the range of the converter, e.g. 0 and 1000);
#' * `angle_min`, `angle_max`: for raw channels, the joint angles in degrees
#'   that `min` and `max` correspond to (the nominal calibration, which
#'   [calibrate()] replaces by one fitted to calibration poses);
#' * `stuck`: channels found constant over every recording (set by
#'   [grasps()] and [calibrate()]).
#'
#' Shipped profiles, by name:
#' * `"hust"`: the 16 joint angles of the thesis' CyberGlove data (HUST), in
#'   degrees ([hust_dofs]); its joint limits are the skeleton's.
#' * `"graspdb14"`: the 23 CyberGlove sensors of GraspDB14 in radians, mapped
#'   as in its report (Table 5.1, see [joint_map()]).
#' * `"cyberglove18"`: an 18-sensor CyberGlove (two flexion sensors per
#'   finger, thumb rotation, four abduction sensors, palm arch, wrist flexion
#'   and abduction), calibrated to degrees.
#' * `"cyberglove22"`: the 22-sensor CyberGlove (the 18 and the four distal
#'   joints), in degrees.
#' * `"resistive"`: a generic resistive glove reporting raw counts 0-1000:
#'   two bend sensors per finger (thumb MCP and IP, finger MCP and PIP), four
#'   abduction sensors between neighbouring fingers and a thumb cross-over
#'   sensor, with nominal angle ranges for the counts.
#' * `"flexglove"`: the six-flex-sensor glove of the shipped real recordings
#'   (`system.file("extdata", "flexglove", package = "handmotion")`, see
#'   [read_glove()]): channels `flex1`..`flex6`, raw 10-bit counts 0-1023
#'   that fall as a finger bends (`sign` -1). Its source does not say which
#'   channel is which finger; the profile assumes flex1-flex5 are the MCP
#'   flexion of thumb, index, middle, ring and little finger and flex6 the
#'   thumb-index adduction (for drawing only), with a nominal map from the
#'   recordings' typical levels (straight at about 230 counts, 0.6 degrees
#'   of flexion per count below it).
#'
#' Your own glove: give a data frame (or the path of a CSV file) with at
#' least the column `channel`; every other column is optional (missing
#' `joint`/`axis` mean not drawn, `sign`/`scale` 1, `frame` `"joint"`, `unit`
#' the `unit` argument, ranges unknown). See the example and
#' `vignette("own-glove")`.
#'
#' @param x A shipped profile's name, a data frame of channels, or the path of
#'   a CSV file of channels.
#' @param name A name for the profile (defaults to the shipped name or
#'   `"custom"`).
#' @param unit The unit of channels whose `unit` column is missing.
#' @return An object of class `glove_profile`: a list with `name` and
#'   `channels` (a data frame with the columns above).
#' @seealso [calibrate()], [grasps()], [joint_map()]
#' @export
#' @examples
#' glove_profile("resistive")
#' # your own glove in a few lines: two bend sensors and a pressure pad
#' glove_profile(data.frame(channel = c("index_mcp", "index_pip", "pad"),
#'                          joint = c("if-mcp", "if-pip", NA), axis = c("x", "x", NA),
#'                          unit = "raw", min = 0, max = 1023,
#'                          angle_min = c(0, 0, NA), angle_max = c(90, 110, NA)))
#' # or from a CSV file
#' f <- tempfile(fileext = ".csv")
#' write.csv(glove_profile("resistive")$channels[, 1:11], f, row.names = FALSE)
#' glove_profile(f, name = "my glove")
glove_profile <- function(x = "hust", name = NULL, unit = "deg") {
  call <- rlang::caller_env()
  unit <- check_unit(unit, call = call)
  if (inherits(x, "glove_profile")) return(x)
  if (is.character(x) && length(x) == 1L && !is.na(x) && x %in% names(shipped_gloves)) {
    return(new_glove_profile(name %||% x, shipped_gloves[[x]]()))
  }
  if (is.character(x) && length(x) == 1L && !is.na(x)) {
    if (!file.exists(x)) {
      hm_abort(c("{.arg x} must be a shipped profile ({.val {names(shipped_gloves)}}), a data frame or a CSV file.",
                 x = "No such profile or file: {.val {x}}."),
               "bad_glove", argument = "x", call = call)
    }
    channels <- tryCatch(utils::read.csv(x, stringsAsFactors = FALSE, strip.white = TRUE),
                         error = function(e) {
                           hm_abort("Cannot read glove profile {.file {x}}: {conditionMessage(e)}",
                                    c("bad_glove", "bad_file"), file = x, call = call)
                         })
    return(new_glove_profile(name %||% tools::file_path_sans_ext(basename(x)),
                             complete_channels(channels, unit, file = x, call = call), call = call))
  }
  if (!is.data.frame(x)) {
    hm_abort("{.arg x} must be a profile name, a data frame of channels or a CSV path, not {.obj_type_friendly {x}}.",
             "bad_glove", argument = "x", call = call)
  }
  new_glove_profile(name %||% "custom", complete_channels(x, unit, call = call), call = call)
}

# Fill the optional columns of a user's channel table with their defaults.
complete_channels <- function(ch, unit, file = NULL, call = rlang::caller_env()) {
  ch <- as.data.frame(ch, stringsAsFactors = FALSE)
  if (!"channel" %in% names(ch)) {
    hm_abort(c("A glove profile needs a {.field channel} column (the channel names).",
               i = "Columns given: {.val {names(ch)}}."),
             "bad_glove", argument = "x", file = file, call = call)
  }
  n <- nrow(ch)
  defaults <- list(joint = NA_character_, axis = NA_character_, sign = 1, scale = 1, frame = "joint",
                   unit = unit, min = NA_real_, max = NA_real_, angle_min = NA_real_,
                   angle_max = NA_real_, stuck = FALSE)
  for (col in names(defaults)) {
    if (!col %in% names(ch)) ch[[col]] <- rep(defaults[[col]], n)
    if (is.character(defaults[[col]])) {
      v <- as.character(ch[[col]])
      v[!is.na(v) & !nzchar(trimws(v))] <- NA
      ch[[col]] <- v
      if (!is.na(defaults[[col]])) ch[[col]][is.na(ch[[col]])] <- defaults[[col]]
    }
  }
  ch$channel <- as.character(ch$channel)
  ch$axis <- tolower(ch$axis)
  # (a CSV column left empty reads as logical NA)
  for (col in c("sign", "scale", "min", "max", "angle_min", "angle_max")) {
    if (is.logical(ch[[col]]) && all(is.na(ch[[col]]))) ch[[col]] <- as.numeric(ch[[col]])
  }
  ch$stuck <- as.logical(ch$stuck)
  ch$stuck[is.na(ch$stuck)] <- FALSE
  ch[glove_channel_cols]
}

# The one constructor of class "glove_profile" and its validator.
new_glove_profile <- function(name, channels, call = rlang::caller_env()) {
  channels <- as.data.frame(channels, stringsAsFactors = FALSE)[glove_channel_cols]
  rownames(channels) <- NULL
  validate_glove_profile(structure(list(name = name, channels = channels), class = "glove_profile"),
                         call = call)
}

validate_glove_profile <- function(x, call = rlang::caller_env()) {
  ch <- x$channels
  bad <- function(msg, ...) hm_abort(msg, "bad_glove", argument = "x", call = call, ...)
  if (!nrow(ch)) bad("A glove profile needs at least one channel.")
  if (anyNA(ch$channel) || any(!nzchar(ch$channel)) || anyDuplicated(ch$channel)) {
    bad("Glove channel names must be unique and non-empty; repeated: {.val {unique(ch$channel[duplicated(ch$channel)])}}.")
  }
  if (any(!ch$unit %in% grasp_units)) {
    b <- which(!ch$unit %in% grasp_units)[1]
    bad("Channel {.val {ch$channel[b]}} has unit {.val {ch$unit[b]}}; use {.val {grasp_units}}.")
  }
  ax <- !is.na(ch$axis)
  if (any(ax & !ch$axis %in% c("x", "y", "z"))) {
    b <- which(ax & !ch$axis %in% c("x", "y", "z"))[1]
    bad("Channel {.val {ch$channel[b]}} has axis {.val {ch$axis[b]}}; use {.val x}, {.val y}, {.val z} or NA.")
  }
  if (any(ax & is.na(ch$joint))) {
    bad("Channel {.val {ch$channel[ax & is.na(ch$joint)][1]}} has an axis but no joint.")
  }
  if (any(!ch$frame %in% c("joint", "parent"))) {
    bad("Channel frame must be {.val joint} or {.val parent}; {.val {ch$channel[!ch$frame %in% c('joint', 'parent')][1]}} is not.")
  }
  for (col in c("sign", "scale", "min", "max", "angle_min", "angle_max")) {
    if (!is.numeric(ch[[col]])) bad("Glove column {.field {col}} must be numeric.")
  }
  if (anyNA(ch$sign) || anyNA(ch$scale)) bad("Glove columns {.field sign} and {.field scale} must not be missing.")
  ranged <- !is.na(ch$min) & !is.na(ch$max)
  if (any(ranged & ch$min >= ch$max)) {
    b <- which(ranged & ch$min >= ch$max)[1]
    bad("Channel {.val {ch$channel[b]}} has range {ch$min[b]} to {ch$max[b]}; {.field min} must be below {.field max}.")
  }
  raw_drawn <- ch$unit == "raw" & ax
  if (any(raw_drawn & (is.na(ch$angle_min) | is.na(ch$angle_max) | !ranged))) {
    b <- which(raw_drawn & (is.na(ch$angle_min) | is.na(ch$angle_max) | !ranged))[1]
    bad(c("Raw channel {.val {ch$channel[b]}} drives a joint but has no nominal map to degrees.",
          i = "Give {.field min}, {.field max}, {.field angle_min} and {.field angle_max}, or leave it undrawn."))
  }
  x
}

#' @export
print.glove_profile <- function(x, ...) {
  ch <- x$channels
  drawn <- !is.na(ch$axis)
  units <- table(ch$unit)
  by_unit <- paste(sprintf("%d %s", as.integer(units), names(units)), collapse = ", ")
  cli::cat_line(cli::pluralize("<glove_profile> {x$name}: {nrow(ch)} channel{?s} ({by_unit})"))
  cli::cat_line("  drawn: ", sum(drawn), "; not drawn: ",
                if (any(!drawn)) paste(ch$channel[!drawn], collapse = " ") else "none")
  if (any(ch$stuck)) cli::cat_line("  stuck (constant, left out of models): ", paste(ch$channel[ch$stuck], collapse = " "))
  print(utils::head(ch[c("channel", "joint", "axis", "sign", "unit", "min", "max")], 8), row.names = FALSE)
  if (nrow(ch) > 8) cli::cat_line(cli::pluralize("  ... and {nrow(ch) - 8} more channel{?s}"))
  invisible(x)
}

# The profile a set gets when none is given: a shipped profile whose channels
# are exactly the set's DoFs (HUST, GraspDB14), else one built from the DoF
# names, drawing the channels a known mapping recognises and listing the
# rest as not drawn.
guess_glove <- function(dofs, unit) {
  for (nm in c("hust", "graspdb14")) {
    ch <- shipped_gloves[[nm]]()
    if (unit != "raw" && length(dofs) == nrow(ch) && all(dof_key(dofs) == dof_key(ch$channel))) {
      ch$channel <- dofs
      if (unit != ch$unit[1]) ch <- convert_channel_ranges(ch, unit)
      return(new_glove_profile(nm, ch))
    }
  }
  ch <- data.frame(channel = dofs, stringsAsFactors = FALSE)
  map <- tryCatch(default_joint_map_impl(dofs, NULL), handmotion_error = function(e) NULL)
  if (!is.null(map)) {
    i <- match(map$dof, dofs)
    for (col in c("joint", "axis", "sign", "scale", "frame")) {
      ch[[col]] <- if (col %in% c("sign", "scale")) 1 else NA_character_
      ch[[col]][i] <- map[[col]]
    }
    ch$frame[is.na(ch$frame)] <- "joint"
  }
  if (unit == "raw") ch$axis <- NA_character_   # raw counts without a nominal map cannot be drawn
  new_glove_profile("unknown", complete_channels(ch, unit))
}

# Ranges of deg/rad channels in another angle unit (a set recorded in
# radians with a profile written in degrees, or the reverse).
convert_channel_ranges <- function(ch, unit) {
  ang <- ch$unit %in% c("deg", "rad")
  if (unit %in% c("deg", "rad")) {
    f <- ifelse(ch$unit[ang] == unit, 1, if (unit == "rad") pi / 180 else 180 / pi)
    ch$min[ang] <- ch$min[ang] * f
    ch$max[ang] <- ch$max[ang] * f
    ch$unit[ang] <- unit
  }
  ch
}

# A profile checked against the DoFs of a set: the channels must be the DoFs,
# in their order (a profile with extra channels is cut to the DoFs).
match_glove <- function(glove, dofs, unit, call = rlang::caller_env()) {
  if (is.null(glove)) return(guess_glove(dofs, unit))
  glove <- glove_profile(glove, unit = unit)
  idx <- match(dof_key(dofs), dof_key(glove$channels$channel))
  if (anyNA(idx)) {
    hm_abort(c("The glove profile {.val {glove$name}} has no channel{?s} {.val {dofs[is.na(idx)]}}.",
               i = "Its channels: {.val {utils::head(glove$channels$channel, 10)}}."),
             "bad_glove", argument = "glove", call = call)
  }
  ch <- glove$channels[idx, , drop = FALSE]
  ch$channel <- dofs
  # the set's unit and the profile's must agree (a set edited after it was
  # built, or a profile written for another unit)
  if (unit %in% c("deg", "rad")) ch <- convert_channel_ranges(ch, unit)
  if (unit == "raw" && !any(ch$unit == "raw")) {
    hm_abort(c("The recordings are raw counts but the glove profile {.val {glove$name}} describes angles ({.val {unique(ch$unit)}}).",
               i = "Give a profile whose channels have {.code unit = \"raw\"} and a map to degrees, or convert the recordings."),
             "bad_input", argument = "unit", call = call)
  }
  new_glove_profile(glove$name, ch, call = call)
}

# The joint mapping (joint_map() format) of a profile's drawn channels.
glove_mapping <- function(glove) {
  ch <- glove$channels[!is.na(glove$channels$axis), , drop = FALSE]
  data.frame(dof = ch$channel, joint = ch$joint, axis = ch$axis, sign = ch$sign, scale = ch$scale,
             frame = ch$frame, stringsAsFactors = FALSE)
}

# Recordings in degrees, channel by channel through the profile: degrees as
# they are, radians converted, raw counts through the nominal (or
# calibrated) linear map; channels without a map stay as recorded (they are
# not drawn).
glove_degrees <- function(recordings, glove) {
  ch <- glove$channels
  a <- ifelse(ch$unit == "rad", 180 / pi, 1)
  b <- rep(0, nrow(ch))
  map <- nominal_map(ch)
  raw <- !is.na(map$gain)
  a[raw] <- map$gain[raw]
  b[raw] <- map$offset[raw]
  if (all(a == 1) && all(b == 0)) return(recordings)
  lapply(recordings, function(r) sweep(sweep(r, 2, a, "*"), 2, b, "+"))
}

# Channels constant over every recording of a set (a stuck or unplugged
# sensor): their range over all frames is below `tol` of the largest range of
# any channel of the same unit (exactly zero for a set of one channel).
find_stuck <- function(recordings, tol = 1e-9) {
  if (!length(recordings)) return(logical())
  r <- channel_ranges(recordings)
  span <- r$hi - r$lo
  span <= tol * max(c(span, 1))
}

# The smallest and largest value of each channel over every frame of a set
# (finite values, as grasps() holds them), in one compiled pass
# (src/channel-ranges.c): two apply() calls per recording were a tenth of
# evaluate_generation()'s time and an eighth of reading a GraspDB14
# directory.
channel_ranges <- function(recordings) {
  p <- ncol(recordings[[1]])
  if (!all(vapply(recordings, is.double, NA))) recordings <- lapply(recordings, `storage.mode<-`, "double")
  r <- .Call(hm_channel_ranges, recordings, p)
  nm <- colnames(recordings[[1]])
  list(lo = stats::setNames(r[1, ], nm), hi = stats::setNames(r[2, ], nm))
}

# Recordings a set needs before a channel constant over all of them counts
# as a stuck sensor.
stuck_min_recordings <- 5L

# Flag stuck channels in a set's profile, with one classed warning.
flag_stuck <- function(x, call = rlang::caller_env()) {
  stuck <- find_stuck(x$recordings)
  # a set in which nothing varies is constant data, not a glove with stuck
  # sensors; and a handful of recordings (a few poses) is not evidence of one
  if (all(stuck) || length(x) < stuck_min_recordings) stuck[] <- FALSE
  if (any(stuck & !x$glove$channels$stuck)) {
    hm_warn(c("{cli::qty(sum(stuck))}Channel{?s} {.val {x$dofs[stuck]}} {?is/are} constant over every recording (a stuck or unplugged sensor?).",
              i = "{cli::qty(sum(stuck))}{?It is/They are} kept in the data, left out of models (held at {?its/their} value) and shown by {.fn print}."),
            "stuck_channels", channels = x$dofs[stuck])
  }
  x$glove$channels$stuck <- stuck
  x
}

# Names of the stuck channels of a set (none for a set without a profile).
stuck_channels <- function(x) {
  g <- x$glove
  if (is.null(g)) character() else g$channels$channel[g$channels$stuck]
}

# --- the shipped profiles ----------------------------------------------------

# The channels of a joint map (joint_map() format) in one unit, ranges unknown.
channels_from_map <- function(m, unit, sign = m$sign) {
  data.frame(channel = m$dof, joint = m$joint, axis = m$axis, sign = sign, scale = m$scale,
             frame = m$frame, unit = unit, min = NA_real_, max = NA_real_, angle_min = NA_real_,
             angle_max = NA_real_, stuck = FALSE, stringsAsFactors = FALSE)
}

# Flexion signs of a joint map for a glove whose readings rise with bending
# (a calibrated CyberGlove, raw counts): +1 for flexion, the map's own sign
# elsewhere (GraspDB14's files store flexion negated, hence its map's -1).
flexion_positive <- function(m) ifelse(!is.na(m$axis) & m$axis == "x", 1, m$sign)

hust_glove_channels <- function() channels_from_map(hust_joint_map(), "deg")

graspdb14_glove_channels <- function() channels_from_map(graspdb14_joint_map(), "rad")

# CyberGlove sensors calibrated to degrees: the GraspDB14 mapping with
# flexion positive.
cyberglove_channels <- function(sensors) {
  m <- graspdb14_joint_map()
  m <- m[match(sensors, m$dof), ]
  channels_from_map(m, "deg", sign = flexion_positive(m))
}

cyberglove18_sensors <- c("T-TMCJ", "T-MCPJ", "T-IPJ", "TI-AA", "I-MCPJ", "I-PIPJ", "M-MCPJ", "M-PIPJ",
                          "MI-AA", "R-MCPJ", "R-PIPJ", "RM-AA", "L-MCPJ", "L-PIPJ", "LR-AA", "P-Arch",
                          "W-FE", "W-AA")
cyberglove22_sensors <- c("T-TMCJ", "T-MCPJ", "T-IPJ", "TI-AA", "I-MCPJ", "I-PIPJ", "I-DIPJ", "M-MCPJ",
                          "M-PIPJ", "M-DIPJ", "MI-AA", "R-MCPJ", "R-PIPJ", "R-DIPJ", "RM-AA", "L-MCPJ",
                          "L-PIPJ", "L-DIPJ", "LR-AA", "P-Arch", "W-FE", "W-AA")

# A generic resistive bend-sensor glove reporting 10-bit-like counts 0-1000:
# two bend sensors per finger, four abduction sensors and a thumb cross-over
# sensor. Nominal angles at the ends of the count range (flexion positive).
resistive_glove_channels <- function() {
  data.frame(
    channel = c("thumb_mcp", "thumb_ip", "index_mcp", "index_pip", "middle_mcp", "middle_pip",
                "ring_mcp", "ring_pip", "little_mcp", "little_pip",
                "thumb_index_abd", "index_middle_abd", "middle_ring_abd", "ring_little_abd",
                "thumb_cross"),
    joint = c("th-mcp", "th-ip", "if-mcp", "if-pip", "mf-mcp", "mf-pip", "rf-mcp", "rf-pip",
              "lf-mcp", "lf-pip", "th-mcp", "if-mcp", "rf-mcp", "lf-mcp", "th-tmc"),
    axis = c(rep("x", 10), "z", "z", "z", "z", "y"),
    sign = c(rep(1, 10), -1, -1, -1, -1, 1), scale = c(rep(1, 10), 1, 0.5, 0.5, 1, 1),
    frame = c(rep("joint", 14), "parent"), unit = "raw", min = 0, max = 1000,
    angle_min = c(-10, -20, -20, -5, -20, -5, -20, -5, -20, -5, -10, -10, -10, -10, -30),
    angle_max = c(80, 90, 100, 120, 100, 120, 100, 120, 100, 120, 80, 30, 30, 30, 90),
    stuck = FALSE, stringsAsFactors = FALSE)
}

# The six-flex-sensor glove of the flexglove recordings (inst/extdata/flexglove,
# Oooorca/AML_LAB_Project): raw 10-bit counts 0-1023 that FALL as a finger
# bends, hence sign -1. The source says "5 fingers + 1 for thumb-index
# adduction" but not which channel is which; the profile assumes flex1-flex5
# are the thumb, index, middle, ring and little MCP flexion and flex6 the
# thumb-index adduction (used only to draw the hand; models use the counts).
# Nominal map from the recordings' typical levels (median rest 130-225
# counts, grasp 90-180): a finger at rest near 230 counts is straight and
# each count of drop is 0.6 degrees of flexion (90 degrees at 80 counts); the
# adduction sensor 0.2 degrees per count about a rest of 130.
flexglove_channels <- function() {
  per_count <- c(rep(0.6, 5), 0.2)
  rest <- c(rep(230, 5), 130)
  data.frame(
    channel = paste0("flex", 1:6),
    joint = c("th-mcp", "if-mcp", "mf-mcp", "rf-mcp", "lf-mcp", "th-mcp"),
    axis = c(rep("x", 5), "z"), sign = -1, scale = 1, frame = "joint", unit = "raw",
    min = 0, max = 1023,
    # the channel's reading before the sign: per_count * (count - rest)
    angle_min = per_count * (0 - rest), angle_max = per_count * (1023 - rest),
    stuck = FALSE, stringsAsFactors = FALSE)
}

shipped_gloves <- list(
  hust = hust_glove_channels,
  graspdb14 = graspdb14_glove_channels,
  cyberglove18 = function() cyberglove_channels(cyberglove18_sensors),
  cyberglove22 = function() cyberglove_channels(cyberglove22_sensors),
  resistive = resistive_glove_channels,
  flexglove = flexglove_channels
)

# One recording of a set as forward kinematics wants it: angles in degrees
# through the set's glove, and the glove's joint mapping (NULL for a set
# without a profile: the mapping is then chosen from the DoF names).
glove_recording <- function(x, i) {
  rec <- x$recordings[[i]]
  if (is.null(x$glove)) return(list(angles = rec, unit = x$unit, mapping = NULL))
  glove <- match_glove(x$glove, x$dofs, x$unit)
  map <- glove_mapping(glove)
  list(angles = glove_degrees(list(rec), glove)[[1]], unit = "deg", mapping = if (nrow(map)) map)
}

# forward_kinematics() of one recording matrix with a glove's mapping, unless
# the caller's `...` gives one.
fk_mapped <- function(angles, skeleton, unit, mapping, ...) {
  dots <- list(...)
  if (is.null(dots$mapping)) dots$mapping <- mapping
  do.call(forward_kinematics, c(list(angles, skeleton, unit = unit), dots))
}

# Raw counts from channels whose names a known mapping recognises (CyberGlove
# sensor names, HUST DoFs) but without a profile: drawn through a guessed
# map, each channel's recorded range onto a typical range of its joint axis
# (flexion increasing with the count), so the hand can be looked at before a
# calibration. NULL when no channel is recognised.
guess_raw_glove <- function(dofs, recordings, template = NULL) {
  map <- if (!is.null(template)) {
    # a profile written for angles (a CyberGlove's), given for raw counts
    glove_mapping(template)
  } else {
    tryCatch(default_joint_map_impl(dofs, NULL), handmotion_error = function(e) NULL)
  }
  if (is.null(map) || !nrow(map)) return(NULL)
  map <- map[dof_key(map$dof) %in% dof_key(dofs), , drop = FALSE]
  map$dof <- dofs[match(dof_key(map$dof), dof_key(dofs))]
  range <- channel_ranges(recordings)
  ch <- data.frame(channel = dofs, joint = NA_character_, axis = NA_character_, sign = 1, scale = 1,
                   frame = "joint", unit = "raw", min = unname(range$lo), max = unname(range$hi),
                   angle_min = NA_real_, angle_max = NA_real_, stuck = FALSE, stringsAsFactors = FALSE)
  i <- match(map$dof, dofs)
  ch$joint[i] <- map$joint
  ch$axis[i] <- map$axis
  ch$frame[i] <- map$frame
  # (a joint map's flexion sign follows its files' convention; counts rise with bending)
  ch$sign[i] <- flexion_positive(map)
  ch$scale[i] <- map$scale
  typical <- function(joint, axis) {
    if (is.na(axis)) return(c(NA, NA))
    if (axis == "z") return(c(-15, 15))
    if (axis == "y") return(c(-30, 60))
    if (grepl("^th-mcp", joint)) return(c(0, 50))
    if (grepl("^th-ip", joint)) return(c(0, 70))
    if (grepl("dip$", joint)) return(c(0, 70))
    if (grepl("pip$", joint)) return(c(0, 100))
    if (grepl("mcp$", joint)) return(c(0, 90))
    c(-30, 30)
  }
  r <- t(mapply(typical, ch$joint, ch$axis))
  ch$angle_min <- r[, 1]
  ch$angle_max <- r[, 2]
  flat <- !(ch$max > ch$min)
  ch$axis[flat] <- NA_character_
  if (!any(!is.na(ch$axis))) return(NULL)
  new_glove_profile(if (is.null(template)) "guessed from channel names"
                    else paste(template$name, "(raw counts, guessed map)"), ch)
}
