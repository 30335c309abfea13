# Reconstruction of full hand motion from sparse markers with a fitted
# hand-over model (Wheatland, Joerg and Zordan): the query's markers, local
# regression per frame, the cone filter, back to joint angles.

#' Reconstruct full hand motion from sparse markers
#'
#' `predict()` on a hand-over model rebuilds every joint angle from the
#' sparse markers of `new_data`.
#'
#' @param object A `handover_model` from [fit_handover()].
#' @param new_data Either a [grasps()] object (its markers are computed by
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
#' fit <- fit_handover(ref, markers = c("index_tip", "ring_tip", "thumb_tip"), neighbours = 30)
#' mk <- forward_kinematics(ang, markers = fit$markers)
#' mk[5, 1:3] <- NaN   # the index tip is occluded in frame 5
#' rec <- predict(fit, mk)
#' attr(rec, "handover")$markers_used[[1]][1:6]
predict.handover_model <- function(object, new_data, ...) {
  call <- rlang::caller_env()
  check_dots_for(list(...), predict.handover_model, "predict.handover_model", call = call)
  check_fitted_parts(object, "object", call = call)
  model <- object
  query <- new_data
  cols <- marker_columns(model$markers)
  if (inherits(query, "grasps")) {
    if (!identical(query$dofs, model$dofs)) {
      first <- which(rep_len(query$dofs, length(model$dofs)) != model$dofs)[1]
      hm_abort(c("The DoFs of {.arg new_data} differ from the model's.",
                 x = if (length(query$dofs) != length(model$dofs)) "{.arg new_data} has {length(query$dofs)} DoFs, the model {length(model$dofs)}."
                     else "DoF {first} is {.val {query$dofs[first]}}, the model's {.val {model$dofs[first]}}."),
               "bad_input", argument = "new_data", call = call)
    }
    mk <- do.call(markers_from_angles, c(list(query, skeleton = model$skeleton, markers = model$markers),
                                         model$fk_args))
    meta <- query$meta
  } else {
    if (is.matrix(query) || is.data.frame(query)) query <- list(query)
    if (!is.list(query) || length(query) == 0L) {
      hm_abort("{.arg new_data} must be a grasps object, a marker matrix or a list of marker matrices, not {.obj_type_friendly {query}}.",
               "bad_input", argument = "new_data", call = call)
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

# Check and reorder one query marker matrix to the model's marker columns.
as_query_markers <- function(m, cols, i, call) {
  if (is.data.frame(m)) m <- as.matrix(m)
  if (!is.matrix(m) || !is.numeric(m)) {
    hm_abort("{.arg new_data[[{i}]]} must be a numeric frames x (3 * markers) matrix, not {.obj_type_friendly {m}}.",
             "bad_markers", argument = "new_data", recording = i, call = call)
  }
  if (!is.null(colnames(m))) {
    miss <- setdiff(cols, colnames(m))
    if (length(miss)) {
      hm_abort(c("{.arg new_data[[{i}]]} lacks marker column{?s} {.val {miss}}.",
                 i = "The model was fitted on markers {.val {sub('\\\\.x$', '', cols[c(TRUE, FALSE, FALSE)])}}."),
               "bad_markers", argument = "new_data", recording = i, column = miss, call = call)
    }
    m <- m[, cols, drop = FALSE]
  } else {
    # unnamed columns cannot be checked: in another order than the model's
    # they would give a plausible but wrong hand
    hm_abort(c("{.arg new_data[[{i}]]} has unnamed columns; name them {.val {utils::head(cols, 3)}}, ... (x, y, z per marker).",
               i = "{.fn markers_from_angles} returns named marker columns."),
             "bad_markers", argument = "new_data", recording = i, call = call)
  }
  if (nrow(m) == 0L) {
    hm_abort("{.arg new_data[[{i}]]} has no frames.", "bad_markers", argument = "new_data", recording = i, call = call)
  }
  inf <- which(is.infinite(m), arr.ind = TRUE)
  if (nrow(inf)) {
    hm_abort(c("{.arg new_data[[{i}]]} has {nrow(inf)} infinite marker coordinate{?s}.",
               x = "First in column {.val {colnames(m)[inf[1, 2]]}}, frame {inf[1, 1]}."),
             "bad_markers", argument = "new_data", recording = i, column = colnames(m)[inf[1, 2]],
             line = inf[1, 1], call = call)
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
             "occluded", recording = id, argument = "new_data", call = call)
  }
  q <- model$ncomp
  if (model$method == "direct") {
    if (any(used < nm)) {
      hm_abort("The no-PCA baseline cannot handle occluded markers (recording {.val {id}}).",
               "occluded", recording = id, argument = "new_data", call = call)
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
                                  m[rows, keep, drop = FALSE], model$neighbours_used, model$ridge, model$eps)
  }
  if (model$smooth) scores <- cone_filter(scores, model$filter_size)
  ang <- sweep(scores %*% t(model$rotation[, seq_len(q), drop = FALSE]), 2, model$center, "+")
  colnames(ang) <- model$dofs
  colnames(scores) <- paste0("PC", seq_len(q))
  list(angles = ang, used = used, scores = scores)
}
