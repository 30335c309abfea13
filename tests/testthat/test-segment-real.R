# Finding the motion on real sensors (issue 40): the hand-marked flexglove
# recordings (fixtures/flexglove-motion.csv and .md: 80 recordings marked on
# plots before the detector was tuned), channels that carry noise but no
# motion, and recordings that only rest.

test_that("flexglove: the hand-marked onsets within 3 frames mean absolute error, the ends within 6", {
  fx <- flexglove_marked()
  m <- find_motion(fx$g)
  expect_true(all(m$found))
  # measured 2.90 and 4.81 frames (the detector before issue 40: 6.80 and 25.8)
  expect_lt(mean(abs(m$start - fx$marks$onset)), 3)
  expect_lt(mean(abs(m$end - fx$marks$end)), 6)
  # the rest lasts about as long as a plain threshold says (measured 0.30 s
  # against 0.36 s; before issue 40 find_motion said 0.00 s)
  plain <- vapply(fx$g$recordings, plain_onset, numeric(1))
  expect_lt(abs(stats::median(m$rest) - stats::median(plain - 1)) / 33.3, 0.3)
  expect_gt(stats::median(m$rest) / 33.3, 0.15)
  # 20 recordings marked after the tuning: measured 2.25 frames (before: 4.05)
  ho <- flexglove_marked("flexglove-motion-heldout.csv")
  expect_lt(mean(abs(find_motion(ho$g)$start - ho$marks$onset)), 3)
})

test_that("flexglove read with its time stamps (resampled to 33.3 Hz): onsets within 3 frames", {
  # the path users take: read_glove(time = "time_ms") resamples the frames
  # (27-32 ms apart) onto one grid by linear interpolation, which shrinks
  # the second differences the noise is read from; the noise is read over
  # the recorded spacing (recorded_rate), so the grid finds the same onsets.
  # Marks moved onto the grid by their time stamps. Measured 2.88 and 2.68
  # frames, ends 4.85 (with the noise read on the grid as it is: 3.27, 2.67
  # and 4.11; as recorded 2.90, 2.25 and 4.81).
  fx <- flexglove_marked_resampled()
  expect_true(all(fx$g$meta$recorded_rate > 30 & fx$g$meta$recorded_rate < 40))
  m <- find_motion(fx$g)
  expect_true(all(m$found))
  expect_lt(mean(abs(m$start - fx$marks$onset)), 3)
  expect_lt(mean(abs(m$end - fx$marks$end)), 6)
  plain <- vapply(fx$g$recordings, plain_onset, numeric(1))
  expect_lt(abs(stats::median(m$rest) - stats::median(plain - 1)) / fx$g$rate, 0.3)
  ho <- flexglove_marked_resampled("flexglove-motion-heldout.csv")
  expect_lt(mean(abs(find_motion(ho$g)$start - ho$marks$onset)), 3)
  # channels planted before resampling (interpolated with the rest): white
  # noise and a channel that changes by one count three times never start
  # a motion (the latter did, with a noise of 1e-14, before the quantisation
  # floor was read on the values as recorded). Spikes are not checked here:
  # interpolation spreads a spike of 2 samples over 3 or 4 grid frames,
  # which the 3-frame sustain lets through (2 to 6 of 80 recordings led by
  # them, where they also move some onsets by a frame; open, see issue 40)
  noisy <- flexglove_marked_resampled(seed = 7)
  m1 <- find_motion(noisy$g)
  expect_false(any(m1$lead %in% c("jitter1", "jitter2", "near")))
  led <- !m1$lead %in% "spikes"
  expect_lte(max(abs(m1$start[led] - m$start[led])), 1)
  expect_lt(mean(abs(m1$start - noisy$marks$onset)), 3.5)
})

test_that("channels with noise but no motion never start a motion (real recordings)", {
  fx <- flexglove_marked()
  m0 <- find_motion(fx$g)
  noisy <- with_noise_channels(fx$g, seed = 1)
  m1 <- find_motion(noisy)
  expect_equal(m1$start, m0$start)
  expect_equal(m1$end, m0$end)
  expect_false(any(m1$lead %in% c("jitter1", "jitter2", "spikes", "near")))
  # a pressure pad rising at contact (3 frames before the marked end) moves,
  # but late: it never starts the motion
  padded <- with_noise_channels(fx$g, seed = 1, contact = pmax(1L, fx$marks$end - 3L))
  m2 <- find_motion(padded)
  expect_equal(m2$start, m0$start)
  expect_false(any(m2$lead == "pad"))
})

test_that("channels with noise but no motion never start a motion (simulated recordings)", {
  p <- plant_motion(rate = 100, seed = 100)
  m0 <- find_motion(p$g)
  m1 <- find_motion(with_noise_channels(p$g, seed = 2, contact = p$end - 10L))
  expect_equal(m1$start, m0$start)
  expect_false(any(m1$lead %in% c("jitter1", "jitter2", "spikes", "near", "pad")))
  expect_lt(mean(abs(m1$start - p$onset)) / 100, 0.025)
})

test_that("recordings that only rest are reported as rest only and kept whole by trim_motion", {
  fx <- flexglove_marked()
  real <- fx$g[1:6]
  # rest only: each recording's first frame held for 3 s with sensor noise
  # (sd 1 count, rounded), a one-frame spike and the planted noise channels
  rest <- withr::with_seed(3, lapply(real$recordings, function(r) {
    X <- round(matrix(r[1, ], 100, ncol(r), byrow = TRUE) + matrix(stats::rnorm(100 * ncol(r)), 100))
    X[sample(100, 1), sample(ncol(r), 1)] <- 800
    colnames(X) <- colnames(r)
    X
  }))
  names(rest) <- paste0("rest", seq_along(rest))
  both <- grasps(c(real$recordings, rest), rate = 33.3, unit = "raw")
  both <- with_noise_channels(both, seed = 4)
  m <- find_motion(both)
  expect_equal(m$status, rep(c("motion", "rest only"), each = 6))
  expect_equal(m$found, rep(c(TRUE, FALSE), each = 6))
  expect_equal(m$end[7:12], rep(100L, 6))
  expect_message(t <- trim_motion(both), "No motion found in 6 of 12", class = "handmotion_message_no_motion")
  expect_equal(t$meta$motion_status, m$status)
  expect_equal(t$meta$n_frames[7:12], rep(100L, 6))
  # the simulator's resting glove (tremor, session offsets, quantisation) as well
  glove <- simulate_grasps(subjects = 1, grasps = c(a = 1), objects = 1, trials = 4, rate = 100,
                           glove = "resistive", rest = 1, hold = 1, seed = 5)
  still <- grasps(lapply(glove$recordings, function(r) r[seq_len(glove$meta$motion_start[1] - 1L), ]),
                  rate = 100, unit = "raw")
  expect_equal(unique(find_motion(still)$status), "rest only")
})

test_that("the onset detector of early recognition reads the same signals as find_motion", {
  fx <- flexglove_marked()
  det <- fit_onset_detector(fx$g)
  on <- vapply(fx$g$recordings, detect_onset, integer(1), det = det)
  m <- find_motion(fx$g)
  expect_false(anyNA(on))
  # it sees only the frames so far, so it is sure a little later; the walk back is the same
  expect_lt(mean(abs(on - fx$marks$onset)), 4)
  expect_lt(stats::median(abs(on - m$start)), 2)
  # a live reader that has seen only rest (the first frame held with noise
  # of 1 count sd) finds nothing
  rest <- withr::with_seed(6, lapply(fx$g$recordings[1:10], function(r) {
    round(matrix(r[1, ], 60, ncol(r), byrow = TRUE) + matrix(stats::rnorm(60 * ncol(r)), 60))
  }))
  expect_true(all(is.na(vapply(rest, detect_onset, integer(1), det = det))))
  # planted noise channels change nothing
  noisy <- with_noise_channels(fx$g, seed = 1)
  det2 <- fit_onset_detector(noisy)
  expect_equal(vapply(noisy$recordings, detect_onset, integer(1), det = det2), on)
})
