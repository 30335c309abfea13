# Hand-over baselines and evaluation: search-based marker selection, the
# reconstruction error, marker-set comparisons, the PCA error per number of
# components.

# Search-based marker selection (after Kang et al. 2012), reached through
# select_markers(method = "search"), which documents it: greedy forward (or
# exhaustive) selection by the reconstruction error on a held-out part of the
# reference, split by the metadata column `holdout`.
search_markers <- function(reference, n = 6, holdout = "grasp", exhaustive = FALSE,
                           max_frames = 1500, seed = 1, neighbours = 256, ridge = 1e-3,
                           skeleton = hand_skeleton(), ..., call = rlang::caller_env()) {
  check_grasps(reference, "x", call = call)
  cand <- hand_marker_set()$marker[hand_marker_set()$segment == "hand"]
  check_whole(n, "n", max = length(cand), class = "bad_markers", call = call)  # (n kept as given: it is the log's step)
  max_frames <- check_whole(max_frames, "max_frames", call = call)
  seed <- check_seed(seed, call = call)
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
    model <- handover_build(ref_all, ref_y, set, neighbours = neighbours, ridge = ridge, rate = reference$rate,
                            unit = reference$unit, call = call)
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
#' With `by = "ncomp"` it is the error of the PCA alone (the paper's Figure
#' 1): how well `truth` is described by the first `q` principal components of
#' `reference`, for every `q`: the average joint-angle error per frame of
#' projecting `truth` onto the reference PCA and back. `recon` is then not
#' used.
#'
#' With `by = "markers"` it compares marker sets (the paper's Figures 2 and
#' 4): one hand-over model per marker set is fitted on `reference`
#' ([fit_handover()]) and reconstructs `truth`, the test set (ideally unseen
#' grasp types and subjects). The default sets are the paper's comparison:
#' the ranked 3- and 6-marker sets ([select_markers()]), the 6-marker set
#' without PCA (`method = "direct"`, Figure 2), the hand-picked set and a
#' search-based 6-marker set (`select_markers(method = "handpicked")` and
#' `"search"`). `recon` is then not used.
#'
#' @param truth,recon [grasps()] objects with the same recordings (ids, frame
#'   counts and DoFs), e.g. a test set and `predict(model, test)` ([predict.handover_model()]).
#' @param by `"overall"` (one number), `"recording"`, `"frame"`, `"dof"`,
#'   `"ncomp"` (the PCA error per number of components) or `"markers"` (per
#'   marker set), see Details.
#' @param reference For `by = "ncomp"`: a [grasps()] object whose frames the
#'   PCA is fitted on, or a `handover_model` (its PCA is used); `truth` by
#'   default. For `by = "markers"` (needed): the [grasps()] reference database
#'   the hand-over models are fitted on.
#' @param sets For `by = "markers"`: `NULL` for the default comparison, or a
#'   named list whose elements are marker-name vectors or lists
#'   `list(markers = , method = )`.
#' @param ... For `by = "markers"` only: `search` (include the search-based
#'   set in the default comparison; default `TRUE`, the slow part) and
#'   arguments of [fit_handover()] (e.g. `neighbours`, `ncomp`).
#' @return A number (degrees) for `by = "overall"`, else a data frame with
#'   column `error`. For `by = "ncomp"` a data frame of class
#'   `handover_pca_error`: `ncomp`, `error` (degrees) and `variance`
#'   (cumulative proportion of reference variance), with an [autoplot()]
#'   method. For `by = "markers"` a data frame of class
#'   `handover_comparison`: `set`, `method`, `n_markers`, `markers`, `error`
#'   (degrees, over all test frames) and `error_sd` (standard deviation of
#'   the per-recording errors), with an [autoplot()] method.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = 1:2, objects = 1, trials = 1)
#' noisy <- g
#' noisy$recordings <- lapply(g$recordings, function(r) r + 2)
#' handover_error(g, noisy)
#' handover_error(g, noisy, by = "recording")
#' pe <- handover_error(g, by = "ncomp")
#' head(pe)
#' ggplot2::autoplot(pe)
#' g3 <- simulate_grasps(subjects = 3, grasps = 1:4, objects = 1, trials = 1)
#' cmp <- handover_error(g3[g3$meta$subject == "S03"], by = "markers",
#'                       reference = g3[g3$meta$subject != "S03"], search = FALSE)
#' cmp
#' ggplot2::autoplot(cmp)
handover_error <- function(truth, recon = NULL, by = c("overall", "recording", "frame", "dof", "ncomp", "markers"),
                           reference = NULL, sets = NULL, ...) {
  call <- rlang::caller_env()
  by <- check_choice(by, arg = "by", call = rlang::current_env())
  check_grasps(truth, "truth", call = call)
  if (by == "markers") {
    if (is.null(reference)) {
      hm_abort("Comparing marker sets needs a {.arg reference} to fit the hand-over models on.",
               "bad_input", argument = "reference", call = call)
    }
    dots <- list(...)
    check_dots_for(dots[rlang::names2(dots) != "search"], fit_handover, "fit_handover",
                   exclude = c("reference", "markers", "method"), call = call)
    return(compare_marker_sets(reference, truth, sets = sets, ..., call = call))
  }
  if (...length() > 0L) {
    hm_abort("{.arg ...} is used only with {.code by = \"markers\"}.", "bad_input",
             argument = "...", call = call)
  }
  if (by == "ncomp") return(handover_pca_error(reference %||% truth, truth, call = call))
  if (is.null(recon)) {
    hm_abort("Give {.arg recon}, e.g. {.code predict(model, truth)}.", "bad_input",
             argument = "recon", call = call)
  }
  check_grasps(recon, "recon", call = call)
  differ <- if (!identical(truth$dofs, recon$dofs)) {
    "DoFs differ: {.val {utils::head(setdiff(union(truth$dofs, recon$dofs), intersect(truth$dofs, recon$dofs)), 3)}}, or their order."
  } else if (!identical(truth$meta$id, recon$meta$id)) {
    "recording ids differ ({length(truth)} in {.arg truth}, {length(recon)} in {.arg recon}); first: {.val {c(setdiff(truth$meta$id, recon$meta$id), setdiff(recon$meta$id, truth$meta$id), truth$meta$id)[1]}}."
  } else if (!identical(truth$meta$n_frames, recon$meta$n_frames)) {
    "frame counts differ, first in recording {.val {truth$meta$id[which(truth$meta$n_frames != recon$meta$n_frames)[1]]}}."
  }
  if (!is.null(differ)) {
    hm_abort(c("{.arg truth} and {.arg recon} must hold the same recordings, frame counts and DoFs.",
               x = differ, i = "Compare a query with {.code predict(model, query)}."),
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

# handover_error(by = "markers") (documented there): one hand-over model
# per marker set, fitted on `reference`, reconstructing `test`; `...` goes to
# fit_handover().
compare_marker_sets <- function(reference, test, sets = NULL, search = TRUE, ..., call = rlang::caller_env()) {
  check_grasps(reference, "reference", call = call)
  check_grasps(test, "truth", call = call)
  search <- check_flag(search, "search", call = call)
  if (is.null(sets)) {
    six <- as.vector(select_markers(reference, 6))
    sets <- list(`ranked (3)` = six[1:3], `ranked (6)` = six,
                 `ranked (6), no PCA` = list(markers = six, method = "direct"),
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
    model <- fit_handover(reference, markers = s$markers, method = s$method, ...)
    rec <- stats::predict(model, test)
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
  cli::cat_line("<handover_comparison> mean joint-angle error per frame (degrees)")
  print(as.data.frame(unclass(x)[c("set", "method", "n_markers", "error", "error_sd")]),
        digits = 3, row.names = FALSE)
  invisible(x)
}

# The PCA error per number of components (handover_error(by = "ncomp")):
# `data` projected onto the reference PCA (a grasps object's, or a
# handover_model's) and back with its first q components, for every q.
handover_pca_error <- function(reference, data = NULL, call = rlang::caller_env()) {
  if (inherits(reference, "handover_model")) {
    center <- reference$center; rot <- reference$rotation; sdev <- reference$sdev
    unit <- reference$unit
  } else {
    check_grasps(reference, "reference", call = call)
    pca <- stats::prcomp(do.call(rbind, reference$recordings), center = TRUE, scale. = FALSE)
    rot <- pca$rotation
    if (ncol(rot) < nrow(rot)) rot <- complete_basis(rot)
    center <- pca$center; sdev <- c(pca$sdev, rep(0, ncol(rot)))[seq_len(ncol(rot))]
    unit <- reference$unit
    if (is.null(data)) data <- reference
  }
  x <- do.call(rbind, data$recordings)
  if (ncol(x) != nrow(rot)) {
    hm_abort("{.arg truth} has {ncol(x)} DoFs but the reference PCA {nrow(rot)}.", "bad_input",
             argument = "truth", call = call)
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
#' fit <- fit_handover(g, n_markers = 3)
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
