# R transcriptions of the compiled EM and k-means (src/gmm-em.c), the tests'
# references: gmm_em_batch_r() against gmm_em_batch() (hm_gmm_em), and
# gmm_kmeans() against gmm_kmeans_all() (hm_gmm_kmeans). Not production code:
# the package runs the compiled versions only (bench/bench-gmm.R sources this
# file to time them against each other).

# A few Lloyd iterations from given centres.
gmm_kmeans <- function(Y, centres, iters = 10L) {
  lab <- integer(nrow(Y))
  for (i in seq_len(iters)) {
    dist <- -2 * Y %*% t(centres) + rep(rowSums(centres^2), each = nrow(Y))
    new <- max.col(-dist, ties.method = "first")
    if (identical(new, lab)) break
    lab <- new
    for (g in unique(lab)) centres[g, ] <- colMeans(Y[lab == g, , drop = FALSE])
  }
  lab
}


# The R version of the batch EM (the compiled one, gmm_em_batch(), step for
# step). The starts are columns of one matrix, so every EM evaluation costs one matrix product
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

# d > 2: a loop over the components, through chol() and chol2inv().
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
