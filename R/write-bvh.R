# BVH export: a hand animation Blender (and most motion tools) can import.
# HIERARCHY: the skeleton's tree with rest offsets from each parent; joints
# without children become "End Site"s. MOTION: per frame the root's position
# (always 0: the wrist stays put) and every joint's rotation relative to its
# parent as Z X Y Euler angles in degrees, BVH's usual channel order. All rest
# frames in BVH are the root's axes, which is how forward_kinematics()
# expresses each joint's rotation, so the export is exact.

#' Write a recording as a BVH hand animation
#'
#' @param x A recording (numeric frames x DoF matrix with DoF column names)
#'   or a [grasps()] object (see `recording`); a generated grasp is a
#'   `grasps` too.
#' @param file Output path (`.bvh`).
#' @param skeleton A [hand_skeleton()].
#' @param recording For a `grasps` with several recordings: which one
#'   (index or id).
#' @param rate Frames per second of a matrix `x` (a `grasps` has its own).
#' @param scale Factor applied to lengths (the skeleton is in mm; `0.001`
#'   writes metres).
#' @param ... Passed to [forward_kinematics()]'s angle handling: `mapping`,
#'   `mode`, `deactivate`, `unit`.
#' @return `file`, invisibly.
#' @seealso [read_bvh()]
#' @export
#' @examples
#' rec <- matrix(0, 10, 16, dimnames = list(NULL, hust_dofs$name))
#' rec[, "PIP2"] <- seq(0, 90, length.out = 10)
#' f <- tempfile(fileext = ".bvh")
#' write_bvh(rec, f)
#' b <- read_bvh(f)
#' b$frames
#' nrow(b$joints)
write_bvh <- function(x, file, skeleton = hand_skeleton(), recording = 1L, rate = 50,
                      scale = 1, ...) {
  call <- rlang::caller_env()
  file <- check_string(file, "file", call = call)
  check_skeleton(skeleton, call = call)
  scale <- check_number(scale, "scale", min = 0, min_open = TRUE, call = call)
  # (checked even for a grasps object, which brings its own rate: a bad
  # value is a mistake either way)
  check_rate(rate, call = call)
  dots <- list(...)
  if (inherits(x, "grasps")) {
    if (is.character(recording)) recording <- match(recording, x$meta$id)
    if (length(recording) != 1L || is.na(recording) || recording < 1L || recording > length(x)) {
      hm_abort("{.arg recording} must pick one of the {length(x)} recording{?s} by index or id, not {describe_value(recording)}.",
               "bad_input", argument = "recording", call = call)
    }
    rate <- x$rate
    v <- glove_recording(x, recording)   # degrees and joints through the set's glove
    unit <- v$unit
    if (is.null(dots$mapping)) dots$mapping <- v$mapping
    x <- v$angles
  } else {
    unit <- if (is.null(dots$unit)) "deg" else dots$unit
  }
  check_rate(rate, call = call)
  input <- fk_input(if (is.data.frame(x)) as.matrix(x) else x, unit, call)
  mode <- if (is.null(dots$mode)) "plain" else check_choice(dots$mode, c("plain", "full", "fixed-root"), arg = "mode", call = call)
  plan <- fk_plan(input$dofs, skeleton, dots$mapping, mode, dots$deactivate, call)
  rec <- input$recordings[[1]]
  ang <- fk_angles(plan, rec, input$factor)
  n <- nrow(rec)

  j <- skeleton$joints
  pidx <- skeleton_parent_index(skeleton)
  kids <- lapply(seq_len(nrow(j)), function(i) which(pidx == i))
  off <- as.matrix(j[c("x", "y", "z")]) * scale
  num <- function(v) paste(format(round(v, 5), trim = TRUE, scientific = FALSE), collapse = " ")
  hier <- character(0)
  order <- integer(0)
  emit <- function(i, depth) {
    pad <- strrep("  ", depth)
    if (!length(kids[[i]])) {
      hier <<- c(hier, paste0(pad, "End Site"), paste0(pad, "{"),
                 paste0(pad, "  OFFSET ", num(off[i, ])), paste0(pad, "}"))
      return(invisible())
    }
    root <- is.na(pidx[i])
    hier <<- c(hier, paste0(pad, if (root) "ROOT " else "JOINT ", j$name[i]), paste0(pad, "{"),
               paste0(pad, "  OFFSET ", num(if (root) c(0, 0, 0) else off[i, ])),
               paste0(pad, "  CHANNELS ", if (root) "6 Xposition Yposition Zposition " else "3 ",
                      "Zrotation Xrotation Yrotation"))
    order <<- c(order, i)
    for (k in kids[[i]]) emit(k, depth + 1L)
    hier <<- c(hier, paste0(pad, "}"))
  }
  emit(which(is.na(pidx)), 0L)

  motion <- matrix(0, n, 3 + 3 * length(order))
  for (k in seq_along(order)) {
    L <- fk_local(plan, ang, order[k])
    if (!is.null(L)) motion[, 3 + 3 * (k - 1) + 1:3] <- euler_zxy(L)
  }
  body <- apply(round(motion, 5), 1, function(r) paste(format(r, trim = TRUE, scientific = FALSE), collapse = " "))
  write_text_file(c("HIERARCHY", hier, "MOTION", paste("Frames:", n),
                    paste("Frame Time:", format(1 / rate, digits = 10)), body), file, call = call)
  invisible(file)
}

# Z X Y Euler angles (degrees) of a batch of rotations R = Rz(a) Rx(b) Ry(c).
euler_zxy <- function(R) {
  b <- asin(pmin(1, pmax(-1, R[, 6])))
  a <- atan2(-R[, 4], R[, 5])
  c <- atan2(-R[, 3], R[, 9])
  cbind(a, b, c) * 180 / pi
}
