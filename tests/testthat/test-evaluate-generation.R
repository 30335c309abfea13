# The naturalness yardstick: calibrated on the simulator itself (fresh
# recordings of new subjects score like the training subjects' recordings),
# and sensitive to what the thesis' model gets wrong (independent DoFs).

subject_no <- function(g) as.integer(sub("S", "", g$meta$subject))

test_that("fresh recordings from the simulator score at the real-vs-real level", {
  # a group of subjects is itself a sample: compare the median over three
  # fresh groups of 15 new subjects with the training group's score
  g <- simulate_grasps(subjects = 75, grasps = c(1, 9), seed = 21, plant_overlong = FALSE)
  s <- subject_no(g)
  train <- g[s <= 15]
  held <- g[s > 15 & s <= 30]
  lda <- fit_feature_lda(train)
  for (ty in levels(droplevels(g$meta$grasp))) {
    ref <- generation_reference(held[held$meta$grasp == ty])
    tr <- train[train$meta$grasp == ty]
    lim <- recorded_limits(tr, tr$dofs)
    base <- generation_measures(list(tr), ref, lda, ty, lim)
    fresh <- lapply(0:2, function(k) {
      fr <- g[s > 30 + 15 * k & s <= 45 + 15 * k]
      generation_measures(list(fr[fr$meta$grasp == ty]), ref, lda, ty, lim)
    })
    med <- function(what) stats::median(vapply(fresh, `[[`, numeric(1), what))
    expect_gt(med("mmd"), 0.5 * base$mmd)
    expect_lt(med("mmd"), 2 * base$mmd)
    expect_lt(abs(med("posture_cor_gap") - base$posture_cor_gap), 0.1)
    expect_gt(med("recognised"), 0.9)
  }
})

test_that("the MMD test holds its level on exchangeable samples and sees covariance", {
  set.seed(3)
  X <- matrix(stats::rnorm(60 * 4), 60)
  Y <- matrix(stats::rnorm(60 * 4), 60)
  bw <- stats::median(stats::dist(Y))
  expect_gt(mmd_test(X, Y, bw)$p, 0.05)
  # same means and variances, different correlation: a test of means misses
  # it, the kernel test does not
  f <- stats::rnorm(150)
  C <- outer(f, rep(1, 4)) * 0.95 + matrix(stats::rnorm(600, sd = sqrt(1 - 0.95^2)), 150)
  I <- matrix(stats::rnorm(600), 150)
  bw <- stats::median(stats::dist(C))
  expect_lt(mmd_test(I, C, bw)$p, 0.01)
})

test_that("velocity correlation and log jerk of stacked recordings equal the per-recording ones", {
  # short recordings (skipped), a DoF that does not move in one recording
  # (its pairs left out there), and ordinary ones
  set.seed(5)
  recs <- lapply(c(3, 4, 7, 12, 30, 30), function(n) {
    t <- seq(0, 1, length.out = n)
    cbind(sin(3 * t) + stats::rnorm(n, sd = 0.1), cumsum(stats::rnorm(n)), 2 * t + stats::rnorm(n, sd = 0.3))
  })
  recs[[5]][, 2] <- 4
  x <- grasps(recs, rate = 50)
  vc <- velocity_correlation(x)
  ref <- velocity_correlation_reference(x)
  up <- upper.tri(ref)
  expect_equal(vc[up], ref[up], tolerance = 1e-12)
  expect_equal(log_jerk(x), log_jerk_reference(x), tolerance = 1e-12)
  expect_true(is.na(log_jerk(x)[1]))
})

test_that("the KS distance and the squared distances equal ks.test() and dist()", {
  set.seed(6)
  a <- round(stats::rnorm(40), 1)   # ties within and between the samples
  b <- round(stats::rnorm(25, 0.5), 1)
  expect_equal(ks_distance(a, b), suppressWarnings(stats::ks.test(a, b)$statistic[[1]]), tolerance = 1e-14)
  expect_equal(ks_distance(a, a), 0)
  A <- matrix(stats::rnorm(30 * 4, mean = 5), 30)
  expect_equal(squared_distances(A), unname(as.matrix(stats::dist(A))^2), tolerance = 1e-10)
})

test_that("the MMD test by quadratic forms equals the former permutation-by-indexing one", {
  # unequal sample sizes, a shift that gives a p-value between the extremes
  set.seed(4)
  X <- matrix(stats::rnorm(25 * 3, mean = 0.1), 25)
  Y <- matrix(stats::rnorm(40 * 3), 40)
  bw <- stats::median(stats::dist(Y))
  new <- withr::with_seed(9, mmd_test(X, Y, bw, permutations = 300))
  old <- withr::with_seed(9, mmd_test_reference(X, Y, bw, permutations = 300))
  expect_equal(new$mmd, old$mmd, tolerance = 1e-12)
  expect_equal(new$p, old$p)
  expect_gt(old$p, 0.01)
  expect_lt(old$p, 0.9)
  # the compiled permutations take as many draws from the session's stream
  # as sample.int() did: what is drawn after it is the same
  after_new <- withr::with_seed(9, {mmd_test(X, Y, bw, permutations = 300); stats::runif(3)})
  after_old <- withr::with_seed(9, {mmd_test_reference(X, Y, bw, permutations = 300); stats::runif(3)})
  expect_identical(after_new, after_old)
  # a permutation that splits the samples as observed scores as the observed
  # split does (the same terms in the same order)
  same <- withr::with_seed(2, mmd_test(X[1:2, ], Y[1:2, ], bw, permutations = 50))
  expect_equal(same$p, withr::with_seed(2, mmd_test_reference(X[1:2, ], Y[1:2, ], bw, permutations = 50))$p)
  # a sample of one recording has no statistic, as before (NaN, NA), not an error
  one <- mmd_test(X[1, , drop = FALSE], Y, bw)
  expect_true(is.nan(one$mmd) && is.na(one$p))
  expect_true(is.nan(withr::with_seed(2, mmd_test_reference(X[1, , drop = FALSE], Y, bw))$mmd))
})

test_that("evaluate_generation() flags independent DoFs and returns a tidy table", {
  g <- simulate_grasps(subjects = 24, grasps = c(1, 9, 14), seed = 2)
  s <- subject_no(g)
  train <- g[s <= 16]
  held <- g[s > 16]
  mi <- fit_grasp_models(train, seed = 1)
  mc <- fit_grasp_models(train, seed = 1, dependence = "copula")
  ev <- evaluate_generation(list(thesis = mi, copula = mc), held, train, reps = 2, seed = 1)
  expect_s3_class(ev, "generation_evaluation")
  expect_setequal(unique(ev$grasp), c(names(mi), "overall"))
  expect_setequal(unique(ev$metric), generation_metrics$metric)
  ov <- ev[ev$grasp == "overall", ]
  gap <- function(m) ov$generated[ov$model == m & ov$metric == "posture_cor_gap"]
  base <- ov$baseline[ov$model == "copula" & ov$metric == "posture_cor_gap"]
  expect_gt(gap("thesis"), 1.5 * base)        # the thesis' model is flagged
  expect_lt(gap("copula"), gap("thesis"))
  expect_equal(ov$generated[ov$model == "copula" & ov$metric == "outside_limits"], 0)
  # the baseline is the same for both models
  expect_equal(ev$baseline[ev$model == "thesis"], ev$baseline[ev$model == "copula"])
  expect_output(print(ev), "posture_cor_gap")
  p <- ggplot2::autoplot(ev)
  expect_s3_class(p, "ggplot")
  expect_false("mmd_p" %in% p$data$metric)
  # reproducible
  expect_equal(evaluate_generation(mc, held, train, reps = 1, seed = 4),
               evaluate_generation(mc, held, train, reps = 1, seed = 4))
})

test_that("evaluate_generation() refuses what it cannot compare", {
  g <- simulate_grasps(subjects = 8, grasps = 1:2, objects = 2, trials = 2, seed = 2)
  m <- fit_grasp_models(g, seed = 1)
  expect_error(evaluate_generation(list(m), g, g), class = "handmotion_error_bad_input")
  expect_error(evaluate_generation(m, g$recordings, g), class = "handmotion_error_bad_input")
  expect_error(evaluate_generation(m, g[g$meta$grasp == "Large Diameter"], g),
               "no recordings of", class = "handmotion_error_bad_input")
  expect_error(evaluate_generation(m, g, g, reps = 0), class = "handmotion_error_bad_input")
  expect_error(evaluate_generation(m, g, g, overlong = 3), class = "handmotion_error_bad_input")
})

test_that("over-long recordings are left out of the real samples, counted and printed", {
  g <- simulate_grasps(subjects = 12, grasps = c(1, 9), seed = 5, plant_overlong = FALSE)
  s <- subject_no(g)
  train <- g[s <= 8]
  held <- g[s > 8]
  m <- fit_grasp_models(train, seed = 1)
  # plant two over-long held-out recordings of type 1: the hand rests for 3x the frames
  ty <- names(m)[1]
  long <- which(held$meta$grasp == ty)[1:2]
  recs <- held$recordings
  for (i in long) recs[[i]] <- recs[[i]][c(seq_len(nrow(recs[[i]])), rep(nrow(recs[[i]]), 3 * nrow(recs[[i]]))), ]
  held2 <- grasps(recs, meta = held$meta[setdiff(names(held$meta), c("id", "n_frames"))],
                  dofs = held$dofs, rate = held$rate)
  ev <- evaluate_generation(m, held2, train, reps = 1, seed = 1)
  ex <- attr(ev, "excluded")
  expect_equal(ex$held_out[ex$grasp == ty], 2L)
  expect_equal(sum(ex$training), 0L)
  expect_output(print(ev), "left out of the real samples: 2 held-out, 0 training")
  # kept when asked
  ev_all <- evaluate_generation(m, held2, train, reps = 1, seed = 1, overlong = NULL)
  expect_equal(sum(attr(ev_all, "excluded")$held_out), 0L)
  expect_false(isTRUE(all.equal(ev_all$baseline, ev$baseline)))
})

test_that("evaluate_generation() takes model sets as models and recordings to fold as recordings", {
  g <- simulate_grasps(subjects = 4, grasps = 1:2, objects = 2, trials = 2, seed = 1)
  # the first argument no longer switches mode: recordings there are an error naming `recordings`
  cnd <- expect_error(evaluate_generation(g, folds = 2), "recordings", class = "handmotion_error_bad_input")
  expect_identical(cnd$argument, "models")
  m <- fit_grasp_models(g, seed = 1)
  expect_error(evaluate_generation(m, g, g, recordings = g), class = "handmotion_error_bad_input")
  expect_error(evaluate_generation(recordings = g$recordings), class = "handmotion_error_bad_input")
  ev <- suppressWarnings(evaluate_generation(recordings = g, folds = 2, reps = 1, seed = 3,
                                             fit = list(copula = list(dependence = "copula"))))
  expect_s3_class(ev, "generation_evaluation")
  expect_identical(unique(ev$model), "copula")
})

test_that("the default compares every training recording: the same MMD in expectation, steadier", {
  # why the default sample is the training set, not the held-out size: the
  # unbiased MMD^2 of a shifted sample (a planted gap of 0.5 sd in one of
  # three features) against 6 held-out points has the same mean with 6 or 30
  # draws on the other side, and a smaller spread with 30
  withr::local_seed(7)
  draw <- function(m, shift) cbind(stats::rnorm(m, shift), stats::rnorm(m), stats::rnorm(m))
  one <- function(m) {
    Y <- draw(6, 0)
    mmd_test(draw(m, 0.5), Y, bandwidth = 1.5, permutations = 1L)$mmd
  }
  small <- replicate(400, one(6))
  large <- replicate(400, one(30))
  expect_lt(abs(mean(small) - mean(large)), 3 * sqrt(stats::var(small) / 400 + stats::var(large) / 400))
  expect_lt(stats::sd(large), 0.8 * stats::sd(small))
  # and evaluate_generation() draws nothing for it: one sample, every recording
  g <- simulate_grasps(subjects = 3, grasps = 1, objects = 2, trials = 3, seed = 2, plant_overlong = FALSE)
  tr <- g[g$meta$subject != "S03"]
  ho <- g[g$meta$subject == "S03"]
  all_tr <- generation_real_samples(ho, tr, "x", n = NULL, reps = 5, overlong = NULL)
  expect_length(all_tr$training, 1L)
  expect_identical(names(all_tr$training[[1]]$recordings), names(tr$recordings))
  some <- generation_real_samples(ho, tr, "x", n = 5, reps = 3, overlong = NULL)
  expect_equal(vapply(some$training, length, integer(1)), rep(5L, 3))
})

test_that("the overall row is over the types where a measure is defined", {
  out <- data.frame(model = "m", grasp = c("a", "b", "c"), family = "discriminability", metric = "mmd",
                    generated = c(1, NaN, 3), baseline = c(2, NaN, 2), better = "lower",
                    ratio = c(0.5, NaN, 1.5), stringsAsFactors = FALSE)
  ov <- generation_overall(out)
  expect_equal(ov$generated, 2)
  expect_equal(ov$baseline, 2)
  expect_equal(ov$ratio, 1)
  # a type-less measure stays undefined rather than becoming 0 or an error
  out$generated <- NaN
  expect_true(is.na(generation_overall(out)$generated))
})
