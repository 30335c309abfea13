# The projection of recordings on a grasp model as R/project.R computed it
# before the native kernel read the recordings in place (issue 36): every
# recording stacked into one matrix, the warp index built by vector
# arithmetic, and the projection itself written out in R (scores with the
# quadrature weights, residual norms with the norm weights). The kernel must
# agree with it to rounding.
project_reference <- function(model, x, time_weights = NULL) {
  L <- model$target_length
  p <- length(model$dofs)
  k <- model$settings$ncomp
  nk <- x$meta$n_frames
  n <- length(nk)
  mat <- do.call(rbind, x$recordings)[, match(model$dofs, x$dofs), drop = FALSE]
  storage.mode(mat) <- "double"
  starts <- cumsum(nk) - nk
  wbar <- handmotion:::warp_basis(model)$mean
  span <- wbar[L] - wbar[1]
  u <- if (is.finite(span) && span > 0) (wbar - wbar[1]) / span else seq(0, 1, length.out = L)
  u <- pmin(pmax(cummax(u), 0), 1)
  times <- 1 + as.vector(outer(u, nk - 1))
  i <- floor(times)
  cap <- rep(pmax(nk - 1L, 1L), each = L)
  i <- pmin(i, cap)
  f <- times - i
  f[rep(nk == 1L, each = L)] <- 0
  start <- rep(starts, each = L)
  rows <- i + start
  nxt <- pmin(rows + 1, start + rep(nk, each = L))
  B <- handmotion:::model_basis(model)
  scores <- array(0, c(n, p, k))
  resid <- matrix(0, n, p)
  warped <- matrix(0, n * L, p)
  for (j in seq_len(p)) {
    w <- model$fpca[[j]]$weights
    nw <- w * (time_weights %||% 1)
    Y <- matrix(mat[rows, j] * (1 - f) + mat[nxt, j] * f, L, n)
    warped[, j] <- as.vector(Y)
    Yc <- Y - B$mean[, j]
    phi <- matrix(B$components[, j, ], L, k)
    a <- t(Yc) %*% (phi * w)
    scores[, j, ] <- a
    R <- Yc - phi %*% t(a)
    resid[, j] <- sqrt(pmax(colSums(R^2 * nw), 0))
  }
  list(scores = scores, residual = resid, distance = sqrt(rowSums(resid^2)), warped = warped)
}
