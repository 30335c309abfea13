# The fast engine of gmm_fit(): EM from several starts side by side, run by
# the compiled batch EM (src/gmm-em.c, any dimension and number of
# components), and the best converged start kept. An R transcription of the
# batch EM, gmm_em_batch_r() in tests/testthat/helper-gmm-reference.R, is the
# tests' reference only: SQUAREM and the merging of starts live in C alone.
#
# Vectorised over observations: one pass over the points gives the
# sufficient statistics of every component (M-step) and all log-densities
# (E-step), because a Gaussian log-density is linear in the monomials
# 1, y_a, y_a y_b (gmm_design()). EM is accelerated by SQUAREM (Varadhan &
# Roland 2008): on the overlapping score clouds of the grasp models plain EM
# crawls (hundreds to thousands of iterations, more the more points), SQUAREM
# needs about a quarter of the evaluations. Above gmm_start_points points the
# starts run on an evenly spread subsample and only the best is refined on
# all points, so the starts' cost stops growing with n.

# The fast engine's candidate fit of X (weights, means, covariances in the
# data's units, iterations), or the outcome of a failure (an error or no
# convergence) for gmm_failure() to name.
gmm_em_fast <- function(X, k, max_iter, tol, seed) {
  n <- nrow(X)
  d <- ncol(X)
  # Standardise so the expanded quadratic forms stay well conditioned; the
  # log-likelihood only shifts by a constant, so `tol` keeps its meaning.
  # The batch EM stops on the total log-likelihood: `tol` per observation is
  # n * tol on the total.
  centre <- colMeans(X)
  scale <- sqrt(colSums((X - rep(centre, each = n))^2) / n)
  Y <- (X - rep(centre, each = n)) / rep(scale, each = n)
  design <- gmm_design(Y)
  logdet0 <- determinant(crossprod(Y) / n)$modulus[1]
  best <- NULL
  if (n > gmm_start_points) {
    # Many points: the starts race on an evenly spread subsample (their cost
    # no longer grows with n) and the best of them is refined on all points
    # from its responsibilities; should that fail, the starts run on all.
    sub <- evenly_spread(n, gmm_start_points)
    pick <- gmm_best_start(Y[sub, , drop = FALSE], k, max_iter, tol, seed, logdet0)
    if (!is.null(pick$best)) {
      z <- gmm_log_components(pick$best$weights, t(pick$best$mu), pick$best$sigma, Y)
      z <- exp(z - (z[, 1] + log(rowSums(exp(z - z[, 1])))))
      refined <- gmm_em_batch(design, list(z), k, max_iter, n * tol, logdet0)[[1]]
      if (is.null(refined$failed) && refined$converged) best <- refined
    }
  }
  if (is.null(best)) {
    pick <- gmm_best_start(Y, k, max_iter, tol, seed, logdet0, design)
    if (is.null(pick$best)) return(pick$outcome)
    best <- pick$best
  }
  means <- t(best$mu) * rep(scale, each = k) + rep(centre, each = k)
  covs <- array(0, c(d, d, k))
  for (j in seq_len(k)) covs[, , j] <- best$sigma[, , j] * outer(scale, scale)
  list(weights = best$weights, means = means, covs = covs, iterations = best$iterations,
       converged = TRUE, diverged = FALSE)
}

# Above this many points the starts run on a subsample of this many
# (gmm_em_fast()); one grasp type of the default data (about 270 recordings)
# stays below it, so its mixtures see every start on every point.
gmm_start_points <- 1000L

# EM from every starting partition of the standardised points Y (gmm_starts())
# and the best converged run: `best`, or NULL with the fit's `outcome` (an
# error or no convergence) when none converged.
gmm_best_start <- function(Y, k, max_iter, tol, seed, logdet0, design = gmm_design(Y)) {
  d <- ncol(Y)
  starts <- gmm_starts(Y, k, seed)
  if (length(starts) == 0L) {
    return(list(outcome = list(error = sprintf("no starting partition has %d points in every component",
                                               d + 1L), iterations = 0L)))
  }
  tol_total <- nrow(Y) * tol
  runs <- gmm_em_batch(design, starts, k, max_iter, tol_total, logdet0)
  done <- vapply(runs, function(r) is.null(r$failed) && r$converged, logical(1))
  if (!any(done)) {
    alive <- vapply(runs, function(r) is.null(r$failed), logical(1))
    if (!any(alive)) {
      first <- runs[[which(vapply(runs, function(r) r$failed != "merged", logical(1)))[1]]]
      return(list(outcome = list(error = paste("every start failed; the first with", first$failed),
                                 iterations = first$iterations)))
    }
    return(list(outcome = list(converged = FALSE, iterations = runs[[which(alive)[1]]]$iterations)))
  }
  runs <- runs[done]
  # Starts whose log-likelihoods differ by less than the convergence
  # tolerance have met the same optimum (as far as EM can tell): the first of
  # them wins, so rounding (compiled against R EM, one BLAS against another)
  # does not pick a different start.
  lls <- vapply(runs, function(r) r$loglik, numeric(1))
  list(best = runs[[which(lls >= max(lls) - tol_total)[1]]])
}

# The monomials a Gaussian log-density is linear in: 1, y_a, y_a * y_b (a <= b).
gmm_design <- function(Y) {
  d <- ncol(Y)
  pairs <- which(upper.tri(diag(d), diag = TRUE), arr.ind = TRUE)
  pairs <- pairs[order(pairs[, 1], pairs[, 2]), , drop = FALSE]
  P <- cbind(1, Y, Y[, pairs[, 1], drop = FALSE] * Y[, pairs[, 2], drop = FALSE])
  list(P = P, d = d, pairs = pairs, n = nrow(Y))
}

# A partition as responsibilities: one column per component, 1 where the
# point belongs.
gmm_unmap <- function(labels, k) {
  z <- matrix(0, length(labels), k)
  z[cbind(seq_along(labels), labels)] <- 1
  z
}

# EM from several starting partitions (or responsibility matrices) at once,
# in compiled code (src/gmm-em.c: hm_gmm_em, the one production path for
# every d and k; the tests check it against gmm_em_batch_r() for d = 1..4,
# k = 1..3).
# Returns one result per start: the last parameters, log-likelihood (of the
# standardised data), iterations and convergence, or `failed` with a reason
# ("merged" when it joined an earlier start).
gmm_em_batch <- function(design, starts, k, max_iter, tol, logdet0) {
  d <- design$d
  state <- gmm_start_state(design, starts, k)
  r <- .Call(hm_gmm_em, design$P, state, as.integer(k), as.integer(max_iter), as.double(tol),
             as.double(logdet0))
  mu <- array(r$mu, c(d, k, length(starts)))
  sigma <- array(r$sigma, c(d, d, k, length(starts)))
  lapply(seq_along(starts), function(a) {
    switch(r$status[a] + 1L,
      list(loglik = r$loglik[a], iterations = r$iterations[a], converged = r$converged[a],
           weights = r$weights[, a], mu = matrix(mu[, , a], d, k),
           sigma = array(sigma[, , , a], c(d, d, k))),
      list(failed = gmm_batch_reason(seq_len(k) == r$bad[a], r$loglik[a]),
           iterations = r$iterations[a]),
      list(failed = "merged", iterations = r$iterations[a]))
  })
}

# The EM state of each start: the sufficient statistics (crossprod of the
# monomials with the responsibilities), nm x k per start; for k = 2 only the
# first component's (the second's are the column sums of P minus them). A
# start is a partition (labels 1..k) or an n x k matrix of responsibilities.
gmm_start_state <- function(design, starts, k) {
  Z <- do.call(cbind, lapply(starts, function(s) if (is.matrix(s)) s else gmm_unmap(s, k)))
  if (k == 2L) Z <- Z[, seq(1L, 2L * length(starts), by = 2L), drop = FALSE]
  crossprod(design$P, Z)
}

# Why a start failed, from the first degenerate component (bad: one logical
# per component) or a non-finite log-likelihood.
gmm_batch_reason <- function(bad, ll) {
  if (any(bad)) sprintf("degenerate component %d (weight below 1/n or singular covariance)",
                        which(bad)[1])
  else "non-finite log-likelihood"
}
