# The shrinkage LDA and the early recogniser's prefix arrays as written
# before issue 36: residuals and their cross product on the rows themselves
# (the fit now works from moments that add over folds), and every recording's
# first H frames in an n x H x p array. The new paths must agree with them.
# The shrinkage of the residuals' correlation is the package's
# shrink_correlation(), which works on the rows themselves as the old fit did
# and is checked pair by pair against Schafer and Strimmer's definition in
# test-dependence.R; a copy of it here would only repeat that check.
fit_shrunk_lda_reference <- function(F, y, prior = c("equal", "data")) {
  prior <- match.arg(prior)
  y <- droplevels(as.factor(y))
  n <- nrow(F)
  K <- nlevels(y)
  counts <- tabulate(y, K)
  means <- rowsum(F, y, reorder = TRUE) / counts
  R <- F - means[as.integer(y), , drop = FALSE]
  sd <- sqrt(colSums(R^2) / max(n - K, 1))
  sd[!is.finite(sd) | sd < 1e-8 * max(sd, 1e-300)] <- 1
  sh <- handmotion:::shrink_correlation(sweep(R, 2, sd, "/"))
  proj <- sweep(handmotion:::inverse_root(sh$cor), 1, sd, "/")
  centres <- means %*% proj
  log_prior <- if (prior == "equal") rep(-log(K), K) else log(counts / n)
  list(classes = levels(y), coef = proj %*% t(centres),
       offset = log_prior - rowSums(centres^2) / 2, log_prior = log_prior,
       shrinkage = sh$lambda, n = counts, features = colnames(F))
}

prefix_arrays_reference <- function(x, H) {
  n <- length(x$recordings)
  p <- length(x$dofs)
  A <- array(0, c(n, H, p))
  for (i in seq_len(n)) {
    r <- x$recordings[[i]]
    A[i, , ] <- r[pmin(seq_len(H), nrow(r)), , drop = FALSE]
  }
  C <- array(0, c(n, H, p))
  if (H > 1L) {
    steps <- abs(A[, -1L, , drop = FALSE] - A[, -H, , drop = FALSE])
    for (t in 2:H) C[, t, ] <- C[, t - 1L, ] + steps[, t - 1L, ]
  }
  list(frames = A, travel = C)
}

prefix_features_reference <- function(prefix, h, at) {
  A <- prefix$frames
  n <- dim(A)[1]
  ix <- handmotion:::fraction_index(h, at)
  P <- A[, ix$lo, , drop = FALSE] * rep(1 - ix$w, each = n) + A[, ix$hi, , drop = FALSE] * rep(ix$w, each = n)
  dim(P) <- c(n, length(at) * dim(A)[3])
  cbind(P, log1p(matrix(prefix$travel[, h, ], n)))
}
