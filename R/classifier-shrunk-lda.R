# Linear discriminant analysis with a shrunk covariance: Gaussian classes
# that share one covariance, whose correlation (pooled within classes) is
# shrunk towards the identity by the analytic rule of Schafer & Strimmer
# (shrink_correlation(), the rule the copula model uses). With 100+
# correlated features (a DIP follows its PIP) and a few hundred recordings
# per class, the plain pooled covariance is near singular; the shrunk one is
# well conditioned without a tuning parameter. The whole-motion classifier
# and every horizon of the streaming recogniser are this one fit.
#
# With W a whitening matrix (W W' = the inverse covariance) and c_k the
# class means whitened, the log posterior of class k is, up to a constant
# per recording, x W c_k' - |c_k|^2 / 2 + log prior_k: linear in x. The fit
# keeps that as `coef` (features x classes) and `offset`, so scoring a
# recording (or a live frame) is one vector-matrix product.

fit_shrunk_lda <- function(F, y, prior = c("equal", "data")) {
  prior <- match.arg(prior)
  y <- droplevels(as.factor(y))
  centre <- colMeans(F)
  Fc <- F - rep(centre, each = nrow(F))
  cls <- as.integer(y)
  lda_from_moments(lda_moments(Fc, cls, nlevels(y)), Fc, seq_len(nrow(F)), cls, levels(y), centre,
                   prior, features = colnames(F))
}

# What the fit needs of the rows, in sums that add: the cross product of
# the (centred) features, each class's sum and count. A held-out evaluation
# subtracts a fold's moments from the whole set's instead of recomputing
# them on the training rows (evaluate_early_recognition()).
lda_moments <- function(Fc, cls, K) {
  sums <- matrix(0, K, ncol(Fc))
  if (length(cls)) {
    rs <- rowsum(Fc, cls, reorder = TRUE)
    sums[as.integer(rownames(rs)), ] <- rs
  }
  list(xtx = crossprod(Fc), sums = sums, n = tabulate(cls, K))
}

lda_moments_minus <- function(a, b) {
  list(xtx = a$xtx - b$xtx, sums = a$sums - b$sums, n = a$n - b$n)
}

lda_moments_plus <- function(a, b) {
  list(xtx = a$xtx + b$xtx, sums = a$sums + b$sums, n = a$n + b$n)
}

# The shrinkage LDA from the moments of its training rows: Fc[rows, ] (the
# features minus `centre`) with classes cls (indices into `levels`; classes
# without a row are left out). The pooled within-class scatter is
# xtx - sum_c n_c m_c m_c' (centring keeps the subtraction from losing
# digits); its correlation is shrunk towards the identity as
# shrink_correlation() does it, the one non-additive term from one pass over
# the rows (src/lda-moments.c).
lda_from_moments <- function(mom, Fc, rows, cls, levels, centre, prior = "equal", features = colnames(Fc)) {
  present <- mom$n > 0
  counts <- mom$n[present]
  K <- length(counts)
  n <- sum(counts)
  M <- mom$sums[present, , drop = FALSE] / counts
  rownames(M) <- levels[present]
  W <- mom$xtx - crossprod(M * sqrt(counts))
  wd <- pmax(diag(W), 0)
  sd <- sqrt(wd / max(n - K, 1))
  # a feature constant within every class carries no noise to whiten
  sd[!is.finite(sd) | sd < 1e-8 * max(sd, 1e-300)] <- 1
  D <- ncol(W)
  sh <- if (D < 2L) list(cor = diag(D), lambda = 0) else {
    inv_s <- ifelse(wd > 0, 1 / sqrt(wd / (n - 1)), 0)
    R <- W * tcrossprod(inv_s) / (n - 1)
    w2 <- .Call(hm_lda_w2, Fc, as.integer(rows), as.integer(cumsum(present)[cls]), M, as.double(inv_s))
    shrink_from_cor(R, w2, n)
  }
  proj <- sweep(inverse_root(sh$cor), 1, sd, "/")
  means <- M + rep(centre, each = K)
  centres <- means %*% proj
  log_prior <- if (prior == "equal") rep(-log(K), K) else log(counts / n)
  list(classes = levels[present], coef = proj %*% t(centres),
       offset = log_prior - rowSums(centres^2) / 2, log_prior = log_prior,
       shrinkage = sh$lambda, n = counts, features = features)
}

# W with W %*% t(W) = C^-1 for a symmetric positive (semi-)definite C: the
# inverse Cholesky factor, or an eigen root without the null directions
# when C is singular (shrinkage 0 and collinear features).
inverse_root <- function(C) {
  U <- tryCatch(chol(C), error = function(e) NULL)
  if (!is.null(U)) return(backsolve(U, diag(nrow(C))))
  e <- eigen(C, symmetric = TRUE)
  keep <- e$values > 1e-10 * max(e$values)
  e$vectors[, keep, drop = FALSE] %*% diag(1 / sqrt(e$values[keep]), sum(keep))
}

# Log posterior (up to a constant per row) of every class: rows of F x K.
shrunk_lda_scores <- function(fit, F) {
  s <- F %*% fit$coef
  s <- s + rep(fit$offset, each = nrow(s))
  colnames(s) <- fit$classes
  s
}

# The class with the highest score in each row (the first on a tie), the
# one rule every prediction from discriminant scores follows.
top_class <- function(classes, s) classes[max.col(s, ties.method = "first")]

# Class probabilities from log posteriors (softmax, stable).
softmax_rows <- function(s) {
  top <- if (nrow(s) == 1L) max(s) else s[cbind(seq_len(nrow(s)), max.col(s, ties.method = "first"))]
  e <- exp(s - top)
  e / rowSums(e)
}
