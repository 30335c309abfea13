# Step 5 of a grasp model: the Gaussian mixtures on the FPC scores (the EM
# itself is gmm_fit()), with the guard against slivers and point masses for
# constant DoFs.

# EM iteration cap of the models' mixtures. On strongly overlapping score
# clouds EM crawls: with gmm_fit()'s default of 500 the cap, not a failure,
# caused nearly all single-Gaussian fallbacks of the full default fit
# (fit_grasp_models(simulate_grasps(), seed = 1): 107 DoF and 26 warp
# mixtures at 500, 1 and 2 at 5000). mixtools' own default, which the thesis
# probably used, is 10000; with the compiled EM 5000 costs little, and the
# fallbacks left are real failures.
gmm_model_max_iter <- 5000L

# A mixture on the FPC scores, or a point mass at zero for a constant DoF;
# with guard = "bic", a mixture that does not describe the data (see
# guard_mixture()) is replaced by one Gaussian, its reason in $guard.
fit_mixture <- function(fpca, k, engine, max_iter = gmm_model_max_iter, guard = "none") {
  S <- as.matrix(fpca$scores)
  if (isTRUE(fpca$constant)) return(point_mass_gmm(ncol(S), engine, n = nrow(S)))
  if (is.null(max_iter)) max_iter <- gmm_model_max_iter # settings from before the cap existed
  fit <- gmm_fit(S, k = k, engine = engine, max_iter = max_iter)
  if (identical(guard, "bic")) guard_mixture(fit, S, engine) else fit
}

# The mixture guard (fit_grasp_model(mixture_guard = "bic")): a fit of k > 1
# components is kept only if every component holds at least
# max(2 (d + 1), 5% of n) recordings (its weight times n) and it has a lower
# BIC than one Gaussian; otherwise one Gaussian (the maximum-likelihood fit)
# replaces it, with the reason in $guard. Slivers fitted to two or three
# outlying recordings (the thesis' Figure 5.6) fail the size rule; a second
# component that only bends a unimodal cloud fails BIC.
guard_mixture <- function(fit, S, engine) {
  k <- length(fit$weights)
  if (k < 2L || isTRUE(fit$fallback)) return(fit)
  n <- nrow(S)
  d <- ncol(S)
  one <- gmm_fit(S, k = 1L, engine = engine)
  min_size <- max(2 * (d + 1), 0.05 * n)
  npar <- function(k) (k - 1) + k * d + k * d * (d + 1) / 2
  bic_k <- -2 * fit$loglik + npar(k) * log(n)
  bic_1 <- -2 * one$loglik + npar(1) * log(n)
  reason <- if (min(fit$weights) * n < min_size) {
    sprintf("smallest component holds %.1f recordings (< %.1f)", min(fit$weights) * n, min_size)
  } else if (!is.finite(bic_k) || bic_k >= bic_1) {
    sprintf("BIC prefers one Gaussian (%.1f vs %.1f for %d components)", bic_1, bic_k, k)
  }
  if (is.null(reason)) return(fit)
  one$guard <- reason
  one
}

point_mass_gmm <- function(d, engine, n = NA_integer_) {
  new_gmm_fit(weights = 1, means = matrix(0, 1, d), covs = array(0, c(d, d, 1)),
              loglik = NA_real_, iterations = 0L, converged = FALSE, fallback = TRUE,
              reason = "constant: point mass at zero", engine = engine, n = n, point_mass = TRUE)
}

gmm_reason <- function(fit) {
  r <- fit$reason
  if (is.null(r) || length(r) == 0L || is.na(r[1]) || !nzchar(r[1])) "EM failed" else as.character(r[1])
}
