# Dependence between DoFs: the Gaussian copula over the thesis' mixtures.
#
# The thesis' model (Jeppsson 2017, eq. 2.5) draws every DoF's FPC scores and
# the warp score from their own mixtures, independently, so fingers do not
# move together (its chapter 6). The copula model keeps every marginal the
# thesis fits (each score's distribution is the marginal of its DoF's
# mixture) and joins them by a Gaussian copula: a correlation matrix between
# the normal scores of all FPC scores of all DoFs and the warp scores,
# estimated from ranks (semi-parametric, so outlying recordings do not drive
# it) and shrunk towards the identity by the analytic rule of Schafer and
# Strimmer (2005), as the number of scores (p * ncomp + warp_ncomp = 35 on
# HUST data) is not small against the ~200-270 recordings of a type.
#
# A draw: z ~ N(0, R), u = pnorm(z), each score = its marginal quantile at u.
# The quantile functions are tabulated once at fit time on a grid of normal
# scores, so a draw costs one matrix product and a linear interpolation per
# score column.

# The normal-score grid of the tabulated quantile functions. Beyond +-5 (a
# probability of 3e-7) a draw takes the end of the table.
copula_z_grid <- seq(-5, 5, length.out = 401L)

# The copula of one fitted model's scores: list(columns (data frame of dof,
# comp and whether it is the warp), cor (D x D, shrunk), shrinkage (lambda),
# root (upper Cholesky factor of cor), z (grid) and quantiles (grid x D)).
# Constant DoFs (point masses) carry no column.
fit_score_copula <- function(model) {
  cols <- score_columns(model)
  S <- score_matrix(model, cols)
  n <- nrow(S)
  Z <- apply(S, 2, function(s) stats::qnorm(rank(s, ties.method = "average") / (n + 1)))
  Z <- matrix(Z, n, nrow(cols))
  shrunk <- shrink_correlation(Z)
  q <- vapply(seq_len(nrow(cols)), function(a) {
    g <- if (cols$warp[a]) model$warp$gmm else model$gmm[[cols$dof[a]]]
    mixture_marginal_quantile(g, cols$comp[a], stats::pnorm(copula_z_grid))
  }, numeric(length(copula_z_grid)))
  list(columns = cols, cor = shrunk$cor, shrinkage = shrunk$lambda,
       root = chol_psd(shrunk$cor), z = copula_z_grid,
       quantiles = matrix(q, length(copula_z_grid), nrow(cols)), n = n)
}

# Which scores the copula joins: every FPC of every non-constant DoF, then
# the warp FPCs (if the warps vary).
score_columns <- function(model) {
  k <- model$settings$ncomp
  kw <- model$settings$warp_ncomp
  live <- !vapply(model$fpca, function(f) isTRUE(f$constant), logical(1))
  dofs <- model$dofs[live]
  # (rep(): a model whose every DoF is constant has no columns)
  cols <- data.frame(dof = rep(dofs, each = k), comp = rep(seq_len(k), length(dofs)),
                     warp = rep(FALSE, length(dofs) * k), stringsAsFactors = FALSE)
  if (!isTRUE(model$warp$constant)) {
    cols <- rbind(cols, data.frame(dof = NA_character_, comp = seq_len(kw), warp = TRUE,
                                   stringsAsFactors = FALSE))
  }
  cols$name <- ifelse(cols$warp, paste0("warp.FPC", cols$comp), paste0(cols$dof, ".FPC", cols$comp))
  cols
}

# The training scores as one n x D matrix in the order of `cols`.
score_matrix <- function(model, cols) {
  n <- model$n_used
  S <- matrix(0, n, nrow(cols), dimnames = list(NULL, cols$name))
  for (a in seq_len(nrow(cols))) {
    S[, a] <- if (cols$warp[a]) warp_basis(model)$scores[, cols$comp[a]]
              else model$fpca[[cols$dof[a]]]$scores[, cols$comp[a]]
  }
  S
}

# Correlation of the columns of Z shrunk towards the identity with the
# analytic optimal intensity of Schafer & Strimmer (2005, target D):
# lambda = sum_{i != j} Var(r_ij) / sum_{i != j} r_ij^2, clipped to [0, 1].
shrink_correlation <- function(Z) {
  n <- nrow(Z)
  D <- ncol(Z)
  if (D < 2L) return(list(cor = diag(D), lambda = 0))
  # standardise by hand: scale() costs as much as a cross product here
  X <- Z - rep(colMeans(Z), each = n)
  X <- X / rep(sqrt(colSums(X^2) / (n - 1)), each = n)
  X[!is.finite(X)] <- 0
  R <- crossprod(X) / (n - 1)
  # Var(r_ij) is the empirical variance of the products w_kij = x_ki x_kj:
  # n / (n - 1)^3 (sum_k w_kij^2 - n wbar_ij^2). Only its sum over i != j
  # enters lambda, and sum_ij sum_k x_ki^2 x_kj^2 = sum_k (sum_i x_ki^2)^2, so
  # the one cross product above is all the D x D work (the recogniser fits
  # one of these per horizon).
  X2 <- X^2
  shrink_from_cor(R, sum(rowSums(X2)^2) - sum(X2^2), n)
}

# Schafer and Strimmer's shrinkage of a correlation matrix R of n
# observations towards the identity, given w2_off = sum over i != j of
# sum_k x_ki^2 x_kj^2 for the standardised observations x (the shrinkage LDA
# of R/shrunk-lda.R computes both from moments and one pass over its rows).
shrink_from_cor <- function(R, w2_off, n) {
  off <- row(R) != col(R)
  wbar2_off <- ((n - 1) / n)^2 * sum(R[off]^2)
  var_off <- n / (n - 1)^3 * (w2_off - n * wbar2_off)
  lambda <- var_off / sum(R[off]^2)
  lambda <- min(1, max(0, if (is.finite(lambda)) lambda else 1))
  out <- (1 - lambda) * R
  diag(out) <- 1
  list(cor = out, lambda = lambda)
}

# Upper-triangular factor U with t(U) %*% U = S for a symmetric positive
# semi-definite S (pivot-free Cholesky; an eigen root if S is singular).
chol_psd <- function(S) {
  U <- tryCatch(chol(S), error = function(e) NULL)
  if (!is.null(U)) return(U)
  e <- eigen(S, symmetric = TRUE)
  t(e$vectors %*% diag(sqrt(pmax(e$values, 0)), nrow(S)))
}

# Quantiles of coordinate `a` of a Gaussian mixture (a mixture of normals in
# one dimension) at probabilities u, by bisection on the mixture's CDF, all
# probabilities at once.
mixture_marginal_quantile <- function(g, a, u) {
  w <- g$weights
  m <- g$means[, a]
  s <- sqrt(pmax(g$covs[a, a, ], 0))
  if (all(s == 0)) return(rep(sum(w * m), length(u)))
  live <- w > 0
  if (sum(live) == 1L) return(m[live] + s[live] * stats::qnorm(u)) # one Gaussian: exact
  s <- pmax(s, 1e-12 * max(s))
  k <- length(m)
  lo <- rep(min(m - 10 * s), length(u))
  hi <- rep(max(m + 10 * s), length(u))
  # 50 halvings of a 20-sd bracket: far below the grid's resolution
  for (it in 1:50) {
    mid <- (lo + hi) / 2
    cdf <- colSums(w * stats::pnorm(matrix((rep(mid, each = k) - m) / s, k)))
    below <- cdf < u
    lo[below] <- mid[below]
    hi[!below] <- mid[!below]
  }
  (lo + hi) / 2
}

# n draws of all scores from a model that joins its DoFs (the copula or the
# kernel density, R/dependence-kernel.R): list(alpha n x p x ncomp, beta n x
# warp_ncomp), from the current RNG stream.
draw_joint_scores <- function(model, n) {
  type <- model$dependence$type
  dep <- model$dependence[[type]]
  if (nrow(dep$columns) == 0L || n == 0L) return(scatter_scores(model, dep$columns, matrix(0, n, 0)))
  V <- if (type == "kernel") draw_kernel_vectors(dep, n)
       # normals, times the root, through the tabulated quantiles: one native
       # pass (src/copula-draw.c; tests/testthat/helper-copula.R is its R
       # transcription), one rnorm(n * D)
       else .Call(hm_copula_draw, as.integer(n), dep$root, dep$z, dep$quantiles)
  scatter_scores(model, dep$columns, V)
}

# The joint draws V (n x D, in the order of `cols`) as the generation
# kernel takes them: alpha n x p x ncomp (zero for constant DoFs), beta n x
# warp_ncomp.
scatter_scores <- function(model, cols, V) {
  n <- nrow(V)
  k <- model$settings$ncomp
  alpha <- array(0, c(n, length(model$dofs), k))
  beta <- matrix(0, n, model$settings$warp_ncomp)
  if (ncol(V) == 0L) return(list(alpha = alpha, beta = beta))
  dof_cols <- which(!cols$warp)
  jdof <- match(cols$dof[dof_cols], model$dofs)
  # alpha[, j, c] is column j + p (c - 1) of alpha viewed as n x (p k)
  dim(alpha) <- c(n, length(model$dofs) * k)
  alpha[, jdof + length(model$dofs) * (cols$comp[dof_cols] - 1L)] <- V[, dof_cols]
  dim(alpha) <- c(n, length(model$dofs), k)
  warp_cols <- which(cols$warp)
  beta[, cols$comp[warp_cols]] <- V[, warp_cols]
  list(alpha = alpha, beta = beta)
}

# Does the model draw its DoFs jointly (copula or kernel density)?
joint_dependence <- function(model) {
  (model$dependence$type %||% "independent") %in% c("copula", "kernel")
}

# The correlation between DoFs' first FPC scores (p x p) a model carries:
# the copula's for a copula model, the kernel's shrunk score correlation for
# a kernel model, zero off the diagonal for the thesis' independent model.
# For print(), summary() and autoplot().
dependence_matrix <- function(model) {
  p <- length(model$dofs)
  R <- diag(p)
  dimnames(R) <- list(model$dofs, model$dofs)
  cop <- model$dependence$copula %||% model$dependence$kernel
  if (is.null(cop)) return(R)
  first <- which(!cop$columns$warp & cop$columns$comp == 1L)
  idx <- match(cop$columns$dof[first], model$dofs)
  R[idx, idx] <- cop$cor[first, first]
  R
}
