# Dependence between DoFs: a Gaussian kernel density on the joint score vector.
#
# A grasp type is recorded on a few objects, so the training recordings'
# joint vectors of FPC scores (all DoFs) and warp scores fall in clusters,
# one per object (or way of holding it). A Gaussian copula joins the
# marginals by one correlation matrix and so blurs the clusters into one
# ellipsoid; on flexglove (8 types, 3 objects each) that costs most of the
# copula model's MMD gap to real recordings. The kernel model draws the
# joint vector from a smoothed bootstrap of the training recordings
# (Silverman 1986, section 6.4): pick a training recording's score vector
# at random, add Gaussian noise of covariance h^2 S, with S the scores'
# covariance shrunk towards its diagonal (Schafer and Strimmer 2005, the
# copula's rule) so it is invertible with 25-65 scores and 40-270
# recordings; the draw is shrunk towards the mean so its covariance stays the
# scores' own (draw_kernel_vectors()). The bandwidth h is chosen on the training scores alone, by
# leave-one-out likelihood cross-validation over a grid (Silverman's
# normal-reference rule assumes one Gaussian and oversmooths clusters: with
# d = 25 scores and n = 40 it gives h = 0.82, wider than the clusters).

# The grid the leave-one-out likelihood is maximised over: multiples of the
# scores' (shrunk) covariance root, from far below to above the normal
# reference rule.
kernel_bandwidth_grid <- exp(seq(log(0.05), log(1.5), length.out = 35L))

# The kernel density of one fitted model's scores: list(columns (as the
# copula's), scores (n x D, the training vectors), cor (D x D, the shrunk
# correlation), shrinkage, bandwidth (h), root (upper Cholesky factor of
# h^2 S), loglik (the leave-one-out log likelihood per recording at h), n).
fit_score_kernel <- function(model) {
  cols <- score_columns(model)
  c(list(columns = cols), kernel_density(score_matrix(model, cols)))
}

# The kernel density of the rows of S (n x D): list(scores, cor, shrinkage,
# bandwidth, root, loglik, n).
kernel_density <- function(S) {
  n <- nrow(S)
  D <- ncol(S)
  if (D == 0L) {
    return(list(scores = S, cor = diag(0), shrinkage = 0, bandwidth = NA_real_,
                root = matrix(0, 0, 0), loglik = NA_real_, n = n))
  }
  sd <- if (n > 1L) apply(S, 2, stats::sd) else rep(0, D)
  # a score without spread (one recording, or identical ones) gets no noise
  # and does not enter the metric
  live <- is.finite(sd) & sd > 0
  shrunk <- shrink_correlation(S[, live, drop = FALSE])
  R <- diag(D)
  R[live, live] <- shrunk$cor
  dimnames(R) <- list(colnames(S), colnames(S))
  bw <- kernel_bandwidth(S[, live, drop = FALSE], shrunk$cor, sd[live])
  Sigma <- matrix(0, D, D)
  Sigma[live, live] <- shrunk$cor * outer(sd[live], sd[live])
  list(scores = S, cor = R, shrinkage = shrunk$lambda, bandwidth = bw$h,
       root = bw$h * chol_psd(Sigma), loglik = bw$loglik, n = n)
}

# The bandwidth h of the kernel N(0, h^2 S) that maximises the leave-one-out
# log likelihood of the training vectors X (n x d) under the kernel density
# of the others (S = R scaled by sd). The Mahalanobis distances are computed
# once; each h on the grid then costs one n x n log-sum-exp. With fewer than
# 3 recordings there is nothing to cross-validate: the normal reference
# rule (Silverman's for d dimensions) is taken.
#
# Above `max_n` recordings the cross-validation runs on `max_n` of them,
# evenly spread (deterministic), and the h found is carried to all n by the
# kernel estimator's rate, h ~ n^(-1/(d + 4)): the n x n distances cost
# O(n^2) per grid point, 7 million of them for a type of ten times the
# default data (2,700 recordings), where 500 give the bandwidth to within
# the grid's step (sets of up to 500 recordings, the default data and
# flexglove among them, are cross-validated whole, as before).
kernel_bandwidth_max_n <- 500L
kernel_bandwidth <- function(X, R, sd, grid = kernel_bandwidth_grid, max_n = kernel_bandwidth_max_n) {
  n <- nrow(X)
  d <- ncol(X)
  silverman <- (4 / (d + 2))^(1 / (d + 4)) * n^(-1 / (d + 4))
  if (n < 3L || d == 0L) return(list(h = silverman, loglik = NA_real_, rule = "silverman"))
  if (n > max_n) {
    sub <- kernel_bandwidth(X[evenly_spread(n, max_n), , drop = FALSE], R, sd, grid, max_n)
    return(list(h = sub$h * (max_n / n)^(1 / (d + 4)), loglik = sub$loglik, rule = "loo_likelihood_subsample"))
  }
  # whitened vectors: Mahalanobis distance under S is Euclidean here
  Y <- (X - rep(colMeans(X), each = n)) / rep(sd, each = n)
  Y <- Y %*% solve(chol_psd(R))
  sq <- rowSums(Y^2)
  D2 <- pmax(outer(sq, sq, `+`) - 2 * tcrossprod(Y), 0)
  diag(D2) <- Inf
  logdet <- sum(log(sd^2)) + determinant(R, logarithm = TRUE)$modulus[[1]]
  # per vector and h, the log-sum-exp of -D2 / (2 h^2) over the others
  # (src/kernel-loo.c: the n x n matrices per grid point in R were a third
  # of fitting ten times the default data)
  lse <- .Call(hm_kernel_loo_lse, D2, as.double(grid))
  ll <- vapply(seq_along(grid), function(k) {
    h <- grid[k]
    mean(lse[, k] - log(n - 1) - d * log(h) - 0.5 * d * log(2 * pi) - 0.5 * logdet)
  }, numeric(1))
  best <- which.max(ll)
  list(h = grid[best], loglik = ll[best], rule = "loo_likelihood")
}

# n draws of the joint score matrix (n x D) from a kernel model, from the
# current RNG stream: a training vector at random plus N(0, h^2 S) noise,
# shrunk towards the training mean by 1 / sqrt(1 + h^2) (Silverman 1986,
# section 6.4.1), so the draws keep the scores' covariance instead of
# inflating it by 1 + h^2 (half as much again at h = 0.7: on the simulated
# data the plain smoothed bootstrap's MMD was 1.6 times real-vs-real).
draw_kernel_vectors <- function(kern, n) {
  D <- ncol(kern$scores)
  pick <- sample.int(nrow(kern$scores), n, replace = TRUE)
  m <- colMeans(kern$scores)
  X <- kern$scores[pick, , drop = FALSE] - rep(m, each = n)
  rep(m, each = n) + (X + rnorm_matrix(n, D) %*% kern$root) / sqrt(1 + kern$bandwidth^2)
}
