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
#
# The scores are scored jointly, all DoFs at once, by a Gaussian kernel
# density of the type's own training score vectors (the kernel model's
# density, R/dependence-kernel.R: the scores' shrunk covariance, a bandwidth
# chosen by leave-one-out likelihood on the training recordings alone), not
# DoF by DoF under each DoF's own mixture. A type grasped round several
# objects puts its recordings in clusters of the joint score vector, one per
# object, and fingers move together: a recording whose every finger is
# typical of the type, but in a combination no recording of the type shows,
# is far. Held out by participant on flexglove this lifts the distance from
# 68.7% (P1 62.2%, P2 77.7%) to 73.5% (P1 63.8%, P2 86.7%). A type with
# fewer than three recordings (no bandwidth to cross-validate) keeps the
# per-DoF mixtures. Like the mixtures, the kernel is unchanged by a gain or
# offset of a channel common to all recordings: the scores' spread carries
# the gain and the mean curve the offset.

# One model's distances for a projection (project_recordings(details =
# FALSE)): a vector over the projected recordings.
fpca_likelihood_distance <- function(model, pr) {
  k <- model$settings$ncomp
  total <- numeric(length(pr$distance))
  # (NULL: fewer than three recordings, or a model fitted before the joint
  # density, which scored DoF by DoF)
  kern <- model$likelihood_kernel
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
    if (is.null(kern)) {
      S <- matrix(pr$scores[, j, ], ncol = k)
      mix <- model$gmm[[j]]
      total <- total - 2 * gmm_log_density(mix$weights, mix$means, mix$covs, S)
    }
  }
  if (!is.null(kern)) total <- total - 2 * score_kernel_log_density(kern, pr$scores)
  stats::setNames(total, pr$ids)
}

# The joint density of a model's FPC scores (see above): list(dof, comp
# (which score of pr$scores each column is), Y (the training vectors,
# standardised and whitened), sd, W, h, logdet (of the kernel's covariance
# h^2 S, over the d directions kept)); NULL with fewer than three training
# recordings or no score that varies.
likelihood_score_kernel <- function(model) {
  if (model$n_used < 3L || !isTRUE(model$settings$ncomp > 0)) return(NULL)
  cols <- score_columns(model)
  cols <- cols[!cols$warp, , drop = FALSE]
  if (!nrow(cols) || model$n_used < 3L) return(NULL)
  X <- score_matrix(model, cols)
  # at most 500 training vectors, evenly spread (deterministic): every
  # distance costs recordings x vectors x scores, and the in-sample
  # calibration of ten times the default data (990 recordings, 33 types of
  # 2,700) spent 8 s on one core in it; 500 vectors in the 25-50 scores of
  # a type estimate its density as well as its bandwidth allows (sets of
  # up to 500 recordings per type, the default data and flexglove among
  # them, use all of theirs)
  # (the bandwidth's own cap, kernel_bandwidth_max_n: with it the density is
  # cross-validated on exactly the vectors it keeps)
  if (nrow(X) > kernel_bandwidth_max_n) X <- X[evenly_spread(nrow(X), kernel_bandwidth_max_n), , drop = FALSE]
  sd <- apply(X, 2, stats::sd)
  # a score without spread (identical recordings) does not enter the metric
  live <- is.finite(sd) & sd > 1e-10 * max(sd, 0, na.rm = TRUE)
  if (!any(live)) return(NULL)
  X <- X[, live, drop = FALSE]
  sd <- sd[live]
  kd <- kernel_density(X)
  e <- eigen(kd$cor, symmetric = TRUE)
  keep <- e$values > 1e-10 * max(e$values)
  W <- e$vectors[, keep, drop = FALSE] %*% diag(1 / sqrt(e$values[keep]), sum(keep))
  d <- sum(keep)
  list(dof = match(cols$dof[live], model$dofs), comp = cols$comp[live],
       Y = sweep(X, 2, sd, "/") %*% W, sd = sd, W = W, h = kd$bandwidth,
       logdet = 2 * d * log(kd$bandwidth) + 2 * sum(log(sd)) + sum(log(e$values[keep])))
}

# Log density of score arrays (recordings x DoFs x ncomp) under the kernel:
# the log of the mean, over the training vectors, of N(s; x_i, h^2 S).
score_kernel_log_density <- function(kern, scores) {
  S <- vapply(seq_along(kern$dof), function(a) scores[, kern$dof[a], kern$comp[a]], numeric(dim(scores)[1]))
  S <- matrix(S, dim(scores)[1])
  m <- nrow(S)
  Ys <- (S / rep(kern$sd, each = m)) %*% kern$W
  # -|y - x_j|^2 / (2 h^2) for every training vector x_j (columns), in place:
  # with ten times the default data a type has 2,700 training vectors, and
  # the in-sample calibration scores 990 recordings against 33 types, so
  # each temporary m x n matrix costs; the row maxima by max.col() (apply()
  # over rows took as long as the products)
  A <- tcrossprod(Ys, kern$Y)
  A <- 2 * A - rep(rowSums(Ys^2), ncol(A))
  A <- A - rep(rowSums(kern$Y^2), each = m)
  A[A > 0] <- 0
  A <- A / (2 * kern$h^2)
  top <- A[cbind(seq_len(m), max.col(A, ties.method = "first"))]
  lse <- top + log(rowSums(exp(A - top)))
  lse - log(nrow(kern$Y)) - 0.5 * kern$logdet - 0.5 * ncol(kern$Y) * log(2 * pi)
}

# The distance a model set ranks by: sets from before the choice existed
# were ranked by the residual.
models_distance <- function(models) attr(models, "distance") %||% "residual"
