# An R transcription of the native generation kernel (src/generate-kernel.c),
# operation for operation and in the same RNG order, kept only to test the
# kernel against: generate_reference(model, n, seed, warp) returns the grasps
# object generate() would, built by R arithmetic.

generate_reference <- function(model, n, seed, warp = TRUE) {
  models <- if (inherits(model, "grasp_models")) model$models else list(model)
  with_seed(seed, assemble_generated(models, lapply(models, draw_batch_reference, n = n, warp = warp)))
}

# Draw the scores of a batch: alpha (n x p x ncomp) and beta (n x warp_ncomp),
# every DoF's mixture sampled at once from the model's precomputed sampler.
sample_scores <- function(model, n) {
  smp <- model$sampler %||% build_sampler(model)
  alpha <- sample_mixtures(smp$dofs, n)
  dimnames(alpha) <- list(NULL, model$dofs, paste0("FPC", seq_len(model$settings$ncomp)))
  beta <- matrix(sample_mixtures(smp$warp, n), n)
  list(alpha = alpha, beta = beta)
}

# n draws from each of the p stacked mixtures: an n x p x d array. The
# component of each draw is found from one uniform, the draw is
# mean + root %*% z with z standard normal.
sample_mixtures <- function(smp, n) {
  p <- smp$p
  k <- smp$k
  d <- smp$d
  np <- n * p
  j <- rep(seq_len(p), each = n)
  u <- stats::runif(np)
  z <- rep.int(1L, np)
  if (k > 1L) for (c in seq_len(k - 1L)) z <- z + (u > smp$cumw[j + p * (c - 1L)])
  Z <- matrix(stats::rnorm(np * d), np, d)
  base <- j + p * (z - 1L)                      # index of (dof, component)
  pk <- p * k
  out <- array(0, c(n, p, d))
  for (a in seq_len(d)) {
    v <- smp$mu[base + pk * (a - 1L)]
    for (b in seq_len(d)) v <- v + smp$root[base + pk * (a - 1L) + pk * d * (b - 1L)] * Z[, b]
    out[, , a] <- v
  }
  out
}

# Curves on the template grid for a batch: an (L * n) x p matrix, draw-major
# (rows (d - 1) * L + 1:L belong to draw d).
build_curves <- function(model, alpha) {
  n <- dim(alpha)[1]
  p <- dim(alpha)[2]
  L <- model$target_length
  B <- model_basis(model)
  out <- matrix(0, L * n, p, dimnames = list(NULL, model$dofs))
  for (j in seq_len(p)) {
    P <- matrix(B$components[, j, ], L)              # L x k
    a <- matrix(alpha[, j, ], n)                       # n x k
    # L x n: each column one draw's curve; column-major order = draw-major rows.
    out[, j] <- as.vector(P %*% t(a) + B$mean[, j])
  }
  out
}

# Warping functions of a batch (n x L, original frame of each template
# frame): monotone, starting at frame 1.
build_warps <- function(model, beta) {
  n <- nrow(beta)
  W <- matrix(warp_basis(model)$mean, n, length(warp_basis(model)$mean), byrow = TRUE) +
    beta %*% t(warp_basis(model)$components)
  W[W < 1] <- 1
  W[, 1] <- 1
  # cummax along rows, vectorised over draws: running max column by column.
  if (ncol(W) > 1L) for (c in 2:ncol(W)) W[, c] <- pmax(W[, c], W[, c - 1L])
  W
}

# Map the curves of a batch back to original time (R reference of the
# kernel's step 3b). For draw d with warp w_d, original frame t takes the
# template time s where w_d(s) = t: the template interval is the last
# template frame j with w_d(j) <= t (warps are monotone, so a count),
# clamped to 1..L-1; past w_d(L) the last frame's value; a flat interval
# takes its left end.
unwarp_batch <- function(curves, W, n_new) {
  n <- nrow(W)
  L <- ncol(W)
  draw <- rep.int(seq_len(n), n_new)
  t_orig <- sequence(n_new)
  j <- rowSums(W[draw, , drop = FALSE] <= t_orig)
  at_end <- j >= L
  j <- pmin(pmax(j, 1L), L - 1L)
  lo <- W[cbind(draw, j)]
  span <- W[cbind(draw, j + 1L)] - lo
  f <- ifelse(span > 0, (t_orig - lo) / span, 0)
  f <- pmin(pmax(f, 0), 1)
  f[at_end] <- 1
  rows <- (draw - 1L) * L + j
  curves[rows, , drop = FALSE] * (1 - f) + curves[rows + 1L, , drop = FALSE] * f
}

# The raw draws of one batch, as draw_batch() returns them.
draw_batch_reference <- function(model, n, warp = TRUE) {
  sc <- sample_scores(model, n)
  L <- model$target_length
  curves <- build_curves(model, sc$alpha)
  if (warp) {
    W <- build_warps(model, sc$beta)
    n_new <- pmax(2L, as.integer(round(W[, L])))
    recs <- split_rows(unwarp_batch(curves, W, n_new), n_new)
  } else {
    n_new <- rep.int(as.integer(L), n)
    recs <- split_rows(curves, n_new)
  }
  list(recordings = recs, n_frames = n_new, beta = sc$beta, alpha = unname(sc$alpha))
}
