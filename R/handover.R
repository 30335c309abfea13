# Sparse-marker hand-over reconstruction (Wheatland, Joerg and Zordan):
# PCA of the reference joint angles, a locally weighted regression (LWR) per
# query frame from the sparse markers to the principal components, a cone
# filter over the component trajectories, back-projection to joint angles.
# Marker placement, ranking and selection are in R/markers.R; the search
# baseline and the evaluation (handover_error()) in
# R/handover-evaluate.R; reconstruction in R/handover-reconstruct.R; the
# regression core is in C (src/handover-lwr.c).

#' Fit a sparse-marker hand-over model
#'
#' Builds the reconstruction model of Wheatland, Joerg and Zordan from a
#' reference database recorded with the full marker set: a PCA of the
#' reference joint angles and, for each reference frame, the positions of the
#' sparse markers (relative to the root link) and the component scores.
#' `predict()` ([predict.handover_model()]) then rebuilds all joint angles
#' from the sparse markers.
#'
#' For each query frame the regression weights every reference frame by the
#' inverse Euclidean distance between its sparse markers and the query's, and
#' fits a weighted linear model from marker positions to the first `ncomp`
#' component scores (centred on the query, so the prediction is the fitted
#' intercept). The paper weights the whole database; for speed only the `neighbours`
#' nearest reference frames (in marker space) enter each regression. Their
#' weights dominate anyway, and `neighbours = Inf` restores the paper's all-frame
#' weighting. A small ridge penalty (`ridge` times the mean diagonal of the
#' slope block) keeps the local fit defined when neighbours are nearly
#' collinear; a reference frame at distance zero gets weight `1 / eps`, so a
#' frame seen in the reference is reconstructed almost exactly (to about
#' 1e-5 degrees with `smooth = FALSE`; the cone filter then blends it with its
#' neighbours in time, a few tenths of a degree on simulated recordings).
#'
#' `method = "direct"` is the no-PCA baseline of the paper's Figure 2
#' ("fitting markers to joint angles directly"): one least-squares linear map
#' from the markers straight to the joint angles over the whole database.
#' It is a global fit on purpose: a *local* regression straight to the joint
#' angles is algebraically the same as `method = "pca"` with all components,
#' because the regression is linear in its targets and the PCA rotation is
#' invertible (the tests check this identity). PCA therefore only changes a
#' local linear reconstruction through `ncomp`; the paper found all
#' components best, which is the default.
#'
#' @param reference A [grasps()] object recorded with the full marker set
#'   (joint angles; markers are computed by [forward_kinematics()]).
#' @param markers Marker names (see [select_markers()]), a marker set as in
#'   [forward_kinematics()] and [hand_3d()]; `NULL` (default) for the
#'   `n_markers` best ranked on `reference` (`select_markers(reference,
#'   n_markers)`).
#' @param n_markers With `markers = NULL`: how many markers to select
#'   (default 6). A count is never given through `markers`.
#' @param ncomp Number of principal components regressed and back-projected;
#'   `NULL` for all (one per DoF).
#' @param neighbours Number of nearest reference frames per regression
#'   (`Inf` = all; `k` in development versions).
#' @param smooth Smooth the reconstructed component trajectories with a cone
#'   (triangular) filter.
#' @param filter_size Cone filter width in frames; by default the paper's 17
#'   frames at 120 Hz scaled to the reference rate (7 at 50 Hz), odd.
#' @param method `"pca"` (the paper's method) or `"direct"` (no-PCA baseline).
#' @param ridge Relative ridge penalty of the local regressions.
#' @param eps Smallest marker distance (mm) used in the inverse-distance
#'   weights.
#' @param skeleton,... Passed to [forward_kinematics()] (e.g. `mapping`).
#' @return An object of class `handover_model`.
#' @seealso [predict.handover_model()], [select_markers()], [handover_error()] (`by = "markers"` compares marker sets)
#' @export
#' @examples
#' set.seed(1)
#' t <- seq(0, 1, length.out = 40)
#' ang <- outer(t, runif(16, 10, 60)) + outer(sin(2 * pi * t), runif(16, 0, 10))
#' ref <- grasps(list(ang, ang[40:1, ] * 0.8), dofs = hust_dofs$name)
#' fit <- fit_handover(ref, markers = c("index_tip", "ring_tip", "thumb_tip"), neighbours = 30)
#' fit
#' rec <- predict(fit, ref[1])
#' handover_error(ref[1], rec)
fit_handover <- function(reference, markers = NULL, n_markers = 6, ncomp = NULL, neighbours = 256, smooth = TRUE,
                         filter_size = NULL, method = c("pca", "direct"), ridge = 1e-3,
                         eps = 1e-6, skeleton = hand_skeleton(), ...) {
  call <- rlang::caller_env()
  method <- check_choice(method, arg = "method", call = rlang::current_env())
  check_grasps(reference, "reference", call = call)
  check_dots_for(list(...), forward_kinematics, "forward_kinematics", exclude = c("x", "skeleton"),
                 call = call)
  # (a count through `markers` was the old meaning: say where it went)
  if (is.numeric(markers)) {
    hm_abort(c("{.arg markers} must be marker names, not {describe_value(markers)}.",
               renamed_argument_hints("markers")), "bad_markers", argument = "markers", call = call)
  }
  n_hand <- sum(hand_marker_set()$segment == "hand")
  n_markers <- check_whole(n_markers, "n_markers", max = n_hand, class = "bad_markers", call = call)
  all_markers <- markers_from_angles(reference, skeleton = skeleton, ...)
  ref_all <- do.call(rbind, all_markers)
  if (is.null(markers)) markers <- rank_markers(ref_all, call = call)$marker[seq_len(n_markers)]
  check_marker_names(markers, call = call)
  markers <- as.vector(markers)  # a select_markers() result's ranking or search stays there
  hand <- hand_marker_set()$marker[hand_marker_set()$segment == "hand"]
  if (!all(markers %in% hand)) {
    hm_abort(c("{.arg markers}: marker{?s} {.val {setdiff(markers, hand)}} ride{?s/} on the root link and {?is/are} constant there.",
               i = "Use hand markers for hand-over."), "bad_markers", argument = "markers", call = call)
  }
  ridge <- check_number(ridge, "ridge", min = 0, min_open = TRUE, call = call)
  eps <- check_number(eps, "eps", min = 0, min_open = TRUE, call = call)
  handover_build(ref_all, do.call(rbind, reference$recordings), markers,
                 ncomp = ncomp, neighbours = neighbours, smooth = smooth, filter_size = filter_size,
                 method = method, ridge = ridge, eps = eps, rate = reference$rate,
                 unit = reference$unit, skeleton = skeleton, fk_args = list(...),
                 reference = data.frame(recordings = length(reference), frames = nrow(ref_all),
                                        grasp_types = length(unique(stats::na.omit(reference$meta$grasp))),
                                        subjects = length(unique(stats::na.omit(reference$meta$subject)))),
                 call = call)
}

# The model proper, from stacked reference marker positions (any superset of
# the chosen markers' columns) and joint angles; shared by fit_handover() and
# the marker search, which must not rerun forward kinematics per candidate.
handover_build <- function(ref_all, ref_y, markers, ncomp = NULL, neighbours = 256, smooth = TRUE,
                           filter_size = NULL, method = "pca", ridge = 1e-3, eps = 1e-6,
                           rate = 50, unit = "deg", skeleton = NULL, fk_args = list(),
                           reference = NULL, call = rlang::caller_env()) {
  cols <- marker_columns(markers)
  ref_x <- ref_all[, cols, drop = FALSE]
  n_ref <- nrow(ref_y)
  d <- length(cols)
  p <- ncol(ref_y)
  if (n_ref < d + 2L) {
    hm_abort(c("The reference has {n_ref} frame{?s}, too few for a regression on {length(markers)} marker{?s}.",
               i = "It needs at least {d + 2} frames (3 coordinates per marker + 2)."),
             "reference_too_small", argument = "reference", call = call)
  }
  ncomp <- check_whole(ncomp, "ncomp", max = p, allow_null = TRUE, call = call) %||% p
  # (at least 3 coordinates per marker + 2 neighbours for a local regression)
  if (!identical(neighbours, Inf)) neighbours <- check_whole(neighbours, "neighbours", min = d + 2, call = call)
  neighbours_used <- as.integer(min(neighbours, n_ref))
  filter_size <- check_number(filter_size, "filter_size", min = 1, allow_null = TRUE, call = call) %||%
    cone_size(rate)
  smooth <- check_flag(smooth, "smooth", call = call)
  pca <- stats::prcomp(ref_y, center = TRUE, scale. = FALSE)
  # keep one component per DoF even when the reference is rank deficient
  rot <- pca$rotation
  if (ncol(rot) < p) rot <- complete_basis(rot)
  scores <- sweep(ref_y, 2, pca$center) %*% rot
  direct <- if (method == "direct") global_linear_fit(ref_x, ref_y, ridge) else NULL
  new_handover_model(
    markers = markers, method = method, ncomp = ncomp, neighbours = neighbours, neighbours_used = neighbours_used,
    ridge = ridge, eps = eps, smooth = isTRUE(smooth), filter_size = as.integer(filter_size),
    center = pca$center, rotation = rot,
    sdev = c(pca$sdev, rep(0, p - length(pca$sdev)))[seq_len(p)],
    ref_x = ref_x, ref_scores = scores, direct = direct,
    dofs = colnames(ref_y), rate = rate, unit = unit, skeleton = skeleton, fk_args = fk_args,
    reference = reference %||% data.frame(recordings = NA_integer_, frames = n_ref,
                                          grasp_types = NA_integer_, subjects = NA_integer_))
}

# The one constructor of class "handover_model" (fit_handover() and the
# marker search both build through handover_build(), which ends here).
new_handover_model <- function(markers, method, ncomp, neighbours, neighbours_used, ridge, eps, smooth, filter_size,
                               center, rotation, sdev, ref_x, ref_scores, direct, dofs, rate, unit,
                               skeleton, fk_args, reference) {
  validate_handover_model(structure(list(
    markers = markers, method = method, ncomp = ncomp, neighbours = neighbours, neighbours_used = neighbours_used, ridge = ridge,
    eps = eps, smooth = smooth, filter_size = filter_size, center = center, rotation = rotation,
    sdev = sdev, ref_x = ref_x, ref_scores = ref_scores, direct = direct, dofs = dofs, rate = rate,
    unit = unit, skeleton = skeleton, fk_args = fk_args, reference = reference
  ), class = "handover_model"))
}

# The fields its predict() reads, re-checked there (check_fitted_parts()).
#' @export
classifier_parts.handover_model <- function(object) {
  c("markers", "center", "rotation", "ref_x", "ref_scores", "dofs")
}

# Shapes that fit together: p DoFs (a full p x p rotation), 3 reference
# marker columns per marker, one score row per reference frame.
validate_handover_model <- function(x) {
  p <- length(x$dofs)
  stopifnot(
    is.character(x$markers), length(x$markers) >= 1L, x$method %in% c("pca", "direct"),
    identical(colnames(x$ref_x), marker_columns(x$markers)),
    has_dim(x$rotation, c(p, p)), length(x$center) == p, length(x$sdev) == p,
    nrow(x$ref_scores) == nrow(x$ref_x), ncol(x$ref_scores) == p,
    x$ncomp >= 1L, x$ncomp <= p, x$neighbours_used >= 1L, x$neighbours_used <= nrow(x$ref_x),
    x$method == "pca" || is.list(x$direct),
    x$unit %in% c("deg", "rad", "raw"), is.null(x$skeleton) || inherits(x$skeleton, "hand_skeleton"),
    is.data.frame(x$reference)
  )
  x
}

# Extend an orthonormal basis with fewer columns than rows to a full one.
complete_basis <- function(rot) {
  p <- nrow(rot)
  q <- qr.Q(qr(cbind(rot, diag(p))))[, seq_len(p)]
  q[, seq_len(ncol(rot))] <- rot
  dimnames(q) <- list(rownames(rot), paste0("PC", seq_len(p)))
  q
}

# Cone filter width for a sampling rate: the paper's 17 frames at 120 Hz,
# scaled to the same duration and made odd.
cone_size <- function(rate) {
  as.integer(max(1, 2 * round((17 * rate / 120 - 1) / 2) + 1))
}

# Triangular (cone) smoothing of each column of x; near the ends the weights
# are renormalised over the frames that exist, so the ends are not pulled
# toward zero.
cone_filter <- function(x, size) {
  n <- nrow(x)
  h <- (size - 1L) %/% 2L
  if (h < 1L || n < 2L) return(x)
  acc <- x * (h + 1)
  wsum <- rep(h + 1, n)
  for (j in seq_len(min(h, n - 1L))) {
    w <- h + 1 - j
    lo <- seq_len(n - j)
    acc[lo, ] <- acc[lo, ] + w * x[lo + j, , drop = FALSE]
    acc[lo + j, ] <- acc[lo + j, ] + w * x[lo, , drop = FALSE]
    wsum[lo] <- wsum[lo] + w
    wsum[lo + j] <- wsum[lo + j] + w
  }
  acc / wsum
}

# Ridge-stabilised global least squares from markers to targets (the no-PCA
# baseline), returned as a coefficient matrix for cbind(1, markers).
global_linear_fit <- function(x, y, ridge) {
  mu <- colMeans(x)
  xc <- sweep(x, 2, mu)
  g <- crossprod(xc)
  diag(g) <- diag(g) + ridge * mean(diag(g)) + 1e-12
  b <- solve(g, crossprod(xc, sweep(y, 2, colMeans(y))))
  list(mu_x = mu, mu_y = colMeans(y), beta = b)
}

# Locally weighted linear regression of ref_y on ref_x, evaluated at each row
# of query. Neighbours are found by brute force on the expanded squared
# distance in blocks (one BLAS product per block); their exact distances are
# then recomputed, so a zero distance is exactly zero. The local fit is
# centred on the query, so its prediction is the intercept, which we get from
# the weighted moments by a Schur complement (one d x d solve per frame).
# Reference markers are stored transposed (d x N) so that a neighbour set is
# a column subset and the query recycles down its columns.
lwr_predict <- function(ref_x, ref_y, query, k, ridge, eps) {
  storage.mode(ref_x) <- storage.mode(ref_y) <- storage.mode(query) <- "double"
  .Call(hm_lwr_predict, ref_x, ref_y, query, as.integer(min(k, nrow(ref_x))), as.double(ridge),
        as.double(eps))
}

#' @export
print.handover_model <- function(x, ...) {
  r <- x$reference
  method <- if (x$method == "pca") "PCA + locally weighted regression" else "direct (no-PCA) linear"
  cli::cat_line(cli::pluralize("<handover_model> {method} reconstruction from {length(x$markers)} marker{?s}"))
  cli::cat_line("  markers: ", paste(x$markers, collapse = ", "))
  counts <- lapply(r[c("frames", "recordings", "grasp_types", "subjects")], as.integer)
  cli::cat_line(cli::pluralize(paste0(
    "  reference: {counts$frames} frame{?s} in {counts$recordings} recording{?s} ",
    "({counts$grasp_types} grasp type{?s}, {counts$subjects} subject{?s}), {sprintf('%g', x$rate)} Hz")))
  if (x$method == "pca") {
    cli::cat_line(sprintf("  components: %d of %d; neighbours per frame: %d; cone filter: %s",
                          as.integer(x$ncomp), length(x$dofs), as.integer(x$neighbours_used),
                          if (x$smooth) paste(x$filter_size, "frames") else "off"))
  }
  invisible(x)
}
