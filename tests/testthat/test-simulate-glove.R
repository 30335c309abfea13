# The simulator's second protocol: a glove's raw counts with rest and hold.

test_that("raw-count recordings through a profile: labels, range, rest and hold, stuck channels", {
  raw <- simulate_grasps(subjects = 2, grasps = c(bottle = "Medium Wrap", pen = "Tripod"), objects = 1,
                         trials = 3, rate = 100, glove = "resistive", rest = 1, hold = 1,
                         stuck = "thumb_cross", seed = 1)
  expect_equal(levels(raw$meta$grasp), c("bottle", "pen"))
  expect_equal(raw$meta$feix_type[raw$meta$grasp == "pen"][1], "Tripod")
  expect_equal(raw$unit, "raw")
  X <- do.call(rbind, raw$recordings)
  expect_true(all(X >= 0 & X <= 1000 & X == round(X)))
  expect_equal(stuck_channels(raw), "thumb_cross")
  expect_equal(length(unique(X[, "thumb_cross"])), 1L)
  # rest and hold of 0.7-1.3 s around the motion
  expect_true(all(raw$meta$motion_start - 1 >= 70 & raw$meta$motion_start - 1 <= 130))
  hold <- raw$meta$n_frames - raw$meta$motion_end
  expect_true(all(hold >= 70 & hold <= 130))
  # the same seed gives the same recordings
  again <- simulate_grasps(subjects = 2, grasps = c(bottle = "Medium Wrap", pen = "Tripod"), objects = 1,
                           trials = 3, rate = 100, glove = "resistive", rest = 1, hold = 1,
                           stuck = "thumb_cross", seed = 1)
  expect_identical(raw$recordings, again$recordings)
})

test_that("session offsets move a subject's counts by about session_sd", {
  args <- list(subjects = 12, grasps = c(a = 1), objects = 1, trials = 1, glove = "resistive", seed = 3)
  a <- do.call(simulate_grasps, c(args, session_sd = 0))
  b <- do.call(simulate_grasps, c(args, session_sd = 40))
  d <- vapply(seq_along(a), function(i) mean(b$recordings[[i]][, "index_pip"] - a$recordings[[i]][, "index_pip"]), 0)
  expect_gt(stats::sd(d), 20)
  expect_lt(stats::sd(d), 70)
})

test_that("bad protocol arguments are classed errors", {
  expect_error(simulate_grasps(grasps = c(a = 1, 2)), class = "handmotion_error_bad_input")
  expect_error(simulate_grasps(subjects = 1, grasps = 1, glove = "resistive", stuck = "nope"),
               class = "handmotion_error_bad_input")
  expect_error(simulate_grasps(subjects = 1, grasps = 1, rest = -1), class = "handmotion_error_bad_input")
})
