# An R transcription of the local regression in src/handover-lwr.c, kept
# only to test the C code against (and to measure it in bench-handover.R).

lwr_predict_r <- function(ref_x, ref_y, query, k, ridge, eps, block = 256L) {
  n <- nrow(query)
  N <- nrow(ref_x)
  d <- ncol(ref_x)
  k <- min(k, N)
  out <- matrix(0, n, ncol(ref_y))
  ref_t <- t(ref_x)
  rsq <- colSums(ref_t^2)
  for (b0 in seq(1L, n, by = block)) {
    rows <- b0:min(n, b0 + block - 1L)
    qb <- query[rows, , drop = FALSE]
    if (k < N) d2 <- rep(rsq, each = length(rows)) - 2 * tcrossprod(qb, ref_x)
    for (ii in seq_along(rows)) {
      q <- qb[ii, ]
      idx <- if (k < N) {
        r <- d2[ii, ]
        which(r <= sort.int(r, partial = k)[k])[seq_len(k)]
      } else seq_len(N)
      xt <- ref_t[, idx, drop = FALSE] - q
      w <- 1 / pmax(sqrt(colSums(xt^2)), eps)
      xw <- xt * rep(w, each = d)
      yk <- ref_y[idx, , drop = FALSE]
      sw <- sum(w)
      sx <- rowSums(xw)
      hy <- drop(crossprod(w, yk))
      sxx <- tcrossprod(xw, xt)
      lam <- ridge * sum(diag(sxx)) / d + 1e-12
      # slopes from the centred normal equations, then the intercept
      a <- sxx - tcrossprod(sx) / sw
      diag(a) <- diag(a) + lam
      beta <- solve(a, xw %*% yk - tcrossprod(sx, hy) / sw)
      out[rows[ii], ] <- (hy - drop(crossprod(sx, beta))) / sw
    }
  }
  out
}
