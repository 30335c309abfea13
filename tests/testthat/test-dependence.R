# Planted truth for the copula model: the simulator with a strong per-subject
# factor (every subject's hand flexes all fingers together, three times the
# default loading) has a known cross-DoF correlation of the final posture,
# measured on a large independent sample of new subjects. The copula model
# fitted on 30 subjects must recover it; the thesis' independent model
# provably cannot (its generated DoFs are independent by construction).

planted_params <- function() {
  p <- simulator_params()
  L <- p$loadings
  L[, "flexion"] <- 3 * L[, "flexion"]
  simulator_params(loadings = L)
}

final_cor <- function(x) stats::cor(final_postures(x))

test_that("the copula model recovers a planted cross-DoF correlation; the independent one does not", {
  params <- planted_params()
  train <- simulate_grasps(subjects = 30, grasps = "Medium Wrap", seed = 11, params = params,
                           plant_overlong = FALSE)
  # the truth: subjects 31-150 of a 150-subject draw of the same seed (the
  # first 30 are close to, not exactly, the training hands: subject draws are
  # whitened within each sample)
  big <- simulate_grasps(subjects = 150, grasps = "Medium Wrap", seed = 11, params = params,
                         plant_overlong = FALSE)
  truth <- final_cor(big[as.integer(sub("S", "", big$meta$subject)) > 30])
  off <- upper.tri(truth)
  strong <- off & abs(truth) > 0.5
  expect_gt(sum(strong), 20) # the planted factor is there to find

  mc <- fit_grasp_model(train, seed = 1, dependence = "copula")
  mi <- fit_grasp_model(train, seed = 1)
  gap_c <- mean(abs(final_cor(generate(mc, n = 3000, seed = 2)) - truth)[off])
  gap_i <- mean(abs(final_cor(generate(mi, n = 3000, seed = 2)) - truth)[off])
  # what 270 real recordings of 30 subjects achieve: the floor for any model
  gap_real <- mean(abs(final_cor(train) - truth)[off])
  expect_lt(gap_c, 0.15)
  expect_lt(gap_c, gap_real + 0.07)
  expect_gt(gap_i, 0.3)
  # on the strongly correlated pairs the independent model is near zero
  expect_lt(mean(abs(final_cor(generate(mi, n = 3000, seed = 2))[strong])), 0.45)
})

test_that("the copula keeps each score's marginal and carries the training correlation", {
  g <- simulate_grasps(subjects = 20, grasps = 3, seed = 3)
  # mixture marginals (mixture_components = 2) and three warp FPCs, so that the tabulated
  # quantile functions are not Gaussian ones
  m <- fit_grasp_model(g, seed = 1, dependence = "copula", ncomp = 2, mixture_components = 2, warp_ncomp = 3,
                       warping = "dtw")
  cop <- m$dependence$copula
  D_all <- length(m$dofs) * 2 + 3
  expect_equal(nrow(cop$columns), D_all)
  expect_equal(dim(cop$cor), c(D_all, D_all))
  expect_true(cop$shrinkage >= 0 && cop$shrinkage <= 1)
  expect_equal(unname(diag(cop$cor)), rep(1, D_all))
  set.seed(1)
  s <- draw_joint_scores(m, 20000)
  S <- score_matrix(m, cop$columns)
  # the drawn scores' correlation is the copula's (normal scores, rank-based)
  D <- cbind(matrix(s$alpha, 20000), s$beta)
  D <- D[, match(cop$columns$name, c(paste0(rep(m$dofs, 2), ".FPC", rep(1:2, each = 16)), paste0("warp.FPC", 1:3)))]
  Zd <- apply(D, 2, function(v) stats::qnorm(rank(v) / (length(v) + 1)))
  expect_lt(max(abs(stats::cor(Zd) - cop$cor)), 0.05)
  # and each column's marginal is its mixture's: quantiles of draws against
  # the tabulated quantile function
  for (a in c(1, 7, 33)) {
    q <- stats::quantile(D[, a], c(0.1, 0.5, 0.9), names = FALSE)
    want <- stats::approx(cop$z, cop$quantiles[, a], xout = stats::qnorm(c(0.1, 0.5, 0.9)))$y
    expect_equal(q, want, tolerance = 0.05 * stats::sd(S[, a]) / max(abs(want)))
  }
})

test_that("least-squares scores reconstruct the final posture the trapezoidal ones miss", {
  g <- simulate_grasps(subjects = 12, grasps = 3, seed = 3)
  fit <- function(rule) fit_grasp_model(g, seed = 1, dependence = "copula", fpc_scores = rule)
  end_sd_ratio <- function(m) {
    L <- m$target_length
    rec <- vapply(seq_along(m$dofs), function(j) {
      model_scores(m)[, j, ] %*% model_basis(m)$components[L, j, ] + model_basis(m)$mean[L, j]
    }, numeric(m$n_used))
    stats::median(apply(rec, 2, stats::sd) / apply(m$alignment$warped[, L, ], 2, stats::sd))
  }
  ls <- end_sd_ratio(fit("least_squares"))
  tz <- end_sd_ratio(fit("trapezoid"))
  expect_gt(ls, 0.97)
  expect_gt(ls - tz, 0.02)
})

test_that("shrink_correlation()'s lambda is Schafer and Strimmer's, from every pair's variance", {
  set.seed(3)
  Z <- matrix(rnorm(60 * 5), 60) %*% matrix(runif(25, -1, 1), 5)
  n <- nrow(Z)
  X <- scale(Z)
  # the definition, pair by pair: Var(r_ij) from the products w_kij = x_ki x_kj
  num <- den <- 0
  for (i in 1:5) for (j in 1:5) if (i != j) {
    w <- X[, i] * X[, j]
    num <- num + n / (n - 1)^3 * sum((w - mean(w))^2)
    den <- den + (sum(w) / (n - 1))^2
  }
  s <- shrink_correlation(Z)
  expect_equal(s$lambda, num / den, tolerance = 1e-12)
  expect_equal(s$cor[upper.tri(s$cor)], ((1 - num / den) * cor(Z))[upper.tri(s$cor)], tolerance = 1e-12)
})

test_that("shrink_correlation() shrinks noise and keeps a strong structure", {
  set.seed(4)
  Z <- matrix(stats::rnorm(50 * 30), 50)
  s <- shrink_correlation(Z)
  expect_gt(s$lambda, 0.5) # pure noise: mostly the identity
  f <- stats::rnorm(500)
  Z2 <- outer(f, rep(1, 10)) + matrix(stats::rnorm(5000, sd = 0.5), 500)
  s2 <- shrink_correlation(Z2)
  expect_lt(s2$lambda, 0.05)
  expect_equal(mean(s2$cor[upper.tri(s2$cor)]), 0.8, tolerance = 0.05)
})

test_that("mixture_marginal_quantile() inverts the mixture's CDF", {
  g <- list(weights = c(0.3, 0.7), means = matrix(c(-2, 3), 2), covs = array(c(1, 4), c(1, 1, 2)))
  u <- c(0.01, 0.3, 0.5, 0.9)
  q <- mixture_marginal_quantile(g, 1, u)
  cdf <- 0.3 * stats::pnorm(q, -2, 1) + 0.7 * stats::pnorm(q, 3, 2)
  expect_equal(cdf, u, tolerance = 1e-8)
})

test_that("the mixture guard replaces slivers and unneeded components, and records it", {
  set.seed(5)
  X <- rbind(matrix(stats::rnorm(400), 200), matrix(c(8, 8.01, 8.02, 8, 8.01, 8.03), 3))
  fit <- gmm_fit(X, k = 2)
  expect_lt(min(fit$weights) * nrow(X), 5) # EM found the sliver
  guarded <- guard_mixture(fit, X, "fast")
  expect_length(guarded$weights, 1L)
  expect_match(guarded$guard, "smallest component")
  # two real clusters are kept
  Y <- rbind(matrix(stats::rnorm(400), 200), matrix(stats::rnorm(400, 6), 200))
  kept <- guard_mixture(gmm_fit(Y, k = 2), Y, "fast")
  expect_length(kept$weights, 2L)
  expect_null(kept$guard)
  # and in a model, the guard is a recorded fallback, on by default for the copula
  g <- simulate_grasps(subjects = 10, grasps = 3, seed = 3)
  m <- fit_grasp_model(g, seed = 1, dependence = "copula")
  expect_equal(m$settings$mixture_guard, "bic")
  n_guard <- sum(m$fallbacks$step %in% c("mixture_guard", "warp_mixture_guard"))
  n_single <- sum(vapply(m$gmm, function(x) length(x$weights) == 1L, logical(1)))
  expect_equal(n_guard + isTRUE(length(m$warp$gmm$weights) == 1L) * 0, sum(m$fallbacks$step == "mixture_guard") +
                 sum(m$fallbacks$step == "warp_mixture_guard"))
  expect_true(n_single >= sum(m$fallbacks$step == "mixture_guard"))
  expect_equal(fit_grasp_model(g, seed = 1)$settings$mixture_guard, "none")
  expect_equal(fit_grasp_model(g, seed = 1, mixture_guard = "bic")$settings$mixture_guard, "bic")
  expect_error(fit_grasp_model(g, dependence = "copul"), class = "handmotion_error_bad_input")
})

test_that("generation keeps angles inside the joint limits smoothly when asked", {
  g <- simulate_grasps(subjects = 12, grasps = 1, seed = 3)
  m <- fit_grasp_model(g, seed = 1, dependence = "copula")
  lim <- m$limits[m$limits$enforced, ]
  expect_true(nrow(lim) > 5)
  expect_false("ABD1" %in% lim$dof) # the glove's thumb abduction is not th-mcp's side swing
  inside <- generate(m, n = 300, seed = 1)
  expect_equal(limit_violations(inside, lim)$frames, 0)
  free <- generate(m, n = 300, seed = 1, limits = FALSE)
  # same draws: on the template grid (warp = FALSE), where the map acts,
  # only values near or beyond a limit change
  a <- do.call(rbind, generate(m, n = 300, seed = 1, limits = FALSE, warp = FALSE)$recordings)[, lim$dof]
  b <- do.call(rbind, generate(m, n = 300, seed = 1, warp = FALSE)$recordings)[, lim$dof]
  width <- rep(lim$hi - lim$lo, each = nrow(a))
  lo <- rep(lim$lo, each = nrow(a))
  hi <- rep(lim$hi, each = nrow(a))
  deep <- a > lo + 0.05 * width & a < hi - 0.05 * width
  expect_equal(a[deep], b[deep])
  expect_true(all(b >= lo & b <= hi))
  # no kinks: the second difference of a limited curve is no larger than the
  # free curve's plus what the map's curvature adds
  d2 <- function(x) max(abs(diff(x, differences = 2)))
  expect_lt(max(vapply(inside$recordings, function(r) d2(r[, "PIP3"]), numeric(1))),
            2 * max(vapply(free$recordings, function(r) d2(r[, "PIP3"]), numeric(1))) + 1)
  # the thesis' model generates as before unless asked
  mi <- fit_grasp_model(g, seed = 1)
  expect_identical(generate(mi, n = 5, seed = 3)$recordings,
                   generate(mi, n = 5, seed = 3, limits = FALSE)$recordings)
})

test_that("print, summary and autoplot show the dependence", {
  g <- simulate_grasps(subjects = 8, grasps = 3, seed = 3)
  mc <- fit_grasp_model(g, seed = 1, dependence = "copula")
  mi <- fit_grasp_model(g, seed = 1)
  expect_output(print(mc), "Gaussian copula over 65 scores") # 16 DoFs x 4 FPCs + 1 warp FPC
  expect_output(print(mi), "independent DoFs")
  expect_output(print(summary(mc)), "copula")
  p <- ggplot2::autoplot(mc, type = "dependence")
  expect_s3_class(p, "ggplot")
  expect_equal(nrow(p$data), 16 * 16)
  expect_true(any(abs(p$data$r[p$data$a != p$data$b]) > 0.2))
  expect_true(all(ggplot2::autoplot(mi, type = "dependence")$data$r %in% c(0, 1)))
  ms <- fit_grasp_models(g, seed = 1, dependence = "copula")
  expect_equal(summary(ms)$dependence, "copula")
  expect_output(print(ms), "copula \\(1 type\\)")
})

test_that("interpolate_columns() is approx() column by column", {
  z <- seq(-5, 5, length.out = 41)
  Q <- cbind(z^3, exp(z / 3), -z)
  set.seed(9)
  Z <- matrix(stats::rnorm(60, sd = 3), 20, 3)
  want <- vapply(1:3, function(a) stats::approx(z, Q[, a], xout = Z[, a], rule = 2)$y, numeric(20))
  expect_equal(interpolate_columns(z, Q, Z), want)
})

test_that("the native copula draw is its R transcription, from the same RNG stream", {
  g <- simulate_grasps(subjects = 12, grasps = 3, objects = 2, trials = 2, seed = 4)
  m <- fit_grasp_model(g, seed = 1, dependence = "copula")
  cop <- m$dependence$copula
  set.seed(11)
  native <- .Call(hm_copula_draw, 500L, cop$root, cop$z, cop$quantiles)
  after_native <- stats::runif(1)
  set.seed(11)
  ref <- copula_draw_reference(500L, cop$root, cop$z, cop$quantiles)
  expect_equal(native, ref, tolerance = 1e-12)
  expect_identical(stats::runif(1), after_native) # the same number of normals drawn
  # a singular correlation (eigen root, not triangular) is drawn the same way
  R <- matrix(1, 3, 3)
  U <- chol_psd(R)
  Q <- cbind(cop$quantiles[, 1:3])
  set.seed(2)
  a <- .Call(hm_copula_draw, 50L, U, cop$z, Q)
  set.seed(2)
  expect_equal(a, copula_draw_reference(50L, U, cop$z, Q), tolerance = 1e-12)
  expect_error(.Call(hm_copula_draw, 5L, U, cop$z, Q[, 1:2]), "quantiles")
  expect_error(.Call(hm_copula_draw, -1L, U, cop$z, Q), "count")
})
