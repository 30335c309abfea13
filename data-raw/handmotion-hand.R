# Builds inst/extdata/handmotion-hand.xmlskel, the package's own default hand
# skeleton (returned by hand_skeleton()). Same joint tree, names and ids as
# GraspDB14's default.xmlskel, but every length and limit is our own, derived
# from published anthropometry so the file can be shipped:
#
#   * Segment lengths: Buchholz, Armstrong and Goldstein (1992), "Anthropometric
#     data for describing the kinematics of the human hand", Ergonomics 35(3),
#     261-273: joint-centre-to-joint-centre lengths of each metacarpal and
#     phalanx as a fraction of hand length HL; the index, ring and little
#     metacarpals also have a hand-breadth (HB) term, because their CMC joint
#     centres lie off the middle ray: length = sqrt((a*HL)^2 + (b*HB)^2) with
#     (a, b) = (0.374, 0.126), (0.336, 0.077), (0.295, 0.179).
#     Which transcription: the proximal phalanges of index/middle/ring/little
#     are Buchholz's own 0.245/0.266/0.244/0.204 of HL. The other values in
#     circulation, 0.265/0.277/0.259/0.206, are not Buchholz's: they are the
#     An et al. (1979) proximal-to-middle phalanx ratios ((1.94+0.45)/1.29,
#     (1.62+0.37)/1.22, (1.56+0.34)/1.21, (1.78+0.49)/1.29) times Buchholz's
#     middle phalanges, as used in the hand model of Sancho-Bru and
#     colleagues (whose published source code writes exactly these formulas
#     next to Buchholz's metacarpal terms); mixing the two sources was how
#     they entered this file before.
#   * Hand length (wrist crease to middle fingertip): 189 mm, and hand breadth
#     (across the metacarpal heads): 84 mm, both about the adult 50th
#     percentile (between the male and female medians of common
#     anthropometric surveys).
#   * Layout: flat right hand in the x-y plane, fingers along -y, thumb
#     towards +x, palm facing -z. The middle fingertip sits exactly one hand
#     length from the root (the wrist crease), so the carpus takes up the
#     hand length the finger segments leave over. Finger rays fan out slightly
#     (index +6 deg, ring -6, little -12 from the middle ray); the thumb ray
#     lies 40 deg radial of the middle ray in the plane of the palm.
#   * Limits: typical active ranges of motion, American Academy of Orthopaedic
#     Surgeons (1965), "Joint Motion: Method of Measuring and Recording".
#     Positive rotation about x is flexion; about z it turns a finger towards
#     the thumb (+x). Axes with limits "0 0" are not degrees of freedom.
#
# Run from the package root: Rscript data-raw/handmotion-hand.R
pkgload::load_all(".", quiet = TRUE)

hand_length <- 189
hand_breadth <- 84
# fraction of hand length: metacarpal, proximal, (middle,) distal phalanx
buchholz <- list(
  th = c(0.251, 0.196, 0.158),
  `if` = c(0.374, 0.245, 0.143, 0.097),
  mf = c(0.373, 0.266, 0.170, 0.108),
  rf = c(0.336, 0.244, 0.165, 0.107),
  lf = c(0.295, 0.204, 0.117, 0.093)
)
# hand-breadth coefficient of each metacarpal (the middle ray has none)
breadth_term <- c(th = 0, `if` = 0.126, mf = 0, rf = 0.077, lf = 0.179)
# segment lengths in mm; the metacarpal combines both terms
segment_mm <- lapply(names(buchholz), function(f) {
  seg <- hand_length * buchholz[[f]]
  seg[1] <- sqrt(seg[1]^2 + (breadth_term[[f]] * hand_breadth)^2)
  seg
})
names(segment_mm) <- names(buchholz)
carpus <- hand_length * (1 - sum(buchholz$mf))          # wrist crease to middle CMC
base <- list(th = c(20, -8), `if` = c(11, -carpus), mf = c(0, -carpus),
             rf = c(-10, -carpus), lf = c(-19, -carpus))
ray_deg <- c(th = 40, `if` = 6, mf = 0, rf = -6, lf = -12)
joint_names <- list(th = c("tmc", "mcp", "ip", "tip"),
                    `if` = c("cmc", "mcp", "pip", "dip", "tip"))
lim <- function(x = c(0, 0), y = c(0, 0), z = c(0, 0)) c(x, y, z)
limits <- list(
  root = lim(x = c(-70, 80), z = c(-30, 20)),            # wrist extension/flexion, ulnar/radial deviation
  `th-tmc` = lim(x = c(-20, 50), z = c(-30, 70)),       # flexion incl. opposition
  `th-mcp` = lim(x = c(-10, 50), z = c(-15, 15)),
  `th-ip` = lim(x = c(-20, 80)), `th-tip` = lim(),
  cmc = lim(), `rf-cmc` = lim(x = c(0, 10)), `lf-cmc` = lim(x = c(0, 20)),   # palmar arch
  mcp = lim(x = c(-30, 90)), pip = lim(x = c(0, 100)), dip = lim(x = c(-10, 90)), tip = lim(),
  `if-mcp_z` = c(-15, 25), `mf-mcp_z` = c(-20, 20), `rf-mcp_z` = c(-20, 15), `lf-mcp_z` = c(-30, 15)
)

rows <- list(data.frame(id = 1L, name = "root", parent = NA_integer_, px = 0, py = 0, pz = 0))
next_id <- 2L
for (f in names(buchholz)) {
  a <- ray_deg[[f]] * pi / 180
  dir <- c(sin(a), -cos(a))
  seg <- segment_mm[[f]]
  pts <- rbind(base[[f]], t(vapply(cumsum(seg), function(s) base[[f]] + s * dir, numeric(2))))
  nm <- paste0(f, "-", if (f == "th") joint_names$th else joint_names$`if`)
  parent <- 1L
  for (k in seq_along(nm)) {
    rows[[length(rows) + 1L]] <- data.frame(id = next_id, name = nm[k], parent = parent,
                                            px = round(pts[k, 1], 1), py = round(pts[k, 2], 1), pz = 0)
    parent <- next_id
    next_id <- next_id + 1L
  }
}
j <- do.call(rbind, rows)
# every declared limit must reach a joint: a name lost in a comment or
# misspelt would silently leave a joint on the generic limits of its kind
kinds <- unique(sub("^.*-", "", j$name))
unused <- setdiff(names(limits), c(j$name, kinds, paste0(j$name, "_z")))
if (length(unused)) stop("limits declared for no joint: ", paste(unused, collapse = ", "))
stopifnot("th-mcp" %in% names(limits))
lims <- t(vapply(j$name, function(nm) {
  kind <- sub("^.*-", "", nm)
  l <- if (is.null(limits[[nm]])) limits[[kind]] else limits[[nm]]
  if (!is.null(limits[[paste0(nm, "_z")]])) l[5:6] <- limits[[paste0(nm, "_z")]]
  l
}, numeric(6)))
colnames(lims) <- c("rotx_min", "rotx_max", "roty_min", "roty_max", "rotz_min", "rotz_max")
pidx <- match(j$parent, j$id)
off <- as.matrix(j[c("px", "py", "pz")])
off[!is.na(pidx), ] <- off[!is.na(pidx), ] - as.matrix(j[pidx[!is.na(pidx)], c("px", "py", "pz")])
joints <- data.frame(id = j$id, name = j$name, parent = j$parent,
                     x = off[, 1], y = off[, 2], z = off[, 3], lims, row.names = NULL)
skel <- new_hand_skeleton(joints, list(angle = "deg", length = "mm"))
stopifnot(nrow(joints) == 25L)

write_skeleton(skel, "inst/extdata/handmotion-hand.xmlskel", overwrite = TRUE, comment = c(
  " handmotion default hand skeleton (GraspDB14 .xmlskel layout; positions are",
  " rest positions relative to the root, in mm). Right hand, flat, fingers",
  " along -y, thumb towards +x, palm facing -z; +rotx = flexion.",
  " Segment lengths: Buchholz, Armstrong and Goldstein (1992), Ergonomics",
  " 35(3):261-273, times a hand length of 189 mm (metacarpals of index, ring",
  " and little with their hand-breadth term, breadth 84 mm). Limits: AAOS (1965) ranges",
  " of motion. Generated by data-raw/handmotion-hand.R; do not edit by hand. "))
