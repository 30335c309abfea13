# The abandoned alternative of Jeppsson (2017, sections 4.1.3 and 5.1.2):
# after alignment, PCA of the 16-dimensional hand posture in every frame
# separately (eq. 4.1), then FPCA of each PC's weight curve over the frames
# (eq. 4.2). Because each frame's PCA is done in isolation, the signs of its
# PCs are arbitrary and flip between neighbouring frames (Figure 5.3), so the
# weight curves jump and two FPCs cannot follow them. The thesis' repair
# flipped each frame's PC to agree with the previous frame; it smooths the
# curves but the model still loses the information of the dropped PCs. This
# file keeps that experiment reproducible for the thesis report
# (reproduce_thesis(), its Figure 5.3 section), which shows why it fails; no
# other verb uses it.

#' Fit the frame-PCA alternative model (abandoned in the thesis)
#'
#' For one grasp type: align the recordings (as [fit_grasp_model()] does),
#' then at every template frame `t` run a PCA of the postures
#' `g_t` (one value per DoF) of all recordings, keeping `d` PCs
#' `p_it` and their weights `alpha_it` (eq. 4.1, with the
#' frame's mean posture added back); concatenate each PC's weights over the
#' frames into a curve and fit an FPCA with `k` components to it (eq. 4.2),
#' and a Gaussian mixture on each PC's FPC scores.
#'
#' The signs of PCs computed frame by frame are arbitrary. `sign_flips` counts,
#' per PC, the frames whose PC points away from the previous frame's
#' (negative inner product); these make the weight curves jump (thesis
#' Figure 5.3). With `align_signs = TRUE` each frame's PC (and its weights) is
#' flipped to agree with the previous frame's, the repair the thesis tried.
#'
#' `reconstruction` compares, per recording, the root-mean-square error of
#' the frame-PCA model's reconstruction (eq. 4.3) with that of the main
#' model's per-DoF FPCA with the same number `k` of components on the same
#' aligned data: the evidence for abandoning the approach.
#'
#' @param x A [grasps()] object of one grasp type, or an alignment from
#'   `align_recordings()`.
#' @param frame_ncomp Number of PCs kept in each frame (`d` in the thesis).
#' @param ncomp Number of FPCs of each PC's weight curve (and of each DoF in the
#'   comparison).
#' @param align_signs Flip each frame's PCs to agree with the previous frame's.
#' @param nbasis Each weight curve is "approximated as a continuous function"
#'   (thesis 4.1.3) by least squares on this many cosine basis functions
#'   before the FPCA; `NULL` skips the smoothing. Without smoothing a sign
#'   flip multiplies one frame of every curve by -1, an orthogonal change of
#'   coordinates that leaves an (unsmoothed) FPCA's reconstruction unchanged;
#'   it is the continuous approximation that the jumps spoil.
#' @param ... Passed to [fit_grasp_model()]'s alignment step when `x` is a
#'   grasps object: `engine`, `overlong`, `warping`, `max_stall`.
#' @return An object of class `frame_pca_model`: a list with `loadings`
#'   (array L x p x d, after any sign repair), `weights` (array n x L x d),
#'   `loadings_raw` and `weights_raw` (before repair), `frame_mean` (L x p),
#'   `frame_var_explained` (L x d proportions of each frame's variance),
#'   `sign_flips` (data frame: `component`, `raw`, `aligned` counts),
#'   `flip_frames` (logical L x d, raw flips), `fpca` (one `fpca_fit()` per
#'   PC), `gmm` (one `gmm_fit()` per PC), `reconstruction` (data frame: `id`,
#'   `frame_pca_rmse`, `fpca_rmse`), `align_signs`, `frame_ncomp`, `ncomp`, `ids`, `dofs`,
#'   `grasp`.
#' @seealso `autoplot.frame_pca_model()`, [fit_grasp_model()] (the model that
#'   was kept).
#' @noRd
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' raw <- fit_frame_pca_model(g)
#' fixed <- fit_frame_pca_model(g, align_signs = TRUE)
#' raw$sign_flips
#' colMeans(fixed$reconstruction[, -1])
fit_frame_pca_model <- function(x, frame_ncomp = 3, ncomp = 2, align_signs = FALSE, nbasis = 10, ...) {
  call <- rlang::caller_env()
  d <- check_whole(frame_ncomp, "frame_ncomp", max = 50, call = call)
  ncomp <- check_whole(ncomp, "ncomp", max = 50, call = call)
  check_whole(nbasis, "nbasis", max = 1000, allow_null = TRUE, call = call)
  if (inherits(x, "grasp_alignment")) {
    aln <- x
    grasp <- NA_character_
  } else {
    check_grasps(x, call = call)
    x <- select_one_type(x, NULL, call)
    aln <- frame_pca_alignment(x, call, ...)
    grasp <- as.character(x$meta$grasp[1])
  }
  W <- aln$warped
  n <- dim(W)[1]
  L <- dim(W)[2]
  p <- dim(W)[3]
  if (d > p) {
    hm_abort("{.arg frame_ncomp} = {d} exceeds the number of DoFs ({p}).", "bad_input", argument = "frame_ncomp", call = call)
  }
  if (n < ncomp + 1L || n < 2L) {
    hm_abort("The frame-PCA model needs at least {max(2, ncomp + 1)} aligned recordings, not {n}.",
             "too_few_recordings", call = call)
  }
  ids <- dimnames(W)[[1]] %||% paste0("r", seq_len(n))
  dofs <- dimnames(W)[[3]] %||% paste0("dof", seq_len(p))
  per_frame <- frame_pcas(W, d)
  raw_flips <- sign_flip_frames(per_frame$loadings)
  loadings <- per_frame$loadings
  weights <- per_frame$weights
  if (isTRUE(align_signs)) {
    rep <- align_frame_signs(loadings, weights)
    loadings <- rep$loadings
    weights <- rep$weights
  }
  aligned_flips <- sign_flip_frames(loadings)
  argvals <- seq(0, 1, length.out = L)
  S <- cosine_smoother(L, nbasis)
  fpca <- lapply(seq_len(d), function(i) {
    fit_fpca_or_constant(matrix(weights[, , i], n, L) %*% S, argvals, ncomp, "fast")
  })
  gmm <- lapply(fpca, fit_mixture, k = 2L, engine = "fast")
  names(fpca) <- names(gmm) <- paste0("PC", seq_len(d))

  # eq. 4.3: posture at frame t = frame mean + sum_i alpha_hat_i(t) p_{i,t}
  recon <- array(per_frame$mean[rep(seq_len(L), each = n), ], c(n, L, p))
  for (i in seq_len(d)) {
    a_hat <- ls_reconstruct(fpca[[i]], matrix(weights[, , i], n, L) %*% S)
    for (t in seq_len(L)) recon[, t, ] <- recon[, t, ] + outer(a_hat[, t], loadings[t, , i])
  }
  rmse_frame <- sqrt(apply((W - recon)^2, 1, mean))
  rmse_fpca <- per_dof_fpca_rmse(W, argvals, ncomp)

  dimnames(loadings) <- dimnames(per_frame$loadings) <- list(NULL, dofs, paste0("PC", seq_len(d)))
  dimnames(weights) <- dimnames(per_frame$weights) <- list(ids, NULL, paste0("PC", seq_len(d)))
  structure(list(
    grasp = grasp, ids = ids, dofs = dofs, frame_ncomp = as.integer(d), ncomp = as.integer(ncomp), nbasis = nbasis,
    align_signs = isTRUE(align_signs),
    loadings = loadings, weights = weights,
    loadings_raw = per_frame$loadings, weights_raw = per_frame$weights,
    frame_mean = per_frame$mean, frame_var_explained = per_frame$var_explained,
    sign_flips = data.frame(component = paste0("PC", seq_len(d)), raw = as.integer(colSums(raw_flips)),
                            aligned = as.integer(colSums(aligned_flips)), row.names = NULL),
    flip_frames = raw_flips,
    fpca = fpca, gmm = gmm,
    reconstruction = data.frame(id = ids, frame_pca_rmse = rmse_frame, fpca_rmse = rmse_fpca,
                                row.names = NULL, stringsAsFactors = FALSE)
  ), class = "frame_pca_model")
}

frame_pca_alignment <- function(x, call, engine = "fast", overlong = overlong_rule(),
                                warping = c("dtw", "linear"), max_stall = 0.25) {
  warping <- check_choice(warping, arg = "warping", call = call)
  settings <- list(overlong = overlong, warping = warping, max_stall = max_stall)
  prepare_alignment(x, settings, resolve_engines(engine, call), call)$alignment
}

# PCA of the postures in each frame, in isolation: loadings L x p x d,
# weights n x L x d, frame means L x p. Signs are whatever the SVD returns.
frame_pcas <- function(W, d) {
  n <- dim(W)[1]
  L <- dim(W)[2]
  p <- dim(W)[3]
  loadings <- array(0, c(L, p, d))
  weights <- array(0, c(n, L, d))
  mu <- matrix(0, L, p)
  ve <- matrix(NA_real_, L, d)
  for (t in seq_len(L)) {
    X <- matrix(W[, t, ], n, p)
    mu[t, ] <- colMeans(X)
    Xc <- sweep(X, 2, mu[t, ])
    s <- svd(Xc, nu = 0, nv = d)
    V <- s$v[, seq_len(d), drop = FALSE]
    loadings[t, , ] <- V
    weights[, t, ] <- Xc %*% V
    tot <- sum(s$d^2)
    if (tot > 0) ve[t, ] <- (s$d^2 / tot)[seq_len(d)]
  }
  list(loadings = loadings, weights = weights, mean = mu, var_explained = ve)
}

# Hat matrix (L x L, symmetric) of least squares on the first `nbasis`
# cosine (DCT-II) basis functions: right-multiplying curves (rows) by it gives
# their smooth approximation. NULL or nbasis >= L: the identity.
cosine_smoother <- function(L, nbasis) {
  if (is.null(nbasis) || nbasis >= L) return(diag(L))
  t <- (seq_len(L) - 0.5) / L
  B <- outer(t, seq_len(nbasis) - 1, function(t, m) cos(pi * m * t))
  B %*% solve(crossprod(B), t(B))
}

# Frames whose PC points away from the previous frame's (L x d logical).
sign_flip_frames <- function(loadings) {
  L <- dim(loadings)[1]
  d <- dim(loadings)[3]
  out <- matrix(FALSE, L, d, dimnames = list(NULL, paste0("PC", seq_len(d))))
  if (L < 2L) return(out)
  for (i in seq_len(d)) {
    V <- matrix(loadings[, , i], L)
    out[-1, i] <- rowSums(V[-1, , drop = FALSE] * V[-L, , drop = FALSE]) < 0
  }
  out
}

# The thesis' repair: walk forward through the frames, flipping each PC (and
# its weights) to agree in sign with the previous frame's.
align_frame_signs <- function(loadings, weights) {
  L <- dim(loadings)[1]
  d <- dim(loadings)[3]
  if (L < 2L) return(list(loadings = loadings, weights = weights))
  for (i in seq_len(d)) for (t in 2:L) {
    if (sum(loadings[t, , i] * loadings[t - 1L, , i]) < 0) {
      loadings[t, , i] <- -loadings[t, , i]
      weights[, t, i] <- -weights[, t, i]
    }
  }
  list(loadings = loadings, weights = weights)
}

# Best reconstruction of curves Y (rows) in the span of a fit's mean and
# components: least squares on the grid. (The FPCA's own scores are
# trapezoidal-rule inner products with components normalised on the uniform
# rule, as in fda.usc, so scores x components does not exactly rebuild even a
# curve inside the span; both models are compared on the same footing here.)
ls_reconstruct <- function(fit, Y) {
  n <- nrow(Y)
  L <- ncol(Y)
  P <- as.matrix(fit$components)
  Yc <- Y - matrix(fit$mean, n, L, byrow = TRUE)
  live <- colSums(P^2) > 0
  if (!any(live)) return(matrix(fit$mean, n, L, byrow = TRUE))
  P <- P[, live, drop = FALSE]
  coef <- Yc %*% P %*% solve(crossprod(P))
  matrix(fit$mean, n, L, byrow = TRUE) + coef %*% t(P)
}

# RMSE per recording of the main model's reconstruction: per-DoF FPCA with k
# components on the same aligned curves.
per_dof_fpca_rmse <- function(W, argvals, k) {
  n <- dim(W)[1]
  L <- dim(W)[2]
  sq <- numeric(n)
  for (j in seq_len(dim(W)[3])) {
    Y <- matrix(W[, , j], n, L)
    f <- fit_fpca_or_constant(Y, argvals, k, "fast")
    R <- Y - ls_reconstruct(f, Y)
    sq <- sq + rowSums(R^2)
  }
  sqrt(sq / (L * dim(W)[3]))
}

#' @export
print.frame_pca_model <- function(x, ...) {
  what <- if (is.na(x$grasp)) "alignment" else x$grasp
  signs <- if (x$align_signs) ", signs aligned" else ""
  cli::cat_line(cli::pluralize(
    "<frame_pca_model> {what}: {length(x$ids)} recording{?s}, {x$frame_ncomp} PC{?s} per frame, {x$ncomp} FPC{?s} per PC{signs}"))
  cli::cat_line("  sign flips between frames (raw / after repair): ",
                paste0(x$sign_flips$component, " ", x$sign_flips$raw, "/", x$sign_flips$aligned, collapse = ", "))
  r <- x$reconstruction
  cli::cat_line(sprintf("  reconstruction RMSE: frame-PCA %.3g vs per-DoF FPCA %.3g (mean over recordings)",
                        mean(r$frame_pca_rmse), mean(r$fpca_rmse)))
  invisible(x)
}

#' Plot the frame-PCA alternative: sign flips between frames (Figure 5.3)
#'
#' `type = "weights"` draws, for one PC, each recording's weight
#' `alpha_it` over the frames, before and after the sign repair
#' (when the model was fitted with `align_signs = TRUE`), with the frames
#' where the raw PC flipped marked by dashed lines: the jumps of Figure 5.3.
#' `type = "loadings"` draws the loading of every DoF on that PC over the
#' frames; a flip mirrors all of them at once.
#'
#' @param object A `frame_pca_model` from [fit_frame_pca_model()].
#' @param type `"weights"` or `"loadings"`.
#' @param component Which PC (1 to `d`).
#' @param max_recordings Draw at most this many recordings' weight curves.
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @method autoplot frame_pca_model
#' @noRd
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' ggplot2::autoplot(fit_frame_pca_model(g, align_signs = TRUE))
autoplot.frame_pca_model <- function(object, type = c("weights", "loadings"), component = 1,
                                     max_recordings = 30, ...) {
  type <- check_choice(type, arg = "type", call = rlang::current_env())
  component <- check_whole(component, "component", max = object$frame_ncomp, call = rlang::current_env())
  L <- dim(object$loadings)[1]
  flips <- which(object$flip_frames[, component])
  versions <- list(raw = list(w = object$weights_raw, l = object$loadings_raw))
  if (object$align_signs) versions$aligned <- list(w = object$weights, l = object$loadings)
  if (type == "weights") {
    keep <- seq_len(min(length(object$ids), max_recordings))
    df <- do.call(rbind, lapply(names(versions), function(v) {
      A <- matrix(versions[[v]]$w[keep, , component], length(keep))
      data.frame(version = v, id = rep(object$ids[keep], times = L), frame = rep(seq_len(L), each = length(keep)),
                 value = as.vector(A), stringsAsFactors = FALSE)
    }))
    ylab <- sprintf("weight on PC%d", component)
  } else {
    df <- do.call(rbind, lapply(names(versions), function(v) {
      V <- matrix(versions[[v]]$l[, , component], L)
      data.frame(version = v, id = rep(object$dofs, each = L), frame = rep(seq_len(L), times = length(object$dofs)),
                 value = as.vector(V), stringsAsFactors = FALSE)
    }))
    ylab <- sprintf("loading on PC%d", component)
  }
  df$version <- factor(df$version, levels = c("raw", "aligned"))
  base <- ggplot2::ggplot(df, ggplot2::aes(x = .data$frame, y = .data$value, group = .data$id))
  lines <- if (type == "weights") {
    ggplot2::geom_line(colour = "grey40", alpha = 0.7)
  } else {
    ggplot2::geom_line(ggplot2::aes(colour = .data$id), alpha = 0.8)
  }
  p <- base + lines +
    ggplot2::facet_wrap(~version, ncol = 1, scales = "free_y") +
    ggplot2::labs(x = "warped frame", y = ylab, colour = "DoF",
                  title = as.character(cli::pluralize("Per-frame PCA: {length(flips)} sign flip{?s} of PC{as.integer(component)}"))) +
    ggplot2::theme_minimal()
  if (length(flips)) {
    p <- p + ggplot2::geom_vline(xintercept = flips - 0.5, linetype = "dashed", colour = "red", alpha = 0.6)
  }
  p
}
