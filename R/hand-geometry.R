# The solid shape of a hand: ONE description, drawn by every renderer (the
# still pictures and the GIF through solid_hand_polygons() in
# R/plot-hand-solid.R, the 3D widget through hand3d.js, which receives this
# description as data). It is a function of the skeleton only; a pose adds
# nothing but the joint positions forward kinematics returns, so the shape
# follows whatever drives the joints.
#
# * Segments: one per bone (parent joint -> joint), a truncated cone with a
#   radius at each end (fingers taper from the knuckle to the tip), capped by
#   spheres of those radii. Radii are fractions of the hand length (wrist to
#   the farthest joint in the rest pose), from finger breadths at the joints
#   of adult hands (about 21 mm at the index PIP, 18 at its DIP, 17 at the
#   little finger's PIP, 22 at the thumb's IP for a 189 mm hand).
# * The palm: a slab, `thickness` thick, whose outline is a ring of points,
#   each an affine combination of joint positions (weights summing to 1).
#   Points of the rigid palm are combinations of three joints of the rigid
#   palm (the root and the index and little knuckles), so they move with it
#   in every pose; the thumb's web follows the thumb's carpometacarpal joint
#   and its metacarpal head. The outline runs from the wrist along the little
#   finger's metacarpal, across the knuckles, to the index metacarpal and
#   round the thumb's web back to the wrist, so the palm spans the metacarpal
#   bases, which the skeleton spreads across the carpus (its `*-cmc` joints,
#   Buchholz et al.'s proportions), not one point at the wrist.
# * Extra points: a segment may end at a point that is no joint, an affine
#   combination of joints like the palm's outline: the forearm, a stub from
#   the wrist along the hand's long axis (behind the palm, so the wrist does
#   not end in a cut).
# * Which segments are drawn: the carpal segments (root -> metacarpal base)
#   and the middle and ring metacarpals lie inside the palm and are not; the
#   index and little metacarpals are the palm's rounded edges.

# Radius at each joint as a fraction of the hand length, by finger and joint
# (the part of the name after the finger's prefix).
hand_radius_table <- list(
  th = c(tmc = 0.070, mcp = 0.064, ip = 0.058, tip = 0.050),
  `if` = c(cmc = 0.066, mcp = 0.057, pip = 0.054, dip = 0.048, tip = 0.042),
  mf = c(cmc = 0.066, mcp = 0.058, pip = 0.055, dip = 0.049, tip = 0.043),
  rf = c(cmc = 0.066, mcp = 0.055, pip = 0.051, dip = 0.046, tip = 0.040),
  lf = c(cmc = 0.062, mcp = 0.050, pip = 0.046, dip = 0.042, tip = 0.037)
)

# Palm thickness (at the knuckles, about 25 mm for a 189 mm hand) and wrist
# breadth, as fractions of the hand length.
hand_palm_thickness <- 0.13
hand_wrist_breadth <- 0.27
# The forearm stub: length and radii (at the wrist, at its far end).
hand_forearm <- c(length = 0.18, r_wrist = 0.105, r_end = 0.115)

hand_skin_colour <- "#E8BD9C"

# The solid-shape description of a hand on `skeleton` (a list; see the file
# header). `colour`: "skin" (every part in skin tone) or "fingers" (each
# finger in its own colour, the palm in skin tone).
hand_geometry <- function(skeleton = hand_skeleton(), colour = c("skin", "fingers")) {
  colour <- match.arg(colour)
  j <- skeleton$joints
  J <- nrow(j)
  rest <- skeleton_rest_positions(skeleton)
  pidx <- skeleton_parent_index(skeleton)
  root <- which(is.na(pidx))
  chain <- skeleton_chains(skeleton)
  hand_length <- max(sqrt(rowSums(sweep(rest, 2, rest[root, ])^2)), 1e-9)
  radius <- joint_radius(j$name, chain, pidx, hand_length)
  palm <- palm_outline_weights(rest, j$name, root, hand_length)
  seg <- which(!is.na(pidx))
  from <- pidx[seg]
  role <- ifelse(from == root, "carpal",
                 ifelse(grepl("-(cmc|tmc)$", j$name[from]) & chain[seg] != "th", "metacarpal", "finger"))
  draw <- rep(TRUE, length(seg))
  if (!is.null(palm)) {
    # inside the palm slab: drawn as the palm, not as bones
    draw <- !(role == "carpal" | (role == "metacarpal" & !chain[seg] %in% c("if", "lf")))
  }
  r_from <- radius[from]
  r_to <- radius[seg]
  # the palm's rounded edges are as thick as the palm
  edge <- role == "metacarpal" & chain[seg] %in% c("if", "lf")
  if (!is.null(palm)) {
    r_from[edge] <- palm$thickness / 2
    r_to[edge] <- palm$thickness / 2
  }
  fill <- if (colour == "skin") rep(hand_skin_colour, length(seg)) else {
    f <- unname(finger_colours[chain[seg]])
    f[is.na(f)] <- "#808080"
    f[role != "finger" & chain[seg] != "th"] <- hand_skin_colour
    hex_colour(f)
  }
  segments <- data.frame(from = from, to = seg, finger = chain[seg], role = role,
                         r_from = r_from, r_to = r_to, fill = fill, draw = draw,
                         stringsAsFactors = FALSE)
  points <- matrix(0, 0, J, dimnames = list(NULL, j$name))
  if (!is.null(palm)) {
    # the forearm: along the line from the middle knuckle through the wrist,
    # its rounded end just behind the palm's wrist edge (so that it does not
    # poke through the palm, which is thinner than the wrist)
    mid <- match("mf-mcp", j$name)
    back <- sqrt(sum((rest[mid, ] - rest[root, ])^2))
    r_wrist <- hand_forearm[["r_wrist"]] * hand_length
    at <- c(forearm_end = r_wrist + hand_forearm[["length"]] * hand_length, forearm_wrist = r_wrist) / back
    points <- matrix(0, 2, J, dimnames = list(names(at), j$name))
    points[, root] <- 1 + at
    points[, mid] <- -at
    segments <- rbind(segments, data.frame(
      from = J + 1L, to = J + 2L, finger = "forearm", role = "forearm",
      r_from = hand_forearm[["r_end"]] * hand_length, r_to = r_wrist,
      fill = hand_skin_colour, draw = TRUE, stringsAsFactors = FALSE))
  }
  structure(list(joints = j$name, points = points, segments = segments, palm = palm,
                 skin = hand_skin_colour, colour = colour, hand_length = hand_length),
            class = "hand_geometry")
}

hex_colour <- function(col) grDevices::rgb(t(grDevices::col2rgb(col)), maxColorValue = 255)

# Radius (mm) at every joint: the table above for the named joints, else a
# rule by depth in the chain (0.05 of the hand length, 8% thinner a joint).
joint_radius <- function(name, chain, pidx, hand_length) {
  J <- length(name)
  depth <- integer(J)
  for (i in seq_len(J)) {
    k <- i
    while (!is.na(pidx[k])) {
      depth[i] <- depth[i] + 1L
      k <- pidx[k]
    }
  }
  r <- hand_length * 0.05 * pmax(0.6, 1 - 0.08 * pmax(depth - 1L, 0L))
  part <- sub("^[^-]*-", "", name)
  for (i in seq_len(J)) {
    tab <- hand_radius_table[[chain[i]]]
    if (!is.null(tab) && part[i] %in% names(tab)) r[i] <- tab[[part[i]]] * hand_length
  }
  r[is.na(pidx)] <- hand_length * hand_palm_thickness / 2
  r
}

# The palm's outline as affine weights over the joints (a V x J matrix whose
# rows sum to 1), with the thickness and the colour; NULL for a skeleton
# without the joints that hold a palm.
palm_outline_weights <- function(rest, names, root, hand_length) {
  need <- c("th-tmc", "th-mcp", "if-cmc", "if-mcp", "mf-mcp", "rf-mcp", "lf-cmc", "lf-mcp")
  if (!all(need %in% names)) return(NULL)
  J <- length(names)
  P <- function(n) rest[match(n, names), ]
  unit <- function(v) v / sqrt(sum(v^2))
  t_half <- hand_length * hand_palm_thickness / 2
  radial <- unit(P("if-mcp") - P("lf-mcp"))
  # sideways from a metacarpal, in the palm's plane, towards `side`
  across <- function(base, head, side) {
    along <- unit(P(head) - P(base))
    v <- side - sum(side * along) * along
    unit(v)
  }
  wrist <- rest[root, ]  # the root is the wrist's centre
  half_wrist <- hand_length * hand_wrist_breadth / 2
  # rest positions of the rigid palm's outline points
  pts <- rbind(
    wrist_ulnar = wrist - half_wrist * radial,
    base_ulnar = P("lf-cmc") + t_half * across("lf-cmc", "lf-mcp", -radial),
    knuckle_ulnar = P("lf-mcp") + t_half * across("lf-cmc", "lf-mcp", -radial),
    `lf-mcp` = P("lf-mcp"), `rf-mcp` = P("rf-mcp"), `mf-mcp` = P("mf-mcp"), `if-mcp` = P("if-mcp"),
    knuckle_radial = P("if-mcp") + t_half * across("if-cmc", "if-mcp", radial),
    web = NA, `th-mcp` = NA, `th-tmc` = NA,
    wrist_radial = wrist + half_wrist * radial)
  W <- matrix(0, nrow(pts), J, dimnames = list(rownames(pts), names))
  anchors <- match(c(names[root], "if-mcp", "lf-mcp"), names)
  A <- rest[anchors, , drop = FALSE]
  # barycentric weights in the palm's plane (least squares if it is not flat)
  basis <- cbind(A[2, ] - A[1, ], A[3, ] - A[1, ])
  for (v in rownames(pts)) {
    if (v %in% c("web", "th-mcp", "th-tmc")) next
    if (v %in% names) {
      W[v, v] <- 1
      next
    }
    ab <- qr.solve(basis, pts[v, ] - A[1, ])
    W[v, anchors] <- c(1 - sum(ab), ab)
  }
  # the thumb's web: from the thumb's metacarpal head to the index knuckle,
  # a third of the way (it moves as the thumb opposes)
  W["th-mcp", "th-mcp"] <- 1
  W["th-tmc", "th-tmc"] <- 1
  W["web", ] <- 0.65 * W["th-mcp", ] + 0.35 * W["knuckle_radial", ]
  list(weights = W, thickness = 2 * t_half, colour = hand_skin_colour,
       # the palm's normal: (knuckle_radial - knuckle_ulnar) x (mf-mcp - wrist centre)
       normal = match(c("knuckle_ulnar", "knuckle_radial", "wrist_ulnar", "lf-mcp"), rownames(pts)))
}

# Affine combinations `W` (rows sum to 1) of the joints of posed hands:
# `pos` an array [hands, joints, 3] in the geometry's joint order; an array
# [hands, rows of W, 3].
affine_points <- function(pos, W) {
  out <- array(0, c(dim(pos)[1], nrow(W), 3))
  for (k in 1:3) out[, , k] <- matrix(pos[, , k], dim(pos)[1]) %*% t(W)
  out
}

palm_points <- function(pos, geometry) affine_points(pos, geometry$palm$weights)

# The joints followed by the geometry's extra points (the ends segments index).
segment_points <- function(pos, geometry) {
  if (!nrow(geometry$points)) return(pos)
  extra <- affine_points(pos, geometry$points)
  out <- array(0, c(dim(pos)[1], dim(pos)[2] + nrow(geometry$points), 3))
  out[, seq_len(dim(pos)[2]), ] <- pos
  out[, dim(pos)[2] + seq_len(nrow(geometry$points)), ] <- extra
  out
}

# Unit normal of each hand's palm (hands x 3), from its outline points.
palm_normals <- function(pts, geometry) {
  i <- geometry$palm$normal
  a <- pts[, i[2], , drop = FALSE] - pts[, i[1], , drop = FALSE]
  b <- pts[, i[4], , drop = FALSE] - pts[, i[3], , drop = FALSE]
  a <- matrix(a, dim(pts)[1])
  b <- matrix(b, dim(pts)[1])
  n <- cbind(a[, 2] * b[, 3] - a[, 3] * b[, 2], a[, 3] * b[, 1] - a[, 1] * b[, 3],
             a[, 1] * b[, 2] - a[, 2] * b[, 1])
  n / pmax(sqrt(rowSums(n^2)), 1e-12)
}

# The description as the 3D widget reads it (0-based indices, row-major
# weights), so hand3d.js draws exactly this shape.
hand_geometry_json <- function(geometry) {
  s <- geometry$segments
  out <- list(from = s$from - 1L, to = s$to - 1L, r_from = round(s$r_from, 2), r_to = round(s$r_to, 2),
              fill = s$fill, draw = s$draw, skin = geometry$skin,
              # extra points (after the joints), row-major weights over the joints
              points = list(n = nrow(geometry$points), weights = round(as.vector(t(geometry$points)), 5)))
  if (!is.null(geometry$palm)) {
    W <- geometry$palm$weights
    out$palm <- list(n = nrow(W), weights = round(as.vector(t(W)), 5),
                     thickness = round(geometry$palm$thickness, 2), normal = geometry$palm$normal - 1L,
                     colour = geometry$palm$colour)
  }
  out
}
