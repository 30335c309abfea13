# Projection of recordings onto a fitted model (Jeppsson 2017, section 4.2):
# warp each recording to the model's time by the model's MEAN warping
# function, rescaled to the recording's own length, then project every DoF on
# its FPCs. The residual norms give the L2 distance of eq. 4.4 over the whole
# hand, which the FPCA classifier ranks. All recordings of a set go to the
# native kernel in one call, which reads them from their list in place.

#' Project recordings onto a grasp model
#'
#' `project()` projects recordings onto a fitted model (or every model of a
#' set). Each recording
#' of `new_data` (any length) is warped to the model's template time by the
#' model's mean warping function `w_bar`, normalised to \[0, 1\] and
#' mapped onto the recording's frames `1..n`, and evaluated there by linear
#' interpolation. Each DoF is then projected onto the model's FPCs; the
#' residual norm per DoF is the L2 norm of the warped curve minus its
#' projection, and `distance` is the square root of the sum over DoFs of the
#' squared residual norms (eq. 4.4 over the whole hand) over a \[0, 1\] time
#' axis; the FPCA classifier ranks it times `sqrt(target_length - 1)`, the
#' thesis' frame axis (see [classify()]; [predict.grasp_models()] gives
#' the classes it implies).
#'
#' The projection is of the recording minus the model's mean function, and
#' the fitted curve is the mean plus the FPCs times the scores. Eq. 4.4 as
#' printed, `||g - sum_k <g, f_k> f_k||`, has no mean term; we read it as
#' centred because the thesis' own projections are: its GMM weights come
#' from the same projection and "had means centered at zero", weight zero
#' giving "only the mean function" (section 5.1.4). Read literally, the distance would rank models by how
#' well two FPCs through the origin span a whole joint-angle curve: on
#' `simulate_grasps()` (seeds 1 and 2) the FPCA classifier then recognises
#' 7-8% of the recordings, against the thesis' 35%, and one model is the
#' closest of 12-13 types in Table 5.3.
#'
#' @param object A `grasp_model` ([fit_grasp_model()]) or a `grasp_models`
#'   set ([fit_grasp_models()]).
#' @param new_data A [grasps()] object with the model's DoFs.
#' @param details Keep the warped and fitted curves (`TRUE` by default for one
#'   model, `FALSE` for a model set, where they would take
#'   recordings x models x frames x DoFs of memory).
#' @param ... Unused.
#' @return For one model, an object of class `grasp_projection`: a list with
#'   `scores` (array recordings x DoF x FPC), `residual` (recordings x DoF
#'   residual norms), `distance` (one per recording), `ids`, `grasp` (the
#'   model's type), `target_length` and, with `details`, `warped` and `fitted`
#'   (lists of L x DoF matrices). For a model set, a named list of such
#'   projections, one per fitted model (failed types have none).
#' @seealso [classify()] and [predict.grasp_models()] rank the distances of
#'   every model.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' pr <- project(m, g[1:3])
#' pr$distance
project <- function(object, new_data, ...) {
  UseMethod("project")
}

#' @rdname project
#' @export
project.grasp_model <- function(object, new_data, details = TRUE, ...) {
  call <- rlang::caller_env()
  check_dots_for(list(...), project.grasp_model, "project", call = call)
  check_new_recordings(new_data, "new_data", "project", call = call)
  validate_projection_model(object, call)
  check_projection_dofs(object, new_data, call)
  # recordings projected on a model of trimmed motion are trimmed alike
  if (identical(object$settings$motion, "trim")) new_data <- trim_motion(new_data)
  project_recordings(object, new_data, details = details)
}

#' @rdname project
#' @export
project.grasp_models <- function(object, new_data, details = FALSE, ...) {
  call <- rlang::caller_env()
  check_dots_for(list(...), project.grasp_models, "project", call = call)
  check_new_recordings(new_data, "new_data", "project", call = call)
  check_grasp_models(object, "object", "project", each = FALSE, call = call)
  models <- fitted_models(object)
  project_models(models, projection_input(models, new_data), "object", details = details, call = call)
}

# A single model is not a classifier: its predict() was the projection,
# now project() (see ?handmotion-renamed).
#' @export
predict.grasp_model <- function(object, ...) {
  hm_abort(c("A single {.cls grasp_model} is not a classifier, so it has no {.fn predict}.",
             i = "Project recordings onto it with {.code project(model, new_data)}; classify with a {.fn fit_grasp_models} set."),
           "bad_input", argument = "object", call = rlang::caller_env())
}

#' @export
project.default <- function(object, new_data, ...) {
  abort_no_method("project", object, "object", call = rlang::caller_env())
}

# The recordings every model of a set projects, made ready once: trimmed
# when the models were fitted to trimmed motion (recordings projected on
# such models are trimmed alike), and their matrices as double, as the
# native kernel reads them. `models`: a list of fitted models.
projection_input <- function(models, new_data) {
  if (any(vapply(models, function(m) identical(m$settings$motion, "trim"), logical(1)))) {
    new_data <- trim_motion(new_data)
  }
  list(x = new_data, recs = double_recordings(new_data))
}

# Every model of `models` (a list of fitted models) projects the recordings
# of `input` (projection_input()): each model is validated and projects the
# recordings straight from their list (R/project.R's kernel reads them in
# place). `keep(projection, model)` reduces each projection as it is made
# (the FPCA classifier keeps only the distances, fpca_model_distance(): all
# scores of every model would be n x 33 x p x ncomp numbers), and
# `distance_only` tells the kernel not to return the rest at all; with
# `keep_going` a model that cannot project gives its error in its place
# instead of stopping the rest. `time_weights`, a function of the model,
# gives each its weights on the template time (the weighted FPCA distance);
# NULL is eq. 4.4. One progress step per model (`progress`, a progressr
# progressor or NULL).
project_models <- function(models, input, arg, details, call, keep = function(pr, m) pr, keep_going = FALSE,
                           time_weights = NULL, distance_only = FALSE, progress = NULL) {
  if (length(models) == 0L) {
    hm_abort("{.arg {arg}} holds no fitted grasp models.", "bad_input", argument = arg, call = call)
  }
  # before the native kernel; an edited model is the caller's error, not a
  # type to skip with keep_going
  for (m in models) validate_projection_model(m, call)
  one <- function(m) {
    check_projection_dofs(m, input$x, call)
    keep(project_recordings(m, input$x, details = details, distance_only = distance_only, recs = input$recs,
                            time_weights = if (!is.null(time_weights)) time_weights(m)), m)
  }
  lapply(models, function(m) {
    out <- if (keep_going) tryCatch(one(m), error = function(e) e) else one(m)
    if (!is.null(progress)) progress()
    out
  })
}

# A model whose basis was changed after fitting would reach the native kernel
# with arrays of the wrong size (it refuses them, with an unclassed error):
# say which part does not fit, as validate_sampler() does for generate().
validate_projection_model <- function(model, call) {
  bad <- model_fault(model, "project", "object", call)
  if (!inherits(model, "grasp_model")) bad("it is not a {.cls grasp_model}")
  fault <- model_parts_fault(model)
  if (!is.null(fault)) bad(fault)
  L <- model$target_length
  p <- length(model$dofs)
  k <- model$settings$ncomp
  if (!is.character(model$dofs) || p == 0L) bad("it names no DoFs")
  if (!is.numeric(L) || length(L) != 1L || !is.finite(L) || L < 2) bad("its target length is not a frame count")
  if (!is.numeric(k) || length(k) != 1L || !is.finite(k) || k < 1) bad("its number of FPCs is not a count")
  fault <- fpca_shape_fault(model, k)
  if (!is.null(fault)) bad(fault)
  if (length(model$fpca) != p ||
      !all(vapply(model$fpca, function(f) length(f$weights) == L, logical(1)))) {
    bad("its quadrature weights do not match {L} frames for {p} DoF{?s}")
  }
  invisible(model)
}

check_projection_dofs <- function(model, x, call) {
  missing <- setdiff(model$dofs, x$dofs)
  if (length(missing)) {
    hm_abort(c("{.arg new_data} lacks the model's DoF{?s} {.val {missing}}.",
               i = "The model of {.val {model$grasp}} was fitted on {.val {model$dofs}}."),
             "bad_input", argument = "new_data", call = call)
  }
}

# The recordings as double matrices, as the kernel reads them (simulated
# and read data already are: then this is the list itself, no copy).
double_recordings <- function(x) {
  recs <- x$recordings
  if (all(vapply(recs, is.double, logical(1)))) return(recs)
  lapply(recs, function(r) {
    storage.mode(r) <- "double"
    r
  })
}

# Where every recording is read on the model's template grid: the model's
# mean warp normalised to [0, 1] (made non-decreasing), so template point s
# of a recording of m frames sits at frame 1 + u_s (m - 1), read by linear
# interpolation between the frames either side (in the kernel).
warp_positions <- function(model) {
  L <- model$target_length
  wbar <- warp_basis(model)$mean
  span <- wbar[L] - wbar[1]
  u <- if (is.finite(span) && span > 0) (wbar - wbar[1]) / span else seq(0, 1, length.out = L)
  as.double(pmin(pmax(cummax(u), 0), 1))
}

# The projection of every recording of x on one model, in the native kernel
# (src/project-kernel.c: warp, centre, scores, residual norms, and the
# distance over DoFs, recording by recording). time_weights: optional weights
# on the model's template grid for the residual norms (the weighted FPCA
# distance); NULL is eq. 4.4. distance_only: the kernel returns only the
# distances (what the classifier ranks). recs: double_recordings(x), when
# the caller projects the same recordings on several models.
project_recordings <- function(model, x, details = TRUE, time_weights = NULL, distance_only = FALSE,
                               recs = double_recordings(x)) {
  L <- model$target_length
  n <- length(recs)
  p <- length(model$dofs)
  k <- model$settings$ncomp
  ids <- x$meta$id
  # quadrature weights per DoF; a constant DoF's basis has zero components,
  # so the kernel gives it zero scores and its distance to the mean
  w <- vapply(model$fpca, function(f) as.double(f$weights), numeric(L))
  dim(w) <- c(L, p)
  B <- model_basis(model)
  mode <- if (details) 2L else if (distance_only) 0L else 1L
  res <- .Call(hm_project_warped, recs, match(model$dofs, x$dofs), warp_positions(model),
               B$mean, B$components, w, w * (time_weights %||% 1), mode)
  distance <- stats::setNames(res$distance, ids)
  if (distance_only) {
    return(structure(list(distance = distance, ids = ids, grasp = model$grasp, target_length = L),
                     class = "grasp_projection"))
  }
  scores <- array(res$scores, c(n, p, k), dimnames = list(ids, model$dofs, paste0("FPC", seq_len(k))))
  resid <- matrix(res$residual, n, p, dimnames = list(ids, model$dofs))
  out <- list(scores = scores, residual = resid, distance = distance,
              ids = ids, grasp = model$grasp, target_length = L)
  if (details) {
    warped <- res$warped
    fitted <- matrix(0, n * L, p)
    for (j in seq_len(p)) {
      fitted[, j] <- as.vector(matrix(B$mean[, j], L, n) +
                                 matrix(B$components[, j, ], L) %*% t(matrix(scores[, j, ], n, k)))
    }
    colnames(warped) <- model$dofs
    colnames(fitted) <- model$dofs
    out$warped <- stats::setNames(split_rows(warped, rep.int(L, n)), ids)
    out$fitted <- stats::setNames(split_rows(fitted, rep.int(L, n)), ids)
  }
  structure(out, class = "grasp_projection")
}

#' @export
print.grasp_projection <- function(x, ...) {
  cli::cat_line(cli::pluralize(
    "<grasp_projection> {length(x$ids)} recording{?s} onto the {x$grasp} model ({as.integer(x$target_length)} frames)"))
  if (length(x$distance)) {
    q <- stats::quantile(x$distance, c(0, 0.5, 1), names = FALSE)
    cli::cat_line(sprintf("  L2 distance to the projection: min %.3g, median %.3g, max %.3g", q[1], q[2], q[3]))
  }
  invisible(x)
}
