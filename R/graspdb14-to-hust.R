# GraspDB14's 23 CyberGlove sensors (radians) to the thesis' 16 HUST DoFs
# (degrees): the conversion that lets GraspDB14 recordings go through the
# thesis pipeline.

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
