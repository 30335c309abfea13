test_that("angles outside the limits are clamped and counted, the rest untouched", {
  s <- hand_skeleton()
  x <- matrix(30, 4, 16, dimnames = list(NULL, hust_dofs$name))
  x[1, "PIP2"] <- 150      # PIP limit 0..100
  x[2, "PIP2"] <- -20
  x[3, "MCP5"] <- -60      # MCP limit -30..90
  out <- clamp_to_limits(x, s)
  expect_true(is.matrix(out))
  expect_equal(unname(out[1:2, "PIP2"]), c(100, 0))
  expect_equal(unname(out[3, "MCP5"]), -30)
  expect_equal(attr(out, "clamped"), 3L)
  expect_equal(attr(out, "clamped_by_dof")[["PIP2"]], 2L)
  expect_equal(out[4, ], x[4, ])
  expect_equal(out[, "PIP3"], x[, "PIP3"])
})

test_that("clamping respects the mapping's sign and the unit", {
  s <- hand_skeleton()
  x <- matrix(0, 2, 23, dimnames = list(NULL, graspdb14_joint_map()$dof))
  x[1, "I-PIPJ"] <- -150 * pi / 180   # flexion is negative in GraspDB14 files
  x[2, "I-PIPJ"] <- 10 * pi / 180     # = 10 degrees of hyperextension
  out <- clamp_to_limits(x, s, unit = "rad")
  expect_equal(unname(out[, "I-PIPJ"]), c(-100, 0) * pi / 180)
  expect_equal(attr(out, "clamped"), 2L)
  # discarded sensors, the thumb's opposition (a turn about the hand's axis)
  # and TI-AA (th-mcp declares no z range) have no limits to clamp to
  expect_setequal(attr(out, "unclamped"), c("I-AA", "P-Arch", "T-TMCJ", "TI-AA"))
})

test_that("grasps in, grasps out", {
  set.seed(2)
  recs <- replicate(2, matrix(runif(10 * 16, -50, 150), 10, 16), simplify = FALSE)
  g <- grasps(recs)
  out <- clamp_to_limits(g)
  expect_s3_class(out, "grasps")
  lim <- hand_skeleton()$joints
  pip <- lim[lim$name == "if-pip", ]
  expect_true(all(out$recordings[[1]][, "PIP2"] <= pip$rotx_max))
  expect_true(all(out$recordings[[2]][, "PIP2"] >= pip$rotx_min))
  n_out <- sum(vapply(g$recordings, function(r) sum(r[, "PIP2"] > 100 | r[, "PIP2"] < 0), numeric(1)))
  expect_equal(attr(out, "clamped_by_dof")[["PIP2"]], n_out)
  # idempotent
  expect_equal(attr(clamp_to_limits(out), "clamped"), 0L)
})
