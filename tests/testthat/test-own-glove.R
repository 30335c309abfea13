# The whole path on recordings as a researcher's own glove delivers them:
# one person, six objects, raw counts, rest and hold phases, a stuck
# channel. Only documented functions, no workaround.

own_glove <- function(seed = 3) {
  simulate_grasps(subjects = 1, grasps = c(bottle = 1, mug = 9, ball = 17, pen = 22, card = 28, key = 31),
                  objects = 1, trials = 28, rate = 100, glove = "resistive", rest = 1, hold = 1,
                  stuck = "thumb_cross", plant_overlong = FALSE, seed = seed)
}

test_that("the thesis model keeps nearly every recording and classifies held out above 90%", {
  skip_if_not(slow_tests_enabled(), "slow test (HANDMOTION_SLOW_TESTS)")
  raw <- own_glove()
  ms <- fit_grasp_models(raw, seed = 1)
  s <- summary(ms)
  expect_gte(sum(s$n_used) / sum(s$n_input), 0.95)
  ev <- evaluate_loso(raw, method = "fpca")
  expect_match(ev$scheme, "by recording")
  expect_gte(ev$accuracy[["held_out"]], 0.90)
  best <- evaluate_loso(raw, method = "discriminant")
  expect_gte(best$accuracy[["held_out"]], 0.95)
})

test_that("generated grasps stay inside the sensors' range and carry rest and hold", {
  raw <- own_glove()
  ms <- fit_grasp_models(raw, seed = 1)
  new <- generate(ms, n = 40, seed = 2)
  X <- do.call(rbind, new$recordings)
  R <- do.call(rbind, raw$recordings)
  expect_true(all(X >= 0 & X <= 1000))
  expect_true(all(sweep(X, 2, apply(R, 2, min), ">=") & sweep(X, 2, apply(R, 2, max), "<=")))
  expect_equal(levels(new$meta$grasp), levels(raw$meta$grasp))
  # generated recordings rest and hold as the recorded ones do
  share <- function(g) stats::median(with(find_motion(g), (rest + hold) / n_frames))
  expect_lt(abs(share(new) - share(raw)), 0.15)
  motion_only <- generate(ms, n = 5, seed = 2, phases = FALSE)
  expect_lt(mean(motion_only$meta$n_frames), 0.6 * mean(new$meta$n_frames))
})

test_that("naturalness by folds: quiet on the stuck channel, generated near the real-vs-real distance", {
  skip_if_not(slow_tests_enabled(), "slow test (HANDMOTION_SLOW_TESTS)")
  raw <- own_glove()
  expect_warning(ev <- evaluate_generation(recordings = raw, reps = 2, fit = list(copula = list(dependence = "copula"))),
                 class = "handmotion_warning_constant_channels")
  o <- ev[ev$grasp == "overall", ]
  mmd <- o[o$metric == "mmd", ]
  expect_lt(mmd$generated, 2 * mmd$baseline)
  expect_equal(o$generated[o$metric == "outside_limits"], 0)
})

test_that("every step answers on the raw recordings: early recognition, the drawn hand", {
  raw <- own_glove()
  er <- evaluate_early_recognition(raw, ms = c(100, 300), fractions = NULL, folds = 3)
  expect_match(attr(er, "scheme"), "by recording")
  expect_gt(er$accuracy[er$value == 300], 0.8)
  w <- hand_3d(list(bottle = raw[1], generated = generate(fit_grasp_models(raw[raw$meta$grasp == "bottle"], seed = 1), n = 1, seed = 1)))
  expect_s3_class(w, "htmlwidget")
})

test_that("real GraspDB14 recordings: the GraspDB14 glove is recognised and its motion found", {
  f <- shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt")
  g <- read_graspdb14(f)
  expect_equal(g$glove$name, "graspdb14")
  m <- find_motion(g)
  expect_true(m$found)
  expect_gt(m$start, 1)
  expect_lte(m$end, m$n_frames)
  expect_s3_class(ggplot2::autoplot(g, type = "hand"), "ggplot")
})

test_that("residual resampling keeps what the FPCs leave out: curves = reconstruction + residuals", {
  raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 1), objects = 1, trials = 12, rate = 50,
                         glove = "resistive", rest = 1, hold = 1, seed = 5)
  m <- fit_grasp_model(raw, seed = 1, residuals = "resample")
  res <- m$residuals
  expect_equal(dim(res), dim(m$alignment$warped))
  f <- m$fpca[[3]]
  rebuilt <- sweep(f$scores %*% t(f$components), 2, f$mean, "+") + res[, , 3]
  expect_equal(rebuilt, m$alignment$warped[, , 3], tolerance = 1e-10, ignore_attr = TRUE)
  # generated grasps vary more with the residuals than without (a quarter of the variance is left out)
  new_r <- generate(m, n = 200, seed = 3, phases = FALSE)
  m0 <- fit_grasp_model(raw, seed = 1)
  new_0 <- generate(m0, n = 200, seed = 3, phases = FALSE)
  v <- function(g) stats::var(vapply(g$recordings, function(r) r[round(nrow(r) / 2), 3], 0))
  expect_gt(v(new_r), v(new_0))
  expect_null(m0$residuals)
})
