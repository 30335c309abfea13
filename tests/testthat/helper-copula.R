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
