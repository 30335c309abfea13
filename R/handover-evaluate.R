# Hand-over baselines and evaluation: search-based marker selection, the
# reconstruction error, marker-set comparisons, the PCA error per number of
# components.

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
  differ <- if (!identical(truth$dofs, recon$dofs)) {
    "DoFs differ: {.val {utils::head(setdiff(union(truth$dofs, recon$dofs), intersect(truth$dofs, recon$dofs)), 3)}}, or their order."
  } else if (!identical(truth$meta$id, recon$meta$id)) {
    "recording ids differ ({length(truth)} in {.arg truth}, {length(recon)} in {.arg recon}); first: {.val {c(setdiff(truth$meta$id, recon$meta$id), setdiff(recon$meta$id, truth$meta$id), truth$meta$id)[1]}}."
  } else if (!identical(truth$meta$n_frames, recon$meta$n_frames)) {
    "frame counts differ, first in recording {.val {truth$meta$id[which(truth$meta$n_frames != recon$meta$n_frames)[1]]}}."
  }
  if (!is.null(differ)) {
    hm_abort(c("{.arg truth} and {.arg recon} must hold the same recordings, frame counts and DoFs.",
               x = differ, i = "Compare a query with {.code reconstruct(model, query)}."),
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
