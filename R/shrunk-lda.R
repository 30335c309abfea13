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
  n <- nrow(F)
  K <- nlevels(y)
  counts <- tabulate(y, K)
  means <- rowsum(F, y, reorder = TRUE) / counts
  R <- F - means[as.integer(y), , drop = FALSE]
  sd <- sqrt(colSums(R^2) / max(n - K, 1))
  # a feature constant within every class carries no noise to whiten
  sd[!is.finite(sd) | sd < 1e-8 * max(sd, 1e-300)] <- 1
  sh <- shrink_correlation(sweep(R, 2, sd, "/"))
  proj <- sweep(inverse_root(sh$cor), 1, sd, "/")
  centres <- means %*% proj
  log_prior <- if (prior == "equal") rep(-log(K), K) else log(counts / n)
  list(classes = levels(y), coef = proj %*% t(centres),
       offset = log_prior - rowSums(centres^2) / 2, log_prior = log_prior,
       shrinkage = sh$lambda, n = counts, features = colnames(F))
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
