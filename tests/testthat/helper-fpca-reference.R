# The R-level projection, reconstruction and residual norm of one fpca_fit()
# (tests only): the package projects whole model sets in one native call
# (src/project-kernel.c, reached here through fpca_project_columns()) and rebuilds curves inside
# generate(); these checked wrappers state what those compute.

# Project curves onto a functional PCA
#
# Scores of new curves on the components of a fit, with the inner product the
# fit used (trapezoidal rule on its grid): `<Y_i - mean, phi_r>`. On the
# curves the model was fitted to this returns `fit$scores`.
#
# @param fit An `fpca_fit()` object.
# @param Ynew Curves on the fit's grid: an `m x L` matrix, a numeric vector of
#   length `L` (one curve), or an `fdata` object.
# @return An `m x ncomp` matrix of scores.
# @examples
# t <- seq(0, 1, length.out = 30)
# Y <- outer(rnorm(40), sin(pi * t)) + outer(rnorm(40, sd = 0.3), cos(pi * t))
# fit <- fpca_fit(Y, argvals = t)
# fpca_project(fit, Y[1:3, ])
fpca_project <- function(fit, Ynew) {
  call <- rlang::caller_env()
  Ynew <- fpca_new_curves(fit, Ynew, call = call)
  fpca_project_columns(fit, t(Ynew), norms = FALSE)$scores
}

# Rebuild curves from functional PCA scores
#
# `mean + scores %*% t(components)`: the curves a set of scores stands for,
# as used to generate new motion from sampled scores.
#
# @param fit An `fpca_fit()` object.
# @param scores An `m x ncomp` matrix (or a vector of length `ncomp`).
# @return An `m x L` matrix of curves.
# @examples
# t <- seq(0, 1, length.out = 30)
# Y <- outer(rnorm(40), sin(pi * t)) + outer(rnorm(40, sd = 0.3), cos(pi * t))
# fit <- fpca_fit(Y, argvals = t)
# dim(fpca_reconstruct(fit, fit$scores[1:5, ]))
fpca_reconstruct <- function(fit, scores) {
  call <- rlang::caller_env()
  check_fpca_fit(fit, call = call)
  k <- ncol(fit$components)
  if (is.null(dim(scores)) && is.numeric(scores) && length(scores) == k) scores <- matrix(scores, 1L)
  if (!is.numeric(scores) || !is.matrix(scores) || ncol(scores) != k || any(!is.finite(scores))) {
    hm_abort("{.arg scores} must be a finite numeric matrix with {k} column{?s} (one per component).",
             "bad_input", argument = "scores", call = call)
  }
  out <- scores %*% t(fit$components)
  out <- sweep(out, 2L, fit$mean, "+")
  dimnames(out) <- NULL
  out
}

# Distance of curves to their functional PCA reconstruction
#
# The L2 norm (trapezoidal rule on the fit's grid) of each curve minus its
# reconstruction from its own projection, `||g - proj(g)||` (thesis eq. 4.4,
# used by the FPCA classifier).
#
# @inheritParams fpca_project
# @param time_weights Optional weights on the grid points (length `L`)
#   multiplying the quadrature weights of the norm.
# @return A numeric vector of length `m`.
# @examples
# t <- seq(0, 1, length.out = 30)
# Y <- outer(rnorm(40), sin(pi * t)) + outer(rnorm(40, sd = 0.3), cos(pi * t))
# fit <- fpca_fit(Y, argvals = t, ncomp = 1)
# summary(fpca_residual_norm(fit, Y))
fpca_residual_norm <- function(fit, Ynew, time_weights = NULL) {
  call <- rlang::caller_env()
  Ynew <- fpca_new_curves(fit, Ynew, call = call)
  # time weights (the weighted FPCA distance) reweigh the grid points of the
  # norm, never the projection itself
  fpca_project_columns(fit, t(Ynew), time_weights = time_weights)$norms
}

check_fpca_fit <- function(fit, arg = "fit", call = rlang::caller_env()) {
  if (!inherits(fit, "fpca_fit")) {
    hm_abort("{.arg {arg}} must be an {.cls fpca_fit} object (from {.fn fpca_fit}).",
             "bad_input", argument = arg, call = call)
  }
  invisible(fit)
}

fpca_new_curves <- function(fit, Ynew, call) {
  check_fpca_fit(fit, call = call)
  # a single curve may come as a plain vector (one row)
  unname(as_numeric_matrix(Ynew, "Ynew", " of curves on the fit's grid", vector = "row",
                           ncol = length(fit$mean), row_name = "curve", col_name = "point",
                           call = call))
}

# The one projection (scores and residual norms) of curves given as the
# COLUMNS of Yt (L x m), unchecked, in the native kernel that predict.grasp_model() uses
# for whole model sets (src/project-kernel.c): scores are <y - mean, phi_c>
# with the quadrature weights, the residual norm is the weighted L2 norm of
# y - mean - sum_c score_c phi_c (time weights multiply the quadrature
# weights of the norm only).
fpca_project_columns <- function(fit, Yt, norms = TRUE, time_weights = NULL) {
  L <- nrow(Yt)
  idx <- seq_len(length(Yt))
  k <- ncol(fit$components)
  w <- fit$weights
  res <- .Call(hm_project_batch, matrix(as.double(Yt), ncol = 1L), idx, idx, numeric(length(Yt)),
               matrix(as.double(fit$mean), L, 1L), array(as.double(fit$components), c(L, 1L, k)),
               matrix(as.double(w), L, 1L), matrix(as.double(w * (time_weights %||% 1)), L, 1L))
  list(scores = matrix(res$scores, ncol(Yt), k), norms = res$residual)
}
