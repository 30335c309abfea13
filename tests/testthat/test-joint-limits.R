test_that("angles outside the limits are clamped and counted, the rest untouched", {
  s <- hand_skeleton()
  x <- matrix(30, 4, 16, dimnames = list(NULL, hust_dofs$name))
  x[, "ABD1"] <- 10        # thumb MCP abduction: -15..15
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
  x <- matrix(0, 2, 23, dimnames = list(NULL, joint_map("graspdb14")$dof))
  x[1, "I-PIPJ"] <- -150 * pi / 180   # flexion is negative in GraspDB14 files
  x[2, "I-PIPJ"] <- 10 * pi / 180     # = 10 degrees of hyperextension
  out <- clamp_to_limits(x, s, unit = "rad")
  expect_equal(unname(out[, "I-PIPJ"]), c(-100, 0) * pi / 180)
  expect_equal(attr(out, "clamped"), 2L)
  # discarded sensors, the thumb's opposition (a turn about the hand's axis)
  # have no limits to clamp to (TI-AA has th-mcp's abduction range)
  expect_setequal(attr(out, "unclamped"), c("I-AA", "P-Arch", "T-TMCJ"))
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

test_that("every joint axis a default joint map drives has its own declared range", {
  # a limit lost in data-raw (th-mcp's once sat inside a comment) leaves a
  # driven axis on generic or empty limits; this catches it for both maps
  skel <- hand_skeleton()
  for (map in list(joint_map("hust"), joint_map("graspdb14"))) {
    used <- map[!is.na(map$axis) & map$frame == "joint" & map$sign * map$scale != 0, ]
    j <- as.matrix(skel$joints[match(used$joint, skel$joints$name), skeleton_limit_cols])
    lo <- j[cbind(seq_len(nrow(j)), match(paste0("rot", used$axis, "_min"), colnames(j)))]
    hi <- j[cbind(seq_len(nrow(j)), match(paste0("rot", used$axis, "_max"), colnames(j)))]
    expect_true(all(hi > lo), info = paste(used$joint[!(hi > lo)], used$axis[!(hi > lo)]))
  }
  # the thumb MCP is not a finger MCP: its flexion range is the thumb's
  th <- skel$joints[skel$joints$name == "th-mcp", ]
  fi <- skel$joints[skel$joints$name == "if-mcp", ]
  expect_false(th$rotx_max == fi$rotx_max && th$rotx_min == fi$rotx_min)
})

test_that("dof_limits() gives each limited DoF its range in its own unit and sign", {
  lim <- dof_limits(hust_dofs$name)
  expect_true(all(lim$lo < lim$hi))
  expect_true("ABD1" %in% lim$dof) # thumb MCP abduction is limited now
  rad <- dof_limits(hust_dofs$name, factor = 180 / pi)
  expect_equal(rad$lo, lim$lo * pi / 180)
  # clamp_to_limits() keeps every limited DoF inside exactly these ranges
  rec <- matrix(500, 3, 16, dimnames = list(NULL, hust_dofs$name))
  rec[2, ] <- -500
  out <- clamp_to_limits(rec)
  expect_equal(unname(out[1, lim$col]), lim$hi)
  expect_equal(unname(out[2, lim$col]), lim$lo)
})

test_that("limit_violations() counts the frames outside the limits, per DoF and overall", {
  # planted: DoF b is below its limit in 3 of 10 frames, c above in 2 (one
  # of them a frame where b is below too); DoF a has no limit
  r1 <- cbind(a = 1:5, b = c(-1, 0, 0, 0, -2), c = c(0, 0, 0, 0, 9))
  r2 <- cbind(a = 6:10, b = c(0, -3, 0, 0, 0), c = c(0, 0, 5, 0, 0))
  x <- grasps(list(r1, r2), rate = 10)
  lim <- data.frame(dof = c("c", "b"), lo = c(-1, -0.5), hi = c(1, 1))
  v <- limit_violations(x, lim)
  expect_equal(v$by_dof, c(c = 0.2, b = 0.3))
  expect_equal(v$frames, 0.4)
  expect_identical(limit_violations(x, lim[0, ])$frames, NA_real_)
})
