# Class "grasp_model": its one constructor and validator, and the stacked
# views of its per-DoF parts that the kernels and methods read.

# The one constructor of class "grasp_model": the fitted parts in (one FPCA
# and one mixture per DoF, the warp model), each stored once. The stacked
# views are derived when needed (model_basis(), model_scores(),
# model_var_explained(): a few arrays of L x p x ncomp numbers, microseconds).
# Two derived parts are kept: the generation `sampler` (the mixtures'
# cumulative weights and covariance roots; rebuilding it costs about 1 ms,
# four times a one-grasp generate()) and the cross-DoF `dependence` (a fit of
# its own); nothing sets them apart from the mixtures and scores they come
# from.
new_grasp_model <- function(grasp, grasp_id, dofs, rate, unit, target_length, argvals, n_input, n_used,
                            ids, removed, warping, fpca, gmm, warp, fallbacks, settings, engine, timing,
                            limits, alignment = NULL, degenerate_data = empty_degenerate_notes(),
                            levels = feix_levels(), glove = NULL, phases = NULL, residuals = NULL) {
  model <- list(grasp = grasp, grasp_id = grasp_id, dofs = dofs, rate = rate, unit = unit,
                target_length = target_length, argvals = argvals, n_input = n_input, n_used = n_used,
                ids = ids, removed = removed, warping = warping, fpca = fpca, gmm = gmm, warp = warp, fallbacks = fallbacks, settings = settings, engine = engine,
                timing = timing)
  model$sampler <- build_sampler(model)
  model$dependence <- list(type = settings$dependence,
                           copula = if (settings$dependence == "copula") fit_score_copula(model))
  # only a kernel model carries the kernel element (an independent or copula
  # model is the same list as before the kernel model existed)
  if (settings$dependence == "kernel") model$dependence$kernel <- fit_score_kernel(model)
  # the joint density of the FPC scores that the likelihood distance reads
  # (R/classifier-fpca-likelihood.R): fitted once here, where the scores are, not at
  # every prediction (33 types re-fitted it at each call: 2.6 s of the
  # default data's 4 s in-sample calibration, on one core)
  model$likelihood_kernel <- likelihood_score_kernel(model)
  model$limits <- limits
  # the labels the model was fitted among (its own is `grasp`) and the glove
  # of its recordings, so generated grasps carry both
  model$levels <- levels
  model$glove <- glove
  model$phases <- phases
  model$residuals <- residuals
  model$degenerate_data <- degenerate_data
  model$alignment <- alignment
  validate_grasp_model(structure(model, class = "grasp_model"))
}

# Shapes that fit together: p DoFs, L template frames, n recordings used,
# ncomp FPCs per DoF; one FPCA and one mixture per DoF; the kept alignment
# (if any) holds exactly the recordings used.
validate_grasp_model <- function(x) {
  p <- length(x$dofs)
  L <- x$target_length
  n <- x$n_used
  q <- x$settings$ncomp
  stopifnot(
    is.character(x$grasp), length(x$grasp) == 1L,
    length(x$argvals) == L, n == length(x$ids), n <= x$n_input,
    identical(names(x$fpca), x$dofs), identical(names(x$gmm), x$dofs),
    all(vapply(x$fpca, inherits, logical(1), "fpca_fit")),
    all(vapply(x$gmm, inherits, logical(1), "gmm_fit")),
    is.null(fpca_shape_fault(x)), has_dim(model_scores(x), c(n, p, q)),
    inherits(x$warp$fpca, "fpca_fit"), length(x$warp$fpca$mean) == L,
    nrow(warp_basis(x)$components) == L, nrow(warp_basis(x)$scores) == n,
    is.data.frame(x$removed), is.data.frame(x$fallbacks), is.data.frame(x$degenerate_data),
    x$dependence$type %in% c("independent", "copula", "kernel"),
    is.null(x$alignment) || (inherits(x$alignment, "grasp_alignment") && dim(x$alignment$warped)[1] == n)
  )
  x
}

has_dim <- function(a, d) length(dim(a)) == length(d) && all(dim(a) == d)

# The views of a model's per-DoF FPCAs that the kernels and methods read,
# stacked over DoFs: the basis (`mean` L x p, `components` L x p x ncomp),
# the training scores (n x p x ncomp) and the variance explained (p x ncomp).
model_basis <- function(model) {
  dofs <- model$dofs
  q <- model$settings$ncomp
  L <- model$target_length
  mean <- matrix(0, L, length(dofs), dimnames = list(NULL, dofs))
  comps <- array(0, c(L, length(dofs), q), dimnames = list(NULL, dofs, paste0("FPC", seq_len(q))))
  for (j in seq_along(dofs)) {
    mean[, j] <- model$fpca[[j]]$mean
    comps[, j, ] <- model$fpca[[j]]$components
  }
  list(mean = mean, components = comps)
}

model_scores <- function(model) {
  dofs <- model$dofs
  q <- model$settings$ncomp
  scores <- array(0, c(model$n_used, length(dofs), q), dimnames = list(model$ids, dofs, paste0("FPC", seq_len(q))))
  for (j in seq_along(dofs)) scores[, j, ] <- model$fpca[[j]]$scores
  scores
}

# The warping FPCA's views, as the kernels take them (stored once, in
# model$warp$fpca): mean (L), components (L x q) and scores (n x q).
warp_basis <- function(model) {
  f <- model$warp$fpca
  L <- model$target_length
  list(mean = as.numeric(f$mean), components = matrix(as.numeric(f$components), L),
       scores = matrix(as.numeric(f$scores), model$n_used))
}

model_var_explained <- function(model) {
  q <- model$settings$ncomp
  matrix(vapply(model$fpca, function(f) as.numeric(f$var_explained), numeric(q)),
         length(model$dofs), q, byrow = TRUE, dimnames = list(model$dofs, paste0("FPC", seq_len(q))))
}

# What in a model's FPCAs the kernels could not take (NULL when nothing): a
# model changed by hand gets a classed error naming it (see model_fault()),
# not a crash or an R error from model_basis().
fpca_shape_fault <- function(model, ncomp = model$settings$ncomp) {
  L <- model$target_length
  if (length(model$fpca) != length(model$dofs)) return("it does not hold one FPCA per DoF")
  for (j in seq_along(model$fpca)) {
    f <- model$fpca[[j]]
    if (!is.numeric(f$mean) || length(f$mean) != L) {
      return(sprintf("the FPCA mean of DoF %s does not have %d frames", model$dofs[j], L))
    }
    if (!is.numeric(f$components) || length(f$components) != L * ncomp) {
      return(sprintf("the FPCs of DoF %s are not %d frames x %d", model$dofs[j], L, ncomp))
    }
  }
  NULL
}
