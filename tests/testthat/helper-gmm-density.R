# The log-likelihood of a fitted mixture and draws from it (tests only: the
# package's fits compute their log-likelihood inside the EM, generate() draws
# scores through its own sampler).

gmm_loglik <- function(fit, X) {
  call <- rlang::caller_env()
  check_gmm_fit(fit, call)
  X <- gmm_points(fit, X, call)
  gmm_loglik_params(fit$weights, fit$means, fit$covs, X)
}

# Draw from a Gaussian mixture
#
# Picks a component for each draw with the mixture weights, then draws from
# that component's Gaussian (through a symmetric square root of its
# covariance, so singular fallback covariances and point masses work too).
# Uses the random number generator: set a seed first for reproducible draws.
#
# @param fit A `gmm_fit()` object.
# @param n Number of draws.
# @return An `n x d` matrix.
# @examples
# X <- rbind(matrix(rnorm(100), 50), matrix(rnorm(100, mean = 4), 50))
# fit <- gmm_fit(X)
# set.seed(1)
# gmm_sample(fit, 5)
gmm_sample <- function(fit, n) {
  call <- rlang::caller_env()
  check_gmm_fit(fit, call)
  if (!is.numeric(n) || length(n) != 1L || is.na(n) || n < 0 || n != round(n)) {
    hm_abort("{.arg n} must be a non-negative whole number, not {.val {n}}.", "bad_input",
             argument = "n", call = call)
  }
  k <- length(fit$weights)
  d <- ncol(fit$means)
  comp <- if (k == 1L) rep(1L, n) else sample.int(k, n, replace = TRUE, prob = fit$weights)
  Z <- matrix(stats::rnorm(n * d), n, d)
  out <- matrix(0, n, d, dimnames = list(NULL, colnames(fit$means)))
  for (j in seq_len(k)) {
    rows <- which(comp == j)
    if (length(rows) == 0L) next
    e <- eigen(as.matrix(fit$covs[, , j]), symmetric = TRUE)
    root <- e$vectors %*% (sqrt(pmax(e$values, 0)) * t(e$vectors))
    out[rows, ] <- Z[rows, , drop = FALSE] %*% root + rep(fit$means[j, ], each = length(rows))
  }
  out
}
