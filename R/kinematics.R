# Forward kinematics: joint angles over time -> 3D joint positions over time.
#
# Conventions (those of the skeleton files, GraspDB14 report section 5.2.1):
# each joint has a local frame in the rest pose with y along its bone
# (pointing back towards the wrist), z along the palm normal and x = y cross z,
# so a rotation about local x is flexion and about local z is ab-/adduction.
# A joint's rotation moves everything distal to it. The local rotation is
# applied as Rz * Ry * Rx (abduction first, then flexion about the abducted
# axis), right-handed, angles in degrees after unit conversion, sign and scale.
# A mapping row may name its parent's rest frame instead (frame = "parent"):
# GraspDB14 turns the thumb's base about the hand's long axis that way; such
# turns come before the joint's own.
#
# Everything is vectorised over frames: a batch of rotations is an n x 9
# matrix (column-major 3 x 3 per row), so a whole recording costs about
# 27 vector multiplications per rotating joint.

#' Joint mappings: which DoF drives which joint axis
#'
#' A mapping is a data frame with one row per DoF: `dof` (column name in the
#' recordings), `joint` (skeleton joint name), `axis` (`"x"` flexion, `"y"`,
#' `"z"` ab-/adduction, or `NA` for a DoF that is not applied), `sign` and
#' `scale` (the angle applied is `sign * scale * angle`, after conversion to
#' degrees) and, optionally, `frame`: `"joint"` (default) when the axis is
#' the joint's own rest axis, `"parent"` when it is the parent's (for the
#' thumb's base, the hand's long axis through the thumb's carpometacarpal
#' joint). Turns about parent axes are applied before the joint's own.
#'
#' * `joint_map("graspdb14")` is Table 5.1 of the GraspDB14 report: the 23
#'   CyberGlove sensors on the default skeleton, with one correction (below).
#'   Sensors the report marks as discarded (`I-AA`, `P-Arch`) have
#'   `axis = NA`. The GraspDB14 files store flexion as negative angles and the
#'   report's viewer applies every angle negated, so `sign = -1` throughout.
#' * `joint_map("hust")` drives the same skeleton from the 16 HUST DoFs. It is
#'   the GraspDB14 mapping carried over through the sensor correspondence of
#'   [cyberglove_sensors] (`CMC1 = -T-TMCJ`, `ABD1 = TI-AA`, flexions
#'   negated): `CMC1` turns the thumb across the palm like `T-TMCJ` (sign 1),
#'   `ABD1` is `TI-AA` at `th-mcp` about z (sign -1), every other DoF a
#'   flexion about x of its joint (sign 1). So a GraspDB14 recording and its
#'   [graspdb14_to_hust()] conversion give the same hand (up to the finger
#'   spread sensors HUST does not have).
#' * `joint_map(dofs = )` picks between them from the DoF names (case,
#'   hyphens and underscores ignored; `T-TMJ` and `T-TMCJ` both name the thumb
#'   rotation sensor) and keeps the rows for `dofs`, in their order. This is
#'   the mapping [forward_kinematics()] uses when given none.
#'
#' @section The thumb rotation (`T-TMCJ`, `CMC1`):
#' Table 5.1 of the report maps `T-TMCJ` ("thumb rotating across palm") to
#' the z axis of `th-tmc`. GraspDB14's own MATLAB code
#' (`constructSensor2JointMap.m`, axis `'pron'`) turns it about the local y
#' axis instead, and its skeleton reader gives `th-tmc` the root's local
#' frame, so the turn is about the hand's long axis through the thumb's base.
#' We follow the code (`axis = "y"`, `frame = "parent"`), on this evidence:
#' * drawn from the real GraspDB14 power-sphere (ball) recording
#'   `01_11_ex03-rad-004-grasp-su04` during the hold (frame 120, where
#'   `T-TMCJ` reads about -106 degrees), the z axis swings the thumb within
#'   the plane of the palm until it points back past the wrist; a turn about
#'   the thumb's own long axis leaves it sticking out sideways, flat; the
#'   hand's long axis brings it in front of the palm, opposite the curled
#'   fingers, as around a ball;
#' * the same holds for the simulated HUST-like grasps: with the old HUST map
#'   (`CMC1` a flexion about x and `ABD1` an abduction about z, both at
#'   `th-tmc`) the thumb tip of pad-opposition types (tip pinch, tripod, ...)
#'   ended a median 12 cm from the nearest index or middle finger joint and
#'   stuck out beside the wrist; with this mapping it reaches in front of the
#'   palm towards the fingers (about 3 cm away);
#' * anatomically, rotation "across the palm" at the trapeziometacarpal joint
#'   is opposition, a turn about an axis along the index metacarpal, not a
#'   spread within the palm plane (that is `TI-AA`).
#' To get Table 5.1 literally, set `axis = "z"`, `frame = "joint"` in the
#' `T-TMCJ` row.
#'
#' @param source `"hust"` or `"graspdb14"`; by default chosen from `dofs`.
#' @param dofs DoF names, e.g. `x$dofs` of a [grasps()] object: keep (and
#'   order) the rows for these DoFs.
#' @return A data frame (`dof`, `joint`, `axis`, `sign`, `scale`, `frame`).
#' @references Stollenwerk, K., Hinkenjann, A. and Klein, R. GraspDB14
#'   technical report, Table 5.1, and the GraspDB14 MATLAB tools
#'   (`constructSensor2JointMap.m`, `readXMLSKEL.m`).
#' @export
#' @examples
#' joint_map("hust")
#' joint_map("graspdb14")[1:5, ]
#' joint_map(dofs = c("MCP2", "PIP2"))
joint_map <- function(source = NULL, dofs = NULL) {
  call <- rlang::caller_env()
  if (!is.null(dofs) && (!is.character(dofs) || anyNA(dofs))) {
    hm_abort("{.arg dofs} must be DoF names, not {.obj_type_friendly {dofs}}.", "bad_input",
             argument = "dofs", call = call)
  }
  if (is.null(source)) {
    if (is.null(dofs)) {
      hm_abort("Give {.arg source} ({.val hust} or {.val graspdb14}) or {.arg dofs}.", "bad_input",
               argument = "source", call = call)
    }
    return(default_joint_map_impl(dofs, call))
  }
  source <- check_choice(source, c("hust", "graspdb14"), arg = "source", call = call)
  m <- if (source == "hust") hust_joint_map() else graspdb14_joint_map()
  if (is.null(dofs)) return(m)
  idx <- match(dof_key(dofs), dof_key(m$dof))
  if (anyNA(idx)) {
    bad <- dofs[is.na(idx)]
    hm_abort("Not in the {.val {source}} mapping: {.val {bad}}.", "bad_mapping", argument = "dofs", call = call)
  }
  out <- m[idx, , drop = FALSE]
  out$dof <- dofs
  rownames(out) <- NULL
  out
}

# The two built-in mappings (documented under joint_map()).
graspdb14_joint_map <- function() {
  data.frame(
    dof = c("T-TMCJ", "T-MCPJ", "T-IPJ", "TI-AA", "I-MCPJ", "I-PIPJ", "I-DIPJ", "I-AA",
            "M-MCPJ", "M-PIPJ", "M-DIPJ", "MI-AA", "R-MCPJ", "R-PIPJ", "R-DIPJ", "RM-AA",
            "L-MCPJ", "L-PIPJ", "L-DIPJ", "LR-AA", "P-Arch", "W-FE", "W-AA"),
    joint = c("th-tmc", "th-mcp", "th-ip", "th-mcp", "if-mcp", "if-pip", "if-dip", "if-mcp",
              "mf-mcp", "mf-pip", "mf-dip", "if-mcp", "rf-mcp", "rf-pip", "rf-dip", "rf-mcp",
              "lf-mcp", "lf-pip", "lf-dip", "lf-mcp", "lf-cmc", "root", "root"),
    axis = c("y", "x", "x", "z", "x", "x", "x", NA, "x", "x", "x", "z", "x", "x", "x", "z",
             "x", "x", "x", "z", NA, "x", "z"),
    sign = -1, scale = 1,
    frame = c("parent", rep("joint", 22)), stringsAsFactors = FALSE)
}

hust_joint_map <- function() {
  data.frame(
    dof = c("CMC1", "ABD1", "MCP1", "IP1", "MCP2", "PIP2", "DIP2", "MCP3", "PIP3", "DIP3",
            "MCP4", "PIP4", "DIP4", "MCP5", "PIP5", "DIP5"),
    joint = c("th-tmc", "th-mcp", "th-mcp", "th-ip", "if-mcp", "if-pip", "if-dip", "mf-mcp",
              "mf-pip", "mf-dip", "rf-mcp", "rf-pip", "rf-dip", "lf-mcp", "lf-pip", "lf-dip"),
    axis = c("y", "z", rep("x", 14)), sign = c(1, -1, rep(1, 14)), scale = 1,
    frame = c("parent", rep("joint", 15)), stringsAsFactors = FALSE)
}

dof_key <- function(x) {
  k <- gsub("[^A-Z0-9]", "", toupper(x))
  k[k == "TTMJ"] <- "TTMCJ"   # Table 4.3 spells the thumb rotation sensor T-TMJ
  k
}

default_joint_map_impl <- function(dofs, call) {
  keys <- dof_key(dofs)
  maps <- list(hust = hust_joint_map(), graspdb14 = graspdb14_joint_map())
  hits <- vapply(maps, function(m) sum(keys %in% dof_key(m$dof)), numeric(1))
  if (max(hits) == 0) {
    hm_abort(c("Cannot choose a joint mapping for DoFs {.val {utils::head(dofs, 6)}}.",
               i = "They are neither HUST DoFs nor GraspDB14 sensor names; pass {.arg mapping}."),
             "bad_mapping", argument = "mapping", call = call)
  }
  m <- maps[[which.max(hits)]]
  idx <- match(keys, dof_key(m$dof))
  out <- m[idx[!is.na(idx)], , drop = FALSE]
  out$dof <- dofs[!is.na(idx)]
  rownames(out) <- NULL
  out
}

check_mapping <- function(mapping, skeleton, call) {
  need <- c("dof", "joint", "axis")
  if (!is.data.frame(mapping) || !all(need %in% names(mapping))) {
    hm_abort("{.arg mapping} must be a data frame with columns {.val {c(need, 'sign', 'scale')}}.",
             "bad_mapping", argument = "mapping", call = call)
  }
  mapping <- as.data.frame(mapping, stringsAsFactors = FALSE)
  if (is.null(mapping$sign)) mapping$sign <- 1
  if (is.null(mapping$scale)) mapping$scale <- 1
  mapping$axis <- tolower(as.character(mapping$axis))
  mapping$axis[mapping$axis %in% c("", "-", "\u2014")] <- NA
  bad <- !is.na(mapping$axis) & !mapping$axis %in% c("x", "y", "z")
  if (any(bad)) {
    hm_abort("Mapping axis must be {.val x}, {.val y}, {.val z} or NA; DoF {.val {mapping$dof[bad][1]}} has {.val {mapping$axis[bad][1]}}.",
             "bad_mapping", argument = "mapping", call = call)
  }
  # `frame` (optional): whose rest frame the axis belongs to, the joint's own
  # or its parent's (GraspDB14's thumb rotation turns about the hand's axis)
  if (is.null(mapping$frame)) mapping$frame <- "joint"
  mapping$frame <- as.character(mapping$frame)
  mapping$frame[is.na(mapping$frame) | mapping$frame == ""] <- "joint"
  bad <- !mapping$frame %in% c("joint", "parent")
  if (any(bad)) {
    hm_abort("Mapping frame must be {.val joint} or {.val parent}; DoF {.val {mapping$dof[bad][1]}} has {.val {mapping$frame[bad][1]}}.",
             "bad_mapping", argument = "mapping", call = call)
  }
  if (!is.numeric(mapping$sign) || !is.numeric(mapping$scale) ||
      anyNA(mapping$sign) || anyNA(mapping$scale)) {
    hm_abort("Mapping columns {.val sign} and {.val scale} must be numbers.", "bad_mapping",
             argument = "mapping", call = call)
  }
  missing <- setdiff(mapping$joint[!is.na(mapping$axis)], skeleton$joints$name)
  if (length(missing)) {
    dofs <- unique(mapping$dof[!is.na(mapping$axis) & mapping$joint %in% missing])
    hm_abort(c("The mapping drives joint{?s} {.val {missing}} that the skeleton does not have (missing joint{?s}).",
               x = "DoF{?s} {.val {dofs}} cannot be posed on it.",
               i = "Skeleton joints: {.val {skeleton$joints$name}}."),
             "bad_skeleton", joint = missing, file = skeleton$file, call = call)
  }
  mapping
}

#' Forward kinematics: 3D joint positions from joint angles
#'
#' Poses a [hand_skeleton()] with every frame of a recording and returns the
#' position of every joint, relative to the root (wrist), in millimetres.
#' The DoFs drive joint axes as given by `mapping` (Table 5.1 of the
#' GraspDB14 report for CyberGlove sensors, see [joint_map()]);
#' DoFs the mapping does not use are listed in the result's `"fk"`
#' attribute, never dropped silently.
#'
#' Modes, after GraspDB14's loader:
#' * `"plain"`: the hand in its own frame: every finger and thumb angle is
#'   applied, angles acting on the root (wrist) are not.
#' * `"full"`: also rotates the whole hand about the root by the wrist angles.
#' * `"fixed-root"`: GraspDB14's fixed-root computation: the root's sensors
#'   are deactivated (set to zero) and reported as such. Same positions as
#'   `"plain"`.
#'
#' @param x A numeric matrix (frames x DoF, with DoF column names), or a
#'   [grasps()] object.
#' @param skeleton A [hand_skeleton()].
#' @param mapping A joint mapping (see [joint_map()]); by default chosen
#'   from the DoF names, `joint_map(dofs = )`.
#' @param mode `"plain"`, `"full"` or `"fixed-root"` (see Details).
#' @param deactivate DoFs to treat as zero: DoF names, column numbers, or
#'   joint names (every DoF driving that joint), like GraspDB14's
#'   `calcJointTrajectories` with deactivated sensors.
#' @param frames Frames to compute: `NULL` (all), indices, `"first"` or
#'   `"last"`.
#' @param unit Angle unit of a matrix `x` (`"deg"` or `"rad"`); a `grasps`
#'   object carries its own.
#' @param markers `NULL` for joint positions, or virtual hand-over marker
#'   names ([select_markers()] lists them; `TRUE` for the 13 hand markers)
#'   for marker positions instead: each marker sits on its bone at a fixed
#'   fraction from its joint (see [fit_handover()]), in mm relative to the
#'   root link.
#' @return With `markers`, a frames x (3 * markers) matrix with columns
#'   `<marker>.x`, `<marker>.y`, `<marker>.z` for a matrix `x`, a list of
#'   them (named by recording id) for a `grasps` object. Otherwise, for a matrix, an array `[frames, joints, 3]` (mm) with dimnames
#'   `list(NULL, joint names, c("x", "y", "z"))`; for a `grasps` object, a list
#'   of such arrays named by recording id (also for a set of one). Each array has an attribute `"fk"`: a list with `mode`, the
#'   `mapping` rows applied, `deactivated` and `ignored` DoFs.
#' @seealso `autoplot(x, type = "hand")` ([autoplot.grasps()]) to draw the hand, [write_bvh()].
#' @export
#' @examples
#' skel <- hand_skeleton()
#' flat <- matrix(0, 1, 16, dimnames = list(NULL, hust_dofs$name))
#' p <- forward_kinematics(flat, skel)
#' p[1, "mf-tip", ]
#' fist <- flat
#' fist[, grep("^(MCP|PIP|DIP)[2-5]", colnames(fist))] <- 80
#' forward_kinematics(fist, skel)[1, "mf-tip", ]
#' forward_kinematics(fist, skel, markers = c("index_tip", "thumb_tip"))
forward_kinematics <- function(x, skeleton = hand_skeleton(), mapping = NULL,
                               mode = c("plain", "full", "fixed-root"),
                               deactivate = NULL, frames = NULL, unit = NULL, markers = NULL) {
  call <- rlang::caller_env()
  if (!is.null(markers)) {
    if (isTRUE(markers)) markers <- NULL   # the 13 hand markers
    else check_marker_names(markers, call = call)
    return(markers_from_angles(x, skeleton = skeleton, markers = markers, mapping = mapping,
                               mode = mode, deactivate = deactivate, frames = frames, unit = unit))
  }
  mode <- check_choice(mode, arg = "mode", call = rlang::current_env())
  check_skeleton(skeleton, call = call)
  input <- fk_input(x, unit, call)
  plan <- fk_plan(input$dofs, skeleton, mapping %||% input$mapping, mode, deactivate, call)
  out <- lapply(names(input$recordings), function(id) {
    rec <- input$recordings[[id]]
    rec <- rec[fk_frames(frames, nrow(rec), id, call), , drop = FALSE]
    fk_run(plan, rec, input$factor)
  })
  names(out) <- names(input$recordings)
  # one class in, one class out: a matrix gives an array, a grasps set a list
  # (of one or more), whatever its length
  if (inherits(x, "grasps")) out else out[[1]]
}

fk_input <- function(x, unit, call) {
  mapping <- NULL
  if (inherits(x, "grasps")) {
    check_grasps(x, call = call)
    check_some_recordings(x, what = "pose", call = call)
    recs <- x$recordings
    unit <- x$unit
    dofs <- x$dofs
    if (!is.null(x$glove)) {
      # the glove says what each channel measures: its angles in degrees
      # (raw counts through the profile's map) and the joints it drives
      glove <- match_glove(x$glove, dofs, unit, call = call)
      mapping <- glove_mapping(glove)
      if (!nrow(mapping)) {
        hm_abort(c("No channel of the glove {.val {glove$name}} drives a joint of the hand, so it cannot be drawn.",
                   i = "Describe the channels with {.fn glove_profile} (joint, axis, and for raw counts a map to degrees) and pass it as {.arg glove} to {.fn grasps}."),
                 "bad_mapping", argument = "x", call = call)
      }
      for (id in names(recs)) if (anyNA(recs[[id]]) || any(is.infinite(recs[[id]]))) as_recording_matrix(recs[[id]], id, call)
      recs <- glove_degrees(recs, glove)
      return(list(recordings = recs, dofs = dofs, factor = 1, mapping = mapping))
    }
  } else {
    if (is.data.frame(x)) x <- as.matrix(x)
    if (!is.matrix(x) || !is.numeric(x)) {
      hm_abort("{.arg x} must be a numeric frames x DoF matrix or a {.cls grasps} object, not {.obj_type_friendly {x}}.",
               "bad_input", argument = "x", call = call)
    }
    dofs <- colnames(x)
    if (is.null(dofs)) {
      if (ncol(x) != 16L) {
        hm_abort("{.arg x} has no column names; name the DoFs (or give the 16 HUST DoFs in order).",
                 "bad_input", argument = "x", call = call)
      }
      dofs <- handmotion::hust_dofs$name
    }
    if (nrow(x) == 0L) {
      hm_abort("{.arg x} has no frames: there is no hand to pose.", "bad_recording",
               argument = "x", recording = "x", call = call)
    }
    recs <- list(x = x)
    if (is.null(unit)) unit <- "deg"
  }
  if (anyNA(dofs) || any(!nzchar(dofs)) || anyDuplicated(dofs)) {
    # two columns named alike would drive one joint twice (the hand posed
    # millimetres off without a word)
    dup <- unique(dofs[duplicated(dofs) & !is.na(dofs)])
    hm_abort(c("The DoF names of {.arg x} must be unique and non-empty.",
               x = if (length(dup)) "Repeated: {.val {dup}}." else "Some names are empty or NA."),
             "bad_input", argument = "x", call = call)
  }
  unit <- check_choice(unit, c("deg", "rad"), "unit", whole = FALSE, call = call,
                       info = "Forward kinematics needs degrees or radians: raw sensor counts must be calibrated first.")
  # a NaN angle would pose the hand at NaN (an empty picture, a page of NaN):
  # refuse it here, naming the recording, frame and DoF
  for (id in names(recs)) if (anyNA(recs[[id]]) || any(is.infinite(recs[[id]]))) as_recording_matrix(recs[[id]], id, call)
  list(recordings = recs, dofs = dofs, factor = if (unit == "rad") 180 / pi else 1, mapping = mapping)
}

fk_frames <- function(frames, n, id, call, arg = "frames") {
  if (is.null(frames)) return(seq_len(n))
  if (is.character(frames)) {
    if (identical(frames, "last")) return(n)
    if (identical(frames, "first")) return(1L)
    hm_abort("{.arg {arg}} must be indices, {.val first} or {.val last}, not {.val {frames}}.",
             "bad_input", argument = arg, call = call)
  }
  check_indices(frames, n, arg, "frame", where = sprintf(" (recording \"%s\" has %d)", id, n),
                recording = id, call = call)
}

# Everything that does not depend on the frames: which columns drive which
# joint axes, and each joint's rest frame and rest offset.
fk_plan <- function(dofs, skeleton, mapping, mode, deactivate, call) {
  if (is.null(mapping)) mapping <- default_joint_map_impl(dofs, call)
  mapping <- check_mapping(mapping, skeleton, call)
  mapping$col <- match(dof_key(mapping$dof), dof_key(dofs))
  used <- mapping[!is.na(mapping$col) & !is.na(mapping$axis), , drop = FALSE]
  ignored <- setdiff(dofs, used$dof)
  joints <- skeleton$joints
  root <- joints$name[is.na(joints$parent)]
  deactivated <- resolve_deactivate(deactivate, dofs, used, joints$name, call)
  skipped <- character(0)
  if (mode != "full") {
    at_root <- used$dof[used$joint == root]
    if (mode == "fixed-root") deactivated <- union(deactivated, at_root) else skipped <- at_root
  }
  used <- used[!used$dof %in% c(deactivated, skipped), , drop = FALSE]
  J <- nrow(joints)
  used$jidx <- match(used$joint, joints$name)
  frames_rest <- skeleton_rest_frames(skeleton)
  AkI <- lapply(frames_rest, kronecker, diag(3))
  offsets <- as.matrix(joints[c("x", "y", "z")])
  list(J = J, names = joints$name, parent = skeleton_parent_index(skeleton),
       offsets = offsets, used = used, by_joint = split(seq_len(nrow(used)), factor(used$jidx, levels = seq_len(J))),
       rest = frames_rest, AkI = AkI, tAkI = lapply(AkI, t), mode = mode, deactivated = deactivated, ignored = union(ignored, skipped),
       skeleton_file = skeleton$file)
}

resolve_deactivate <- function(deactivate, dofs, used, joint_names, call) {
  if (is.null(deactivate) || length(deactivate) == 0L) return(character(0))
  if (is.numeric(deactivate)) {
    return(dofs[check_indices(deactivate, length(dofs), "deactivate", "DoF column", call = call)])
  }
  deactivate <- as.character(deactivate)
  as_dof <- dofs[match(dof_key(deactivate), dof_key(dofs))]
  as_joint <- deactivate %in% joint_names
  bad <- deactivate[is.na(as_dof) & !as_joint]
  if (length(bad)) {
    hm_abort(c("Cannot deactivate {.val {bad}}: neither a DoF nor a skeleton joint.",
               i = "DoFs: {.val {dofs}}."), "bad_input", argument = "deactivate", call = call)
  }
  unique(c(as_dof[!is.na(as_dof)], used$dof[used$joint %in% deactivate[as_joint]]))
}

# Rest-pose local frames (3 x 3, columns = local x, y, z in root coordinates).
# y points from the joint's child back to the joint (along the bone it moves),
# z is the palm normal made orthogonal to y, x = y cross z. The root (several
# children) keeps the root axes; end effectors inherit their parent's frame.
skeleton_rest_frames <- function(skeleton) {
  pos <- skeleton_rest_positions(skeleton)
  pidx <- skeleton_parent_index(skeleton)
  J <- nrow(pos)
  out <- vector("list", J)
  unit_v <- function(v) v / sqrt(sum(v^2))
  for (j in seq_len(J)) {
    kids <- which(pidx == j)
    if (length(kids) != 1L) {
      out[[j]] <- if (length(kids) == 0L && !is.na(pidx[j])) out[[pidx[j]]] else diag(3)
      next
    }
    bone <- pos[j, ] - pos[kids, ]
    if (sum(bone^2) < 1e-12) {
      out[[j]] <- if (is.na(pidx[j])) diag(3) else out[[pidx[j]]]
      next
    }
    y <- unit_v(bone)
    zref <- if (abs(y[3]) > 0.99) c(1, 0, 0) else c(0, 0, 1)
    z <- unit_v(zref - sum(zref * y) * y)
    x <- c(y[2] * z[3] - y[3] * z[2], y[3] * z[1] - y[1] * z[3], y[1] * z[2] - y[2] * z[1])
    out[[j]] <- cbind(x, y, z, deparse.level = 0)
  }
  out
}

# Applied angles in radians, one column per used mapping row.
fk_angles <- function(plan, rec, factor) {
  used <- plan$used
  ang <- rec[, used$col, drop = FALSE]
  if (ncol(ang)) ang <- ang * rep(used$sign * used$scale * factor * pi / 180, each = nrow(ang))
  ang
}

# World rotation of joint j's subtree for all frames (n x 9): Mp A Q A^T with
# Mp the parent's (NULL = identity), A the joint's rest frame and Q its local
# rotation Rz Ry Rx. Q is applied column-wise to B = Mp A, which costs a
# dozen vector operations per axis instead of a full batch product. NULL when
# no DoF drives the joint and the parent does not turn.
fk_rotate <- function(plan, ang, j, Mp, n) {
  rows <- plan$by_joint[[j]]
  if (!length(rows)) return(Mp)
  in_parent <- plan$used$frame[rows] == "parent"
  if (any(in_parent)) {
    # turns about the parent's rest axes come first (GraspDB14 applies the
    # thumb rotation before any other angle); the root's parent frame is the
    # root's own
    p <- plan$parent[j]
    Mp <- fk_turn(plan, if (is.na(p)) j else p, rows[in_parent], ang, Mp, n)
    rows <- rows[!in_parent]
    if (!length(rows)) return(Mp)
  }
  fk_turn(plan, j, rows, ang, Mp, n)
}

# Mp A Q A^T for the rotations `rows` about the axes of joint f's rest frame A.
fk_turn <- function(plan, f, rows, ang, Mp, n) {
  A <- plan$rest[[f]]
  axes <- plan$used$axis
  B <- if (is.null(Mp)) matrix(rep(as.vector(A), each = n), n, 9) else Mp %*% plan$AkI[[f]]
  for (a in c("z", "y", "x")) {
    k <- rows[axes[rows] == a]
    if (!length(k)) next
    th <- if (length(k) == 1L) ang[, k] else rowSums(ang[, k, drop = FALSE])
    B <- rotate_columns(B, a, cos(th), sin(th))
  }
  B %*% plan$tAkI[[f]]
}

# B %*% R_axis(theta) for a batch (rows = column-major 3 x 3).
rotate_columns <- function(B, axis, c, s) {
  i <- switch(axis, x = c(2L, 3L), y = c(3L, 1L), z = c(1L, 2L))
  u <- (i[1] - 1L) * 3L + 1:3
  v <- (i[2] - 1L) * 3L + 1:3
  bu <- B[, u]
  bv <- B[, v]
  B[, u] <- c * bu + s * bv
  B[, v] <- c * bv - s * bu
  B
}

# Rotation of joint j relative to its parent, in rest-pose root axes (n x 9),
# or NULL when no DoF drives it.
fk_local <- function(plan, ang, j) fk_rotate(plan, ang, j, NULL, nrow(ang))

fk_run <- function(plan, rec, factor) {
  n <- nrow(rec)
  used <- plan$used
  ang <- fk_angles(plan, rec, factor)
  J <- plan$J
  M <- vector("list", J)          # world rotation of each joint's subtree; NULL = identity
  P <- vector("list", J)          # n x 3 positions
  out <- array(0, c(n, J, 3), dimnames = list(NULL, plan$names, c("x", "y", "z")))
  for (j in seq_len(J)) {
    p <- plan$parent[j]
    off <- plan$offsets[j, ]
    if (is.na(p)) {
      P[[j]] <- matrix(0, n, 3)
      Mp <- NULL
    } else {
      Mp <- M[[p]]
      P[[j]] <- if (is.null(Mp)) sweep(P[[p]], 2, off, `+`) else
        P[[p]] + Mp %*% kronecker(off, diag(3))
    }
    out[, j, ] <- P[[j]]
    M[j] <- list(fk_rotate(plan, ang, j, Mp, n))
  }
  attr(out, "fk") <- list(mode = plan$mode, mapping = used[c("dof", "joint", "axis", "sign", "scale", "frame")],
                          deactivated = plan$deactivated, ignored = plan$ignored)
  out
}
