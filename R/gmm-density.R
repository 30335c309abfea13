# The density of a fitted mixture (the model plots evaluate it). The
# log-likelihood and draws are in the tests' helper-gmm-density.R: the fits
# compute their log-likelihood inside the EM and generation draws through
# its own kernel.

# Log-density of each row of X under N(mu, S). A singular S (a fallback on
# collinear or identical points, or a point mass) is handled as the density on
# its support: points off the support get -Inf.
gmm_log_dnorm <- function(X, mu, S) {
  d <- ncol(X)
  Xc <- X - rep(mu, each = nrow(X))
  e <- eigen(S, symmetric = TRUE)
  lam <- e$values
  pos <- lam > max(lam, 0) * d * 1e-12 & lam > 0
  Z <- Xc %*% e$vectors
  q <- rowSums(Z[, pos, drop = FALSE]^2 / rep(lam[pos], each = nrow(X)))
  out <- -0.5 * q - 0.5 * sum(log(lam[pos])) - 0.5 * sum(pos) * log(2 * pi)
  if (any(!pos)) {
    size <- max(1, sqrt(max(lam, 0)), abs(mu))
    off <- rowSums(Z[, !pos, drop = FALSE]^2) > (1e-8 * size)^2
    out[off] <- -Inf
  }
  out
}

gmm_log_components <- function(weights, means, covs, X) {
  k <- length(weights)
  L <- matrix(0, nrow(X), k)
  for (j in seq_len(k)) {
    L[, j] <- log(weights[j]) + gmm_log_dnorm(X, means[j, ], as.matrix(covs[, , j]))
  }
  L
}

gmm_log_density <- function(weights, means, covs, X) {
  L <- gmm_log_components(weights, means, covs, X)
  top <- L[, 1L]
  for (j in seq_len(ncol(L))[-1L]) top <- pmax(top, L[, j])
  out <- top + log(rowSums(exp(L - top)))
  out[top == -Inf] <- -Inf
  out
}

gmm_loglik_params <- function(weights, means, covs, X) {
  sum(gmm_log_density(weights, matrix(means, length(weights)), covs, X))
}

gmm_points <- function(fit, X, call) {
  d <- ncol(fit$means)
  if (is.numeric(X) && is.null(dim(X))) X <- matrix(X, ncol = d, byrow = TRUE)
  X <- as_numeric_matrix(X, "X", " (one observation per row)", call = call)
  if (ncol(X) != d) {
    hm_abort("{.arg X} must have {d} column{?s}, like the data the mixture was fitted to.",
             "bad_input", argument = "X", call = call)
  }
  X
}

#' Density of a Gaussian mixture
#'
#' `gmm_density()` evaluates the mixture density at each row of `X`
#' (computed on the log scale). A component with a singular
#' covariance (a fallback fitted to collinear or identical points) has its
#' density taken on its support, and zero off it.
#'
#' @param fit A `gmm_fit()` object.
#' @param X An `m x d` matrix of points (a vector of length `d` is one point;
#'   for `d = 1` a vector is a set of points).
#' @return A numeric vector of length `m`.
#' @noRd
#' @examples
#' X <- rbind(matrix(rnorm(100), 50), matrix(rnorm(100, mean = 4), 50))
#' fit <- gmm_fit(X)
#' gmm_density(fit, rbind(c(0, 0), c(4, 4), c(2, 2)))
gmm_density <- function(fit, X) {
  call <- rlang::caller_env()
  check_gmm_fit(fit, call)
  X <- gmm_points(fit, X, call)
  exp(gmm_log_density(fit$weights, fit$means, fit$covs, X))
}
