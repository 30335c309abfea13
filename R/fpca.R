# Functional principal component analysis of a set of curves sampled on a
# common grid (thesis sections 3.4 and 4.1.3).
#
# Two engines compute the same thing:
# * "reference" calls fda.usc::fdata2pc(), the package the thesis used;
# * "fast" reproduces fdata2pc's arithmetic with one eigen-decomposition and
#   one matrix product, so it is a few hundred times quicker.
#
# What fdata2pc computes (fda.usc 2.x, norm = TRUE, lambda = 0), and hence
# what both engines return:
# 1. centre the curves on their pointwise mean;
# 2. take the SVD of the centred n x L data matrix *without* quadrature
#    weights: Yc = U diag(s) V';
# 3. rescale the right singular vectors by 1 / delta, where delta is the
#    square root of the mean grid spacing, so that the components have unit
#    norm under the uniform rule (sum(phi^2) * delta^2 = 1); the reported
#    singular values become s * delta;
# 4. compute the scores as inner products <Yc_i, phi_r> with the trapezoidal
#    rule (fda.usc's default integration method "TRAPZ").
# The proportion of variance of component r is s_r^2 / sum(s^2). We report the
# eigenvalues of the covariance operator as (s * delta)^2 / n (the 1/N
# convention of the thesis' eq. in section 3.3).

#' Functional principal component analysis of curves
#'
#' Fits a functional PCA to curves sampled on a common grid, as the thesis does
#' for each joint angle after time warping (two components) and for the
#' warping functions (one component).
#'
#' Both engines centre the curves, take the singular value decomposition of
#' the centred data, scale the components to unit norm on the grid (the right
#' singular vectors divided by `delta`, the square root of the mean grid
#' spacing) and compute scores as trapezoidal-rule inner products, exactly as
#' [fda.usc::fdata2pc()] does. `engine = "reference"` calls `fdata2pc()`;
#' `engine = "fast"` (the default) does the same arithmetic with one
#' eigen-decomposition of the smaller Gram matrix and agrees with the
#' reference to about 1e-10 (up to the sign, which both then fix).
#'
#' Like `fdata2pc()`, the components have unit norm under the uniform weight
#' `delta^2` while inner products (scores, projections, residual norms) use
#' the trapezoidal rule; the two differ only through the halved end points,
#' so re-projecting a reconstructed curve returns its scores up to that small
#' end-point term. `eigenvalues` are `(s * delta)^2 / n` for the singular
#' values `s` of the centred data (the 1/N convention of the thesis), and
#' `var_explained` is `s_r^2 / sum(s^2)`, as `summary()` of an `fdata2pc()`
#' fit reports it.
#'
#' **Sign convention.** The sign of a principal component is arbitrary. Each
#' component is flipped so that its integral (trapezoidal rule) is positive;
#' when the integral is zero to rounding, so that its value of largest absolute
#' size is positive. Scores are flipped with it. Refits, row permutations and
#' subsets of similar data therefore give comparable components.
#'
#' **Degenerate data.** Components whose eigenvalue is zero to rounding (for
#' instance when `ncomp` exceeds the rank: `ncomp > n - 1` or `ncomp > L`, or
#' when all curves are identical) are returned as zero curves with zero
#' scores; `var_explained` is 0 for them, or `NA` when the curves do not vary
#' at all. Each such case is recorded in `notes`.
#'
#' @param Y Curves: an `n x L` numeric matrix with one curve per row, or an
#'   [fda.usc::fdata()] object.
#' @param argvals The grid the curves are sampled on, strictly increasing, of
#'   length `L`. Defaults to the `fdata` object's grid, or to
#'   `seq(0, 1, length.out = L)` for a matrix (the thesis' normalised time).
#' @param ncomp Number of components to keep.
#' @param engine `"fast"` (default) or `"reference"` ([fda.usc::fdata2pc()]).
#' @param scores How scores (and projections, residual norms) integrate:
#'   `"trapezoid"` (default) is fda.usc's trapezoidal rule, as the thesis
#'   computed them. The components are orthonormal under the uniform rule,
#'   not the trapezoidal one, so trapezoidal scores of different components
#'   are correlated and `mean + components %*% scores` misses part of a
#'   curve's end points (where grasp curves vary most: the final posture).
#'   `"least_squares"` integrates with the uniform weight `delta^2`: each
#'   score is then the least-squares coefficient of the curve on its
#'   component and the reconstruction is the curve's orthogonal projection.
#' @return An object of class `fpca_fit`: a list with `mean` (length `L`),
#'   `components` (`L x ncomp`), `scores` (`n x ncomp`), `eigenvalues` (all
#'   non-zero eigenvalues of the covariance operator, decreasing),
#'   `var_explained` (proportion of the total variance for each kept
#'   component), `argvals`, `weights` (the quadrature weights used for inner
#'   products and norms, by `score_rule`), `delta`, `rangeval`, `n`, `ncomp`,
#'   `engine`, `score_rule` (`scores`) and `notes` (character vector of
#'   recorded special cases).
#' @seealso [project()], which projects new curves (src/project-kernel.c).
#' @noRd
#' @examples
#' t <- seq(0, 1, length.out = 30)
#' Y <- outer(rnorm(40), sin(pi * t)) + outer(rnorm(40, sd = 0.3), cos(pi * t))
#' fit <- fpca_fit(Y, argvals = t, ncomp = 2)
#' fit
#' head(fit$scores)
fpca_fit <- function(Y, argvals = NULL, ncomp = 2, engine = c("fast", "reference"),
                     scores = c("trapezoid", "least_squares")) {
  call <- rlang::caller_env()
  engine <- check_choice(engine, arg = "engine", call = rlang::current_env())
  scores <- check_choice(scores, arg = "scores", call = rlang::current_env())
  cur <- fpca_curves(Y, argvals, call = call)
  # (more components than grid points are padded with zero components; the
  # bound only refuses absurd requests)
  ncomp <- check_whole(ncomp, "ncomp", max = max(ncol(cur$Y), 1000L), call = call)
  mean <- colMeans(cur$Y)
  Yc <- cur$Y - rep(mean, each = nrow(cur$Y))
  delta <- fpca_delta(cur$argvals, cur$rangeval)
  weights <- fpca_weights(cur$argvals, delta, scores)
  raw <- switch(engine,
    fast = fpca_engine_fast(Yc, ncomp),
    reference = fpca_engine_reference(cur, ncomp, call = call))
  if (scores == "least_squares") raw$scores <- NULL  # fdata2pc's own are trapezoidal
  fit <- fpca_finish(raw, Yc, cur, mean, ncomp, delta, weights, scores)
  fit$engine <- engine
  fit
}

# Validate curves and grid; returns list(Y, argvals, rangeval).
fpca_curves <- function(Y, argvals, arg = "Y", call = rlang::caller_env()) {
  rangeval <- NULL
  if (inherits(Y, "fdata")) {
    if (is.null(argvals)) argvals <- Y$argvals
    rangeval <- Y$rangeval
    Y <- Y$data
  }
  Y <- as_numeric_matrix(Y, arg, " (one curve per row, at least 2 points)", vector = "none",
                         min_cols = 2L, row_name = "curve", col_name = "point", call = call)
  L <- ncol(Y)
  if (is.null(argvals)) argvals <- seq(0, 1, length.out = L)
  if (!is.numeric(argvals) || length(argvals) != L || any(!is.finite(argvals)) ||
      any(diff(argvals) <= 0)) {
    hm_abort("{.arg argvals} must be {L} finite, strictly increasing values (one per column of {.arg {arg}}).",
             "bad_input", argument = "argvals", call = call)
  }
  argvals <- as.numeric(argvals)
  if (is.null(rangeval)) rangeval <- range(argvals)
  storage.mode(Y) <- "double"
  list(Y = unname(Y), argvals = argvals, rangeval = as.numeric(rangeval))
}

# The quadrature weights of the inner products (scores, projections, norms)
# under a score rule: fda.usc's trapezoidal rule, or the uniform weight
# delta^2 under which the components are orthonormal, so that a score is the
# least-squares coefficient of the curve on its component and
# mean + components %*% scores is the curve's orthogonal projection.
fpca_weights <- function(argvals, delta, rule = "trapezoid") {
  if (identical(rule, "least_squares")) rep(delta^2, length(argvals)) else trapezoid_weights(argvals)
}

# Trapezoidal weights as fda.usc's "TRAPZ" rule applies them: on a grid that
# is equispaced to 0.1% it uses the nominal spacing range / (L - 1), otherwise
# the actual spacings.
trapezoid_weights <- function(argvals) {
  L <- length(argvals)
  h_nominal <- diff(range(argvals)) / (L - 1)
  dt <- diff(argvals)
  if (all(abs(dt - h_nominal) < 0.001 * h_nominal)) dt <- rep(h_nominal, L - 1L)
  c(dt, 0) / 2 + c(0, dt) / 2
}

# The normalising constant of fdata2pc: sqrt(range / (L - 1)). fdata2pc tests
# "equispaced" against a tolerance of 10 machine epsilons around each spacing
# itself, which holds unless the spacing is so large (> ~32) that the
# tolerance vanishes in rounding; then it falls back to the harmonic mean
# spacing. We reproduce both branches so the engines agree on any grid.
fpca_delta <- function(argvals, rangeval) {
  L <- length(argvals)
  dt <- diff(argvals)
  eps <- 10 * .Machine$double.eps
  if (all(dt > dt - eps) && all(dt < dt + eps)) sqrt(diff(rangeval) / (L - 1)) else 1 / sqrt(mean(1 / dt))
}

# Leading right singular vectors and all squared singular values of Yc, from
# the eigen-decomposition of the smaller Gram matrix (4x cheaper than svd()).
fpca_engine_fast <- function(Yc, ncomp) {
  n <- nrow(Yc)
  L <- ncol(Yc)
  k <- min(ncomp, n, L)
  if (L <= n) {
    e <- eigen(crossprod(Yc), symmetric = TRUE)
    V <- e$vectors[, seq_len(k), drop = FALSE]
  } else {
    e <- eigen(tcrossprod(Yc), symmetric = TRUE)
    s <- sqrt(pmax(e$values[seq_len(k)], 0))
    V <- crossprod(Yc, e$vectors[, seq_len(k), drop = FALSE])
    V <- sweep(V, 2L, ifelse(s > 0, s, 1), "/")
  }
  list(V = V, s2 = pmax(e$values, 0))
}

# fda.usc::fdata2pc itself: its unit-norm singular vectors (components times
# delta, to share fpca_finish() with the fast engine), singular values and
# scores.
fpca_engine_reference <- function(cur, ncomp, call) {
  k <- min(ncomp, nrow(cur$Y), ncol(cur$Y))
  fd <- fda.usc::fdata(cur$Y, argvals = cur$argvals, rangeval = cur$rangeval)
  pc <- tryCatch(
    withCallingHandlers(fda.usc::fdata2pc(fd, ncomp = k),
      # fda.usc runs its inner products through foreach; without a registered
      # backend foreach warns once per session, which is noise here.
      warning = function(w) {
        if (grepl("executing %dopar% sequentially", conditionMessage(w), fixed = TRUE)) {
          invokeRestart("muffleWarning")
        }
      }),
    error = function(e) {
      hm_abort(c("fda.usc::fdata2pc() failed.", x = conditionMessage(e)), "engine_failed",
               argument = "engine", call = call)
    })
  delta <- fpca_delta(cur$argvals, cur$rangeval)
  comps <- t(pc$rotation$data)[, seq_len(k), drop = FALSE]
  list(V = unname(comps) * delta, s2 = (pc$d / delta)^2,
       scores = unname(pc$x[, seq_len(k), drop = FALSE]))
}

# Shared tail of both engines: zero components, sign convention, scores,
# variance explained, padding to ncomp.
fpca_finish <- function(raw, Yc, cur, mean, ncomp, delta, weights, score_rule = "trapezoid") {
  n <- nrow(Yc)
  L <- ncol(Yc)
  s2 <- sort(raw$s2, decreasing = TRUE)
  notes <- character(0)
  # Eigenvalues below this are rounding noise: relative to the largest (the
  # eigen route leaves noise of about L * eps there, the SVD route less), or
  # absolute relative to the size of the data (all curves identical).
  scale2 <- max(abs(cur$Y))^2 * n * L
  zero_tol <- max(1e-12 * s2[1], 1e-24 * scale2)
  nonzero <- s2 > zero_tol
  total <- sum(s2[nonzero])
  comps <- matrix(0, L, ncomp)
  k <- ncol(raw$V)
  comps[, seq_len(k)] <- raw$V / delta
  live <- seq_len(ncomp) <= min(k, sum(nonzero))
  comps[, !live] <- 0
  flip <- rep(1, ncomp)
  for (r in which(live)) flip[r] <- fpca_sign(comps[, r], weights)
  comps <- comps * rep(flip, each = L)
  if (is.null(raw$scores)) {
    scores <- Yc %*% (comps * weights)
  } else {
    # the reference engine's own scores (same trapezoidal inner products)
    scores <- matrix(0, n, ncomp)
    scores[, seq_len(k)] <- raw$scores
    scores <- scores * rep(flip * live, each = n)
  }
  var_explained <- numeric(ncomp)
  var_explained[live] <- s2[which(live)] / total
  if (total == 0) {
    var_explained[] <- NA_real_
    notes <- c(notes, "the curves do not vary: all components are zero and var_explained is NA")
  } else if (any(!live)) {
    dead <- paste(which(!live), collapse = ", ")
    notes <- c(notes, as.character(cli::pluralize(
      "{cli::qty(sum(!live))}component{?s} {dead}: zero variance (the centred curves have rank {sum(nonzero)}), returned as zero")))
  }
  new_fpca_fit(mean = mean, components = comps, scores = scores,
               eigenvalues = s2[nonzero] * delta^2 / n, var_explained = var_explained,
               argvals = cur$argvals, weights = weights, delta = delta, rangeval = cur$rangeval,
               engine = NA_character_, notes = notes, score_rule = score_rule)
}

# The one constructor of class "fpca_fit": every producer (fpca_fit()'s
# engines, the constant stand-in of a model) goes through it, so every fit
# has every field print(), predict() and the model code read.
new_fpca_fit <- function(mean, components, scores, eigenvalues, var_explained, argvals, weights,
                         delta, rangeval, engine, notes = character(), constant = FALSE,
                         score_rule = "trapezoid") {
  components <- as.matrix(components)
  ncomp <- ncol(components)
  labels <- paste0("FPC", seq_len(ncomp))
  scores <- as.matrix(scores)
  colnames(components) <- colnames(scores) <- labels
  var_explained <- stats::setNames(as.numeric(var_explained), labels)
  validate_fpca_fit(structure(list(
    mean = as.numeric(mean), components = components, scores = scores,
    eigenvalues = eigenvalues, var_explained = var_explained,
    argvals = argvals, weights = weights, delta = delta, rangeval = rangeval,
    n = nrow(scores), ncomp = ncomp, engine = engine, notes = notes, constant = constant,
    score_rule = score_rule),
    class = "fpca_fit"))
}

# Shapes that fit together: L grid points, ncomp components, n curves.
validate_fpca_fit <- function(x) {
  L <- length(x$mean)
  stopifnot(
    nrow(x$components) == L, length(x$argvals) == L, length(x$weights) == L,
    ncol(x$scores) == x$ncomp, length(x$var_explained) == x$ncomp,
    is.numeric(x$delta), length(x$delta) == 1L, length(x$rangeval) == 2L,
    x$score_rule %in% c("trapezoid", "least_squares")
  )
  x
}

# +1 or -1: makes the component's integral positive, or, when the integral is
# zero to rounding, its largest-magnitude value positive.
fpca_sign <- function(phi, weights) {
  integral <- sum(weights * phi)
  if (abs(integral) > 1e-8 * sum(weights * abs(phi))) return(sign(integral))
  if (phi[which.max(abs(phi))] < 0) -1 else 1
}

#' @export
print.fpca_fit <- function(x, ...) {
  k <- ncol(x$components)
  n <- as.integer(x$n)
  scores <- if (identical(x$score_rule, "least_squares")) ", least-squares scores" else ""
  cli::cat_line(cli::pluralize(
    "<fpca_fit> {n} curve{?s} x {length(x$mean)} points, {k} component{?s} ({x$engine} engine{scores})"))
  ve <- x$var_explained
  cli::cat_line("  variance explained: ", paste(sprintf("%.2f%%", 100 * ve), collapse = ", "),
                " (total ", sprintf("%.2f%%", 100 * sum(ve)), ")")
  if (length(x$notes)) cli::cat_line("  note: ", x$notes)
  invisible(x)
}

# The residual curves of aligned curves `warped` (n x L x p) after each DoF's
# FPC reconstruction: an n x L x p array.
fpca_residual_curves <- function(warped, fpca) {
  out <- warped
  for (j in seq_along(fpca)) {
    f <- fpca[[j]]
    fitted <- sweep(f$scores %*% t(f$components), 2, f$mean, "+")
    out[, , j] <- warped[, , j] - fitted
  }
  out
}
