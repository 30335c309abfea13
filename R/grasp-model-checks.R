# Fitted models checked where they are used. A model edited after fitting
# (a part dropped, a mean set to NaN, a set holding something that is not a
# model) used to generate or classify silently from the damaged part, or to
# fail in base R far from the edit. The constructors validate what they
# build (validate_grasp_model(), validate_grasp_models()); these re-check,
# cheaply (O(size of the model)), what the verbs read, and name the part.

# What is wrong with a fitted grasp_model's parts, as a sentence fragment
# (cli inline markup) for model_fault(), or NULL when they fit together.
model_parts_fault <- function(model) {
  if (!inherits(model, "grasp_model")) return("it is not a {.cls grasp_model}")
  finite_num <- function(v) is.numeric(v) && length(v) > 0L && all(is.finite(v))
  dofs <- model$dofs
  p <- length(dofs)
  if (!is.character(dofs) || p == 0L || anyNA(dofs) || anyDuplicated(dofs)) {
    return("its {.field dofs} are not unique DoF names")
  }
  if (!finite_num(model$rate) || length(model$rate) != 1L || model$rate <= 0) {
    return("its {.field rate} is not a positive number")
  }
  if (!is.character(model$unit) || length(model$unit) != 1L || !model$unit %in% grasp_units) {
    return("its {.field unit} is not one of {.val {grasp_units}}")
  }
  L <- model$target_length
  if (!finite_num(L) || length(L) != 1L || L < 2 || L != round(L)) {
    return("its {.field target_length} is not a frame count")
  }
  if (!finite_num(model$argvals) || length(model$argvals) != L) {
    return(sprintf("its {.field argvals} are not %d finite time points", L))
  }
  parts <- list(fpca = "fpca_fit", gmm = "gmm_fit")
  for (part in names(parts)) {
    el <- model[[part]]
    if (!is.list(el) || length(el) != p || !identical(names(el), dofs) ||
        !all(vapply(el, inherits, logical(1), parts[[part]]))) {
      return(sprintf("its {.field %s} does not hold one %s per DoF", part, if (part == "fpca") "FPCA" else "mixture"))
    }
  }
  for (j in seq_len(p)) {
    f <- model$fpca[[j]]
    if (!finite_num(f$mean) || length(f$mean) != L) {
      return(sprintf("the {.field fpca} mean of DoF %s is not %d finite values", dofs[j], L))
    }
    if (!is.numeric(f$components) || NROW(f$components) != L || !all(is.finite(f$components))) {
      return(sprintf("the {.field fpca} components of DoF %s are not finite, with %d frames", dofs[j], L))
    }
    m <- model$gmm[[j]]
    if (!finite_num(m$weights) || any(m$weights < 0) || abs(sum(m$weights) - 1) > 1e-6 ||
        !finite_num(m$means) || NROW(m$means) != length(m$weights) || !finite_num(m$covs)) {
      return(sprintf("the {.field gmm} mixture of DoF %s does not have finite weights summing to 1, means and covariances",
                     dofs[j]))
    }
  }
  w <- model$warp
  if (!is.list(w) || !inherits(w$fpca, "fpca_fit") || !finite_num(w$fpca$mean) || length(w$fpca$mean) != L) {
    return("its {.field warp} model is missing or does not match its frames")
  }
  NULL
}

# A fitted model given as argument `arg` to a verb that `action`s with it:
# a classed bad_model error naming the argument, the type and the part.
check_grasp_model <- function(model, arg, action, call = rlang::caller_env()) {
  fault <- model_parts_fault(model)
  if (!is.null(fault)) model_fault(if (is.list(model)) model else list(), action, arg, call)(fault)
  invisible(model)
}

# A grasp_models set: only models and failed types, named by their types,
# with (when set) a positive temperature; every fitted model
# checked as above.
check_grasp_models <- function(x, arg, action, each = TRUE, call = rlang::caller_env()) {
  bad <- function(what) {
    hm_abort(c(paste0("{.arg {arg}} is not a valid {.cls grasp_models} set: ", what, "."),
               i = "Was it changed after fitting? Refit it with {.fn fit_grasp_models}."),
             "bad_model", argument = arg, call = call, .envir = parent.frame())
  }
  m <- if (is.list(x)) .subset2(x, "models")
  if (!is.list(m) || is.object(m)) bad("it holds no list of models (a set saved by an earlier version of handmotion?)")
  ok <- vapply(m, function(e) inherits(e, "grasp_model") || inherits(e, "grasp_model_failed"), logical(1))
  if (!all(ok)) {
    i <- which(!ok)[1]
    what <- sprintf("%s$models[[%d]]%s", arg, i, if (!is.null(names(m)) && nzchar(names(m)[i])) sprintf(" (%s)", names(m)[i]) else "")
    bad("element {.code {what}} is not a fitted model but {.obj_type_friendly {m[[i]]}}")
  }
  if (length(m) && (is.null(names(m)) || anyDuplicated(names(m)))) bad("its models are not named by unique grasp types")
  temp <- x$temperature
  if (!is.null(temp) && (!is.numeric(temp) || length(temp) != 1L || !is.finite(temp) || temp <= 0)) {
    bad("its {.field temperature} is not a positive number")
  }
  if (each) for (e in m[vapply(m, inherits, logical(1), "grasp_model")]) check_grasp_model(e, arg, action, call)
  invisible(x)
}

# The first numeric part (by its path, `fit$coef`) holding a missing or
# infinite value, or NULL. Data frames (reports) are not model parts; a
# single number may be infinite (a setting: neighbours = Inf), not
# missing.
nonfinite_part <- function(x, path) {
  if (is.data.frame(x) || is.environment(x) || is.function(x)) return(NULL)
  if (is.list(x)) {
    nms <- names(x) %||% rep("", length(x))
    for (i in seq_along(x)) {
      sub <- if (nzchar(nms[i])) paste0(path, "$", nms[i]) else sprintf("%s[[%d]]", path, i)
      found <- nonfinite_part(x[[i]], sub)
      if (!is.null(found)) return(found)
    }
    return(NULL)
  }
  bad <- if (length(x) == 1L) is.na(x) else !all(is.finite(x))
  if (is.numeric(x) && bad) path else NULL
}

# A fitted classifier or hand-over model given as `arg`: the parts its
# predict() reads are there, finite, and agree with one another.
# The fields it reads are its classifier_parts() (a method beside each
# classifier; a hand-over model's beside fit_handover()).
check_fitted_parts <- function(object, arg, call = rlang::caller_env()) {
  parts <- classifier_parts(object)
  if (!length(parts)) return(invisible(object))
  kind <- class(object)[1]
  bad <- function(what) {
    hm_abort(c(paste0("{.arg {arg}} is not a valid {.cls {kind}} fit: ", what, "."),
               i = "Was it changed after fitting? Refit it."),
             "bad_model", argument = arg, call = call, .envir = parent.frame())
  }
  lost <- parts[vapply(parts, function(f) is.null(object[[f]]), logical(1))]
  if (length(lost)) bad("it has no {.field {lost}}")
  if (!is.null(object$classes) && !is.null(object$n) && length(object$classes) != length(object$n)) {
    bad("its {.field classes} ({length(object$classes)}) do not match its class counts {.field n} ({length(object$n)})")
  }
  if (!is.null(object$at) && (!is.numeric(object$at) || any(!is.finite(object$at) | object$at < 0 | object$at > 1))) {
    bad("its fractions {.field at} are not in [0, 1]")
  }
  temp <- object$temperature
  if (!is.null(temp) && (!is.numeric(temp) || length(temp) != 1L || !is.finite(temp) || temp <= 0)) {
    bad("its {.field temperature} is not a positive number")
  }
  part <- nonfinite_part(unclass(object)[setdiff(names(object), "models")], arg)
  if (!is.null(part)) bad("{.code {part}} holds missing or infinite values")
  if (inherits(object$models, "grasp_models")) check_grasp_models(object$models, paste0(arg, "$models"), "classify", call = call)
  invisible(object)
}
