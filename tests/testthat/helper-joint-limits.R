# clamp_to_limits() (tests only): every mapped angle of a matrix or a grasps set
# pulled back inside the skeleton's limits, with counts; tests use it to
# check dof_limits(), the ranges generate(limits = TRUE) keeps to.

# Keep joint angles inside the skeleton's limits
#
# For every DoF the mapping applies to a joint axis, the applied angle
# (`sign * scale * angle`, in degrees) is clamped to that axis' limits in the
# skeleton and converted back to the DoF's own unit and sign. DoFs the
# mapping does not apply are left as they are and listed in the
# `"unclamped"` attribute. Several DoFs on one axis are clamped one by one.
#
# @param x A numeric frames x DoF matrix (with DoF column names) or a
#   [grasps()] object.
# @param skeleton A [hand_skeleton()].
# @param mapping A joint mapping (see [joint_map()]); chosen from
#   the DoF names by default.
# @param unit Angle unit of a matrix `x` (`"deg"` or `"rad"`).
# @return An object of the same class as `x` with clamped angles and
#   attributes `"clamped"` (number of values changed), `"clamped_by_dof"`
#   (named counts) and `"unclamped"` (DoFs without limits).
# @examples
# rec <- matrix(c(120, -50, 40), 3, 16, dimnames = list(NULL, hust_dofs$name))
# out <- clamp_to_limits(rec)
# out[, "PIP2"]
# attr(out, "clamped")
clamp_to_limits <- function(x, skeleton = hand_skeleton(), mapping = NULL, unit = NULL) {
  call <- rlang::caller_env()
  check_skeleton(skeleton, call = call)
  input <- fk_input(x, unit, call)
  if (!is.null(input$mapping) && inherits(x, "grasps") && x$unit == "raw") {
    hm_abort(c("Joint limits are angles; {.arg x} holds raw counts.", i = "Calibrate it first: {.code calibrate(x)}."),
             "bad_input", argument = "x", call = call)
  }
  lim <- dof_limits(input$dofs, input$factor, skeleton, mapping %||% input$mapping, call)
  counts <- stats::setNames(integer(nrow(lim)), lim$dof)
  clamp_one <- function(rec) {
    for (k in seq_len(nrow(lim))) {
      v <- rec[, lim$col[k]]
      out <- pmin(pmax(v, lim$lo[k]), lim$hi[k])
      changed <- out != v
      if (any(changed)) {
        counts[k] <<- counts[k] + sum(changed)
        rec[changed, lim$col[k]] <- out[changed]
      }
    }
    rec
  }
  res <- if (inherits(x, "grasps")) {
    x$recordings <- lapply(x$recordings, clamp_one)
    x
  } else {
    clamp_one(input$recordings[[1]])
  }
  attr(res, "clamped") <- sum(counts)
  attr(res, "clamped_by_dof") <- counts
  attr(res, "unclamped") <- setdiff(input$dofs, lim$dof)
  res
}
