# The hand's solid shape (R/hand-geometry.R): properties of the description,
# not pixels.

test_that("the skeleton spreads the metacarpal bases across the carpus, and the palm spans them", {
  sk <- hand_skeleton()
  rest <- skeleton_rest_positions(sk)
  bases <- rest[c("if-cmc", "mf-cmc", "rf-cmc", "lf-cmc"), ]
  # not one point at the wrist: about 30 mm from the index to the little finger's base
  expect_gt(diff(range(bases[, "x"])), 25)
  expect_true(all(sqrt(rowSums(bases^2)) > 10))
  geo <- hand_geometry(sk)
  W <- geo$palm$weights
  expect_equal(unname(rowSums(W)), rep(1, nrow(W)), tolerance = 1e-12)   # affine
  outline <- W %*% rest
  # every metacarpal base and head lies inside the palm's outline (in the palm's plane)
  inside <- function(p, poly) {
    n <- nrow(poly)
    hit <- FALSE
    for (i in seq_len(n)) {
      a <- poly[i, ]
      b <- poly[i %% n + 1, ]
      if ((a[2] > p[2]) != (b[2] > p[2]) && p[1] < (b[1] - a[1]) * (p[2] - a[2]) / (b[2] - a[2]) + a[1]) hit <- !hit
    }
    hit
  }
  for (j in c("if-cmc", "mf-cmc", "rf-cmc", "lf-cmc", "th-tmc", "mf-mcp", "rf-mcp")) {
    # (the outline passes through the thumb's base and the knuckles: nudge towards the palm's centre)
    p <- rest[j, 1:2] + 0.02 * (colMeans(outline[, 1:2]) - rest[j, 1:2])
    expect_true(inside(p, outline[, 1:2]), label = j)
  }
  # the palm is as wide as the hand across its knuckles (edges offset from the index and little metacarpals)
  width <- diff(range(outline[, "x"][rownames(outline) %in% c("knuckle_ulnar", "knuckle_radial")]))
  expect_gt(width, sqrt(sum((rest["if-mcp", ] - rest["lf-mcp", ])^2)) + geo$palm$thickness * 0.9)
  # the thumb's carpometacarpal joint is on the palm's outline, radial of the index base
  expect_true("th-tmc" %in% rownames(W))
  expect_gt(rest["th-tmc", "x"], rest["if-cmc", "x"])
})

test_that("finger segments taper from the knuckle to the tip", {
  geo <- hand_geometry()
  s <- geo$segments
  f <- s[s$role == "finger", ]
  expect_true(all(f$r_to <= f$r_from + 1e-9))
  for (finger in c("th", "if", "mf", "rf", "lf")) {
    ch <- f[f$finger == finger, ]
    expect_gte(nrow(ch), 2L)
    # each finger narrows overall and its tip is the thinnest end
    expect_lt(min(ch$r_to), max(ch$r_from) * 0.85)
    expect_equal(ch$r_to[nrow(ch)], min(c(ch$r_from, ch$r_to)))
  }
  # the carpal segments and the middle and ring metacarpals lie inside the palm
  expect_false(any(s$draw[s$role == "carpal"]))
  expect_equal(sort(s$finger[s$role == "metacarpal" & s$draw]), c("if", "lf"))
})

test_that("the palm's outline moves rigidly with the palm in any pose", {
  sk <- hand_skeleton()
  geo <- hand_geometry(sk)
  x <- matrix(0, 2, 16, dimnames = list(NULL, hust_dofs$name))
  x[2, ] <- 40                     # every finger and the thumb bent
  pos <- forward_kinematics(x, sk, mode = "plain")[, geo$joints, ]
  pts <- palm_points(pos, geo)
  rigid <- !rownames(geo$palm$weights) %in% c("web", "th-mcp")
  d <- function(k) as.matrix(stats::dist(pts[k, rigid, ]))
  expect_equal(d(1), d(2), tolerance = 1e-9)
  # a whole-hand rotation (the wrist, mode "full") turns the outline with the joints
  R <- matrix(c(cos(1), sin(1), 0, -sin(1), cos(1), 0, 0, 0, 1), 3)
  turned <- pos
  for (f in 1:2) turned[f, , ] <- pos[f, , ] %*% t(R)
  expect_equal(palm_points(turned, geo)[2, , ], pts[2, , ] %*% t(R), tolerance = 1e-9)
})

test_that("one description reaches every renderer", {
  geo <- hand_geometry(hand_skeleton(), "fingers")
  j <- hand_geometry_json(geo)
  # the widget gets the description itself: segments, radii, colours, palm weights
  expect_equal(j$from + 1L, geo$segments$from)
  expect_equal(j$r_to, round(geo$segments$r_to, 2))
  expect_equal(matrix(j$palm$weights, nrow = j$palm$n, byrow = TRUE),
               unname(round(geo$palm$weights, 5)))
  g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
  w <- hand_3d(g, hand_colour = "fingers")
  expect_identical(w$x$geometry, j)
  # the still pictures draw its drawn segments, and the frames of a video the same polygons
  pose <- hand_pose(g, frame = 5)
  pr <- project_pose(as.data.frame(unclass(pose)), "oblique")
  still <- solid_hand_polygons(pr, geometry = geo)
  pos <- forward_kinematics(g$recordings[[1]], frames = 5)[, geo$joints, , drop = FALSE]
  frame <- solid_polygons(project_array(pos, "oblique"), geo)
  expect_equal(still$px, frame$x)
  expect_equal(still$py, frame$y)
  expect_setequal(unique(still$piece[still$kind == "bone"]),
                  c(geo$joints[geo$segments$to[geo$segments$draw & geo$segments$role != "forearm"]], "forearm"))
})

test_that("a skeleton without the palm's joints is drawn bone by bone, its own shape", {
  sk <- hand_skeleton()
  sk$joints$name <- sub("^if-", "ix-", sk$joints$name)    # no index finger as the palm knows it
  geo <- hand_geometry(sk)
  expect_null(geo$palm)
  expect_true(all(geo$segments$draw))
  expect_equal(nrow(geo$points), 0L)
  p <- ggplot2::autoplot(sk, labels = FALSE)
  solid <- p$layers[[1]]$data
  expect_false("palm" %in% solid$kind)
  expect_setequal(unique(solid$piece[solid$kind == "bone"]), sk$joints$name[-1])
  # and the picture of a skeleton is drawn with that skeleton's shape, not the package's hand
  longer <- hand_skeleton()
  longer$joints[c("x", "y", "z")] <- 1.5 * longer$joints[c("x", "y", "z")]
  expect_equal(hand_geometry(longer)$hand_length, 1.5 * hand_geometry()$hand_length)
  wide <- ggplot2::autoplot(longer, labels = FALSE)$layers[[1]]$data
  base <- ggplot2::autoplot(hand_skeleton(), labels = FALSE)$layers[[1]]$data
  expect_equal(diff(range(wide$px)), 1.5 * diff(range(base$px)), tolerance = 1e-6)
})
