test_that("the full marker set has 13 hand and 3 forearm markers on skeleton joints", {
  ms <- hand_marker_set()
  expect_equal(nrow(ms), 16)
  expect_equal(sum(ms$segment == "hand"), 13)
  expect_equal(sum(ms$segment == "forearm"), 3)
  expect_false(anyDuplicated(ms$marker) > 0)
  jn <- hand_skeleton()$joints$name
  expect_true(all(ms$joint %in% jn))
  expect_true(all(stats::na.omit(ms$toward) %in% jn))
  hp <- select_markers(method = "handpicked")
  expect_true(all(hp %in% ms$marker))
  # the hand-picked set, like Hoyet et al.'s, leaves the middle and ring fingers bare
  expect_false(any(grepl("^(middle|ring)", hp)))
  expect_error(select_markers(method = "handpicked", n = 3), class = "handmotion_error_bad_markers")
})

test_that("markers sit on the forward-kinematics joints, relative to the root", {
  ang <- matrix(0, 3, 16, dimnames = list(NULL, hust_dofs$name))
  ang[2, ] <- 30
  ang[3, c("MCP2", "PIP2", "DIP2")] <- c(70, 80, 40)
  fk <- forward_kinematics(ang)
  m <- markers_from_angles(ang, forearm = TRUE)
  expect_equal(dim(m), c(3, 48))
  expect_equal(unname(m[, c("index_tip.x", "index_tip.y", "index_tip.z")]), unname(fk[, "if-tip", ]))
  expect_equal(unname(m[, c("ring_pip.x", "ring_pip.y", "ring_pip.z")]), unname(fk[, "rf-pip", ]))
  # a base-knuckle marker lies 20% of the way along the proximal phalanx
  expect_equal(unname(m[, c("index_mcp.x", "index_mcp.y", "index_mcp.z")]),
               unname(fk[, "if-mcp", ] + 0.2 * (fk[, "if-pip", ] - fk[, "if-mcp", ])))
  # forearm markers ride the root link, so they never move in its frame
  fa <- m[, grep("^forearm", colnames(m))]
  expect_equal(apply(fa, 2, stats::sd), rep(0, 9), ignore_attr = TRUE)
  # bending the index moves its tip, flexion changes the tip by tens of mm
  expect_gt(sqrt(sum((m[3, 4:6] - m[1, 4:6])^2)), 30)
})

test_that("markers_from_angles works on grasps objects and checks names", {
  g <- simulate_grasps(subjects = 1, grasps = 1:2, objects = 1, trials = 1, seed = 3)
  m <- markers_from_angles(g)
  expect_named(m, g$meta$id)
  expect_equal(dim(m[[1]]), c(g$meta$n_frames[1], 39))
  one <- markers_from_angles(g[1], markers = c("thumb_tip", "little_tip"))
  expect_equal(colnames(one[[1]]), c("thumb_tip.x", "thumb_tip.y", "thumb_tip.z",
                                     "little_tip.x", "little_tip.y", "little_tip.z"))
  expect_error(markers_from_angles(g, markers = c("thumb_tip", "sixth_finger")),
               class = "handmotion_error_bad_markers")
  expect_error(markers_from_angles(g, markers = c("thumb_tip", "thumb_tip")),
               class = "handmotion_error_bad_markers")
  expect_error(markers_from_angles("x"), class = "handmotion_error_bad_input")
})

# Marker matrix with a planted truth: markers move with planted spreads
# (mm) along random directions, independently.
planted_markers <- function(sd, n = 400, seed = 1) {
  with_seed(seed, {
    mk <- hand_marker_set()$marker[1:13]
    m <- matrix(0, n, 39, dimnames = list(NULL, marker_columns(mk)))
    for (i in seq_along(mk)) {
      dir <- stats::rnorm(3)
      m[, 3 * i - (2:0)] <- outer(stats::rnorm(n, 0, sd[i]), dir / sqrt(sum(dir^2))) +
        matrix(stats::rnorm(3 * n, 0, 0.01), n, 3)
    }
    m
  })
}

test_that("Algorithm 1 ranks the markers that drive the variance first", {
  sd <- rep(1, 13)
  sd[c(4, 2, 8)] <- c(40, 20, 10)       # ring tip >> index tip >> middle pip
  m <- planted_markers(sd)
  top <- select_markers(m, 3)
  rk <- attr(top, "ranking")
  expect_equal(as.vector(top), rk$marker[1:3])
  expect_s3_class(rk, "marker_ranking")
  expect_equal(rk$marker[1:3], c("ring_tip", "index_tip", "middle_pip"))
  expect_equal(sum(rk$share), 1)
  expect_equal(attr(rk, "weighting"), "eigenvalue")
  # the top-N variant: with N = 3 only the three planted directions count
  eq <- select_markers(m, 3, weighting = "equal", n_components = 3)
  expect_setequal(as.vector(eq), c("ring_tip", "index_tip", "middle_pip"))
  expect_equal(attr(attr(eq, "ranking"), "weighting"), "equal")
  expect_error(select_markers(m, 3, weighting = "equal", n_components = 40),
               class = "handmotion_error_bad_input")
  expect_output(print(rk), "marker_ranking")
})

test_that("selected sets are nested prefixes of the ranking", {
  g <- simulate_grasps(subjects = 2, grasps = 1:5, objects = 1, trials = 1, seed = 4)
  rk <- attr(select_markers(g, 1), "ranking")
  s3 <- select_markers(rk, 3)
  s6 <- select_markers(rk, 6)
  expect_length(s6, 6)
  expect_identical(s6[1:3], as.vector(s3))
  expect_identical(select_markers(g, 6), s6)
  expect_error(select_markers(rk, 0), class = "handmotion_error_bad_markers")
  expect_error(select_markers(rk, 14), class = "handmotion_error_bad_markers")
  expect_error(select_markers(rk, 2.5), class = "handmotion_error_bad_markers")
  expect_error(select_markers(n = 3), class = "handmotion_error_bad_input")   # ranking needs x
  expect_error(select_markers(rk, 3, method = "rank"), class = "handmotion_error_bad_input")
})

test_that("forward_kinematics(markers = ) gives the marker positions", {
  ang <- matrix(0, 3, 16, dimnames = list(NULL, hust_dofs$name))
  ang[2, ] <- 30
  expect_equal(forward_kinematics(ang, markers = c("index_tip", "thumb_tip")),
               markers_from_angles(ang, markers = c("index_tip", "thumb_tip")))
  expect_equal(ncol(forward_kinematics(ang, markers = TRUE)), 39)
  g <- grasps(list(ang, ang[3:1, ]), dofs = hust_dofs$name)
  m <- forward_kinematics(g, markers = "index_tip")
  expect_named(m, g$meta$id)
  expect_equal(m[[2]], markers_from_angles(ang[3:1, ], markers = "index_tip"))
  expect_error(forward_kinematics(ang, markers = "nose_tip"), class = "handmotion_error_bad_markers")
})

test_that("forearm markers are not ranked and bad marker matrices are refused", {
  m <- planted_markers(seq(1, 13))
  fa <- matrix(1, nrow(m), 9, dimnames = list(NULL, marker_columns(c("forearm_radial", "forearm_ulnar", "forearm_dorsal"))))
  rk <- attr(select_markers(cbind(m, fa), 13), "ranking")
  expect_equal(nrow(rk), 13)
  expect_false(any(grepl("forearm", rk$marker)))
  bad <- m
  colnames(bad) <- NULL
  expect_error(select_markers(bad), class = "handmotion_error_bad_markers")
  expect_error(select_markers(m[, 1:5]), class = "handmotion_error_bad_markers")
  expect_error(select_markers(m[1, , drop = FALSE]), class = "handmotion_error_reference_too_small")
})
