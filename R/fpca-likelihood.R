# The FPCA likelihood distance (fit_grasp_models(distance = "likelihood")):
# minus twice the log-likelihood of a recording under one grasp type's model,
# DoF by DoF (the models treat DoFs as independent):
#   * its FPC scores under the type's Gaussian mixture on the scores, and
#   * its squared residual norm (what the FPCs leave over, the thesis'
#     eq. 4.4 distance) under the residual the type's own recordings left:
#     sum_{c > k} lambda_c z_c^2 with the FPCA's discarded eigenvalues
#     lambda_c, taken as a scaled chi-square a chi2_nu with a and nu matching
#     its mean and variance (Satterthwaite: a = sum l^2 / sum l,
#     nu = (sum l)^2 / sum l^2).
# Why: the thesis' distance reads the residual only, and a recording's
# projection on a type's FPCs absorbs its amplitude, so types that share a
# shape but differ in amplitude (a flex glove's grasp types do) are not told
# apart; the score term says how unlikely that amplitude is for the type,
# and the residual term is scaled by each type's own residual size.

# One model's distances for a projection (project_recordings(details =
# FALSE)): a vector over the projected recordings.
fpca_likelihood_distance <- function(model, pr) {
  k <- model$settings$ncomp
  total <- numeric(length(pr$distance))
  for (j in seq_along(model$dofs)) {
    f <- model$fpca[[j]]
    # a constant DoF (zero basis, point-mass mixture) says nothing about type
    if (isTRUE(f$constant)) next
    rest <- f$eigenvalues[-seq_len(k)]
    rest <- rest[is.finite(rest) & rest > 0]
    s1 <- sum(rest)
    s2 <- sum(rest^2)
    # floor: a model whose FPCs explain everything still has rounding error
    scale <- max(if (s1 > 0) s2 / s1 else 0, 1e-8 * max(f$eigenvalues, 1))
    nu <- if (s2 > 0) max(s1^2 / s2, 1) else 1
    rss <- pmax(pr$residual[, j]^2, .Machine$double.xmin)
    total <- total - 2 * (stats::dchisq(rss / scale, nu, log = TRUE) - log(scale))
    S <- matrix(pr$scores[, j, ], ncol = k)
    mix <- model$gmm[[j]]
    total <- total - 2 * gmm_log_density(mix$weights, mix$means, mix$covs, S)
  }
  stats::setNames(total, pr$ids)
}

# The distance a model set ranks by: sets from before the choice existed
# were ranked by the residual.
models_distance <- function(models) attr(models, "distance") %||% "residual"
