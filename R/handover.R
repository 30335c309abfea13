# Sparse-marker hand-over reconstruction (Wheatland, Joerg and Zordan):
# PCA of the reference joint angles, a locally weighted regression (LWR) per
# query frame from the sparse markers to the principal components, a cone
# filter over the component trajectories, back-projection to joint angles.
# Marker placement and ranking are in R/markers.R; the baselines and the
# evaluation helpers (search_markers(), handover_error(), compare_marker_sets(),
# handover_pca_error()) are at the end of this file; the regression core is
# in C (src/handover-lwr.c) with an R reference engine here.

#' Fit a sparse-marker hand-over model
#'
#' Builds the reconstruction model of Wheatland, Joerg and Zordan from a
#' reference database recorded with the full marker set: a PCA of the
#' reference joint angles and, for each reference frame, the positions of the
#' sparse markers (relative to the root link) and the component scores.
#' [reconstruct()] then rebuilds all joint angles from the sparse markers.
#'
#' For each query frame the regression weights every reference frame by the
#' inverse Euclidean distance between its sparse markers and the query's, and
#' fits a weighted linear model from marker positions to the first `ncomp`
#' component scores (centred on the query, so the prediction is the fitted
#' intercept). The paper weights the whole database; for speed only the `k`
#' nearest reference frames (in marker space) enter each regression. Their
#' weights dominate anyway, and `k = Inf` restores the paper's all-frame
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
#'   (joint angles; markers are computed by [markers_from_angles()]).
#' @param markers Marker names (see `hand_marker_set()`), or a number `n` to
#'   use `select_markers(reference, n)`.
#' @param ncomp Number of principal components regressed and back-projected;
#'   `NULL` for all (one per DoF).
#' @param k Number of nearest reference frames per regression (`Inf` = all).
#' @param smooth Smooth the reconstructed component trajectories with a cone
#'   (triangular) filter.
#' @param filter_size Cone filter width in frames; by default the paper's 17
#'   frames at 120 Hz scaled to the reference rate (7 at 50 Hz), odd.
#' @param method `"pca"` (the paper's method) or `"direct"` (no-PCA baseline).
#' @param ridge Relative ridge penalty of the local regressions.
#' @param eps Smallest marker distance (mm) used in the inverse-distance
#'   weights.
#' @param skeleton,... Passed to [markers_from_angles()] (e.g. `mapping`).
#' @return An object of class `handover_model`.
#' @seealso [reconstruct()], [select_markers()], [compare_marker_sets()]
#' @export
#' @examples
#' set.seed(1)
#' t <- seq(0, 1, length.out = 40)
#' ang <- outer(t, runif(16, 10, 60)) + outer(sin(2 * pi * t), runif(16, 0, 10))
#' ref <- grasps(list(ang, ang[40:1, ] * 0.8), dofs = hust_dofs$name)
#' fit <- fit_handover(ref, markers = c("index_tip", "ring_tip", "thumb_tip"), k = 30)
#' fit
#' rec <- reconstruct(fit, ref[1])
#' handover_error(ref[1], rec)
fit_handover <- function(reference, markers = 6, ncomp = NULL, k = 256, smooth = TRUE,
                         filter_size = NULL, method = c("pca", "direct"), ridge = 1e-3,
                         eps = 1e-6, skeleton = hand_skeleton(), ...) {
  call <- rlang::caller_env()
  method <- check_choice(method, arg = "method", call = rlang::current_env())
  check_grasps(reference, "reference", call = call)
  all_markers <- markers_from_angles(reference, skeleton = skeleton, ...)
  ref_all <- do.call(rbind, all_markers)
  if (is.numeric(markers) && length(markers) == 1L) {
    markers <- select_markers(rank_markers(ref_all), markers)
  }
  check_marker_names(markers, call = call)
  hand <- hand_marker_set()$marker[hand_marker_set()$segment == "hand"]
  if (!all(markers %in% hand)) {
    hm_abort(c("Marker{?s} {.val {setdiff(markers, hand)}} ride{?s/} on the root link and {?is/are} constant there.",
               i = "Use hand markers for hand-over."), "bad_markers", argument = "markers", call = call)
  }
  ridge <- check_number(ridge, "ridge", min = 0, min_open = TRUE, call = call)
  eps <- check_number(eps, "eps", min = 0, min_open = TRUE, call = call)
  model <- handover_build(ref_all, do.call(rbind, reference$recordings), markers,
                          ncomp = ncomp, k = k, smooth = smooth, filter_size = filter_size,
                          method = method, ridge = ridge, eps = eps, rate = reference$rate,
                          call = call)
  model$dofs <- reference$dofs
  model$unit <- reference$unit
  model$skeleton <- skeleton
  model$fk_args <- list(...)
  model$reference <- data.frame(recordings = length(reference), frames = nrow(ref_all),
                                grasp_types = length(unique(stats::na.omit(reference$meta$grasp))),
                                subjects = length(unique(stats::na.omit(reference$meta$subject))))
  model
}

# The model proper, from stacked reference marker positions (any superset of
# the chosen markers' columns) and joint angles; shared by fit_handover() and
# the marker search, which must not rerun forward kinematics per candidate.
handover_build <- function(ref_all, ref_y, markers, ncomp = NULL, k = 256, smooth = TRUE,
                           filter_size = NULL, method = "pca", ridge = 1e-3, eps = 1e-6,
                           rate = 50, call = rlang::caller_env()) {
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
  if (!is.numeric(k) || length(k) != 1L || is.na(k) || k < d + 2) {
    hm_abort("{.arg k} must be a number of neighbours of at least {d + 2}, not {.val {format(k)}}.",
             "bad_input", argument = "k", call = call)
  }
  k_used <- as.integer(min(k, n_ref))
  if (is.null(filter_size)) filter_size <- cone_size(rate)
  if (!is.numeric(filter_size) || length(filter_size) != 1L || is.na(filter_size) || filter_size < 1) {
    hm_abort("{.arg filter_size} must be a positive number of frames, not {.val {format(filter_size)}}.",
             "bad_input", argument = "filter_size", call = call)
  }
  pca <- stats::prcomp(ref_y, center = TRUE, scale. = FALSE)
  # keep one component per DoF even when the reference is rank deficient
  rot <- pca$rotation
  if (ncol(rot) < p) rot <- complete_basis(rot)
  scores <- sweep(ref_y, 2, pca$center) %*% rot
  direct <- if (method == "direct") global_linear_fit(ref_x, ref_y, ridge) else NULL
  structure(list(
    markers = markers, method = method, ncomp = ncomp, k = k, k_used = k_used,
    ridge = ridge, eps = eps, smooth = isTRUE(smooth), filter_size = as.integer(filter_size),
    center = pca$center, rotation = rot,
    sdev = c(pca$sdev, rep(0, p - length(pca$sdev)))[seq_len(p)],
    ref_x = ref_x, ref_scores = scores, direct = direct,
    dofs = colnames(ref_y), rate = rate, unit = "deg", skeleton = NULL, fk_args = list(),
    reference = data.frame(recordings = NA_integer_, frames = n_ref, grasp_types = NA_integer_,
                           subjects = NA_integer_)
  ), class = "handover_model")
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
lwr_predict <- function(ref_x, ref_y, query, k, ridge, eps, engine = c("c", "r")) {
  engine <- check_choice(engine, arg = "engine", call = rlang::current_env())
  if (engine == "r") return(lwr_predict_r(ref_x, ref_y, query, k, ridge, eps))
  storage.mode(ref_x) <- storage.mode(ref_y) <- storage.mode(query) <- "double"
  .Call(hm_lwr_predict, ref_x, ref_y, query, as.integer(min(k, nrow(ref_x))), as.double(ridge),
        as.double(eps))
}

# Reference implementation in R (the C engine in src/handover-lwr.c does the
# same per frame with a partial-distance nearest-neighbour search and is much faster).
lwr_predict_r <- function(ref_x, ref_y, query, k, ridge, eps, block = 256L) {
  n <- nrow(query)
  N <- nrow(ref_x)
  d <- ncol(ref_x)
  k <- min(k, N)
  out <- matrix(0, n, ncol(ref_y))
  ref_t <- t(ref_x)
  rsq <- colSums(ref_t^2)
  for (b0 in seq(1L, n, by = block)) {
    rows <- b0:min(n, b0 + block - 1L)
    qb <- query[rows, , drop = FALSE]
    if (k < N) d2 <- rep(rsq, each = length(rows)) - 2 * tcrossprod(qb, ref_x)
    for (ii in seq_along(rows)) {
      q <- qb[ii, ]
      idx <- if (k < N) {
        r <- d2[ii, ]
        which(r <= sort.int(r, partial = k)[k])[seq_len(k)]
      } else seq_len(N)
      xt <- ref_t[, idx, drop = FALSE] - q
      w <- 1 / pmax(sqrt(colSums(xt^2)), eps)
      xw <- xt * rep(w, each = d)
      yk <- ref_y[idx, , drop = FALSE]
      sw <- sum(w)
      sx <- rowSums(xw)
      hy <- drop(crossprod(w, yk))
      sxx <- tcrossprod(xw, xt)
      lam <- ridge * sum(diag(sxx)) / d + 1e-12
      # slopes from the centred normal equations, then the intercept
      a <- sxx - tcrossprod(sx) / sw
      diag(a) <- diag(a) + lam
      beta <- solve(a, xw %*% yk - tcrossprod(sx, hy) / sw)
      out[rows[ii], ] <- (hy - drop(crossprod(sx, beta))) / sw
    }
  }
  out
}

#' Reconstruct full hand motion from sparse markers
#'
#' @param model A fitted model, here a `handover_model` from [fit_handover()].
#' @param query Either a [grasps()] object (its markers are computed by
#'   forward kinematics, for evaluation against its own joint angles), or a
#'   frames x (3 * m) matrix of recorded marker positions relative to the
#'   root link (one recording), or a list of such matrices. Matrix columns
#'   named `<marker>.x`, `.y`, `.z` may come in any order and extra markers
#'   are ignored; unnamed columns are an error (their order cannot be checked).
#' @param ... Unused.
#' @details **Occlusion.** A marker with any missing (`NA`/`NaN`) coordinate
#'   in a frame is dropped from that frame's distance and regression, which
#'   then uses the remaining markers. A frame with no visible marker cannot be
#'   reconstructed and raises an error of class
#'   `handmotion_error_occluded` naming the frames. The number of markers
#'   used per frame is kept in the result (see Value).
#' @return A [grasps()] object with the reconstructed joint angles (the query's
#'   metadata for a grasps query; ids `"r1"`, ... otherwise), with metadata
#'   columns `handover_markers` (number of sparse markers) and
#'   `occluded_frames` (frames reconstructed from fewer markers), and an
#'   attribute `"handover"`: a list with, per recording, `markers_used`
#'   (markers visible in each frame) and `scores` (the smoothed component
#'   trajectories).
#' @export
#' @examples
#' set.seed(1)
#' t <- seq(0, 1, length.out = 40)
#' ang <- outer(t, runif(16, 10, 60)) + outer(sin(2 * pi * t), runif(16, 0, 10))
#' ref <- grasps(list(ang, ang[40:1, ] * 0.8), dofs = hust_dofs$name)
#' fit <- fit_handover(ref, markers = c("index_tip", "ring_tip", "thumb_tip"), k = 30)
#' mk <- markers_from_angles(ang, markers = fit$markers)
#' mk[5, 1:3] <- NaN   # the index tip is occluded in frame 5
#' rec <- reconstruct(fit, mk)
#' attr(rec, "handover")$markers_used[[1]][1:6]
reconstruct <- function(model, query, ...) UseMethod("reconstruct")

#' @rdname reconstruct
#' @export
reconstruct.handover_model <- function(model, query, ...) {
  call <- rlang::caller_env()
  cols <- marker_columns(model$markers)
  if (inherits(query, "grasps")) {
    if (!identical(query$dofs, model$dofs)) {
      hm_abort("The query's DoFs ({.val {query$dofs}}) differ from the model's ({.val {model$dofs}}).",
               "bad_input", argument = "query", call = call)
    }
    mk <- do.call(markers_from_angles, c(list(query, skeleton = model$skeleton, markers = model$markers),
                                         model$fk_args))
    meta <- query$meta
  } else {
    if (is.matrix(query)) query <- list(query)
    if (!is.list(query) || length(query) == 0L) {
      hm_abort("{.arg query} must be a grasps object, a marker matrix or a list of marker matrices, not {.obj_type_friendly {query}}.",
               "bad_input", argument = "query", call = call)
    }
    mk <- lapply(seq_along(query), function(i) as_query_markers(query[[i]], cols, i, call))
    meta <- data.frame(id = if (!is.null(names(query)) && all(nzchar(names(query))))
      names(query) else paste0("r", seq_along(query)), stringsAsFactors = FALSE)
    meta <- build_meta(meta, mk, meta$id, call = call)
    meta$source <- "handover"
  }
  res <- lapply(seq_along(mk), function(i) reconstruct_one(model, mk[[i]], meta$id[i], call))
  recs <- lapply(res, `[[`, "angles")
  names(recs) <- meta$id
  meta$handover_markers <- length(model$markers)
  meta$occluded_frames <- vapply(res, function(r) sum(r$used < length(model$markers)), integer(1))
  out <- new_grasps(recs, meta, model$dofs, model$rate, model$unit)
  attr(out, "handover") <- list(
    markers = model$markers,
    markers_used = stats::setNames(lapply(res, `[[`, "used"), meta$id),
    scores = stats::setNames(lapply(res, `[[`, "scores"), meta$id))
  out
}

#' @rdname reconstruct
#' @param object A `handover_model`.
#' @param newdata The query, as `query` in `reconstruct()`.
#' @export
predict.handover_model <- function(object, newdata, ...) reconstruct(object, newdata, ...)

# Check and reorder one query marker matrix to the model's marker columns.
as_query_markers <- function(m, cols, i, call) {
  if (is.data.frame(m)) m <- as.matrix(m)
  if (!is.matrix(m) || !is.numeric(m)) {
    hm_abort("Query {i} must be a numeric frames x (3 * markers) matrix, not {.obj_type_friendly {m}}.",
             "bad_markers", argument = "query", recording = i, call = call)
  }
  if (!is.null(colnames(m))) {
    miss <- setdiff(cols, colnames(m))
    if (length(miss)) {
      hm_abort(c("Query {i} lacks marker column{?s} {.val {miss}}.",
                 i = "The model was fitted on markers {.val {sub('\\\\.x$', '', cols[c(TRUE, FALSE, FALSE)])}}."),
               "bad_markers", argument = "query", recording = i, call = call)
    }
    m <- m[, cols, drop = FALSE]
  } else {
    # unnamed columns cannot be checked: in another order than the model's
    # they would give a plausible but wrong hand
    hm_abort(c("Query {i} has unnamed columns; name them {.val {utils::head(cols, 3)}}, ... (x, y, z per marker).",
               i = "{.fn markers_from_angles} returns named marker columns."),
             "bad_markers", argument = "query", recording = i, call = call)
  }
  if (nrow(m) == 0L) {
    hm_abort("Query {i} has no frames.", "bad_markers", argument = "query", recording = i, call = call)
  }
  if (any(is.infinite(m))) {
    hm_abort("Query {i} has infinite marker coordinates.", "bad_markers",
             argument = "query", recording = i, call = call)
  }
  storage.mode(m) <- "double"
  m
}

# Reconstruct one recording: group frames by their pattern of visible
# markers, regress each group on its visible markers, smooth, back-project.
reconstruct_one <- function(model, m, id, call) {
  nm <- length(model$markers)
  vis <- matrix(!is.na(m), nrow(m))
  vis_marker <- vis[, c(TRUE, FALSE, FALSE), drop = FALSE] & vis[, c(FALSE, TRUE, FALSE), drop = FALSE] &
    vis[, c(FALSE, FALSE, TRUE), drop = FALSE]
  used <- rowSums(vis_marker)
  if (any(used == 0L)) {
    bad <- which(used == 0L)
    hm_abort(c("In recording {.val {id}}, {length(bad)} frame{?s} ha{?s/ve} no visible marker: {.val {utils::head(bad, 10)}}{if (length(bad) > 10) ', ...' else ''}.",
               i = "Hand-over needs at least one of the markers {.val {model$markers}} in every frame; trim or fill those frames."),
             "occluded", recording = id, argument = "query", call = call)
  }
  q <- model$ncomp
  if (model$method == "direct") {
    if (any(used < nm)) {
      hm_abort("The no-PCA baseline cannot handle occluded markers (recording {.val {id}}).",
               "occluded", recording = id, argument = "query", call = call)
    }
    dr <- model$direct
    ang <- sweep(sweep(m, 2, dr$mu_x) %*% dr$beta, 2, dr$mu_y, "+")
    if (model$smooth) ang <- cone_filter(ang, model$filter_size)
    colnames(ang) <- model$dofs
    return(list(angles = ang, used = used, scores = NULL))
  }
  scores <- matrix(0, nrow(m), q)
  key <- drop(vis_marker %*% 2^(seq_len(nm) - 1))   # one code per visibility pattern
  for (pat in unique(key)) {
    rows <- which(key == pat)
    keep_m <- vis_marker[rows[1], ]
    keep <- rep(keep_m, each = 3)
    scores[rows, ] <- lwr_predict(model$ref_x[, keep, drop = FALSE],
                                  model$ref_scores[, seq_len(q), drop = FALSE],
                                  m[rows, keep, drop = FALSE], model$k_used, model$ridge, model$eps)
  }
  if (model$smooth) scores <- cone_filter(scores, model$filter_size)
  ang <- sweep(scores %*% t(model$rotation[, seq_len(q), drop = FALSE]), 2, model$center, "+")
  colnames(ang) <- model$dofs
  colnames(scores) <- paste0("PC", seq_len(q))
  list(angles = ang, used = used, scores = scores)
}

#' @export
print.handover_model <- function(x, ...) {
  r <- x$reference
  cat(sprintf("<handover_model> %s reconstruction from %d marker%s\n",
              if (x$method == "pca") "PCA + locally weighted regression" else "direct (no-PCA) linear",
              length(x$markers), if (length(x$markers) == 1) "" else "s"))
  cat("  markers:", paste(x$markers, collapse = ", "), "\n")
  cat(sprintf("  reference: %d frames in %d recordings (%d grasp types, %d subjects), %g Hz\n",
              r$frames, r$recordings, r$grasp_types, r$subjects, x$rate))
  if (x$method == "pca") {
    cat(sprintf("  components: %d of %d; neighbours per frame: %d; cone filter: %s\n",
                x$ncomp, length(x$dofs), x$k_used,
                if (x$smooth) paste(x$filter_size, "frames") else "off"))
  }
  invisible(x)
}

# ---- baselines and evaluation ----------------------------------------------

#' Search-based marker selection (after Kang et al. 2012)
#'
#' The search baseline of the hand-over paper: choose the marker set with the
#' least reconstruction error on held-out reference data. The reference is
#' split by a metadata column (by default grasp type, so the search rewards
#' generalisation to unseen motions): alternate values of `holdout` (after a
#' seeded shuffle) form the validation part. The search is greedy forward
#' selection (add the marker that lowers the validation error most, `n`
#' times; about `13 n` reconstructions), or with `exhaustive = TRUE` every
#' `choose(13, n)` set (1,716 for six markers: slow).
#'
#' @param reference A [grasps()] reference database.
#' @param n Number of markers.
#' @param holdout Metadata column whose values are split between fitting and
#'   validation.
#' @param exhaustive Try every set instead of the greedy search.
#' @param max_frames Validation frames used per evaluation (whole recordings,
#'   a seeded sample), to bound the cost.
#' @param seed Seed for the split and the sample (the global RNG is left
#'   untouched).
#' @param skeleton,... Passed to [markers_from_angles()].
#' @param k,ridge Passed to [fit_handover()].
#' @return A character vector of `n` marker names, in the order the greedy
#'   search added them; attribute `"search"`: a data frame of the evaluated
#'   sets and their validation errors (degrees).
#' @seealso [select_markers()], [compare_marker_sets()]
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:4, objects = 1, trials = 1)
#' search_markers(g, n = 2, max_frames = 200)
search_markers <- function(reference, n = 6, holdout = "grasp", exhaustive = FALSE,
                           max_frames = 1500, seed = 1, k = 256, ridge = 1e-3,
                           skeleton = hand_skeleton(), ...) {
  call <- rlang::caller_env()
  check_grasps(reference, "reference", call = call)
  cand <- hand_marker_set()$marker[hand_marker_set()$segment == "hand"]
  if (!is.numeric(n) || length(n) != 1L || is.na(n) || n < 1 || n > length(cand) || n != round(n)) {
    hm_abort("{.arg n} must be a whole number from 1 to {length(cand)}, not {.val {format(n)}}.",
             "bad_markers", argument = "n", call = call)
  }
  if (!holdout %in% names(reference$meta)) {
    hm_abort("{.arg holdout} must name a metadata column ({.val {names(reference$meta)}}), not {.val {holdout}}.",
             "bad_input", argument = "holdout", call = call)
  }
  groups <- as.character(reference$meta[[holdout]])
  groups[is.na(groups)] <- "(none)"
  ug <- unique(groups)
  if (length(ug) < 2L) {
    hm_abort("Holding out by {.val {holdout}} needs at least two distinct values; the reference has {length(ug)}.",
             "reference_too_small", argument = "holdout", call = call)
  }
  split <- with_seed(seed, {
    val_groups <- sample(ug)[c(FALSE, TRUE)]
    val <- which(groups %in% val_groups)
    nf <- reference$meta$n_frames[val]
    o <- sample(seq_along(val))
    keep <- o[cumsum(nf[o]) <= max_frames]
    if (!length(keep)) keep <- o[1]
    list(val = sort(val[keep]), fit = which(!groups %in% val_groups))
  })
  mk <- markers_from_angles(reference, skeleton = skeleton, markers = cand, ...)
  ref_all <- do.call(rbind, mk[split$fit])
  ref_y <- do.call(rbind, reference$recordings[split$fit])
  val_mk <- mk[split$val]
  val_y <- do.call(rbind, reference$recordings[split$val])
  val_err <- function(set) {
    model <- handover_build(ref_all, ref_y, set, k = k, ridge = ridge, rate = reference$rate,
                            call = call)
    rec <- do.call(rbind, lapply(seq_along(val_mk), function(i) {
      reconstruct_one(model, val_mk[[i]][, marker_columns(set), drop = FALSE], names(val_mk)[i], call)$angles
    }))
    mean(abs(rec - val_y)) * unit_factor(reference$unit)
  }
  log <- list()
  if (exhaustive) {
    sets <- utils::combn(cand, n, simplify = FALSE)
    errs <- vapply(sets, val_err, numeric(1))
    log <- data.frame(step = n, set = vapply(sets, paste, "", collapse = ","), error = errs)
    chosen <- sets[[which.min(errs)]]
  } else {
    chosen <- character()
    for (step in seq_len(n)) {
      left <- setdiff(cand, chosen)
      errs <- vapply(left, function(m) val_err(c(chosen, m)), numeric(1))
      log[[step]] <- data.frame(step = step, set = vapply(left, function(m) paste(c(chosen, m), collapse = ","), ""),
                                error = errs, row.names = NULL)
      chosen <- c(chosen, left[which.min(errs)])
    }
    log <- do.call(rbind, log)
  }
  structure(chosen, search = log)
}

# Factor from a grasps unit to degrees, for errors reported in degrees.
unit_factor <- function(unit) if (identical(unit, "rad")) 180 / pi else 1

#' Joint-angle error of a reconstruction
#'
#' The paper's figure of merit: the average absolute joint-angle error per
#' frame (mean over DoFs, then over frames), in degrees (radians are
#' converted).
#'
#' @param truth,recon [grasps()] objects with the same recordings (ids, frame
#'   counts and DoFs), e.g. a test set and `reconstruct(model, test)`.
#' @param by `"overall"` (one number), `"recording"`, `"frame"` or `"dof"`.
#' @return A number (degrees) for `by = "overall"`, else a data frame with
#'   column `error`.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = 1:2, objects = 1, trials = 1)
#' noisy <- g
#' noisy$recordings <- lapply(g$recordings, function(r) r + 2)
#' handover_error(g, noisy)
#' handover_error(g, noisy, by = "recording")
handover_error <- function(truth, recon, by = c("overall", "recording", "frame", "dof")) {
  call <- rlang::caller_env()
  by <- check_choice(by, arg = "by", call = rlang::current_env())
  check_grasps(truth, "truth", call = call)
  check_grasps(recon, "recon", call = call)
  if (!identical(truth$meta$id, recon$meta$id) || !identical(truth$meta$n_frames, recon$meta$n_frames) ||
      !identical(truth$dofs, recon$dofs)) {
    hm_abort(c("{.arg truth} and {.arg recon} must hold the same recordings, frame counts and DoFs.",
               i = "Compare a query with {.code reconstruct(model, query)}."),
             "bad_input", argument = "recon", call = call)
  }
  if (!identical(truth$unit, recon$unit)) {
    hm_abort("{.arg truth} is in {.val {truth$unit}} but {.arg recon} in {.val {recon$unit}}.",
             "bad_input", argument = "recon", call = call)
  }
  f <- unit_factor(truth$unit)
  err <- lapply(seq_along(truth$recordings), function(i) abs(truth$recordings[[i]] - recon$recordings[[i]]) * f)
  switch(by,
    overall = mean(unlist(lapply(err, rowMeans))),
    recording = data.frame(id = truth$meta$id, grasp = truth$meta$grasp, subject = truth$meta$subject,
                           frames = truth$meta$n_frames,
                           error = vapply(err, function(e) mean(rowMeans(e)), numeric(1))),
    frame = data.frame(id = rep(truth$meta$id, truth$meta$n_frames),
                       frame = unlist(lapply(truth$meta$n_frames, seq_len)),
                       error = unlist(lapply(err, rowMeans))),
    dof = data.frame(dof = truth$dofs, error = colMeans(do.call(rbind, err)), row.names = NULL))
}

#' Compare marker sets and methods for hand-over
#'
#' Fits one hand-over model per marker set on `reference` and reports the
#' joint-angle error of reconstructing `test` (the paper's Figures 2 and 4).
#' The default sets are the paper's comparison: our ranked 3- and 6-marker
#' sets ([select_markers()]), the 6-marker set without PCA (`method =
#' "direct"`, Figure 2), the hand-picked set ([handpicked_markers()]) and a
#' search-based 6-marker set ([search_markers()]).
#'
#' @param reference A [grasps()] reference database.
#' @param test A [grasps()] test set (ideally unseen grasp types and subjects).
#' @param sets `NULL` for the default comparison, or a named list whose
#'   elements are marker-name vectors or lists `list(markers = , method = )`.
#' @param search Include the search-based set in the default comparison.
#' @param ... Passed to [fit_handover()] (e.g. `k`, `ncomp`).
#' @return A data frame of class `handover_comparison`: `set`, `method`,
#'   `n_markers`, `markers`, `error` (degrees, [handover_error()] over all
#'   test frames) and `error_sd` (standard deviation of the per-recording
#'   errors).
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 3, grasps = 1:4, objects = 1, trials = 1)
#' ref <- g[g$meta$subject != "S03"]
#' cmp <- compare_marker_sets(ref, g[g$meta$subject == "S03"], search = FALSE)
#' cmp
#' ggplot2::autoplot(cmp)
compare_marker_sets <- function(reference, test, sets = NULL, search = TRUE, ...) {
  call <- rlang::caller_env()
  check_grasps(reference, "reference", call = call)
  check_grasps(test, "test", call = call)
  if (is.null(sets)) {
    rk <- rank_markers(reference)
    sets <- list(`ranked (3)` = select_markers(rk, 3), `ranked (6)` = select_markers(rk, 6),
                 `ranked (6), no PCA` = list(markers = select_markers(rk, 6), method = "direct"),
                 `hand-picked (6)` = handpicked_markers())
    if (search) sets$`search (6)` <- as.vector(search_markers(reference, 6))
  }
  if (!is.list(sets) || is.null(names(sets)) || any(!nzchar(names(sets)))) {
    hm_abort("{.arg sets} must be a named list of marker sets.", "bad_input", argument = "sets", call = call)
  }
  rows <- lapply(names(sets), function(nm) {
    s <- sets[[nm]]
    if (!is.list(s)) s <- list(markers = s, method = "pca")
    if (is.null(s$method)) s$method <- "pca"
    model <- fit_handover(reference, s$markers, method = s$method, ...)
    rec <- reconstruct(model, test)
    e <- handover_error(test, rec, by = "recording")
    data.frame(set = nm, method = s$method, n_markers = length(s$markers),
               markers = paste(s$markers, collapse = ", "), error = handover_error(test, rec),
               error_sd = stats::sd(e$error), stringsAsFactors = FALSE)
  })
  out <- do.call(rbind, rows)
  out$set <- factor(out$set, levels = names(sets))
  structure(out, class = c("handover_comparison", "data.frame"))
}

#' @export
print.handover_comparison <- function(x, ...) {
  cat("<handover_comparison> mean joint-angle error per frame (degrees)\n")
  print(as.data.frame(unclass(x)[c("set", "method", "n_markers", "error", "error_sd")]),
        digits = 3, row.names = FALSE)
  invisible(x)
}

#' PCA reconstruction error against the number of components
#'
#' How well the joint angles are described by the first `q` principal
#' components of the reference (the paper's Figure 1): the average
#' joint-angle error per frame of projecting `data` onto the reference PCA
#' and back, for each `q`.
#'
#' @param reference A [grasps()] object (the PCA is fitted on its frames), or
#'   a `handover_model` (its PCA is used).
#' @param data A [grasps()] object to reconstruct; the reference by default.
#' @return A data frame of class `handover_pca_error`: `ncomp`, `error`
#'   (degrees) and `variance` (cumulative proportion of reference variance).
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:5, objects = 1, trials = 1)
#' handover_pca_error(g)
handover_pca_error <- function(reference, data = NULL) {
  call <- rlang::caller_env()
  if (inherits(reference, "handover_model")) {
    center <- reference$center; rot <- reference$rotation; sdev <- reference$sdev
    unit <- reference$unit
    if (is.null(data)) {
      hm_abort("Give {.arg data} (a grasps object) with a {.cls handover_model}.", "bad_input",
               argument = "data", call = call)
    }
  } else {
    check_grasps(reference, "reference", call = call)
    pca <- stats::prcomp(do.call(rbind, reference$recordings), center = TRUE, scale. = FALSE)
    rot <- pca$rotation
    if (ncol(rot) < nrow(rot)) rot <- complete_basis(rot)
    center <- pca$center; sdev <- c(pca$sdev, rep(0, ncol(rot)))[seq_len(ncol(rot))]
    unit <- reference$unit
    if (is.null(data)) data <- reference
  }
  check_grasps(data, "data", call = call)
  x <- do.call(rbind, data$recordings)
  if (ncol(x) != nrow(rot)) {
    hm_abort("{.arg data} has {ncol(x)} DoFs but the reference PCA {nrow(rot)}.", "bad_input",
             argument = "data", call = call)
  }
  xc <- sweep(x, 2, center)
  sc <- xc %*% rot
  p <- ncol(rot)
  err <- vapply(seq_len(p), function(q) {
    fit <- sc[, seq_len(q), drop = FALSE] %*% t(rot[, seq_len(q), drop = FALSE])
    mean(abs(xc - fit)) * unit_factor(unit)
  }, numeric(1))
  structure(data.frame(ncomp = seq_len(p), error = err, variance = cumsum(sdev^2) / sum(sdev^2)),
            class = c("handover_pca_error", "data.frame"))
}

#' Principal component trajectories of joint angles
#'
#' Projects joint-angle recordings onto a hand-over model's reference PCA,
#' giving the "ground truth" component trajectories the paper compares the
#' regression's output against (its Figure 5).
#'
#' @param model A `handover_model`.
#' @param x A [grasps()] object.
#' @return A list of frames x DoF score matrices (columns `PC1`, ...), named
#'   by recording id.
#' @noRd
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:3, objects = 1, trials = 1)
#' fit <- fit_handover(g, markers = 3)
#' str(handover_scores(fit, g[1]))
handover_scores <- function(model, x) {
  call <- rlang::caller_env()
  if (!inherits(model, "handover_model")) {
    hm_abort("{.arg model} must be a {.cls handover_model}.", "bad_input", argument = "model", call = call)
  }
  check_grasps(x, call = call)
  out <- lapply(x$recordings, function(r) {
    s <- sweep(r, 2, model$center) %*% model$rotation
    colnames(s) <- paste0("PC", seq_len(ncol(s)))
    s
  })
  names(out) <- x$meta$id
  out
}
