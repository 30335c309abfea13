# R transcription of the copula draw's native pass (src/copula-draw.c), to
# check it: normals in rnorm()'s order, times the root, through each
# column's tabulated quantile function.
# Linear interpolation of every column of Z in its own column of the table
# Q on the common, evenly spaced grid `z` (ends held beyond it), all at once:
# stats::approx() per column costs more than the draw itself for one grasp.
interpolate_columns <- function(z, Q, Z) {
  G <- length(z)
  h <- (z[G] - z[1]) / (G - 1)
  # plain vector operations: pmin()/pmax() on a matrix cost more than the rest
  pos <- (as.vector(Z) - z[1]) / h
  pos[pos < 0] <- 0
  pos[pos > G - 1] <- G - 1
  lo <- floor(pos)
  lo[lo > G - 2] <- G - 2
  f <- pos - lo
  base <- lo + (1 + rep.int((seq_len(ncol(Z)) - 1L) * G, rep.int(nrow(Z), ncol(Z))))
  V <- Q[base] * (1 - f) + Q[base + 1] * f
  dim(V) <- dim(Z)
  V
}

copula_draw_reference <- function(n, root, z, Q) {
  Z <- matrix(stats::rnorm(n * ncol(root)), n, ncol(root)) %*% root
  interpolate_columns(z, Q, Z)
}

# evaluate_generation()'s MMD test as it was written before issue 36: the
# three kernel sums of every permutation by indexing K. The quadratic-form
# version must give the same statistic and p-value.
mmd_test_reference <- function(X, Y, bandwidth, permutations = 200L) {
  n <- nrow(X)
  m <- nrow(Y)
  K <- exp(-as.matrix(stats::dist(rbind(X, Y)))^2 / (2 * bandwidth^2))
  stat <- function(i) {
    a <- i[seq_len(n)]
    b <- i[n + seq_len(m)]
    Kaa <- K[a, a]
    Kbb <- K[b, b]
    (sum(Kaa) - sum(diag(Kaa))) / (n * (n - 1)) + (sum(Kbb) - sum(diag(Kbb))) / (m * (m - 1)) -
      2 * mean(K[a, b])
  }
  obs <- stat(seq_len(n + m))
  perm <- vapply(seq_len(permutations), function(k) stat(sample.int(n + m)), numeric(1))
  list(mmd = obs, p = (1 + sum(perm >= obs)) / (1 + permutations))
}

# evaluate_generation()'s velocity correlation and log jerk as written
# before issue 36 (one recording at a time); the stacked versions must agree.
velocity_correlation_reference <- function(x) {
  p <- length(x$dofs)
  acc <- matrix(0, p, p)
  cnt <- matrix(0, p, p)
  at <- seq(0, 1, by = 0.1)
  for (r in x$recordings) {
    if (nrow(r) < 4L) next
    pos <- 1 + at * (nrow(r) - 1)
    lo <- floor(pos)
    w <- pos - lo
    prof <- r[lo, , drop = FALSE] * (1 - w) + r[pmin(lo + 1L, nrow(r)), , drop = FALSE] * w
    C <- suppressWarnings(stats::cor(diff(prof)))
    ok <- is.finite(C)
    acc[ok] <- acc[ok] + C[ok]
    cnt <- cnt + ok
  }
  out <- acc / cnt
  dimnames(out) <- list(x$dofs, x$dofs)
  out
}

log_jerk_reference <- function(x) {
  vapply(x$recordings, function(r) {
    if (nrow(r) < 5L) return(NA_real_)
    j <- diff(r, differences = 3) * x$rate^3
    log10(mean(j^2))
  }, numeric(1))
}
