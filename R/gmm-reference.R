# The reference engine of gmm_fit(engine = "reference"): mixtools, the
# package of the thesis (mvnormalmixEM() for d >= 2, normalmixEM() for d = 1),
# kept as a named engine so that fits can be compared with what the thesis
# used. Random starting values (drawn under `seed`), seconds per fit, and
# mixtools' stopping rule: `tol` bounds the increase of the total
# log-likelihood (its `epsilon`).

gmm_em_reference <- function(X, k, max_iter, tol, seed) {
  d <- ncol(X)
  run <- function() {
    if (d == 1L) {
      mixtools::normalmixEM(X[, 1], k = k, epsilon = tol, maxit = max_iter)
    } else {
      mixtools::mvnormalmixEM(X, k = k, epsilon = tol, maxit = max_iter)
    }
  }
  # mixtools prints its iteration count and restarts with cat(); keep quiet.
  utils::capture.output(res <- with_seed(seed, run()))
  ll_path <- res$all.loglik
  iterations <- length(ll_path) - 1L
  last_step <- if (iterations >= 1L) ll_path[iterations + 1L] - ll_path[iterations] else 0
  if (d == 1L) {
    means <- matrix(res$mu, k, 1L)
    covs <- array(res$sigma^2, c(1L, 1L, k))
  } else {
    means <- do.call(rbind, lapply(res$mu, as.numeric))
    covs <- array(unlist(res$sigma), c(d, d, k))
  }
  list(weights = as.numeric(res$lambda), means = means, covs = covs,
       iterations = iterations,
       converged = iterations < max_iter || last_step <= tol,
       diverged = last_step < -sqrt(.Machine$double.eps) * (1 + abs(res$loglik)))
}

