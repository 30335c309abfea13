# gmm_fit(), the package's one verb for Gaussian mixture models fitted by EM
# (thesis sections 4.1.4 and 5.1.4): a bivariate two-component mixture per
# DoF on the FPC scores, a univariate one on the warp scores (more dimensions
# with ncomp > 2). The argument checks, the data checks before any EM, the
# failure tests after it and the thesis' single-Gaussian fallback live here;
# the engines elsewhere:
# * "fast" (R/gmm-em.R): our EM, compiled for every dimension (src/gmm-em.c),
#   from several starts side by side, accelerated by SQUAREM;
# * "reference" (R/gmm-reference.R): mixtools, the package of the thesis;
#   random starting values (seeded by `seed`) and seconds per fit.
#
# The fast engine stops when an iteration raises the log-likelihood per
# observation (the mean over the n points) by less than `tol`: the total
# log-likelihood grows with n, so an absolute bound tightens as the data grow
# and the iterations with it (at 10x the data, median 374 -> ~2,400 per DoF,
# many at the cap), while the mean's increments do not. The reference engine
# keeps mixtools' rule, `tol` on the total (its `epsilon`). Whatever the engine, a fit that failed
# (error, no convergence within max_iter, a degenerate component, a weight
# below 1/n, a non-finite log-likelihood) is replaced by a single Gaussian with
# the sample mean and covariance, as the thesis did, and the reason recorded.

# Default tolerances: per observation (fast), on the total (mixtools).
gmm_default_tol <- c(fast = 1e-10, reference = 1e-8)

# A component whose covariance determinant is below this fraction of the
# determinant of the data's covariance has collapsed onto a point or a line.
gmm_det_floor <- 1e-8

#' Fit a Gaussian mixture model
#'
#' Fits a `k`-component Gaussian mixture with unrestricted covariances to the
#' rows of `X` by the EM algorithm, as the thesis does on the FPC scores of
#' each DoF (bivariate, 2 components) and on the warp scores (univariate).
#'
#' `engine = "fast"` (default) runs a vectorised EM from several starts side
#' by side (splits along the principal axes, k-means from spread-out centres
#' and from four random centres drawn under `seed`) and keeps the converged
#' run with the highest log-likelihood (the first of the runs within `n * tol`
#' of it, so that rounding does not decide between runs that met the same
#' optimum); `iterations` are that run's. Each run stops when an EM step
#' raises the mean log-likelihood per observation by less than `tol`. EM is
#' accelerated by SQUAREM (Varadhan & Roland 2008, scheme S3, on the
#' sufficient statistics; an extrapolation is kept only when it does not
#' lower the log-likelihood); `iterations` count EM evaluations,
#' extrapolations included. With more than 1000 points the starts run on an
#' evenly spread subsample of 1000 points and the best of them is refined on
#' all points (`iterations` are the refinement's). The EM runs in compiled
#' code (src/gmm-em.c) for every dimension. It is deterministic and leaves
#' the global random number generator as it was.
#' `engine = "reference"` calls [mixtools::mvnormalmixEM()] (d >= 2) or
#' [mixtools::normalmixEM()] (d = 1) with `epsilon = tol` and
#' `maxit = max_iter` (mixtools' rule: `tol` bounds the increase of the total
#' log-likelihood); their random starting values are drawn under `seed`.
#'
#' **Failure and fallback.** When EM fails -- an error (mixtools gives up after
#' repeated singularities), no convergence within `max_iter` iterations, a
#' decreasing log-likelihood, a component with weight below `1/n`, a
#' covariance whose determinant is below `1e-8` times that of the data, a
#' non-finite log-likelihood -- or when the data cannot support `k` full
#' covariances (fewer than `k * (d + 1)` points, or a singular sample
#' covariance: identical or collinear points), the mixture is replaced by a
#' single Gaussian with the sample mean and sample covariance (thesis section
#' 5.1.4), with `fallback = TRUE` and the `reason` recorded.
#'
#' Components are ordered by decreasing weight, ties by the first mean
#' coordinate.
#'
#' @param X An `n x d` numeric matrix (a vector is one column).
#' @param k Number of components.
#' @param engine `"fast"` (default) or `"reference"` (mixtools).
#' @param max_iter Maximum number of EM iterations; a fit still improving by
#'   more than the tolerance after that many falls back to a single Gaussian.
#'   (mixtools' own defaults are 10000 for `mvnormalmixEM()` and 1000 for
#'   `normalmixEM()`; on strongly overlapping score clouds EM can need more
#'   than 500.)
#' @param tol Convergence tolerance: for the fast engine on the increase of
#'   the mean log-likelihood per observation between two iterations; for the
#'   reference engine mixtools' `epsilon`, on the increase of the total
#'   log-likelihood. `NULL` (default): `1e-10` per observation for the fast
#'   engine (the absolute `1e-8` it used before, at the size of one grasp type
#'   of the default data, n about 260: the same fits there, tested) and
#'   mixtools' `1e-8` for the reference engine.
#' @param seed Seed for the reference engine's random starting values
#'   (`NULL`: use the current RNG stream). The fast engine is deterministic;
#'   its random starts use `seed` (default 1) without disturbing the global
#'   RNG.
#' @return An object of class `gmm_fit`: a list with `weights` (length k),
#'   `means` (`k x d`), `covs` (`d x d x k`), `loglik` (of `X` under the fit),
#'   `iterations`, `converged`, `fallback`, `reason` (`NA` unless
#'   `fallback`), `engine`, `n` and `colnames`.
#' @seealso `gmm_density()`.
#' @noRd
#' @examples
#' X <- rbind(matrix(rnorm(100), 50), matrix(rnorm(100, mean = 4), 50))
#' fit <- gmm_fit(X, k = 2)
#' fit
#' gmm_density(fit, X[1:3, ])
gmm_fit <- function(X, k = 2, engine = c("fast", "reference"), max_iter = 500, tol = NULL,
                    seed = NULL) {
  call <- rlang::caller_env()
  engine <- check_choice(engine, arg = "engine", call = rlang::current_env())
  X <- as_numeric_matrix(X, "X", " (one observation per row)", call = call)
  k <- check_whole(k, "k", max = max(1L, nrow(X)), call = call)
  max_iter <- check_whole(max_iter, "max_iter", call = call)
  tol <- tol %||% gmm_default_tol[[engine]]
  tol <- check_number(tol, "tol", min = 0, min_open = TRUE, call = call)
  n <- nrow(X)
  d <- ncol(X)
  if (k == 1L && n >= 2L) {
    # One component has a closed-form maximum-likelihood fit: no EM to fail.
    S <- stats::cov(X) * (n - 1) / n
    return(gmm_result(1, matrix(colMeans(X), 1L), array(S, c(d, d, 1L)), X, iterations = 0L,
                      converged = TRUE, fallback = FALSE, reason = NA_character_, engine = engine))
  }
  reason <- gmm_precheck(X, k)
  if (!is.null(reason)) return(gmm_fallback(X, reason, engine, iterations = 0L))
  cand <- tryCatch(
    switch(engine,
      fast = gmm_em_fast(X, k, max_iter, tol, seed),
      reference = gmm_em_reference(X, k, max_iter, tol, seed)),
    error = function(e) list(error = conditionMessage(e), iterations = NA_integer_))
  reason <- gmm_failure(cand, X, max_iter)
  if (!is.null(reason)) return(gmm_fallback(X, reason, engine, iterations = cand$iterations))
  ord <- order(-round(cand$weights, 12), cand$means[, 1])
  fit <- gmm_result(cand$weights[ord], cand$means[ord, , drop = FALSE],
                    cand$covs[, , ord, drop = FALSE], X, iterations = as.integer(cand$iterations),
                    converged = TRUE, fallback = FALSE, reason = NA_character_, engine = engine)
  # (the last failure test, on the log-likelihood gmm_result() computed anyway)
  if (!is.finite(fit$loglik)) {
    return(gmm_fallback(X, "non-finite log-likelihood", engine, iterations = cand$iterations))
  }
  fit
}

# Reasons the data cannot carry k full-covariance components, before any EM.
gmm_precheck <- function(X, k) {
  n <- nrow(X)
  d <- ncol(X)
  if (n < k * (d + 1L)) {
    return(as.character(cli::pluralize("too few points ({n}) for {as.integer(k)} components with full covariances in {d} dimension{?s}")))
  }
  ev <- eigen(stats::cov(X), symmetric = TRUE, only.values = TRUE)$values
  if (ev[1] <= 0 || ev[d] <= 1e-10 * ev[1]) {
    return(if (ev[1] <= 0) "all points identical (zero sample covariance)"
           else "singular sample covariance (points collinear)")
  }
  NULL
}

# Why a candidate fit is unusable, or NULL.
gmm_failure <- function(cand, X, max_iter) {
  if (!is.null(cand$error)) return(paste("EM failed:", cand$error))
  if (isTRUE(cand$diverged)) return("EM diverged (the log-likelihood decreased)")
  if (!isTRUE(cand$converged)) return(sprintf("EM did not converge within %d iterations", max_iter))
  n <- nrow(X)
  if (any(!is.finite(c(cand$weights, cand$means, cand$covs)))) return("non-finite EM estimates")
  if (any(cand$weights * n < 1)) return("a component's weight fell below 1/n")
  det0 <- det(stats::cov(X) * (n - 1) / n)
  for (j in seq_along(cand$weights)) {
    dj <- det(as.matrix(cand$covs[, , j]))
    if (!is.finite(dj) || dj < gmm_det_floor * det0) {
      return(sprintf("singular covariance in component %d (determinant %.3g of the data's)", j,
                     dj / det0))
    }
  }
  NULL
}

# A fit's result from its parameters and the data: the dimensions named
# after X's columns and the log-likelihood of X, then the one constructor.
gmm_result <- function(weights, means, covs, X, iterations, converged, fallback, reason,
                       engine) {
  d <- ncol(X)
  k <- length(weights)
  cn <- colnames(X)
  means <- matrix(means, k, d, dimnames = list(NULL, cn))
  covs <- array(covs, c(d, d, k), dimnames = list(cn, cn, NULL))
  new_gmm_fit(weights, means, covs, loglik = gmm_loglik_params(weights, means, covs, X),
              iterations = iterations, converged = converged, fallback = fallback,
              reason = reason, engine = engine, n = nrow(X))
}

# The thesis' fallback: one Gaussian with the sample mean and covariance.
gmm_fallback <- function(X, reason, engine, iterations) {
  d <- ncol(X)
  S <- if (nrow(X) >= 2L) stats::cov(X) else matrix(0, d, d)
  gmm_result(1, matrix(colMeans(X), 1L), array(S, c(d, d, 1L)), X,
             iterations = if (length(iterations) == 1L) iterations else NA_integer_,
             converged = FALSE, fallback = TRUE, reason = reason, engine = engine)
}
