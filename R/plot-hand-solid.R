# Solid hands for the still pictures (every ggplot2 hand drawing comes
# through pose_layers()). A bone is a capsule, a polygon in data units (so a
# hand is as thick at thumbnail size as in a full page, unlike a line width),
# sized from the hand's own bone lengths; the palm is a plate in skin tone
# with the metacarpals as its rounded edges. Everything is drawn back to
# front by depth, and shaded darker with distance from the viewer, with a
# highlight along each bone, so crossing fingers read in 3D.

# Bone radius (mm) at each joint from the hand's length (wrist to the
# farthest fingertip along the bones) and the joint's depth in its chain:
# thinner towards the tips. The 3D viewer (hand_3d()) uses the same rule.
bone_radius_rule <- function(hand_length, depth) {
  hand_length * 0.042 * pmax(0.6, 1 - 0.1 * pmax(depth - 1L, 0L))
}

# Chain depth of every joint from the (joint, parent) pairs: 0 at the root.
joint_depths <- function(joint, parent) {
  depth <- stats::setNames(rep(NA_integer_, length(joint)), joint)
  depth[is.na(parent) | !parent %in% joint] <- 0L
  for (pass in seq_along(joint)) {
    todo <- is.na(depth)
    if (!any(todo)) break
    depth[todo] <- depth[parent[todo]] + 1L
  }
  depth
}

# Radii by joint name for the poses in `p` (the first hand's bones: every
# hand drawn with one skeleton has the same bone lengths).
pose_radii <- function(p) {
  first <- p$id == p$id[1] & p$frame == p$frame[1]
  h <- p[first, , drop = FALSE]
  depth <- joint_depths(h$joint, h$parent)
  k <- match(h$parent, h$joint)
  len <- ifelse(is.na(k), 0, sqrt((h$x - h$x[k])^2 + (h$y - h$y[k])^2 + (h$z - h$z[k])^2))
  len[is.na(len)] <- 0
  # path length from the root, parents before children (by depth)
  path <- stats::setNames(numeric(nrow(h)), h$joint)
  for (i in order(depth)) if (!is.na(k[i])) path[i] <- path[k[i]] + len[i]
  hand_length <- max(path, 1e-9)
  stats::setNames(bone_radius_rule(hand_length, depth), h$joint)
}

palm_bone_joints <- function(joint) grepl("-(cmc|mcp|tmc)$", joint)

# Shade a colour towards black by `amount` in [0, 1] (0 = unchanged), or
# towards white with `to = "white"`.
shade_colour <- function(col, amount, to = c("black", "white")) {
  to <- match.arg(to)
  n <- max(length(col), length(amount))
  rgb <- grDevices::col2rgb(rep_len(col, n)) / 255
  amount <- rep_len(amount, n)
  target <- if (to == "black") 0 else 1
  mixed <- rgb * rep(1 - amount, each = 3) + target * rep(amount, each = 3)
  grDevices::rgb(mixed[1, ], mixed[2, ], mixed[3, ])
}

skin_colour <- "#efd5bd"

# The polygons of every hand in `pr` (a projected pose), back to front: one
# row per vertex with the columns of the pose row it came from (so facets
# work), `px`, `py`, `fill` and `draw` (the drawing order, for group).
solid_hand_polygons <- function(pr, scale = 1) {
  radii <- pose_radii(pr) * scale
  bones <- pose_bones(pr)
  hand <- paste(pr$id, pr$frame, sep = "\r")
  # depth within each hand in [0, 1], 1 nearest the viewer
  lo <- tapply(pr$depth, hand, min)
  hi <- tapply(pr$depth, hand, max)
  near <- function(d, h) (d - lo[h]) / pmax(hi[h] - lo[h], 1e-9)
  bh <- paste(bones$id, bones$frame, sep = "\r")
  r <- unname(radii[bones$joint])
  r[is.na(r)] <- stats::median(radii)
  base <- ifelse(palm_bone_joints(bones$joint), skin_colour, unname(finger_colours[bones$finger]))
  base[is.na(base)] <- "grey50"
  nb <- nrow(bones)
  arc <- seq(-pi / 2, pi / 2, length.out = 9L)
  # capsules of all bones at once: 18 vertices each (9 around the joint end,
  # 9 around the parent end), one row per bone
  capsules <- function(x0, y0, x1, y1, rad) {
    th <- atan2(y1 - y0, x1 - x0)
    a <- cbind(outer(th, arc, "+"), outer(th + pi, arc, "+"))
    cx <- cbind(matrix(x1, nb, 9L), matrix(x0, nb, 9L))
    cy <- cbind(matrix(y1, nb, 9L), matrix(y0, nb, 9L))
    list(x = cx + rad * cos(a), y = cy + rad * sin(a))
  }
  shade <- 0.38 * (1 - near(bones$depth, bh))
  fill <- shade_colour(base, shade)
  body <- capsules(bones$sxend, bones$syend, bones$sx, bones$sy, r)
  # a highlight along each bone, towards the light (upper left)
  off <- 0.32 * r
  light <- capsules(bones$sxend - off, bones$syend + off, bones$sx - off, bones$sy + off, 0.22 * r)
  rows <- rep(seq_len(nb), each = 18L)
  part <- function(cap, fills, sub, kind) {
    d <- bones[rows, , drop = FALSE]
    d$px <- as.vector(t(cap$x))
    d$py <- as.vector(t(cap$y))
    d$fill <- fills[rows]
    d$order_depth <- bones$depth[rows]
    d$sub <- sub
    d$kind <- kind
    d$piece <- d$joint
    d
  }
  out <- rbind(part(body, fill, 0, "bone"), part(light, shade_colour(fill, 0.3, "white"), 1, "highlight"))
  palm <- pose_palm(pr)
  if (nrow(palm)) {
    ph <- palm$hand
    pd <- tapply(palm$depth, ph, mean)
    palm$px <- palm$sx
    palm$py <- palm$sy
    palm$fill <- shade_colour(skin_colour, 0.38 * (1 - near(pd[ph], paste(palm$id, palm$frame, sep = "\r"))))
    # behind the metacarpals that edge it
    palm$order_depth <- unname(pd[ph]) - 1e-6 * (hi[ph] - lo[ph] + 1)
    palm$sub <- 0
    palm$kind <- "palm"
    palm$piece <- "palm"
    palm$row <- NULL
    palm$hand <- NULL
    keep <- intersect(names(out), names(palm))
    out <- rbind(out[keep], palm[keep])
  }
  key <- paste(out$id, out$frame, out$piece, out$kind, sep = "\r")
  draw_key <- unique(data.frame(key = key, depth = out$order_depth, sub = out$sub, stringsAsFactors = FALSE))
  draw_key <- draw_key[order(draw_key$depth, draw_key$sub), ]
  out$draw <- match(key, draw_key$key)
  out[order(out$draw), , drop = FALSE]
}
