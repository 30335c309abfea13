# The FPCA likelihood distance (fit_grasp_models(distance = "likelihood")):
# minus twice the log-likelihood of a recording under one grasp type's model,
# DoF by DoF (the models treat DoFs as independent):
#   * its FPC scores under the type's Gaussian mixture on the scores, and
#   * its squared residual norm (what the FPCs leave over, the thesis'
#     eq. 4.4 distance) under the residual recordings leave:
#     sum_{c > k} lambda_c z_c^2 with the FPCA's discarded eigenvalues
#     lambda_c, matched in mean and variance by nu Gaussian coordinates of
#     variance a (Satterthwaite: a = sum l^2 / sum l, nu = (sum l)^2 /
#     sum l^2), the sums pooled over the set's types (below).
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
# is far. Held out by participant on flexglove (each type's own residual
# scale) this lifted the distance from
# 68.7% (P1 62.2%, P2 77.7%) to 73.5% (P1 63.8%, P2 86.7%). A type with
# fewer than three recordings (no bandwidth to cross-validate) keeps the
# per-DoF mixtures. Like the mixtures, the kernel is unchanged by a gain or
# offset of a channel common to all recordings: the scores' spread carries
# the gain and the mean curve the offset.

# The residual term's scale is pooled over the set's types (each fitted
# model carries the pooled moments, pool_likelihood_residuals()): per DoF,
# the discarded eigenvalues' sum and sum of squares (the mean and half the
# variance of the squared residual norm) averaged over the types, weighted
# by their recordings less one, as linear discriminant analysis pools the
# within-class covariance. Why: a type's own discarded eigenvalues are
# measured on few recordings of few people, and a type whose recordings
# happened to vary more makes a large residual cheap, so it takes every
# recording its FPCs fit badly (held out by participant on flexglove, P2's
# Sphere 4 Finger model took 102 of P1's 362 recordings, 59 of them wrong).
# Pooled, the residual says how well a type's FPCs fit the recording on one
# scale for all types. Held out by participant on flexglove 73.2% -> 76.8%
# (P1 63.5% -> 68.0%, P2 86.4% -> 89.0%), on the default data held out by
# subject 50.6% -> 61.4%; the wide simulated glove of bench/bench-real.R
# (5 folds by recording) 98.2% -> 99.4% (3 -> 1 of 168 wrong). Found on flexglove's participant folds after
# a set-wide number of FPCs chosen by nested folds (69.6%), rest-level and
# range invariance and a wider kernel had not helped
# (bench/bench-real-classify.R); it has no parameter. A model fitted before
# the pooling uses its own moments.

# One model's distances for a projection (project_recordings(details =
# FALSE)): a vector over the projected recordings.
fpca_likelihood_distance <- function(model, pr) {
  stats::setNames(likelihood_score_term(model, pr) + likelihood_residual_term(model, pr$residual), pr$ids)
}

# Minus twice the log density of the projection's FPC scores: jointly under
# the kernel, or DoF by DoF under each DoF's mixture (fewer than three
# recordings, or a model fitted before the joint density).
likelihood_score_term <- function(model, pr) {
  kern <- model$likelihood_kernel
  if (!is.null(kern)) return(-2 * score_kernel_log_density(kern, pr$scores))
  k <- model$settings$ncomp
  total <- numeric(dim(pr$scores)[1])
  for (j in seq_along(model$dofs)) {
    # a constant DoF (zero basis, point-mass mixture) says nothing about type
    if (isTRUE(model$fpca[[j]]$constant)) next
    S <- matrix(pr$scores[, j, ], ncol = k)
    mix <- model$gmm[[j]]
    total <- total - 2 * gmm_log_density(mix$weights, mix$means, mix$covs, S)
  }
  total
}

# Minus twice the log density of the residuals (`residual`, their norms,
# recordings x DoFs), DoF by DoF: nu Gaussian coordinates of variance a,
# rss / a + nu log(2 pi a), with a and nu matched to the (pooled) discarded
# eigenvalues. Not the scaled chi-square's density of rss itself: with a
# scale shared by all types, its (nu / 2 - 1) log(rss) says that a residual
# far below the pooled one is unlikely, and a type whose FPCs fit its own
# recordings almost exactly then lost them (in-sample temperature at its
# upper bound on a simulated set); this one never favours the worse fit.
likelihood_residual_term <- function(model, residual) {
  mom <- model$likelihood_residual %||% residual_moments(model)
  total <- numeric(nrow(residual))
  for (j in seq_along(model$dofs)) {
    f <- model$fpca[[j]]
    if (isTRUE(f$constant) || !is.finite(mom$s1[j])) next
    s1 <- mom$s1[j]
    s2 <- mom$s2[j]
    # floor: a model whose FPCs explain everything still has rounding error
    scale <- max(if (s1 > 0) s2 / s1 else 0, 1e-8 * max(f$eigenvalues, 1))
    nu <- if (s2 > 0) max(s1^2 / s2, 1) else 1
    total <- total + residual[, j]^2 / scale + nu * log(2 * pi * scale)
  }
  total
}

# Per DoF, the sum and the sum of squares of a model's discarded
# eigenvalues (NA for a constant DoF): list(s1, s2).
residual_moments <- function(model) {
  k <- model$settings$ncomp
  m <- vapply(model$fpca, function(f) {
    if (isTRUE(f$constant)) return(c(NA_real_, NA_real_))
    rest <- f$eigenvalues[-seq_len(k)]
    rest <- rest[is.finite(rest) & rest > 0]
    c(sum(rest), sum(rest^2))
  }, numeric(2))
  list(s1 = unname(m[1, ]), s2 = unname(m[2, ]))
}

# The set's fitted models (a list of models and failures, as fit_model_set()
# assembles it), each given the residual moments pooled over the fitted
# types (see above): per DoF, weighted by n_used - 1 over the types where
# the DoF varies. Failures are returned as they are.
pool_likelihood_residuals <- function(models) {
  fitted <- vapply(models, inherits, logical(1), "grasp_model")
  if (!any(fitted)) return(models)
  own <- lapply(models[fitted], residual_moments)
  w <- vapply(models[fitted], function(m) m$n_used - 1, numeric(1))
  pool <- function(part) {
    M <- matrix(vapply(own, `[[`, numeric(length(own[[1]][[part]])), part), ncol = length(own))
    ok <- is.finite(M)
    num <- rowSums(ifelse(ok, M, 0) * rep(w, each = nrow(M)))
    den <- rowSums(ok * rep(w, each = nrow(M)))
    ifelse(den > 0, num / den, NA_real_)
  }
  pooled <- list(s1 = pool("s1"), s2 = pool("s2"), types = sum(fitted))
  models[fitted] <- lapply(models[fitted], function(m) {
    m$likelihood_residual <- pooled
    m
  })
  models
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
  # the log-sum-exp over the training vectors x_j of -|y - x_j|^2 / (2 h^2),
  # from the cross products (BLAS) in one compiled pass (src/kernel-score.c:
  # the six m x n temporaries of the R expression, kept as the tests'
  # reference, were three quarters of classify() on the default data)
  lse <- .Call(hm_kernel_score_lse, tcrossprod(Ys, kern$Y), rowSums(Ys^2), rowSums(kern$Y^2),
               as.double(kern$h))
  lse - log(nrow(kern$Y)) - 0.5 * kern$logdet - 0.5 * ncol(kern$Y) * log(2 * pi)
}

# The distance a model set ranks by (its field, see new_grasp_models()).
models_distance <- function(models) models$distance
