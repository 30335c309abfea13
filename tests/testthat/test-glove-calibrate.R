# Calibration: counts to degrees, from poses, ranges or the nominal map.

raw_set <- function(...) {
  simulate_grasps(subjects = 2, grasps = c(bottle = 3, pen = 20), objects = 1, trials = 2, glove = "resistive",
                  rest = 0.5, hold = 0.5, seed = 1, ...)
}

test_that("calibration from two poses recovers a planted linear map per channel", {
  raw <- raw_set()
  ch <- raw$glove$channels
  gain <- seq(0.08, 0.15, length.out = nrow(ch))
  offset <- seq(-30, 10, length.out = nrow(ch))
  counts <- function(a) {
    m <- matrix((a - offset) / gain, 8, nrow(ch), byrow = TRUE, dimnames = list(NULL, ch$channel))
    m + matrix(stats::rnorm(length(m), 0, 0.5), nrow(m))
  }
  set.seed(2)
  fist <- calibration_pose_angles(raw$glove, "fist")
  deg <- calibrate(raw, poses = list(flat = counts(rep(0, nrow(ch))), fist = counts(fist)))
  cal <- attr(deg, "calibration")
  two <- fist != 0   # channels whose poses differ: gain and offset both fitted
  expect_equal(cal$gain[two], gain[two], tolerance = 0.02)
  expect_lt(max(abs(cal$offset[two] - offset[two])), 0.5)
  # channels at 0 in both poses keep the nominal gain and map the flat pose to 0
  flat_counts <- (0 - offset[!two]) / gain[!two]
  expect_lt(max(abs(cal$offset[!two] + cal$gain[!two] * flat_counts)), 0.5)
  expect_true(all(cal$source == "poses"))
  expect_equal(deg$unit, "deg")
  expect_true(all(deg$glove$channels$unit == "deg"))
})

test_that("the nominal calibration inverts the simulator's nominal map", {
  raw <- raw_set(session_sd = 0)
  deg <- calibrate(raw)
  g0 <- simulate_grasps(subjects = 2, grasps = c(bottle = 3, pen = 20), objects = 1, trials = 2, seed = 1)
  # the final posture of the index MCP: degrees of the twin against calibrated counts
  last <- function(r, j) r[nrow(r), j]
  a <- vapply(deg$recordings, last, 0, j = "index_mcp")
  b <- vapply(g0$recordings, last, 0, j = "MCP2")
  expect_lt(max(abs(a - b)), 8)   # 5% gain jitter of a 0-90 degree range, and noise
})

test_that("calibration from ranges, and the errors of bad input", {
  raw <- raw_set()
  r <- data.frame(channel = "index_mcp", min = 100, max = 900, angle_min = 0, angle_max = 80)
  deg <- calibrate(raw, ranges = r)
  cal <- attr(deg, "calibration")
  expect_equal(cal$gain[cal$channel == "index_mcp"], 0.1)
  expect_equal(cal$source[cal$channel == "index_mcp"], "ranges")
  expect_error(calibrate(raw, ranges = data.frame(channel = "nope", min = 0, max = 1)),
               class = "handmotion_error_bad_input")
  expect_error(calibrate(raw, poses = list(1)), class = "handmotion_error_bad_input")
  expect_error(calibrate(raw, poses = list(mine = matrix(0, 2, 15))), class = "handmotion_error_bad_input")
  g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 1, seed = 1)
  expect_error(calibrate(g), class = "handmotion_error_bad_input")
})
