test_that("a planted bivariate mixture is recovered", {
  X <- planted_mixture(1, 400, 0.65, c(5, 3), S2 = matrix(c(1, 0.4, 0.4, 0.8), 2))
  fit <- gmm_fit(X)
  expect_s3_class(fit, "gmm_fit")
  expect_false(fit$fallback)
  expect_true(fit$converged)
  expect_true(is.na(fit$reason))
  # ordered by weight: the planted heavier component first
  expect_equal(fit$weights, c(0.65, 0.35), tolerance = 0.05)
  expect_equal(unname(fit$means[1, ]), c(0, 0), tolerance = 0.2)
  expect_equal(unname(fit$means[2, ]), c(5, 3), tolerance = 0.05)
  expect_equal(unname(fit$covs[, , 2]), matrix(c(1, 0.4, 0.4, 0.8), 2), tolerance = 0.3)
  expect_equal(dim(fit$covs), c(2, 2, 2))
  expect_equal(fit$loglik, gmm_loglik(fit, X))
  # refitting permuted rows gives the same mixture in the same order
  perm <- withr::with_seed(2, sample(nrow(X)))
  refit <- gmm_fit(X[perm, ])
  expect_equal(refit$weights, fit$weights, tolerance = 1e-6)
  expect_equal(refit$means, fit$means, tolerance = 1e-6)
})

test_that("a planted univariate mixture is recovered, vectors accepted", {
  x <- withr::with_seed(3, c(rnorm(150, 10, 1), rnorm(100, 16, 2)))
  fit <- gmm_fit(x)
  expect_false(fit$fallback)
  expect_equal(fit$weights, c(0.6, 0.4), tolerance = 0.05)
  expect_equal(as.numeric(fit$means), c(10, 16), tolerance = 0.05)
  expect_equal(sqrt(as.numeric(fit$covs)), c(1, 2), tolerance = 0.2)
  # the density integrates to one
  expect_equal(integrate(function(v) gmm_density(fit, v), -Inf, Inf)$value, 1, tolerance = 1e-6)
})

test_that("the fast engine reaches at least the mixtools log-likelihood", {
  skip_if_not_installed("mixtools")
  sets <- list(
    planted_mixture(11, 60, 0.6, c(4, 2), S2 = matrix(c(1, 0.5, 0.5, 1), 2)),
    planted_mixture(12, 60, 0.5, c(-3, 3), S1 = matrix(c(2, -0.8, -0.8, 1), 2),
                    S2 = diag(c(0.5, 2))),
    planted_mixture(21, 80, 0.6, 3, S2 = matrix(0.25)),
    planted_mixture(22, 80, 0.6, 2),
    planted_mixture(23, 80, 0.6, 4, S2 = matrix(4)))
  for (i in seq_along(sets)) {
    fast <- gmm_fit(sets[[i]])
    ref <- gmm_fit(sets[[i]], engine = "reference", seed = i)
    expect_false(ref$fallback)
    expect_false(fast$fallback)
    expect_gte(fast$loglik, ref$loglik - 1e-6)
    # and the log-likelihoods are computed the same way for both
    expect_equal(ref$loglik, gmm_loglik(ref, sets[[i]]))
  }
})

test_that("the fast engine is deterministic and leaves the RNG as it was", {
  X <- planted_mixture(3, 150, 0.5, c(2, 2))
  set.seed(1)
  before <- .Random.seed
  a <- gmm_fit(X)
  expect_identical(.Random.seed, before)
  expect_identical(gmm_fit(X), a)
})

test_that("degenerate inputs fall back to one Gaussian with the reason recorded", {
  cases <- list(
    identical = list(X = matrix(2, 20, 2), reason = "identical"),
    collinear = list(X = cbind(1:30, 3 * (1:30) + 1), reason = "collinear"),
    three = list(X = matrix(c(1, 2, 4, 0, 1, 5), 3), reason = "too few points"),
    univariate_identical = list(X = rep(1, 10), reason = "identical"))
  for (case in cases) {
    for (engine in c("fast", "reference")) {
      fit <- gmm_fit(case$X, engine = engine)
      X <- as.matrix(case$X)
      expect_true(fit$fallback)
      expect_false(fit$converged)
      expect_match(fit$reason, case$reason)
      expect_equal(fit$weights, 1)
      expect_equal(unname(fit$means[1, ]), colMeans(X))
      expect_equal(unname(as.matrix(fit$covs[, , 1])), unname(cov(X)))
      draws <- withr::with_seed(1, gmm_sample(fit, 50))
      expect_true(all(is.finite(draws)))
    }
  }
  # draws from the collinear fallback stay on the line
  fit <- gmm_fit(cases$collinear$X)
  draws <- withr::with_seed(1, gmm_sample(fit, 100))
  expect_equal(draws[, 2], 3 * draws[, 1] + 1, tolerance = 1e-8)
  expect_true(is.finite(fit$loglik))
  # EM that has not converged within max_iter is a recorded fallback too
  X <- planted_mixture(4, 200, 0.5, c(1, 1))
  fit <- gmm_fit(X, max_iter = 2)
  expect_true(fit$fallback)
  expect_match(fit$reason, "did not converge within 2 iterations")
  expect_equal(fit$iterations, 2L)
  # one requested component is a closed-form fit, not a failure
  one <- gmm_fit(X, k = 1)
  expect_false(one$fallback)
  expect_equal(unname(one$means[1, ]), colMeans(X))
})

test_that("a component collapsing onto repeated points is never returned", {
  X <- rbind(withr::with_seed(6, matrix(rnorm(120), 60)), matrix(c(8, 8), 8, 2, byrow = TRUE))
  for (engine in c("fast", "reference")) {
    # every start collapses onto the repeated points, in both engines: the
    # fit falls back to one Gaussian, with the reason, and keeps no sliver
    fit <- gmm_fit(X, engine = engine, seed = 1)
    dets <- apply(fit$covs, 3, det)
    expect_true(fit$fallback)
    expect_match(fit$reason, "EM failed")
    expect_true(all(dets > 1e-8 * det(cov(X))))
  }
  # here the fast engine's every start collapses: a recorded fallback
  fit <- gmm_fit(X)
  expect_true(fit$fallback)
  expect_match(fit$reason, "every start failed; the first with degenerate component")
  expect_gt(fit$iterations, 0)
})

test_that("gmm_sample draws follow the fitted mixture", {
  X <- planted_mixture(7, 500, 0.8, c(6, -4), S2 = matrix(c(1, -0.3, -0.3, 0.5), 2))
  fit <- gmm_fit(X)
  draws <- withr::with_seed(8, gmm_sample(fit, 4000))
  expect_equal(dim(draws), c(4000, 2))
  # KS test of a projection against the mixture's exact distribution of it
  a <- c(0.6, -0.8)
  mix_cdf <- function(fit, a) {
    m <- drop(fit$means %*% a)
    s <- sqrt(apply(fit$covs, 3, function(S) drop(t(a) %*% S %*% a)))
    function(q) rowSums(sapply(seq_along(fit$weights),
                               function(j) fit$weights[j] * pnorm(q, m[j], s[j])))
  }
  cdf <- mix_cdf(fit, a)
  expect_gt(suppressWarnings(ks.test(drop(draws %*% a), cdf))$p.value, 0.001)
  # the same test rejects a sampler that ignores the weights
  wrong <- fit
  wrong$weights <- c(0.5, 0.5)
  bad_draws <- withr::with_seed(8, gmm_sample(wrong, 4000))
  expect_lt(suppressWarnings(ks.test(drop(bad_draws %*% a), cdf))$p.value, 0.001)
  # same seed, same draws; the draws use the global RNG
  expect_identical(withr::with_seed(8, gmm_sample(fit, 10)), withr::with_seed(8, gmm_sample(fit, 10)))
  expect_false(identical(gmm_sample(fit, 10), gmm_sample(fit, 10)))
  expect_equal(dim(gmm_sample(fit, 0)), c(0, 2))
})

test_that("bad inputs raise classed errors", {
  X <- planted_mixture(1, 50, 0.5, c(3, 3))
  X[4, 2] <- NaN
  expect_error(gmm_fit(X), class = "handmotion_error_bad_input")
  expect_error(gmm_fit(X), "row 4, column 2")
  expect_error(gmm_fit(matrix(1:10, 5), k = 0), class = "handmotion_error_bad_input")
  expect_error(gmm_fit(matrix(1:10, 5), tol = -1), class = "handmotion_error_bad_input")
  expect_error(gmm_fit("a"), class = "handmotion_error_bad_input")
  fit <- gmm_fit(planted_mixture(1, 50, 0.5, c(3, 3)))
  expect_error(gmm_density(fit, matrix(0, 2, 3)), class = "handmotion_error_bad_input")
  expect_error(gmm_sample(fit, -1), class = "handmotion_error_bad_input")
  expect_error(gmm_sample(list(), 2), class = "handmotion_error_bad_input")
})

# ---- the compiled EM (src/gmm-em.c) against the R implementation -----------

# Every start's outcome from both batch implementations on the same design.
em_both <- function(X, k, max_iter = 2000L, tol = 1e-8) {
  X <- as.matrix(X)
  n <- nrow(X)
  Y <- scale(X, scale = sqrt(colSums(scale(X, scale = FALSE)^2) / n))
  Y <- matrix(Y, n)
  design <- gmm_design(Y)
  logdet0 <- determinant(crossprod(Y) / n)$modulus[1]
  starts <- gmm_starts(Y, k, 1)
  list(c = gmm_em_batch(design, starts, k, max_iter, tol, logdet0),
       r = gmm_em_batch_r(design, starts, k, max_iter, tol, logdet0))
}

# Both engines' runs agree start by start: the same failures, and the same
# fit for every start that did not fail; `converged` is how many starts
# must have converged (so the comparison of fits is never empty).
# `exact = TRUE` (clouds that converge briskly): the same iterations, and
# the parameters to 1e-8 as well.
expect_same_runs <- function(runs, converged = 1L, exact = FALSE) {
  expect_equal(length(runs$c), length(runs$r))
  for (a in seq_along(runs$r)) {
    rc <- runs$c[[a]]
    rr <- runs$r[[a]]
    expect_identical(rc$failed, rr$failed)
    # The EM steps agree to rounding, but SQUAREM's step length |r| / |v|
    # divides by a second difference that near the optimum is mostly
    # rounding: on a crawling cloud the two may stop (or merge) some
    # iterations apart, both at the tolerance's distance from the optimum.
    if (exact) expect_identical(rc$iterations, rr$iterations)
    else expect_lte(abs(rc$iterations - rr$iterations), max(1, 0.1 * rr$iterations))
  }
  ok <- which(vapply(runs$r, function(r) is.null(r$failed), logical(1)))
  expect_gte(length(ok), converged)
  for (a in ok) {
    rc <- runs$c[[a]]
    rr <- runs$r[[a]]
    tol_par <- if (exact) 1e-8 else 1e-4
    expect_equal(rc$loglik, rr$loglik, tolerance = 1e-8)
    expect_equal(rc$weights, rr$weights, tolerance = tol_par)
    expect_equal(rc$mu, rr$mu, tolerance = tol_par)
    expect_equal(rc$sigma, rr$sigma, tolerance = tol_par)
  }
}

test_that("the compiled EM reproduces the R implementation start by start", {
  # bivariate and univariate, separated and overlapping (slow) mixtures,
  # k = 2 (the thesis) and k = 3 (the general path), a run cut off at
  # max_iter, starts that collapse, exp() overflowing
  {
    sets <- list(
      list(X = planted_mixture(1, 401, 0.65, c(5, 3)), k = 2), # odd n: the SIMD tails
      list(X = planted_mixture(6, 500, 0.6, c(1, 1)), k = 2),
      list(X = planted_mixture(21, 83, 0.6, 3, S2 = matrix(0.25)), k = 2),
      list(X = withr::with_seed(8, c(rnorm(150), rnorm(100, 1.2))), k = 2),
      list(X = rbind(planted_mixture(2, 200, 0.5, c(6, 0)), planted_mixture(3, 100, 0.5, c(0, 3)) + 12),
           k = 3),
      list(X = withr::with_seed(9, c(rnorm(100), rnorm(100, 5), rnorm(100, 10))), k = 3))
    for (s in sets) expect_same_runs(em_both(s$X, s$k))
    # a run cut off at max_iter, and starts that collapse onto repeated points
    expect_same_runs(em_both(planted_mixture(4, 200, 0.5, c(1, 1)), 2, max_iter = 7L))
    X <- rbind(withr::with_seed(6, matrix(rnorm(120), 60)), matrix(c(8, 8), 8, 2, byrow = TRUE))
    runs <- em_both(X, 2)
    expect_same_runs(runs, converged = 0L)   # every start collapses: the failures must agree
    expect_true(all(vapply(runs$c, function(r) grepl("degenerate", r$failed %||% ""), logical(1))))
    # two tight clusters far apart: exp() overflows in the E-step of running
    # starts, and both implementations switch to the overflow-safe form
    X <- withr::with_seed(7, rbind(matrix(rnorm(200, sd = 1.5), ncol = 2),
                                   matrix(rnorm(200, mean = 100, sd = 1.5), ncol = 2)))
    runs <- em_both(X, 2)
    expect_same_runs(runs)
    expect_true(all(vapply(runs$c, function(r) is.null(r$failed), logical(1))))
  }
})

test_that("the compiled EM reproduces the R transcription for d = 1..4 and k = 1..3", {
  # every dimension runs the one compiled EM; the R transcription in the
  # helper is the reference: on separated groups the same iterations, the
  # same failures and merges, and the fits to 1e-8
  for (d in 1:4) {
    for (k in 1:3) {
      runs <- em_both(planted_groups(10 * d + k, 240, d, k), k)
      expect_same_runs(runs, exact = TRUE)
    }
  }
})

test_that("a planted three-dimensional mixture is recovered", {
  X <- planted_mixture(31, 600, 0.6, c(4, -3, 2), S2 = matrix(c(1, 0.3, 0, 0.3, 1, 0.2, 0, 0.2, 0.5), 3))
  fit <- gmm_fit(X)
  expect_false(fit$fallback)
  expect_equal(fit$weights, c(0.6, 0.4), tolerance = 0.05)
  expect_equal(unname(fit$means[1, ]), c(0, 0, 0), tolerance = 0.15)
  expect_equal(unname(fit$means[2, ]), c(4, -3, 2), tolerance = 0.05)
  expect_equal(unname(fit$covs[, , 2]), matrix(c(1, 0.3, 0, 0.3, 1, 0.2, 0, 0.2, 0.5), 3),
               tolerance = 0.3)
})

test_that("gmm_fit gives the same fits with the compiled and the R EM", {
  sets <- list(planted_mixture(12, 60, 0.5, c(-3, 3), S1 = matrix(c(2, -0.8, -0.8, 1), 2)),
               planted_mixture(23, 80, 0.6, 4, S2 = matrix(4)),
               planted_mixture(5, 300, 0.6, c(1.2, 1.2)),
               planted_mixture(7, 200, 0.5, c(2, 1, 1)),
               planted_mixture(8, 1200, 0.5, c(2, 2, 0, 1)))  # d = 4 above gmm_start_points
  for (X in sets) {
    fc <- gmm_fit(X, max_iter = 5000)
    fr <- local({
      local_mocked_internal("gmm_em_batch", function(design, ...) gmm_em_batch_r(design, ...))
      gmm_fit(X, max_iter = 5000)
    })
    expect_equal(fc$loglik, fr$loglik, tolerance = 1e-8)
    expect_equal(fc$means, fr$means, tolerance = 1e-6)
    expect_equal(fc$covs, fr$covs, tolerance = 1e-6)
    expect_identical(fc$fallback, fr$fallback)
  }
})

test_that("a slowly converging mixture: SQUAREM reaches the optimum plain EM crawls towards", {
  # two strongly overlapping components: plain EM crawls (it had not met the
  # rule after 500 iterations; mixtools' EM takes thousands), the
  # accelerated EM converges in a few hundred evaluations, cut short it is a
  # recorded fallback
  X <- withr::with_seed(6, rbind(matrix(rnorm(300), ncol = 2),
                                 matrix(rnorm(200, mean = 1), ncol = 2) %*% matrix(c(1, 0.5, 0, 1), 2)))
  capped <- gmm_fit(X, max_iter = 20)
  expect_true(capped$fallback)
  expect_match(capped$reason, "did not converge within 20")
  fit <- gmm_fit(X)
  expect_false(fit$fallback)
  expect_gt(fit$iterations, 20)
  expect_lt(fit$iterations, 500)
  expect_gt(fit$loglik, capped$loglik)
  ref <- gmm_fit(X, engine = "reference", seed = 1, max_iter = 20000)
  expect_false(ref$fallback)
  expect_gt(ref$iterations, 1000)
  expect_gte(fit$loglik, ref$loglik - 1e-3)
})

test_that("the fast engine's stopping rule is per observation: ten copies of the data, the same fit", {
  # Ten copies of every point leave the maximum-likelihood fit and every EM
  # step unchanged and multiply the log-likelihood by ten; a rule on the mean
  # log-likelihood stops at the same iteration (an absolute one would not).
  X <- planted_mixture(31, 120, 0.6, c(1.2, 0.6), S2 = matrix(c(1, 0.3, 0.3, 1.5), 2))
  # (every start on every point, as below 1000 points)
  local_mocked_internal("gmm_start_points", Inf)
  one <- gmm_fit(X, max_iter = 5000L)
  ten <- gmm_fit(X[rep(seq_len(nrow(X)), 10), ], max_iter = 5000L)
  expect_false(one$fallback)
  expect_gt(one$iterations, 50L)
  expect_equal(ten$iterations, one$iterations, tolerance = 0.02)
  expect_equal(ten$loglik, 10 * one$loglik, tolerance = 1e-8)
  expect_equal(ten$means, one$means, tolerance = 1e-4)
  expect_equal(ten$weights, one$weights, tolerance = 1e-4)
  # the reference engine keeps mixtools' rule: tol on the total
  expect_identical(gmm_default_tol[["reference"]], 1e-8)
})

test_that("with many points the starts race on a subsample and the best is refined on all", {
  # 3000 points from a planted, overlapping mixture: the subsample's best
  # start refined on every point meets the optimum of all starts on every
  # point, and the planted truth
  X <- planted_mixture(41, 3000, 0.6, c(1.6, 1.2), S2 = matrix(c(1, 0.3, 0.3, 1.2), 2))
  expect_gt(nrow(X), gmm_start_points)
  fit <- gmm_fit(X, max_iter = 5000)
  all_points <- local({
    local_mocked_internal("gmm_start_points", Inf)
    gmm_fit(X, max_iter = 5000)
  })
  expect_false(fit$fallback)
  expect_equal(fit$loglik, all_points$loglik, tolerance = 1e-6)
  # (along the flat ridge of two overlapping components the two runs stop
  # at the tolerance's distance from the optimum, not at the same point)
  expect_equal(fit$weights, all_points$weights, tolerance = 5e-3)
  expect_equal(fit$means, all_points$means, tolerance = 5e-3)
  expect_equal(fit$weights, c(0.6, 0.4), tolerance = 0.1)
  expect_equal(unname(fit$means[2, ]), c(1.6, 1.2), tolerance = 0.2)
})
