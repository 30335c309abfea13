# The 23 CyberGlove sensor columns of GraspDB14, the GraspDB14 object and
# action tables, and the mapping from GraspDB14 sensors to the 16 HUST DoFs.

#' The 23 CyberGlove sensors of GraspDB14 motion files
#'
#' One row per sensor column of a GraspDB14 motion file, in file order
#' (Stollenwerk et al. 2018, Tables 3.1, 4.3 and 5.1), with the HUST DoF each
#' one corresponds to (used by [graspdb14_to_hust()]).
#'
#' @format A data frame with 23 rows and 12 columns:
#' \describe{
#'   \item{index}{Column among the 23 sensors, 1-23.}
#'   \item{sensor_no}{Sensor number 0-22 of the report (Figure 3.1b).}
#'   \item{key}{Field of the sensor in the 30-field data row (8-30).}
#'   \item{name}{Sensor denotation of Table 4.3, e.g. `"T-TMJ"`, `"I-MCPJ"`,
#'     `"MI-AA"`; the DoF names of grasps read by [read_graspdb14()].}
#'   \item{finger}{thumb, index, middle, ring, little, the finger pair of an
#'     abduction sensor (e.g. `"middle-index"`), palm or wrist.}
#'   \item{joint}{TMJ, MCP, PIP, DIP, IP, CMC or wrist.}
#'   \item{motion}{flexion, abduction, rotation across palm or palm arch.}
#'   \item{status}{`"measured"` (the 18 sensors of the 18-sensor glove),
#'     `"inferred"` (the four DIP joints, marked * in Table 4.3: zero in raw
#'     files, estimated in angle files) or `"unsupported"` (I-AA, marked **:
#'     always 0).}
#'   \item{joint_skel}{Joint of the GraspDB14 default skeleton the sensor
#'     drives (Table 5.1).}
#'   \item{axis}{Local rotation axis of that joint (`x` flexion, `z`
#'     abduction); `NA` where the report discards the sensor (I-AA, P-Arch).}
#'   \item{hust_dof}{The HUST DoF ([hust_dofs]) the sensor corresponds to;
#'     `NA` for the sensors HUST has no DoF for (finger ab-/adduction, palm
#'     arch, wrist).}
#'   \item{hust_sign}{Sign applied when converting to HUST angles: -1 for
#'     flexion sensors (GraspDB14 angle files store flexion as negative
#'     angles), 1 for the thumb abduction TI-AA.}
#' }
#' @source Stollenwerk, K., Hinkenjann, A. and Klein, R. (2018). *GraspDB14 -
#'   Documentation on a database of grasp motions and its creation*. Technical
#'   report 01-2018, Hochschule Bonn-Rhein-Sieg. \doi{10.18418/978-3-96043-061-2}.
#'   Built by `data-raw/cyberglove_sensors.R`.
#' @seealso [graspdb14_to_hust()], [read_graspdb14()]
#' @examples
#' cyberglove_sensors[, c("name", "status", "hust_dof")]
"cyberglove_sensors"

#' GraspDB14 objects
#'
#' The objects of GraspDB14 and the Feix grasp types used on each in
#' controlled transport (Table 4.1 of the report).
#'
#' @format A data frame with 16 rows: `id` (object id of the file names),
#'   `name`, `grasp_ids` (Feix grasp ids, comma-separated, `NA` when the
#'   object was not used in controlled transport), `controlled` (logical).
#' @source Stollenwerk, Hinkenjann and Klein (2018), Table 4.1. Built by
#'   `data-raw/graspdb14-tables.R`.
#' @examples
#' graspdb14_objects[graspdb14_objects$controlled, c("id", "name", "grasp_ids")]
"graspdb14_objects"

#' GraspDB14 actions (scenario 2)
#'
#' The action ids of the object use and interaction scenario (Table 4.2 of the
#' report): `<obj>_<action>_<hand>_ex02-...` file names.
#'
#' @format A data frame with 7 rows: `code` (e.g. `"o_r"`), `action_id`,
#'   `hand_id`, `action` (open, close, close tightly, interact) and `hand`
#'   (leading hand, left or right).
#' @source Stollenwerk, Hinkenjann and Klein (2018), Table 4.2. Built by
#'   `data-raw/graspdb14-tables.R`.
#' @examples
#' graspdb14_actions
"graspdb14_actions"

#' Convert GraspDB14 sensor angles to the 16 HUST DoFs
#'
#' Maps a 23-sensor GraspDB14 [grasps()] object (unit `"rad"`) onto the 16
#' HUST DoFs ([hust_dofs]) in degrees, so GraspDB14 recordings can be used
#' wherever HUST-like recordings are expected (models, plots, [write_hust()]).
#'
#' Sensor to DoF (see `cyberglove_sensors[, c("name", "hust_dof")]`):
#' T-TMJ -> CMC1 (thumb rotation across the palm, taken as CMC flexion),
#' TI-AA -> ABD1, T-MCPJ -> MCP1, T-IPJ -> IP1, and for finger f = index,
#' middle, ring, little (HUST 2-5): x-MCPJ -> MCPf, x-PIPJ -> PIPf,
#' x-DIPJ -> DIPf. Flexion angles change sign (GraspDB14 stores flexion as
#' negative angles, HUST as positive); TI-AA keeps its sign.
#'
#' Not available: the 18-sensor glove has no DIP sensors, so the four DIP
#' values of GraspDB14 angle files are *inferred* by the recording software,
#' not measured (`dip = "inferred"` uses them, `dip = "pip"` replaces each by
#' two thirds of the same finger's PIP angle, a common DIP-PIP coupling, and
#' `dip = "zero"` sets them to 0). Sensors without a HUST DoF are dropped and
#' listed in attribute `"unmapped"`: I-AA (unsupported, always 0), the
#' finger abductions MI-AA, RM-AA, LR-AA, the palm arch P-Arch and the wrist
#' W-FE, W-AA. The chosen DIP source is recorded in metadata column
#' `dip_source`.
#'
#' @param x A `grasps` object with the 23 GraspDB14 sensors, unit `"rad"`.
#' @param dip Source of the DIP angles: `"inferred"`, `"pip"` or `"zero"`.
#' @return A `grasps` object with the 16 HUST DoFs in degrees, the same
#'   metadata plus `dip_source`, the same rate; per-recording attributes
#'   (`switch`, `time`) are kept.
#' @seealso [cyberglove_sensors], [read_graspdb14()], [write_hust()]
#' @export
#' @examples
#' g <- read_graspdb14(system.file("extdata", "graspdb14", package = "handmotion"))
#' h <- graspdb14_to_hust(g)
#' h
#' attr(h, "unmapped")
graspdb14_to_hust <- function(x, dip = c("inferred", "pip", "zero")) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  dip <- check_choice(dip, arg = "dip", call = call)
  sensors <- handmotion::cyberglove_sensors
  missing <- setdiff(sensors$name[!is.na(sensors$hust_dof)], x$dofs)
  if (length(missing)) {
    hm_abort(c("{.arg x} lacks the GraspDB14 sensor{?s} {.val {missing}}.",
               i = "Expected the 23 sensors of {.code cyberglove_sensors$name}."),
             "bad_input", argument = "x", call = call)
  }
  if (x$unit != "rad") {
    hm_abort(c("{.arg x} is in {.val {x$unit}}; the conversion needs joint angles in radians.",
               i = if (x$unit == "raw") "Raw 8-bit sensor counts need the glove calibration to become angles; read the {.code -rad-} files." else NULL),
             "bad_input", argument = "x", call = call)
  }
  hust <- handmotion::hust_dofs$name
  map <- sensors[!is.na(sensors$hust_dof), , drop = FALSE]
  map <- map[match(hust, map$hust_dof), , drop = FALSE]
  scale <- map$hust_sign * 180 / pi
  dip_cols <- grep("^DIP", hust)
  pip_cols <- match(sub("^DIP", "PIP", hust[dip_cols]), hust)
  recs <- lapply(x$recordings, function(rec) {
    out <- sweep(rec[, map$name, drop = FALSE], 2L, scale, `*`)
    if (dip == "pip") out[, dip_cols] <- out[, pip_cols] * 2 / 3
    if (dip == "zero") out[, dip_cols] <- 0
    colnames(out) <- hust
    for (a in c("switch", "time")) attr(out, a) <- attr(rec, a, exact = TRUE)
    out
  })
  meta <- x$meta
  meta$dip_source <- dip
  out <- new_grasps(recs, meta, hust, x$rate, "deg")
  attr(out, "unmapped") <- sensors$name[is.na(sensors$hust_dof)]
  attr(out, "mapping") <- data.frame(hust_dof = hust, sensor = map$name, status = map$status,
                                     sign = map$hust_sign, stringsAsFactors = FALSE)
  out
}
