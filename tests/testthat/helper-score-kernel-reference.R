# The FPCA likelihood's score kernel as the R expression wrote it before
# src/kernel-score.c (six m x n temporaries per type): the compiled pass
# must give the same log densities, to the bit.
score_kernel_log_density_reference <- function(kern, scores) {
  S <- vapply(seq_along(kern$dof), function(a) scores[, kern$dof[a], kern$comp[a]], numeric(dim(scores)[1]))
  S <- matrix(S, dim(scores)[1])
  m <- nrow(S)
  Ys <- (S / rep(kern$sd, each = m)) %*% kern$W
  A <- tcrossprod(Ys, kern$Y)
  A <- 2 * A - rep(rowSums(Ys^2), ncol(A))
  A <- A - rep(rowSums(kern$Y^2), each = m)
  A[A > 0] <- 0
  A <- A / (2 * kern$h^2)
  top <- A[cbind(seq_len(m), max.col(A, ties.method = "first"))]
  lse <- top + log(rowSums(exp(A - top)))
  lse - log(nrow(kern$Y)) - 0.5 * kern$logdet - 0.5 * ncol(kern$Y) * log(2 * pi)
}
