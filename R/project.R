# Projection of recordings onto a fitted model (Jeppsson 2017, section 4.2):
# warp each recording to the model's time by the model's MEAN warping
# function, rescaled to the recording's own length, then project every DoF on
# its FPCs. The residual norms give the L2 distance of eq. 4.4 over the whole
# hand, which the FPCA classifier ranks. All recordings are handled at once:
# they are stacked into one matrix and interpolated by index arithmetic.

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
  check_grasps(new_data, "new_data", call = call)
  validate_projection_model(object, call)
  check_projection_dofs(object, new_data, call)
  project_stacked(object, stack_recordings(new_data, object$dofs), details = details)
}

#' @rdname project
#' @export
project.grasp_models <- function(object, new_data, details = FALSE, ...) {
  call <- rlang::caller_env()
  check_dots_for(list(...), project.grasp_models, "project", call = call)
  check_grasps(new_data, "new_data", call = call)
  project_models(object, new_data, "object", details = details, call = call)
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
  hm_abort("{.fn project} needs a {.cls grasp_model} or {.cls grasp_models} fit, not {.obj_type_friendly {object}}.",
           "bad_input", argument = "object", call = rlang::caller_env())
}

# Every fitted model of a set projects `newdata`: each model is validated
# and the recordings are stacked once per DoF set (all models share one in
# practice). `keep` reduces each projection as it is made (the FPCA
# classifier keeps only the distances: all scores of every model would be
# n x 33 x p x ncomp numbers); with `keep_going` a model that cannot project
# gives its error in its place instead of stopping the rest. `time_weights`,
# a function of the model, gives each its weights on the template time (the
# weighted FPCA distance); NULL is eq. 4.4.
project_models <- function(models, newdata, arg, details, call, keep = identity, keep_going = FALSE,
                           time_weights = NULL) {
  models <- fitted_models(models)
  if (length(models) == 0L) {
    hm_abort("{.arg {arg}} holds no fitted grasp models.", "bad_input", argument = arg, call = call)
  }
  stacks <- list()
  # recordings projected on models fitted to trimmed motion are trimmed alike
  if (any(vapply(models, function(m) identical(m$settings$motion, "trim"), logical(1)))) {
    newdata <- trim_motion(newdata)
  }
  one <- function(m) {
    validate_projection_model(m, call)  # before the native kernel
    check_projection_dofs(m, newdata, call)
    key <- paste(m$dofs, collapse = "\r")
    if (is.null(stacks[[key]])) stacks[[key]] <<- stack_recordings(newdata, m$dofs)
    keep(project_stacked(m, stacks[[key]], details = details,
                         time_weights = if (!is.null(time_weights)) time_weights(m)))
  }
  lapply(models, function(m) if (keep_going) tryCatch(one(m), error = function(e) e) else one(m))
}

# A model whose basis was changed after fitting would reach the native kernel
# with arrays of the wrong size (it refuses them, with an unclassed error):
# say which part does not fit, as validate_sampler() does for generate().
validate_projection_model <- function(model, call) {
  bad <- model_fault(model, "project", "object", call)
  if (!inherits(model, "grasp_model")) bad("it is not a {.cls grasp_model}")
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

# All recordings stacked into one (sum n_k) x p matrix with their offsets, so
# interpolation for every recording is one vectorised step.
stack_recordings <- function(x, dofs) {
  recs <- x$recordings
  n_frames <- x$meta$n_frames
  cols <- match(dofs, x$dofs)
  mat <- do.call(rbind, recs)
  if (!identical(cols, seq_along(x$dofs))) mat <- mat[, cols, drop = FALSE]
  storage.mode(mat) <- "double"
  list(values = mat, n_frames = n_frames, starts = cumsum(n_frames) - n_frames, ids = x$meta$id)
}

# Where every stacked recording is read on the model's template grid with the
# model's mean warp: for template point s of recording i (entry s + L (i - 1)),
# the stacked rows either side and the weight of the later one. warp_dof()
# then interpolates one DoF at a time, straight into an L x n matrix.
warp_index <- function(model, st) {
  L <- model$target_length
  wbar <- warp_basis(model)$mean
  span <- wbar[L] - wbar[1]
  u <- if (is.finite(span) && span > 0) (wbar - wbar[1]) / span else seq(0, 1, length.out = L)
  u <- pmin(pmax(cummax(u), 0), 1)
  nk <- st$n_frames
  n <- length(nk)
  # plain vectors, entry s + L (i - 1): pmin() on matrices costs more than the rest
  times <- 1 + as.vector(outer(u, nk - 1))                 # frame position on recording i
  i <- floor(times)
  cap <- rep(pmax(nk - 1L, 1L), each = L)
  over <- i > cap
  i[over] <- cap[over]
  f <- times - i
  f[rep(nk == 1L, each = L)] <- 0
  start <- rep(st$starts, each = L)
  rows <- i + start
  nxt <- rows + 1
  last <- start + rep(nk, each = L)
  over <- nxt > last
  nxt[over] <- last[over]
  f <- as.vector(f)
  list(rows = as.integer(rows), nxt = as.integer(nxt), f = f, g = 1 - f, L = L, n = n)
}

# One DoF of every recording warped onto the template grid: L x n.
warp_dof <- function(ix, v) {
  y <- v[ix$rows] * ix$g + v[ix$nxt] * ix$f
  dim(y) <- c(ix$L, ix$n)
  y
}

# time_weights: optional weights on the model's template grid for the
# residual norms (the weighted FPCA distance); NULL is eq. 4.4.
project_stacked <- function(model, st, details = TRUE, time_weights = NULL) {
  L <- model$target_length
  n <- length(st$n_frames)
  p <- length(model$dofs)
  k <- model$settings$ncomp
  ix <- warp_index(model, st)
  # quadrature weights per DoF; a constant DoF's basis has zero components,
  # so the kernel gives it zero scores and its distance to the mean
  w <- vapply(model$fpca, function(f) as.double(f$weights), numeric(L))
  B <- model_basis(model)
  res <- .Call(hm_project_batch, st$values, ix$rows, ix$nxt, ix$f, B$mean,
               B$components, w, w * (time_weights %||% 1))
  scores <- array(res$scores, c(n, p, k), dimnames = list(st$ids, model$dofs, paste0("FPC", seq_len(k))))
  resid <- matrix(res$residual, n, p, dimnames = list(st$ids, model$dofs))
  if (details) {
    warped <- fitted <- matrix(0, n * L, p)
    for (j in seq_len(p)) {
      warped[, j] <- warp_dof(ix, st$values[, j])
      fitted[, j] <- as.vector(matrix(B$mean[, j], L, n) +
                                 matrix(B$components[, j, ], L) %*% t(matrix(scores[, j, ], n, k)))
    }
  }
  out <- list(scores = scores, residual = resid, distance = sqrt(rowSums(resid^2)),
              ids = st$ids, grasp = model$grasp, target_length = L)
  names(out$distance) <- st$ids
  if (details) {
    colnames(warped) <- model$dofs
    colnames(fitted) <- model$dofs
    out$warped <- stats::setNames(split_rows(warped, rep.int(L, n)), st$ids)
    out$fitted <- stats::setNames(split_rows(fitted, rep.int(L, n)), st$ids)
  }
  structure(out, class = "grasp_projection")
}

#' @export
print.grasp_projection <- function(x, ...) {
  cat(sprintf("<grasp_projection> %d recording%s onto the %s model (%d frames)\n",
              length(x$ids), if (length(x$ids) == 1) "" else "s", x$grasp, x$target_length))
  if (length(x$distance)) {
    q <- stats::quantile(x$distance, c(0, 0.5, 1), names = FALSE)
    cat(sprintf("  L2 distance to the projection: min %.3g, median %.3g, max %.3g\n", q[1], q[2], q[3]))
  }
  invisible(x)
}
