# Finding the grasping motion between rest and hold.

test_that("planted onsets are recovered within 25 ms mean absolute error at 50 and 100 Hz", {
  # 25 ms: 1.25 frames at 50 Hz, 2.5 at 100 Hz (the first 5% of a
  # minimum-jerk reach moves less than the noise of any one channel)
  for (rate in c(50, 100)) {
    p <- plant_motion(rate = rate, seed = rate)
    m <- find_motion(p$g)
    expect_true(all(m$found))
    expect_equal(unique(m$status), "motion")
    expect_lt(mean(abs(m$start - p$onset)) / rate, 0.025)
    # the end of a minimum-jerk motion is as slow as its start: within 40 ms
    expect_lt(mean(abs(m$end - p$end)) / rate, 0.04)
  }
})

test_that("trim_motion cuts each recording to its motion and records where", {
  p <- plant_motion(n_rec = 6, seed = 3)
  t <- trim_motion(p$g)
  m <- attr(t, "motion")
  expect_equal(t$meta$n_frames, m$end - m$start + 1L)
  expect_equal(t$recordings[[2]], p$g$recordings[[2]][m$start[2]:m$end[2], ])
  expect_equal(t$meta$trim_start, m$start)
})

test_that("a recording without motion is kept whole and marked not found", {
  set.seed(1)
  still <- grasps(list(matrix(round(rnorm(200, 500, 1)), 100, 2, dimnames = list(NULL, c("a", "b")))),
                  unit = "raw")
  m <- find_motion(still)
  expect_false(m$found)
  expect_equal(m$status, "rest only")
  expect_equal(c(m$start, m$end), c(1L, 100L))
})

test_that("cut_motion finds every grasp in a continuous stream", {
  p <- plant_motion(n_rec = 3, seed = 7)
  stream <- grasps(list(do.call(rbind, p$g$recordings)), rate = 100, unit = "raw")
  pieces <- cut_motion(stream)
  expect_equal(length(pieces), 3L)
  starts <- cumsum(c(0, p$g$meta$n_frames[-3])) + p$onset
  expect_lt(mean(abs(pieces$meta$trim_start - starts)), 8)
  expect_lt(max(abs(pieces$meta$trim_start - starts)), 12)
  expect_error(cut_motion(grasps(list(matrix(5, 50, 2, dimnames = list(NULL, c("a", "b")))))),
               class = "handmotion_error_no_segments")
})

test_that("the twin of HUST, cut to the motion, is not trimmed by default; glove recordings are", {
  g <- simulate_grasps(subjects = 3, grasps = 1:10, objects = 1, trials = 1, seed = 1)
  expect_equal(resolve_motion(g, "auto"), "as_recorded")
  raw <- simulate_grasps(subjects = 1, grasps = c(a = 1, b = 9), objects = 1, trials = 5, rate = 100,
                         glove = "resistive", rest = 1, hold = 1, seed = 1)
  expect_equal(resolve_motion(raw, "auto"), "trim")
  m <- fit_grasp_model(raw, grasp = "a", seed = 1, mixture_components = 1)
  expect_equal(m$settings$motion, "trim")
  expect_equal(m$settings$warping, "linear")
  expect_equal(m$n_used, 5L)
  expect_output(print(m), "trimmed to the motion")
})

test_that("bad arguments are classed errors", {
  p <- plant_motion(n_rec = 2)
  expect_error(find_motion(p$g, min_move = 1), class = "handmotion_error_bad_input")
  expect_error(find_motion(p$g, min_still = -1), class = "handmotion_error_bad_input")
  expect_error(cut_motion(p$g, min_move = "a"), class = "handmotion_error_bad_input")
  expect_error(find_motion(list()), class = "handmotion_error_bad_input")
})
