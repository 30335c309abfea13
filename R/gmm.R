# Gaussian mixture models fitted by EM (thesis sections 4.1.4 and 5.1.4): a
# bivariate two-component mixture per DoF on the FPC scores, a univariate one
# on the warp scores.
#
# Two engines:
# * "reference": mixtools::mvnormalmixEM (d >= 2) / mixtools::normalmixEM
#   (d = 1), the package of the thesis; random starting values (seeded by
#   `seed`) and seconds per fit;
# * "fast": our EM (compiled for d = 1 and 2, src/gmm-em.c; the R version
#   below for d > 2; the tests check the two against each other),
#   vectorised over observations. One matrix product gives
#   the sufficient statistics of every component (M-step) and one gives all
#   log-densities (E-step), because a Gaussian log-density is linear in the
#   monomials 1, x_a, x_a x_b. Several starts (principal-axis splits, k-means
#   from spread-out and from random centres) run side by side as columns of
#   one matrix, each to convergence, and the best is kept, so the fast engine
#   reaches at least the log-likelihood of a single random-start run. EM is
#   accelerated by SQUAREM (Varadhan & Roland 2008): on the overlapping score
#   clouds of the grasp models plain EM crawls (hundreds to thousands of
#   iterations, more the more points), SQUAREM needs about a quarter of the
#   evaluations. Above 1000 points the starts run on an evenly spread
#   subsample of 1000 and only the best is refined on all points, so the
#   starts' cost stops growing with n.
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
#' all points (`iterations` are the refinement's). For `d` = 1 and 2 the EM runs in
#' compiled code (src/gmm-em.c), which reproduces the R implementation still
#' used for `d` > 2. It is deterministic and leaves the global random number
#' generator as it was.
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
#' @seealso `gmm_sample()`, `gmm_density()`, `gmm_loglik()`.
#' @noRd
#' @examples
#' X <- rbind(matrix(rnorm(100), 50), matrix(rnorm(100, mean = 4), 50))
#' fit <- gmm_fit(X, k = 2)
#' fit
#' gmm_sample(fit, 3)
gmm_fit <- function(X, k = 2, engine = c("fast", "reference"), max_iter = 500, tol = NULL,
                    seed = NULL) {
  call <- rlang::caller_env()
  engine <- check_choice(engine, arg = "engine", call = rlang::current_env())
  X <- as_numeric_matrix(X, "X", " (one observation per row)", call = call)
  k <- check_whole(k, "k", max = max(1L, nrow(X)), call = call)
  max_iter <- check_whole(max_iter, "max_iter", call = call)
  tol <- tol %||% gmm_default_tol[[engine]]
  if (!is.numeric(tol) || length(tol) != 1L || !is.finite(tol) || tol <= 0) {
    hm_abort("{.arg tol} must be a positive number, not {.val {tol}}.", "bad_input",
             argument = "tol", call = call)
  }
  n <- nrow(X)
  d <- ncol(X)
  if (k == 1L && n >= 2L) {
    # One component has a closed-form maximum-likelihood fit: no EM to fail.
    S <- stats::cov(X) * (n - 1) / n
    return(gmm_new(1, matrix(colMeans(X), 1L), array(S, c(d, d, 1L)), X, iterations = 0L,
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
  fit <- gmm_new(cand$weights[ord], cand$means[ord, , drop = FALSE],
                 cand$covs[, , ord, drop = FALSE], X, iterations = as.integer(cand$iterations),
                 converged = TRUE, fallback = FALSE, reason = NA_character_, engine = engine)
  # (the last failure test, on the log-likelihood gmm_new() computed anyway)
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
    return(sprintf("too few points (%d) for %d components with full covariances in %d dimension%s",
                   n, k, d, if (d == 1) "" else "s"))
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

gmm_new <- function(weights, means, covs, X, iterations, converged, fallback, reason, engine) {
  d <- ncol(X)
  k <- length(weights)
  cn <- colnames(X)
  means <- matrix(means, k, d, dimnames = list(NULL, cn))
  covs <- array(covs, c(d, d, k), dimnames = list(cn, cn, NULL))
  new_gmm_fit(weights, means, covs, loglik = gmm_loglik_params(weights, means, covs, X),
              iterations = iterations, converged = converged, fallback = fallback,
              reason = reason, engine = engine, n = nrow(X))
}

# The one constructor of class "gmm_fit" (the EM result, its fallbacks, and
# the point mass of a constant DoF all go through it).
new_gmm_fit <- function(weights, means, covs, loglik, iterations, converged, fallback, reason,
                        engine, n, point_mass = FALSE) {
  validate_gmm_fit(structure(
    list(weights = as.numeric(weights), means = means, covs = covs, loglik = loglik,
         iterations = as.integer(iterations), converged = converged, fallback = fallback,
         reason = reason, engine = engine, n = n, colnames = colnames(means),
         point_mass = point_mass),
    class = "gmm_fit"))
}

validate_gmm_fit <- function(x) {
  k <- length(x$weights)
  d <- ncol(x$means)
  stopifnot(k >= 1L, nrow(x$means) == k, identical(dim(x$covs), c(d, d, k)),
            all(x$weights >= 0), abs(sum(x$weights) - 1) < 1e-8)
  x
}

# The thesis' fallback: one Gaussian with the sample mean and covariance.
gmm_fallback <- function(X, reason, engine, iterations) {
  d <- ncol(X)
  S <- if (nrow(X) >= 2L) stats::cov(X) else matrix(0, d, d)
  gmm_new(1, matrix(colMeans(X), 1L), array(S, c(d, d, 1L)), X,
          iterations = if (length(iterations) == 1L) iterations else NA_integer_,
          converged = FALSE, fallback = TRUE, reason = reason, engine = engine)
}

# ---- reference engine: mixtools ------------------------------------------

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

# ---- fast engine -----------------------------------------------------------

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
    sub <- unique(round(seq(1, n, length.out = gmm_start_points)))
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

gmm_unmap <- function(labels, k) {
  z <- matrix(0, length(labels), k)
  z[cbind(seq_along(labels), labels)] <- 1
  z
}

# EM from several starting partitions at once: the compiled EM
# (src/gmm-em.c) for d = 1 and d = 2 (the thesis' warp scores and FPC score
# pairs, every fit of the default model), the R version below for more
# dimensions (ncomp > 2); tests compare the two on d <= 2.
# Returns one result per start: the last parameters, log-likelihood (of the
# standardised data), iterations and convergence, or `failed` with a reason.
gmm_em_batch <- function(design, starts, k, max_iter, tol, logdet0) {
  if (design$d <= 2L) {
    gmm_em_batch_c(design, starts, k, max_iter, tol, logdet0)
  } else {
    gmm_em_batch_r(design, starts, k, max_iter, tol, logdet0)
  }
}

gmm_em_batch_c <- function(design, starts, k, max_iter, tol, logdet0) {
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

# The R version of the batch EM (the compiled one step for step). The starts
# are columns of one matrix, so every EM evaluation costs one matrix product
# for all starts' M-steps and one for their E-steps. Columns of the state:
# start-major blocks of k (for k = 2 one column per start: the first
# component's statistics). EM is accelerated by SQUAREM (Varadhan & Roland
# 2008, scheme S3, in the space of the sufficient statistics): each cycle
# makes two EM steps s0 -> s1 -> s2, each tested as plain EM (a start stops
# when an EM step raises its log-likelihood by less than `tol`, fails on a
# degenerate component or a non-finite log-likelihood, or reaches
# `max_iter` evaluations); then evaluates the parameters of the extrapolated
# state s0 + 2a r + a^2 v (r = s1 - s0, v = s2 - 2 s1 + s0, a = |r| / |v| in
# [1, step_max]) and moves one EM step past them if they raise the
# log-likelihood to at least that of the second step (step_max then grows
# fourfold when a reached it), to s2 otherwise (step_max shrinks fourfold,
# not below 1). The log-likelihood never decreases, and a start leaves at an
# EM step, as plain EM. Every third cycle, starts whose parameters came
# together merge into the first of them.
gmm_em_batch_r <- function(design, starts, k, max_iter, tol, logdet0) {
  P <- design$P
  d <- design$d
  psum <- colSums(P)
  two <- k == 2L
  kk <- if (two) 1L else k
  n_starts <- length(starts)
  cols <- function(idx) as.vector(outer(seq_len(kk), (idx - 1L) * kk, "+"))
  s0 <- gmm_start_state(design, starts, k)
  s1 <- s2 <- sn <- s0
  W <- matrix(0, k, n_starts)
  MU <- array(0, c(d, k, n_starts))
  SG <- array(0, c(d, d, k, n_starts))
  results <- vector("list", n_starts)
  iters <- integer(n_starts)
  llv <- rep(-Inf, n_starts)
  step_max <- rep(1, n_starts)
  # One EM evaluation of the starts `idx` from their states in `src`: the
  # log-likelihood of the M-step's parameters, those parameters, the first
  # degenerate component (0 if none) and the E-step's statistics.
  em_eval <- function(idx, src) {
    A <- length(idx)
    st <- src[, cols(idx), drop = FALSE]
    # (an extrapolated state may give a component a negative weight: log()
    # of it is NaN, the component degenerate and the extrapolation rejected)
    if (two) {
      m <- suppressWarnings(gmm_mstep(cbind(st, psum - st, deparse.level = 0), design, logdet0))
      comp <- function(q) c(q, A + q)
    } else {
      m <- suppressWarnings(gmm_mstep(st, design, logdet0))
      comp <- function(q) (q - 1L) * k + seq_len(k)
    }
    bad <- vapply(seq_len(A), function(q) {
      b <- which(m$bad[comp(q)])
      if (length(b)) b[1] else 0L
    }, integer(1))
    ok <- bad == 0L
    ll <- rep(NA_real_, A)
    new <- matrix(NA_real_, ncol(P), A * kk)
    if (two) {
      # With the constants folded into the intercept row, P %*% C1 is the log
      # of w1 f1 at every point; the first component's responsibility is a
      # logistic of the difference of the two, and sum(log w1 f1) a dot
      # product with the column sums of P.
      C <- m$C
      C[1L, ] <- C[1L, ] + m$const
      C1 <- C[, seq_len(A), drop = FALSE]
      C2 <- C[, A + seq_len(A), drop = FALSE]
      if (any(ok)) {
        neg <- P %*% (C2[, ok, drop = FALSE] - C1[, ok, drop = FALSE])
        E <- exp(neg)
        if (all(E < Inf)) {
          # log(w1 f1 + w2 f2) = log(w1 f1) + log1p(w2 f2 / (w1 f1))
          ll[ok] <- drop(crossprod(psum, C1[, ok, drop = FALSE])) + .colSums(log1p(E), nrow(E), ncol(E))
          Z <- 1 / (1 + E)
        } else {
          # the same, safe from overflow (plogis is slower)
          ll[ok] <- drop(crossprod(psum, C2[, ok, drop = FALSE])) -
            .colSums(stats::plogis(neg, log.p = TRUE), nrow(E), ncol(E))
          Z <- stats::plogis(neg, lower.tail = FALSE)
        }
        new[, ok] <- crossprod(P, Z)
      }
    } else {
      L <- P %*% m$C + rep(m$const, each = design$n)
      for (q in which(ok)) {
        La <- L[, comp(q), drop = FALSE]
        top <- La[cbind(seq_len(design$n), max.col(La, "first"))]
        lse <- top + log(rowSums(exp(La - top)))
        ll[q] <- sum(lse)
        new[, cols(q)] <- crossprod(P, exp(La - lse))
      }
    }
    params <- lapply(seq_len(A), function(q) {
      j <- comp(q)
      list(w = m$params$weights[j], mu = m$params$mu[, j, drop = FALSE],
           sigma = m$params$sigma[, , j, drop = FALSE])
    })
    list(ll = ll, bad = bad, new = new, params = params)
  }
  keep_params <- function(idx, params) {
    for (q in seq_along(idx)) {
      W[, idx[q]] <<- params[[q]]$w
      MU[, , idx[q]] <<- params[[q]]$mu
      SG[, , , idx[q]] <<- params[[q]]$sigma
    }
  }
  active <- seq_len(n_starts)
  cycle <- 0L
  while (length(active) > 0L) {
    cycle <- cycle + 1L
    for (ph in 1:2) {
      if (!length(active)) break
      ev <- em_eval(active, if (ph == 1L) s0 else s1)
      keep_params(active, ev$params)
      if (ph == 1L) s1[, cols(active)] <- ev$new else s2[, cols(active)] <- ev$new
      iters[active] <- iters[active] + 1L
      failed <- ev$bad > 0L | !is.finite(ev$ll)
      conv <- !failed & (ev$ll - llv[active] < tol)
      llv[active] <- ev$ll
      stop_now <- failed | conv | iters[active] >= max_iter
      for (q in which(stop_now)) {
        a <- active[q]
        results[[a]] <- if (failed[q]) {
          list(failed = gmm_batch_reason(seq_len(k) == ev$bad[q], ev$ll[q]), iterations = iters[a])
        } else {
          list(loglik = ev$ll[q], iterations = iters[a], converged = conv[q], weights = W[, a],
               mu = matrix(MU[, , a], d, k), sigma = array(SG[, , , a], c(d, d, k)))
        }
      }
      active <- active[!stop_now]
    }
    if (length(active) > 1L && cycle %% 3L == 0L) {
      merged <- gmm_merged_starts(W, MU, SG, active)
      for (a in active[merged]) results[[a]] <- list(failed = "merged", iterations = iters[a])
      active <- active[!merged]
    }
    near_cap <- iters[active] + 1L >= max_iter
    for (a in active[near_cap]) s0[, cols(a)] <- s2[, cols(a)]
    ext <- active[!near_cap]
    if (!length(ext)) next
    alpha <- numeric(length(ext))
    for (q in seq_along(ext)) {
      j <- cols(ext[q])
      r <- s1[, j] - s0[, j]
      v <- s2[, j] - 2 * s1[, j] + s0[, j]
      sv2 <- sum(v^2)
      a <- if (sv2 > 0) sqrt(sum(r^2) / sv2) else 1
      if (!(a >= 1)) a <- 1
      alpha[q] <- min(a, step_max[ext[q]])
      sn[, j] <- s0[, j] + 2 * alpha[q] * r + alpha[q]^2 * v
    }
    ev <- em_eval(ext, sn)
    iters[ext] <- iters[ext] + 1L
    at_max <- alpha == step_max[ext]
    accept <- ev$bad == 0L & is.finite(ev$ll) & ev$ll >= llv[ext]
    for (q in seq_along(ext)) {
      a <- ext[q]
      j <- cols(a)
      if (isTRUE(accept[q])) {
        s0[, j] <- ev$new[, (q - 1L) * kk + seq_len(kk)]
        llv[a] <- ev$ll[q]
        if (at_max[q]) step_max[a] <- 4 * step_max[a]
      } else {
        s0[, j] <- s2[, j]
        if (at_max[q] && step_max[a] > 1) step_max[a] <- max(1, step_max[a] / 4)
      }
    }
  }
  results
}

# Which of the starts `idx` sit within 1e-2 (standardised units) of an
# earlier one's weights, means and covariances, components matched by their
# order along the first mean coordinate.
gmm_merged_starts <- function(W, MU, SG, idx) {
  d <- dim(MU)[1]
  k <- dim(MU)[2]
  sig <- do.call(rbind, lapply(idx, function(a) {
    o <- order(MU[1, , a])
    c(W[o, a], matrix(MU[, , a], d, k)[, o], array(SG[, , , a], c(d, d, k))[, , o])
  }))
  A <- length(idx)
  merged <- logical(A)
  for (b in seq_len(A)[-1]) {
    for (a in seq_len(b - 1L)) {
      if (!merged[a] && isTRUE(max(abs(sig[a, ] - sig[b, ])) < 1e-2)) {
        merged[b] <- TRUE
        break
      }
    }
  }
  merged
}

gmm_batch_reason <- function(bad, ll) {
  if (any(bad)) sprintf("degenerate component %d (weight below 1/n or singular covariance)",
                        which(bad)[1])
  else "non-finite log-likelihood"
}

# M-step from the sufficient statistics (crossprod of the monomials with the
# responsibilities), one column per component: the coefficients C (monomials
# x components) and constants of each component's log-density, i.e.
# log w_j + log N(y; mu_j, S_j) = const_j + sum_m C[m, j] * monomial_m(y),
# and `bad`, the components with a weight below 1/n or a covariance below the
# determinant floor (their coefficients are not usable). Vectorised over
# components for d = 1 and d = 2 (the thesis' cases), a loop otherwise.
gmm_mstep <- function(stats, design, logdet0) {
  d <- design$d
  n <- design$n
  nk <- stats[1, ]
  floor <- logdet0 + log(gmm_det_floor)
  if (d == 1L) {
    m <- stats[2, ] / nk
    v <- stats[3, ] / nk - m^2
    logdet <- log(pmax(v, 0))
    C <- rbind(-0.5 * m^2 / v, m / v, -0.5 / v)
    params <- list(weights = nk / n, mu = matrix(m, 1L), sigma = array(v, c(1L, 1L, length(nk))))
  } else if (d == 2L) {
    m1 <- stats[2, ] / nk
    m2 <- stats[3, ] / nk
    s11 <- stats[4, ] / nk - m1^2
    s12 <- stats[5, ] / nk - m1 * m2
    s22 <- stats[6, ] / nk - m2^2
    det <- s11 * s22 - s12^2
    logdet <- log(pmax(det, 0))
    logdet[!(s11 > 0)] <- -Inf
    a11 <- s22 / det
    a12 <- -s12 / det
    a22 <- s11 / det
    am1 <- a11 * m1 + a12 * m2
    am2 <- a12 * m1 + a22 * m2
    C <- rbind(-0.5 * (m1 * am1 + m2 * am2), am1, am2, -0.5 * a11, -a12, -0.5 * a22)
    params <- list(weights = nk / n, mu = rbind(m1, m2, deparse.level = 0),
                   sigma = array(rbind(s11, s12, s12, s22), c(2L, 2L, length(nk))))
  } else {
    return(gmm_mstep_general(stats, design, logdet0))
  }
  bad <- !(nk >= 1) | !(logdet >= floor)
  list(C = C, const = log(nk / n) - 0.5 * d * log(2 * pi) - 0.5 * logdet, params = params,
       bad = bad)
}

gmm_mstep_general <- function(stats, design, logdet0) {
  d <- design$d
  n <- design$n
  k <- ncol(stats)
  pairs <- design$pairs
  sq_idx <- pairs[, 1] + (pairs[, 2] - 1L) * d
  twice <- ifelse(pairs[, 1] == pairs[, 2], 1, 2)
  lower <- lower.tri(diag(d))
  nk <- stats[1, ]
  mu <- stats[1 + seq_len(d), , drop = FALSE] / rep(nk, each = d)
  C <- matrix(0, nrow(stats), k)
  logdet <- rep(-Inf, k)
  sigma <- array(0, c(d, d, k))
  for (j in seq_len(k)) {
    M2 <- matrix(0, d, d)
    M2[sq_idx] <- stats[1L + d + seq_len(nrow(pairs)), j] / nk[j]
    M2[lower] <- t(M2)[lower]
    S <- M2 - tcrossprod(mu[, j])
    sigma[, , j] <- S
    R <- if (nk[j] >= 1) tryCatch(chol(S), error = function(e) NULL) else NULL
    if (is.null(R)) next
    logdet[j] <- 2 * sum(log(diag(R)))
    A <- chol2inv(R)
    Am <- drop(A %*% mu[, j])
    # -0.5 * (y'Ay - 2 m'Ay + m'Am) in the monomial basis
    C[, j] <- -0.5 * c(sum(mu[, j] * Am), -2 * Am, twice * A[sq_idx])
  }
  bad <- !(nk >= 1) | !(logdet >= logdet0 + log(gmm_det_floor))
  list(C = C, const = log(nk / n) - 0.5 * d * log(2 * pi) - 0.5 * logdet,
       params = list(weights = nk / n, mu = mu, sigma = sigma), bad = bad)
}

# Starting partitions: quantile groups along the first and second principal
# axes, k-means seeded along the first axis, and k-means from random centres
# (drawn under `seed`, without disturbing the global RNG). Partitions with a
# group too small for a covariance are dropped.
gmm_starts <- function(Y, k, seed) {
  n <- nrow(Y)
  d <- ncol(Y)
  axes <- eigen(crossprod(Y) / n, symmetric = TRUE)$vectors
  proj <- Y %*% axes
  by_quantile <- function(x) {
    r <- integer(n)
    r[order(x)] <- seq_len(n) # rank(x, ties.method = "first"), faster
    pmin(k, 1L + floor((r - 1) * k / n))
  }
  starts <- list(by_quantile(proj[, 1]))
  if (d >= 2L) starts <- c(starts, list(by_quantile(proj[, 2])))
  r1 <- rank(proj[, 1])
  spread <- vapply(seq_len(k), function(g) which.min(abs(r1 - (g - 0.5) * n / k)), integer(1))
  random <- with_seed(if (is.null(seed)) 1L else seed,
                      lapply(1:4, function(i) sample.int(n, k)))
  centres <- lapply(c(list(spread), random), function(idx) Y[idx, , drop = FALSE])
  by_kmeans <- gmm_kmeans_all(Y, centres)
  starts <- c(starts, by_kmeans[1])
  if (k == 2L) starts <- c(starts, list(gmm_best_split(proj[, 1])))
  starts <- c(starts, by_kmeans[-1])
  big_enough <- vapply(starts, function(lab) {
    length(unique(lab)) == k && min(tabulate(lab, k)) >= d + 1L
  }, logical(1))
  # the same partition under permuted labels is one start
  canonical <- lapply(starts[big_enough], function(lab) match(lab, unique(lab)))
  unique(canonical)
}

# k-means from each of a list of centre matrices (src/gmm-em.c; an R
# transcription in the tests checks it).
gmm_kmeans_all <- function(Y, centres, iters = 10L) {
  lab <- .Call(hm_gmm_kmeans, Y, lapply(centres, function(cen) {
    storage.mode(cen) <- "double"
    cen
  }), as.integer(iters))
  lapply(seq_along(centres), function(s) lab[, s])
}

# The two-group split of a projection with the least within-group sum of
# squares (a one-dimensional 2-means, solved exactly).
gmm_best_split <- function(x) {
  n <- length(x)
  o <- order(x)
  s <- x[o]
  cs <- cumsum(s)
  cs2 <- cumsum(s^2)
  m <- seq_len(n - 1L)
  within <- (cs2[m] - cs[m]^2 / m) + ((cs2[n] - cs2[m]) - (cs[n] - cs[m])^2 / (n - m))
  cut <- which.min(within)
  lab <- integer(n)
  lab[o] <- ifelse(seq_len(n) <= cut, 1L, 2L)
  lab
}

# ---- densities, log-likelihood, sampling ------------------------------------

# Log-density of each row of X under N(mu, S). A singular S (a fallback on
# collinear or identical points, or a point mass) is handled as the density on
# its support: points off the support get -Inf.
gmm_log_dnorm <- function(X, mu, S) {
  d <- ncol(X)
  Xc <- X - rep(mu, each = nrow(X))
  e <- eigen(S, symmetric = TRUE)
  lam <- e$values
  pos <- lam > max(lam, 0) * d * 1e-12 & lam > 0
  Z <- Xc %*% e$vectors
  q <- rowSums(Z[, pos, drop = FALSE]^2 / rep(lam[pos], each = nrow(X)))
  out <- -0.5 * q - 0.5 * sum(log(lam[pos])) - 0.5 * sum(pos) * log(2 * pi)
  if (any(!pos)) {
    size <- max(1, sqrt(max(lam, 0)), abs(mu))
    off <- rowSums(Z[, !pos, drop = FALSE]^2) > (1e-8 * size)^2
    out[off] <- -Inf
  }
  out
}

gmm_log_components <- function(weights, means, covs, X) {
  k <- length(weights)
  L <- matrix(0, nrow(X), k)
  for (j in seq_len(k)) {
    L[, j] <- log(weights[j]) + gmm_log_dnorm(X, means[j, ], as.matrix(covs[, , j]))
  }
  L
}

gmm_log_density <- function(weights, means, covs, X) {
  L <- gmm_log_components(weights, means, covs, X)
  top <- L[, 1L]
  for (j in seq_len(ncol(L))[-1L]) top <- pmax(top, L[, j])
  out <- top + log(rowSums(exp(L - top)))
  out[top == -Inf] <- -Inf
  out
}

gmm_loglik_params <- function(weights, means, covs, X) {
  sum(gmm_log_density(weights, matrix(means, length(weights)), covs, X))
}

check_gmm_fit <- function(fit, call) {
  if (!inherits(fit, "gmm_fit")) {
    hm_abort("{.arg fit} must be a {.cls gmm_fit} object (from {.fn gmm_fit}).", "bad_input",
             argument = "fit", call = call)
  }
  invisible(fit)
}

gmm_points <- function(fit, X, call) {
  d <- ncol(fit$means)
  if (is.numeric(X) && is.null(dim(X))) X <- matrix(X, ncol = d, byrow = TRUE)
  X <- as_numeric_matrix(X, "X", " (one observation per row)", call = call)
  if (ncol(X) != d) {
    hm_abort("{.arg X} must have {d} column{?s}, like the data the mixture was fitted to.",
             "bad_input", argument = "X", call = call)
  }
  X
}

#' Density and log-likelihood of a Gaussian mixture
#'
#' `gmm_density()` evaluates the mixture density at each row of `X`;
#' `gmm_loglik()` sums the log-densities (computed on the log scale, so it
#' stays finite where the density underflows). A component with a singular
#' covariance (a fallback fitted to collinear or identical points) has its
#' density taken on its support, and zero off it.
#'
#' @param fit A `gmm_fit()` object.
#' @param X An `m x d` matrix of points (a vector of length `d` is one point;
#'   for `d = 1` a vector is a set of points).
#' @return `gmm_density()`: a numeric vector of length `m`; `gmm_loglik()`:
#'   a number.
#' @noRd
#' @examples
#' X <- rbind(matrix(rnorm(100), 50), matrix(rnorm(100, mean = 4), 50))
#' fit <- gmm_fit(X)
#' gmm_density(fit, rbind(c(0, 0), c(4, 4), c(2, 2)))
#' gmm_loglik(fit, X)
gmm_density <- function(fit, X) {
  call <- rlang::caller_env()
  check_gmm_fit(fit, call)
  X <- gmm_points(fit, X, call)
  exp(gmm_log_density(fit$weights, fit$means, fit$covs, X))
}

#' @noRd
gmm_loglik <- function(fit, X) {
  call <- rlang::caller_env()
  check_gmm_fit(fit, call)
  X <- gmm_points(fit, X, call)
  gmm_loglik_params(fit$weights, fit$means, fit$covs, X)
}

#' Draw from a Gaussian mixture
#'
#' Picks a component for each draw with the mixture weights, then draws from
#' that component's Gaussian (through a symmetric square root of its
#' covariance, so singular fallback covariances and point masses work too).
#' Uses the random number generator: set a seed first for reproducible draws.
#'
#' @param fit A `gmm_fit()` object.
#' @param n Number of draws.
#' @return An `n x d` matrix.
#' @noRd
#' @examples
#' X <- rbind(matrix(rnorm(100), 50), matrix(rnorm(100, mean = 4), 50))
#' fit <- gmm_fit(X)
#' set.seed(1)
#' gmm_sample(fit, 5)
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

#' @export
print.gmm_fit <- function(x, ...) {
  k <- length(x$weights)
  d <- ncol(x$means)
  cat(sprintf("<gmm_fit> %d component%s in %d dimension%s, n = %s (%s engine)\n", k,
              if (k == 1) "" else "s", d, if (d == 1) "" else "s",
              if (is.null(x$n)) "?" else x$n, x$engine))
  cat(sprintf("  log-likelihood %.4f after %s EM iteration%s%s\n", x$loglik,
              if (is.na(x$iterations)) "?" else x$iterations,
              if (identical(x$iterations, 1L)) "" else "s",
              if (isTRUE(x$converged)) " (converged)" else ""))
  if (isTRUE(x$fallback)) cat("  fallback: single Gaussian -- ", x$reason, "\n", sep = "")
  tab <- data.frame(weight = x$weights, x$means, check.names = FALSE)
  names(tab)[-1] <- paste0("mean_", if (is.null(colnames(x$means))) seq_len(d) else colnames(x$means))
  print(tab, digits = 4, row.names = FALSE)
  invisible(x)
}
