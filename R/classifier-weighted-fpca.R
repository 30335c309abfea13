# The thesis' own proposals for its FPCA classifier (its chapter 6): weigh
# the DoFs that tell a type apart, and weigh the end of the motion more. Its
# distance (eq. 4.4) adds every DoF's residual norm alike, so a DoF whose
# residual is always large for a type (it varies a lot there) drowns the one
# DoF that would have told two types apart. Worse, the residual is what is
# left after the projection, and the projection absorbs exactly what tells
# types apart: a recording of another type that flexes a finger more is
# fitted by a large score on the amplitude FPC, with a small residual. The
# weighted distance therefore weighs each DoF by the type's own spread in
# both parts: the residual (its typical size) and the scores (the type's
# mixture), i.e. minus twice the recording's log-likelihood under the model.

# fit_grasp_classifier(method = "weighted_fpca") (documented there): the
# per-type scales s2 of every DoF's residual norm on the type's own training
# recordings, with `...` passed to fit_grasp_models() when `models` is NULL.
fit_weighted_fpca <- function(x, models = NULL, time = c("uniform", "end"), ..., call = rlang::caller_env()) {
  check_grasps(x, call = call)
  time <- check_choice(time, c("uniform", "end"), arg = "time", call = call)
  check_training_labels(x, call = call)
  if (is.null(models)) {
    args <- list(...)
    if (is.null(args$mixture_components)) args$mixture_components <- 1L
    # (its own distance is a log-likelihood: the set needs no temperature)
    models <- do.call(fit_model_set, c(list(x), args, calibrate = FALSE))
  }
  if (!inherits(models, "grasp_models")) {
    hm_abort("{.arg models} must be a {.cls grasp_models} fit, not {.obj_type_friendly {models}}.",
             "bad_input", argument = "models", call = call)
  }
  # the types that have a model (a failed type cannot be a class)
  models <- new_grasp_models(fitted_models(models), seed = models$seed)
  types <- names(models)
  missing <- setdiff(types, as.character(unique(x$meta$grasp)))
  if (length(missing)) {
    hm_abort("{.arg x} has no recordings of the modelled type{?s} {.val {missing}}.", "bad_input",
             argument = "x", call = call)
  }
  scale <- t(vapply(types, function(ty) {
    m <- models[[ty]]
    own <- x[x$meta$grasp == ty]
    r <- project_recordings(m, own, details = FALSE,
                            time_weights = distance_time_weights(m$target_length, time))$residual
    s2 <- colMeans(r^2)
    # a DoF the type reproduces exactly still gets a finite scale
    pmax(s2, 1e-6 * max(mean(s2), 1e-12))
  }, numeric(length(models[[1]]$dofs))))
  dimnames(scale) <- list(types, models[[1]]$dofs)
  # the distance is minus twice the log-likelihood: temperature 2 gives the
  # models' posterior with equal priors
  new_grasp_classifier(models = models, time = time, scale = scale, classes = types, levels = grasp_levels(x),
                       n = table(factor(as.character(x$meta$grasp), levels = types)), temperature = 2,
                       class = "weighted_fpca")
}

# The weighted FPCA distance in the classifier family (R/classifier.R).
#' @export
classifier_distances.weighted_fpca <- function(object, new_data, ..., call = rlang::caller_env()) {
  weighted_fpca_distances(object, new_data, call = call)
}

#' @export
classifier_method.weighted_fpca <- function(object) "weighted_fpca"

#' @export
classifier_parts.weighted_fpca <- function(object) c(NextMethod(), "models", "scale")

# Weights on a template grid of L points: uniform (the thesis) or rising
# linearly from 0 to 2 (mean 1).
distance_time_weights <- function(L, time) {
  if (time == "uniform" || L < 2L) return(rep(1, L))
  2 * (seq_len(L) - 1) / (L - 1)
}

# The weighted distances, recordings x models.
weighted_fpca_distances <- function(object, x, call = rlang::caller_env()) {
  types <- rownames(object$scale)
  models <- fitted_models(object$models)
  d <- project_models(models, projection_input(models, x), "models", details = FALSE, call = call,
                      progress = hm_progressor(length(models)),
                      time_weights = function(m) distance_time_weights(m$target_length, object$time),
                      keep = function(r, m) {
                        s2 <- object$scale[r$grasp, ]
                        drop(r$residual^2 %*% (1 / s2)) + sum(log(s2)) -
                          2 * score_log_density(m, r$scores)
                      })
  matrix(unlist(d[types], use.names = FALSE), length(x$recordings), length(types),
         dimnames = list(x$meta$id, types))
}

# Sum over DoFs of the log density of each recording's FPC scores under the
# DoF's mixture, each floored (see fit_weighted_fpca()).
score_log_density <- function(model, scores) {
  n <- dim(scores)[1]
  out <- numeric(n)
  for (j in seq_along(model$dofs)) {
    G <- model$gmm[[j]]
    X <- matrix(scores[, j, ], n)
    out <- out + pmax(gmm_log_density(G$weights, G$means, G$covs, X), weighted_fpca_log_floor)
  }
  out
}

weighted_fpca_log_floor <- -50

#' @export
print.weighted_fpca <- function(x, ...) {
  time <- if (x$time == "end") "end-of-motion" else "uniform"
  cli::cat_line(cli::pluralize("<weighted_fpca> {nrow(x$scale)} grasp model{?s}, {time} time weights, per-type DoF weights"))
  w <- 1 / x$scale
  w <- w / rowMeans(w)
  top <- apply(w, 1L, function(v) paste(names(sort(v, decreasing = TRUE))[1:2], collapse = "+"))
  cli::cat_line("  most weighted DoFs: ", paste(utils::head(sprintf("%s (%s)", names(top), top), 4), collapse = "; "))
  invisible(x)
}

#' @rdname summary.grasp_classifier
#' @export
summary.weighted_fpca <- function(object, ...) {
  w <- 1 / object$scale[object$classes, , drop = FALSE]
  classifier_summary_frame(object,
                           top_dofs = apply(w, 1L, function(v) paste(names(sort(v, decreasing = TRUE))[1:min(2L, length(v))],
                                                                     collapse = "+")),
                           weight_range = apply(w, 1L, function(v) max(v) / min(v)))
}
