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
#'   `grasps` too. A `grasps` read by [read_bvh()] is written back with its
#'   own hierarchy (`skeleton` and `...` are then not used).
#' @param file Output path (`.bvh`).
#' @param skeleton A [hand_skeleton()].
#' @param recording For a `grasps` with several recordings: which one
#'   (index or id).
#' @param rate Frames per second of a matrix `x` (a `grasps` has its own).
#' @param scale Factor applied to lengths (the skeleton is in mm; `0.001`
#'   writes metres).
#' @param overwrite Replace an existing `file`? By default an existing file
#'   is an error of class `handmotion_error_file_exists` naming it.
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
#' b
#' nrow(attr(b, "bvh")$joints)
write_bvh <- function(x, file, skeleton = hand_skeleton(), recording = 1L, rate = 50,
                      scale = 1, overwrite = FALSE, ...) {
  call <- rlang::caller_env()
  file <- check_string(file, "file", call = call)
  check_overwrite(file, overwrite, call = call)
  check_skeleton(skeleton, call = call)
  scale <- check_number(scale, "scale", min = 0, min_open = TRUE, call = call)
  # (checked even for a grasps object, which brings its own rate: a bad
  # value is a mistake either way)
  check_rate(rate, call = call)
  dots <- list(...)
  if (inherits(x, "grasps")) {
    check_grasps(x, call = call)
    check_some_recordings(x, what = "write", call = call)
    recording <- check_recording_pick(recording, x, call = call)
    # a BVH read back: its own hierarchy and channels
    if (!is.null(attr(x, "bvh"))) {
      parts <- bvh_parts(x, recording)
      parts$offsets <- parts$offsets * scale
      parts$motion[, parts$position] <- parts$motion[, parts$position] * scale
      return(write_bvh_parts(parts, x$rate, file, call))
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

  # the skeleton's tree in depth-first order: joints with children carry
  # channels (the root also its position), leaves become End Sites
  j <- skeleton$joints
  pidx <- skeleton_parent_index(skeleton)
  kids <- lapply(seq_len(nrow(j)), function(i) which(pidx == i))
  off <- as.matrix(j[c("x", "y", "z")]) * scale
  rows <- list()
  walk <- function(i) {
    root <- is.na(pidx[i])
    if (!length(kids[[i]])) {
      rows[[length(rows) + 1L]] <<- list(name = paste0(j$name[pidx[i]], "_End"), parent = j$name[pidx[i]],
                                          end_site = TRUE, offset = off[i, ], channels = character(0), joint = i)
      return(invisible())
    }
    rows[[length(rows) + 1L]] <<- list(name = j$name[i], parent = if (root) NA_character_ else j$name[pidx[i]],
                                        end_site = FALSE, offset = if (root) c(0, 0, 0) else off[i, ],
                                        channels = c(if (root) c("Xposition", "Yposition", "Zposition"),
                                                     "Zrotation", "Xrotation", "Yrotation"), joint = i)
    for (k in kids[[i]]) walk(k)
  }
  walk(which(is.na(pidx)))
  # the motion: the wrist stays put, every joint turns by its local rotation
  motion <- lapply(rows[!vapply(rows, `[[`, TRUE, "end_site")], function(r) {
    L <- fk_local(plan, ang, r$joint)
    rot <- if (is.null(L)) matrix(0, n, 3) else euler_zxy(L)
    if (is.na(r$parent)) cbind(matrix(0, n, 3), rot) else rot
  })
  parts <- list(joints = data.frame(name = vapply(rows, `[[`, "", "name"), parent = vapply(rows, `[[`, "", "parent"),
                                    end_site = vapply(rows, `[[`, TRUE, "end_site"), stringsAsFactors = FALSE),
                offsets = do.call(rbind, lapply(rows, `[[`, "offset")),
                channels = lapply(rows, `[[`, "channels"), motion = do.call(cbind, motion))
  write_bvh_parts(parts, rate, file, call)
}

# The one BVH writer: the hierarchy of `parts` (joints in depth-first order,
# their offsets and channels) and its motion (frames x channels).
write_bvh_parts <- function(parts, rate, file, call) {
  j <- parts$joints
  num <- function(v) paste(format(round(v, 5), trim = TRUE, scientific = FALSE), collapse = " ")
  hier <- character(0)
  emit <- function(i, depth) {
    pad <- strrep("  ", depth)
    if (j$end_site[i]) {
      hier <<- c(hier, paste0(pad, "End Site"), paste0(pad, "{"),
                 paste0(pad, "  OFFSET ", num(parts$offsets[i, ])), paste0(pad, "}"))
      return(invisible())
    }
    ch <- parts$channels[[i]]
    hier <<- c(hier, paste0(pad, if (is.na(j$parent[i])) "ROOT " else "JOINT ", j$name[i]), paste0(pad, "{"),
               paste0(pad, "  OFFSET ", num(parts$offsets[i, ])),
               paste0(pad, "  CHANNELS ", length(ch), " ", paste(ch, collapse = " ")))
    for (k in which(j$parent %in% j$name[i] & seq_len(nrow(j)) > i)) emit(k, depth + 1L)
    hier <<- c(hier, paste0(pad, "}"))
  }
  emit(which(is.na(j$parent))[1], 0L)
  body <- apply(round(parts$motion, 5), 1, function(r) paste(format(r, trim = TRUE, scientific = FALSE), collapse = " "))
  write_text_file(c("HIERARCHY", hier, "MOTION", paste("Frames:", nrow(parts$motion)),
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
