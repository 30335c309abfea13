# Steps 3-4 of a grasp model: FPCA of the aligned curves per DoF and of the
# warping functions, with sign conventions that make refits comparable.

# FPCA of one set of curves, or a zero-component stand-in when the curves do
# not vary (a constant DoF or identical warps), so later steps never divide
# by a zero variance.
fit_fpca_or_constant <- function(Y, argvals, ncomp, engine, score_rule = "trapezoid") {
  # total variance over time points, sum(colSums((Y - rep(colMeans(Y), each
  # = n))^2)) / (n - 1), and the mean square mean(Y^2), in one compiled pass
  # (src/curve-spread.c; this runs once per DoF and type)
  n <- nrow(Y)
  if (!is.double(Y)) storage.mode(Y) <- "double"
  spread <- .Call(hm_curve_spread, Y)
  v <- spread[1]
  scale <- max(1, spread[2])
  if (!is.finite(v) || v <= 1e-12 * scale) {
    return(new_fpca_fit(mean = colMeans(Y), components = matrix(0, ncol(Y), ncomp),
                        scores = matrix(0, n, ncomp), eigenvalues = rep(0, ncomp),
                        var_explained = rep(NA_real_, ncomp), argvals = argvals,
                        weights = fpca_weights(argvals, fpca_delta(argvals, range(argvals)), score_rule),
                        delta = fpca_delta(argvals, range(argvals)), rangeval = range(argvals),
                        engine = engine, notes = "constant: the curves do not vary",
                        constant = TRUE, score_rule = score_rule))
  }
  fit <- fpca_fit(Y, argvals = argvals, ncomp = ncomp, engine = engine, scores = score_rule)
  fit$constant <- FALSE
  fit
}

# Sign convention for the DoF components. fpca_fit() makes each component's
# integral positive, which is arbitrary for a component whose integral is
# near zero (an S-shaped second component): refits then flip it at random.
# Here each component is flipped so that its largest projection onto the
# first three Legendre polynomials on [0, 1] (constant, ramp, parabola) is
# positive: one of the three is always clearly non-zero, so the sign is
# stable across refits and subsets. Scores are flipped with it.
orient_components <- function(fit) {
  if (isTRUE(fit$constant)) return(fit)
  s <- (fit$argvals - min(fit$argvals)) / diff(range(fit$argvals))
  legendre <- cbind(1, sqrt(3) * (2 * s - 1), sqrt(5) * (6 * s^2 - 6 * s + 1))
  comps <- as.matrix(fit$components)
  proj <- crossprod(comps * fit$weights, legendre)        # ncomp x 3
  for (c in seq_len(ncol(comps))) {
    pick <- which.max(abs(proj[c, ]))
    if (proj[c, pick] < 0) {
      fit$components[, c] <- -fit$components[, c]
      fit$scores[, c] <- -fit$scores[, c]
    }
  }
  fit
}

# Sign convention for the warp FPC: a positive score means a longer grasp
# (the component is positive at the last template frame).
orient_warp_fpca <- function(fit) {
  if (isTRUE(fit$constant)) return(fit)
  comps <- as.matrix(fit$components)
  L <- nrow(comps)
  for (c in seq_len(ncol(comps))) {
    if (comps[L, c] < 0) {
      fit$components[, c] <- -fit$components[, c]
      fit$scores[, c] <- -fit$scores[, c]
    }
  }
  fit
}
