# Starting points of the fast engine's EM (gmm_best_start()): partitions of
# the standardised points from principal-axis splits and k-means, so that
# several runs race and the best converged one is kept. Deterministic: the
# random k-means centres are drawn under a seed without touching the global
# RNG.

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

