# Solid hands in 2D: the shape of R/hand-geometry.R (tapered segments capped
# by spheres, a palm slab) projected for a view and cut into polygons in
# data units (so a hand is as thick at thumbnail size as on a full page).
# Every 2D picture comes through here: the ggplot2 stills (pose_layers()) and
# the frames of write_hand_animation(), which draws the same polygons with
# grid directly. Painter's algorithm: back to front by depth; the palm is one
# piece at its mean depth (its sides, rounded edges and top face in that
# order); the faces facing away are not drawn. Shading: darker with distance
# from the viewer, lit from the upper left (the palm's faces by their
# normal), with a highlight along each segment.

# A tapered segment's outline: the two end circles and their outer tangents
# (10 points on each arc), for all hands at once. c0, c1: hands x 2 screen
# positions; r0, r1: radii. Returns list(x, y), hands x 20.
tapered_outline <- function(c0, c1, r0, r1, n_arc = 10L) {
  dx <- c1[, 1] - c0[, 1]
  dy <- c1[, 2] - c0[, 2]
  d <- sqrt(dx^2 + dy^2)
  th <- atan2(dy, dx)
  # the tangents touch the circles at th +- (pi/2 - phi), sin(phi) = (r0 - r1) / d;
  # a circle inside the other (a segment seen end on) leaves only the larger
  s <- ifelse(d > 1e-9, (r0 - r1) / pmax(d, 1e-9), sign(r0 - r1 + 1e-12))
  half <- pi / 2 - asin(pmin(1, pmax(-1, s)))
  u <- seq(-1, 1, length.out = n_arc)
  a1 <- th + outer(half, u)
  a0 <- th + pi + outer(pi - half, u)
  list(x = cbind(c1[, 1] + r1 * cos(a1), c0[, 1] + r0 * cos(a0)),
       y = cbind(c1[, 2] + r1 * sin(a1), c0[, 2] + r0 * sin(a0)))
}

# A segment is named by the joint it ends at (the forearm by its role).
seg_name <- function(geometry, s) if (s$role == "forearm") "forearm" else geometry$joints[s$to]

hand_light <- c(-0.25, 0.35, 0.90) / sqrt(0.25^2 + 0.35^2 + 0.90^2)

# The polygons of posed, projected hands. `S`: array [hands, joints, 3] of
# screen x, screen y and depth (towards the viewer), joints in the
# geometry's order. Returns list(x, y) of vertices and `poly`, one row per
# polygon in drawing order (back to front within each hand): hand, piece,
# kind ("bone", "highlight", "palm_side", "palm"), fill, lwd (outline width,
# 0 for none), depth, start and n (its vertices in x and y).
solid_polygons <- function(S, geometry, scale = 1) {
  H <- dim(S)[1]
  seg <- geometry$segments
  seg <- seg[seg$draw, , drop = FALSE]
  dep <- matrix(S[, , 3], H)
  hi <- apply(dep, 1, max)
  # 1 at the hand's nearest point, 0 from a hand length behind it on (a flat
  # hand seen face on is evenly lit)
  near <- function(d) pmin(1, pmax(0, 1 - (hi - d) / (geometry$hand_length * scale)))
  P <- segment_points(S, geometry)
  pieces <- list()
  add <- function(x, y, fill, kind, piece, order, sub, lwd, keep = rep(TRUE, H)) {
    pieces[[length(pieces) + 1L]] <<- list(x = x, y = y, fill = fill, kind = kind, piece = piece,
                                           order = order, sub = sub, lwd = lwd, keep = keep)
  }
  palm <- geometry$palm
  palm_depth <- NULL
  if (!is.null(palm)) {
    pts <- palm_points(S, geometry)
    n <- palm_normals(pts, geometry)
    n[n[, 3] < 0, ] <- -n[n[, 3] < 0, ]          # towards the viewer
    off <- n * palm$thickness / 2 * scale
    V <- dim(pts)[2]
    top <- bot <- pts
    for (k in 1:3) {
      top[, , k] <- pts[, , k] + off[, k]
      bot[, , k] <- pts[, , k] - off[, k]
    }
    palm_depth <- rowMeans(matrix(pts[, , 3], H))
    # a face turned away from the light is darker than one seen face on
    lit <- function(nz, nx, ny) 1 - 0.22 * pmax(0, hand_light[3] - (nx * hand_light[1] + ny * hand_light[2] +
                                                                      nz * hand_light[3]))
    shade_lit <- function(l) (1 - l) + 0.12 * (1 - near(palm_depth))
    face_fill <- shade_colour(palm$colour, shade_lit(lit(n[, 3], n[, 1], n[, 2])))
    # the sides that face the viewer
    for (k in seq_len(V)) {
      k2 <- k %% V + 1L
      qx <- cbind(top[, k, 1], top[, k2, 1], bot[, k2, 1], bot[, k, 1])
      qy <- cbind(top[, k, 2], top[, k2, 2], bot[, k2, 2], bot[, k, 2])
      # outward normal of the side: edge direction x palm normal, pointing away from the centre
      e <- matrix(pts[, k2, ] - pts[, k, ], H)
      sn <- cbind(e[, 2] * n[, 3] - e[, 3] * n[, 2], e[, 3] * n[, 1] - e[, 1] * n[, 3],
                  e[, 1] * n[, 2] - e[, 2] * n[, 1])
      mid <- matrix((pts[, k2, ] + pts[, k, ]) / 2, H) - apply(pts, c(1, 3), mean)
      sn <- sn * sign(rowSums(sn * mid))
      sn <- sn / pmax(sqrt(rowSums(sn^2)), 1e-12)
      add(qx, qy, shade_colour(palm$colour, shade_lit(lit(sn[, 3], sn[, 1], sn[, 2]))),
          "palm_side", "palm", palm_depth, 0 + k / (V + 1), 0, keep = sn[, 3] > 0)
    }
    add(matrix(top[, , 1], H), matrix(top[, , 2], H), face_fill, "palm", "palm", palm_depth, 3, 0)
  }
  for (i in seq_len(nrow(seg))) {
    s <- seg[i, ]
    c0 <- matrix(P[, s$from, 1:2], H)
    c1 <- matrix(P[, s$to, 1:2], H)
    r0 <- s$r_from * scale
    r1 <- s$r_to * scale
    d <- (P[, s$from, 3] + P[, s$to, 3]) / 2
    # the palm's rounded edges belong to the palm (after its sides, before
    # its face); the forearm lies behind it
    in_palm <- s$role %in% c("metacarpal", "forearm") && !is.null(palm)
    order <- if (in_palm) palm_depth else d
    sub <- if (!in_palm) 0 else if (s$role == "forearm") -1 else 2
    body <- tapered_outline(c0, c1, r0, r1)
    fill <- shade_colour(s$fill, 0.22 * (1 - near(d)))
    add(body$x, body$y, fill, "bone", seg_name(geometry, s), order, sub, 0.18)
    # a highlight along the segment, towards the light (upper left)
    o <- 0.35 * c(-1, 1)
    hl <- tapered_outline(sweep(c0, 2, o * r0, "+"), sweep(c1, 2, o * r1, "+"), 0.3 * r0, 0.3 * r1)
    add(hl$x, hl$y, shade_colour(fill, 0.18, "white"), "highlight", seg_name(geometry, s), order,
        sub + 0.5, 0)
  }
  # one row per (piece, hand), then drawing order within each hand
  np <- length(pieces)
  nv <- vapply(pieces, function(p) ncol(p$x), integer(1))
  poly <- data.frame(hand = rep(seq_len(H), np), p = rep(seq_len(np), each = H),
                     kind = rep(vapply(pieces, `[[`, "", "kind"), each = H),
                     piece = rep(vapply(pieces, `[[`, "", "piece"), each = H),
                     fill = unlist(lapply(pieces, `[[`, "fill")),
                     lwd = rep(vapply(pieces, `[[`, 0, "lwd"), each = H),
                     depth = unlist(lapply(pieces, function(p) rep_len(p$order, H))),
                     sub = rep(vapply(pieces, `[[`, 0, "sub"), each = H),
                     keep = unlist(lapply(pieces, `[[`, "keep")),
                     n = rep(nv, each = H), stringsAsFactors = FALSE)
  # vertices of piece p, hand h start at: offset of p + (h - 1) * nv[p]
  offset <- c(0, cumsum(nv * H))[seq_len(np)]
  poly$start <- offset[poly$p] + (poly$hand - 1L) * poly$n + 1L
  x <- unlist(lapply(pieces, function(p) as.vector(t(p$x))))
  y <- unlist(lapply(pieces, function(p) as.vector(t(p$y))))
  poly <- poly[poly$keep, , drop = FALSE]
  poly <- poly[order(poly$hand, poly$depth, poly$sub), , drop = FALSE]
  idx <- rep(poly$start, poly$n) + sequence(poly$n) - 1L
  poly$start <- c(1L, cumsum(poly$n)[-nrow(poly)] + 1L)
  poly$p <- NULL
  poly$keep <- NULL
  rownames(poly) <- NULL
  list(x = x[idx], y = y[idx], poly = poly)
}

# Shade a colour towards black by `amount` in [0, 1] (0 = unchanged), or
# towards white with `to = "white"`.
shade_colour <- function(col, amount, to = c("black", "white")) {
  to <- match.arg(to)
  n <- max(length(col), length(amount))
  rgb <- grDevices::col2rgb(rep_len(col, n)) / 255
  amount <- pmin(1, pmax(0, rep_len(amount, n)))
  target <- if (to == "black") 0 else 1
  mixed <- rgb * rep(1 - amount, each = 3) + target * rep(amount, each = 3)
  grDevices::rgb(mixed[1, ], mixed[2, ], mixed[3, ])
}

# Outline colour of the solid hands (a darker skin, half transparent).
hand_outline_colour <- "#6b4633"

# Screen positions of every hand in a projected pose `pr` as an array
# [hands, joints, 3] in the geometry's joint order, with the hands' keys.
pose_screen_array <- function(pr, geometry) {
  hand <- paste(pr$id, pr$frame, sep = "\r")
  keys <- unique(hand)
  S <- array(NA_real_, c(length(keys), length(geometry$joints), 3))
  hi <- match(hand, keys)
  ji <- match(pr$joint, geometry$joints)
  ok <- !is.na(ji)
  for (k in 1:3) S[cbind(hi[ok], ji[ok], k)] <- pr[[c("sx", "sy", "depth")[k]]][ok]
  list(S = S, keys = keys, first = match(keys, hand))
}

# The polygons of every hand in `pr` (a projected pose) as a data frame for
# ggplot2: one row per vertex with the columns of the hand's pose rows that
# do not vary by joint (so facets work), plus `px`, `py`, `fill`, `lwd`,
# `kind`, `piece`, `order_depth` and `draw` (the drawing order, for group).
solid_hand_polygons <- function(pr, scale = 1, geometry = hand_geometry()) {
  a <- pose_screen_array(pr, geometry)
  missing <- setdiff(geometry$joints, pr$joint)
  if (length(missing)) {
    hm_abort("The pose lacks joint{?s} {.val {missing}} of the skeleton it is drawn with.", "bad_skeleton",
             joint = missing)
  }
  sp <- solid_polygons(a$S, geometry, scale)
  poly <- sp$poly
  keep <- setdiff(names(pr), c("joint", "parent", "finger", "x", "y", "z", "sx", "sy", "depth"))
  meta <- pr[a$first[poly$hand], keep, drop = FALSE]
  meta$piece <- poly$piece
  meta$kind <- poly$kind
  meta$fill <- poly$fill
  meta$lwd <- poly$lwd
  meta$order_depth <- poly$depth
  # drawing order across hands: hands do not overlap (panels, or side by side)
  meta$draw <- seq_len(nrow(poly))
  out <- meta[rep(seq_len(nrow(poly)), poly$n), , drop = FALSE]
  out$px <- sp$x
  out$py <- sp$y
  rownames(out) <- NULL
  out
}
