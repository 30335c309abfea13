# Pictures of hands: a pose is the skeleton's joint positions at one frame,
# projected onto the screen for a chosen view and drawn as the solid hand of
# hand_geometry() (R/hand-geometry.R, R/plot-hand-solid.R).

# The 3D joint positions of one or more frames as a long data frame
# (class hand_pose: id, frame, joint, parent, finger, x, y, z in mm, plus a
# grasps input's metadata) that autoplot.hand_pose() draws. `x`: an array from
# forward_kinematics(), a list of them, a recording matrix, a grasps object or
# a hand_skeleton (its rest pose); `...` goes to forward_kinematics().
hand_pose <- function(x, frame = "last", skeleton = hand_skeleton(), ..., call = rlang::caller_env()) {
  check_skeleton(skeleton, call = call)
  meta <- NULL
  if (inherits(x, "hand_skeleton")) return(skeleton_rest_pose(x))
  if (inherits(x, "grasps")) {
    check_some_recordings(x, call = call)
    meta <- x$meta
    arrays <- lapply(seq_along(x), function(i) {
      rec <- as_recording_matrix(x$recordings[[i]], x$meta$id[i], call)  # names the recording
      fr <- fk_frames(frame, nrow(rec), x$meta$id[i], call, arg = "frame")
      v <- glove_recording(x, i)   # degrees and joints through the set's glove
      a <- fk_mapped(v$angles, skeleton, v$unit, v$mapping, frames = fr, ...)
      attr(a, "frames") <- fr
      a
    })
    names(arrays) <- x$meta$id
  } else if (is.array(x) && length(dim(x)) == 3L) {
    arrays <- list(x = pose_frames(x, frame, "x", call))
  } else if (is.list(x) && length(x) && all(vapply(x, function(a) is.array(a) && length(dim(a)) == 3L, logical(1)))) {
    ids <- if (is.null(names(x))) paste0("r", seq_along(x)) else names(x)
    arrays <- Map(function(a, id) pose_frames(a, frame, id, call), x, ids)
    names(arrays) <- ids
  } else if (is.matrix(x) || is.data.frame(x)) {
    x <- as.matrix(x)
    fr <- fk_frames(frame, nrow(x), "x", call, arg = "frame")
    a <- forward_kinematics(x, skeleton, frames = fr, ...)
    attr(a, "frames") <- fr
    arrays <- list(x = a)
  } else {
    hm_abort("{.arg x} must be a forward-kinematics array, a recording matrix, a {.cls grasps} or a {.cls hand_skeleton}, not {.obj_type_friendly {x}}.",
             "bad_input", argument = "x", call = call)
  }
  out <- do.call(rbind, Map(pose_long, arrays, names(arrays), MoreArgs = list(skeleton = skeleton, call = call)))
  if (!is.null(meta)) {
    extra <- setdiff(names(meta), c("id", "n_frames"))
    out <- cbind(out, meta[match(out$id, meta$id), extra, drop = FALSE])
  }
  rownames(out) <- NULL
  # the skeleton that posed the hand decides its solid shape (hand_geometry())
  structure(out, class = c("hand_pose", "data.frame"), skeleton = skeleton)
}

pose_frames <- function(a, frame, id, call) {
  fr <- fk_frames(frame, dim(a)[1], id, call, arg = "frame")
  out <- a[fr, , , drop = FALSE]
  attr(out, "frames") <- fr
  out
}

pose_long <- function(a, id, skeleton, call) {
  jn <- dimnames(a)[[2]]
  missing <- setdiff(jn, skeleton$joints$name)
  if (is.null(jn) || length(missing)) {
    hm_abort("The positions name joint{?s} {.val {missing}} that the skeleton does not have.",
             "bad_skeleton", joint = missing, call = call)
  }
  fr <- attr(a, "frames") %||0% seq_len(dim(a)[1])
  j <- skeleton$joints[match(jn, skeleton$joints$name), ]
  parent <- skeleton$joints$name[match(j$parent, skeleton$joints$id)]
  finger <- skeleton_chains(skeleton)[match(jn, skeleton$joints$name)]
  nf <- dim(a)[1]
  data.frame(id = id, frame = rep(fr, times = length(jn)),
             joint = rep(jn, each = nf), parent = rep(parent, each = nf),
             finger = rep(finger, each = nf),
             x = as.vector(a[, , 1]), y = as.vector(a[, , 2]), z = as.vector(a[, , 3]),
             stringsAsFactors = FALSE)
}

`%||0%` <- function(x, y) if (is.null(x)) y else x

skeleton_rest_pose <- function(skeleton) {
  pos <- skeleton_rest_positions(skeleton)
  a <- array(pos, c(1, dim(pos)), dimnames = list(NULL, rownames(pos), c("x", "y", "z")))
  out <- pose_long(a, "rest", skeleton, rlang::caller_env())
  structure(out, class = c("hand_pose", "data.frame"), skeleton = skeleton)
}

# Screen axes for a view: rows are screen right, screen up and towards the
# viewer, in skeleton coordinates (fingers along -y, thumb +x, palm -z).
hand_views <- list(
  back = rbind(c(-1, 0, 0), c(0, -1, 0), c(0, 0, 1)),
  palm = rbind(c(1, 0, 0), c(0, -1, 0), c(0, 0, -1)),
  radial = rbind(c(0, 0, 1), c(0, -1, 0), c(1, 0, 0)),
  ulnar = rbind(c(0, 0, -1), c(0, -1, 0), c(-1, 0, 0)),
  tip = rbind(c(1, 0, 0), c(0, 0, 1), c(0, -1, 0))
)

oblique_view <- c(-135, 20)

#' @noRd
view_matrix <- function(view, call = rlang::caller_env()) {
  # from the palm, turned towards the thumb: the view of grasp photographs,
  # showing the palm, the thumb's opposition and the fingers' curl at once
  if (is.character(view) && length(view) == 1L && view == "oblique") view <- oblique_view
  if (is.character(view)) {
    if (length(view) != 1L || !view %in% names(hand_views)) {
      hm_abort("{.arg view} must be one of {.val {c(names(hand_views), 'oblique')}} or c(azimuth, elevation) in degrees.",
               "bad_input", argument = "view", call = call)
    }
    return(hand_views[[view]])
  }
  if (!is.numeric(view) || length(view) != 2L || anyNA(view)) {
    hm_abort("{.arg view} must be a view name or c(azimuth, elevation) in degrees.", "bad_input",
             argument = "view", call = call)
  }
  # turn the back view about the screen's vertical, then tilt it
  az <- view[1] * pi / 180
  el <- view[2] * pi / 180
  turn <- rbind(c(cos(az), 0, sin(az)), c(0, 1, 0), c(-sin(az), 0, cos(az)))
  tilt <- rbind(c(1, 0, 0), c(0, cos(el), -sin(el)), c(0, sin(el), cos(el)))
  tilt %*% turn %*% hand_views$back
}

project_pose <- function(pose, view, call = rlang::caller_env()) {
  V <- view_matrix(view, call)
  xyz <- as.matrix(pose[c("x", "y", "z")])
  scr <- xyz %*% t(V)
  pose$sx <- scr[, 1]
  pose$sy <- scr[, 2]
  pose$depth <- scr[, 3]
  pose
}

# Panel labels: the grasp type names a recording better than its id; the id
# is added only where one type has several recordings.
pose_panels <- function(p) {
  multi_id <- length(unique(p$id)) > 1L
  # frame numbers only where one recording is drawn at several frames
  multi_fr <- any(tapply(p$frame, p$id, function(f) length(unique(f))) > 1L)
  name <- p$id
  if (!is.null(p$grasp) && !anyNA(p$grasp)) {
    name <- as.character(p$grasp)
    per_type <- tapply(p$id, name, function(i) length(unique(i)))
    dup <- name %in% names(per_type)[per_type > 1L]
    name[dup] <- paste0(name[dup], " (", p$id[dup], ")")
  }
  lab <- if (multi_id && multi_fr) paste0(name, ", frame ", p$frame) else if (multi_fr)
    paste("frame", p$frame) else name
  factor(lab, levels = unique(lab))
}

finger_colours <- c(root = "grey40", th = "#D55E00", `if` = "#0072B2", mf = "#009E73",
                    rf = "#CC79A7", lf = "#E69F00")
finger_labels <- c(th = "thumb", `if` = "index", mf = "middle", rf = "ring", lf = "little")

# Layers shared by every hand drawing (autoplot.hand_pose, plot_pose_grid,
# plot_frame_strip, plot_marker_sets): the solid hands (the shape of
# hand_geometry(), cut into polygons by R/plot-hand-solid.R), then, with
# finger colours, the joints as invisible points that carry the finger
# legend (and the pose data for anyone reading the plot's layers).
# Text sizes are in points; vignettes and reports show figures at 72 dpi,
# so a point is a screen pixel there and nothing should be below 9.
pose_layers <- function(pr, scale = 1, legend = TRUE, strip_size = 10, geometry = hand_geometry(),
                        solid = solid_hand_polygons(pr, scale, geometry)) {
  fingers <- intersect(names(finger_labels), unique(pr$finger))
  legend <- legend && geometry$colour == "fingers"
  list(
    ggplot2::geom_polygon(data = solid, ggplot2::aes(x = .data$px, y = .data$py, group = .data$draw,
                                                     fill = .data$fill, linewidth = .data$lwd),
                          colour = grDevices::adjustcolor(hand_outline_colour, 0.55)),
    ggplot2::scale_fill_identity(),
    ggplot2::scale_linewidth_identity(),
    # the legend names the fingers (the polygons' colours are shaded by depth)
    ggplot2::geom_point(data = pr, ggplot2::aes(x = .data$sx, y = .data$sy, colour = .data$finger),
                        alpha = 0, size = 0.1),
    ggplot2::scale_colour_manual(values = finger_colours, breaks = fingers,
                                 labels = finger_labels[fingers], name = NULL,
                                 guide = if (legend) ggplot2::guide_legend(
                                   override.aes = list(alpha = 1, size = 3.2)) else "none"),
    ggplot2::coord_equal(),
    ggplot2::theme_void(),
    ggplot2::theme(strip.text = ggplot2::element_text(size = strip_size, margin = ggplot2::margin(2, 2, 2, 2)),
                   # a long label may run past a narrow panel rather than lose its ends
                   strip.clip = "off",
                   legend.position = "bottom", legend.text = ggplot2::element_text(size = 10),
                   plot.title = ggplot2::element_text(size = 12),
                   # titles start at the figure's edge, not the (narrow, centred) panels'
                   plot.title.position = "plot",
                   plot.subtitle = ggplot2::element_text(size = 10, colour = "grey30"),
                   panel.spacing = ggplot2::unit(6, "pt"))
  )
}

# The geometry a pose is drawn with: from the skeleton that posed it (kept by
# hand_pose()), else the package's hand.
pose_geometry <- function(pose, hand_colour, skeleton = NULL, call = rlang::caller_env()) {
  hand_colour <- check_choice(hand_colour, c("skin", "fingers"), arg = "hand_colour", call = call)
  skeleton <- skeleton %||% attr(pose, "skeleton") %||% hand_skeleton()
  hand_geometry(skeleton, hand_colour)
}

view_label <- function(view) {
  if (is.numeric(view)) return(sprintf("view: azimuth %g, elevation %g degrees", view[1], view[2]))
  switch(view, back = "seen from the back of the hand", palm = "seen from the palm",
         radial = "seen from the thumb side (palm to the left)",
         ulnar = "seen from the little-finger side (palm to the right)",
         tip = "seen from the fingertips (palm down)",
         oblique = "seen from the palm, turned towards the thumb side", paste("view:", view))
}

#' Draw a hand pose
#'
#' Projects the hand onto the screen for `view` and draws it solid: a palm
#' spanning the metacarpals from their bases across the carpus to the
#' knuckles, the thumb from its carpometacarpal joint, finger segments that
#' taper towards the tips, in skin tone shaded by depth and light (or one
#' colour per finger, with a legend). The shape is the one every hand
#' picture of the package draws, the 3D widget ([hand_3d()]) and the videos
#' ([write_hand_animation()]) included. Several recordings or frames give
#' one panel each, labelled by grasp type when the pose carries one.
#'
#' @param object A hand pose: what `autoplot(<grasps>, type = "hand")`
#'   ([autoplot.grasps()]) and `autoplot(<hand_skeleton>)` draw with this method.
#' @param view `"back"`, `"palm"`, `"radial"` (thumb side), `"ulnar"`,
#'   `"tip"` (from the fingertips), `"oblique"` (the default: from the palm,
#'   turned towards the thumb side, like a photograph of a grasp; the same as
#'   `c(-135, 20)`), or `c(azimuth, elevation)` in degrees (turning the back
#'   view about the screen's vertical, then tilting it).
#' @param labels Label the joints with their names?
#' @param hand_colour `"skin"` (default) or `"fingers"` (each finger in its
#'   own colour, named in a legend).
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @method autoplot hand_pose
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 1, seed = 1)
#' ggplot2::autoplot(g, type = "hand", view = "palm")
autoplot.hand_pose <- function(object, view = "oblique", labels = FALSE, hand_colour = c("skin", "fingers"), ...) {
  geometry <- pose_geometry(object, hand_colour, call = rlang::caller_env())
  p <- project_pose(as.data.frame(unclass(object), stringsAsFactors = FALSE), view, rlang::caller_env())
  p$panel <- pose_panels(p)
  g <- ggplot2::ggplot() + pose_layers(p, geometry = geometry) + ggplot2::labs(subtitle = view_label(view))
  if (labels) {
    g <- g + ggplot2::geom_text(data = p, ggplot2::aes(x = .data$sx, y = .data$sy, label = .data$joint),
                                size = 2.3, vjust = -0.8)
  }
  if (nlevels(p$panel) > 1L) {
    g <- g + ggplot2::facet_wrap(~panel, labeller = ggplot2::label_wrap_gen(22))
  } else if (!levels(p$panel) %in% c("rest", "x")) {
    g <- g + ggplot2::labs(title = levels(p$panel))
  }
  g
}

# The last (or first, or a chosen) frame of one recording per group, the
# thesis' Appendix A; several sets (a named list) stand side by side in each
# panel. Reached through autoplot(<grasps>, type = "poses"), which documents it.
# `ncol`: columns of panels (NULL lets facet_wrap() choose); fewer columns give
# larger hands, which keep their shape, so a grid fills the width of a figure
# only when its height allows (about 1.5 times the panel width per row).
plot_pose_grid <- function(x, frame = "last", by = "grasp", per_group = 1L,
                           skeleton = hand_skeleton(), view = "oblique", ncol = NULL,
                           hand_colour = "skin", ..., call = rlang::caller_env()) {
  check_whole(ncol, "ncol", allow_null = TRUE, call = call)
  geometry <- pose_geometry(NULL, hand_colour, skeleton, call = call)
  per_group <- check_whole(per_group, "per_group", call = call)
  sets <- if (inherits(x, "grasps")) list(x) else x
  if (!is.list(sets) || !length(sets) || !all(vapply(sets, inherits, logical(1), "grasps"))) {
    hm_abort("{.arg x} must be a {.cls grasps} object or a list of them.", "bad_input",
             argument = "x", call = call)
  }
  for (k in seq_along(sets)) check_some_recordings(sets[[k]], if (length(sets) == 1L) "x" else sprintf("x[[%d]]", k), call = call)
  if (is.null(names(sets))) names(sets) <- if (length(sets) == 1L) "" else paste("set", seq_along(sets))
  poses <- lapply(seq_along(sets), function(k) {
    g <- sets[[k]]
    s <- names(sets)[k]
    if (!by %in% names(g$meta)) {
      hm_abort("{.arg by} must name a metadata column ({.val {names(g$meta)}}), not {.val {by}}.",
               "bad_input", argument = "by", call = call)
    }
    grp <- g$meta[[by]]
    grp_chr <- ifelse(is.na(grp), "(none)", as.character(grp))
    keep <- unlist(lapply(split(seq_along(grp_chr), factor(grp_chr, levels = unique(grp_chr))),
                          utils::head, per_group), use.names = FALSE)
    p <- hand_pose(g[keep], frame = frame, skeleton = skeleton, ...)
    p$set <- s
    p$group <- grp_chr[match(p$id, g$meta$id)]
    p
  })
  lev <- unique(unlist(lapply(sets, function(g) {
    v <- g$meta[[by]]
    if (is.factor(v)) intersect(levels(v), as.character(v)) else unique(as.character(v))
  })))
  # sets may carry different metadata (recorded vs generated): keep the shared columns
  common <- Reduce(intersect, lapply(poses, names))
  p <- do.call(rbind, lapply(poses, function(d) d[common]))
  p$group <- factor(p$group, levels = unique(c(lev, unique(p$group))))
  p$set <- factor(p$set, levels = names(sets))
  # several recordings of one group and set are overlaid in the same panel
  p$id <- paste(p$set, p$id)
  pr <- project_pose(p, view, call)
  title <- sprintf("%s frame of each %s", if (identical(frame, "last")) "Last" else if (identical(frame, "first"))
    "First" else paste("Frame", paste(frame, collapse = ", ")), if (by == "grasp") "grasp type" else by)
  subtitle <- view_label(view)
  labels <- NULL
  # the solid hands (their extent, not the joints', places them and their names)
  solid <- solid_hand_polygons(pr, geometry = geometry)
  if (length(sets) > 1L) {
    # the sets' hands side by side in one panel per group (recorded left of
    # generated, as in the thesis' Appendix A), each named underneath: one
    # strip per type instead of one per type and set, so 33 types fit a page
    width <- diff(range(solid$px)) * 1.06
    pr$sx <- pr$sx + (as.integer(pr$set) - 1L) * width
    solid$px <- solid$px + (as.integer(solid$set) - 1L) * width
    labels <- unique(pr[c("group", "set")])
    labels$sx <- (as.integer(labels$set) - 1L) * width + mean(range(solid$px[solid$set == levels(pr$set)[1]]))
    labels$sy <- min(solid$py) - 0.05 * diff(range(solid$py))
    # on two lines: a grid of one or two types is narrow (its aspect is fixed)
    subtitle <- paste0(paste(levels(pr$set), collapse = " | "), "\n", subtitle)
  }
  # type names wrap onto two lines ("Large / Diameter") so that six or more
  # panels a row keep them whole at 9 pt
  g <- ggplot2::ggplot() + pose_layers(pr, strip_size = 9, geometry = geometry, solid = solid) +
    ggplot2::labs(title = title, subtitle = subtitle) +
    ggplot2::facet_wrap(~group, labeller = ggplot2::label_wrap_gen(11), drop = FALSE,
                        ncol = ncol)
  if (!is.null(labels)) {
    g <- g + ggplot2::geom_text(data = labels, ggplot2::aes(x = .data$sx, y = .data$sy, label = .data$set),
                                size = 3, colour = "grey35", vjust = 0.5) +
      # room for the names under the hands
      ggplot2::expand_limits(y = labels$sy[1] - 0.05 * diff(range(solid$py)))
  }
  g
}
