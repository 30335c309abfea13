# print() and summary() of a grasp model.

#' @export
print.grasp_model <- function(x, ...) {
  s <- x$settings
  id <- if (!is.na(x$grasp_id)) sprintf(" (type %d)", as.integer(x$grasp_id)) else ""
  cli::cat_line(cli::pluralize(paste0(
    "<grasp_model> {x$grasp}{id}: {length(x$dofs)} DoF{?s} x {s$ncomp} FPC{?s} + {s$warp_ncomp} warp FPC{?s}, ",
    "{s$mixture_components}-component mixtures")))
  rm <- table(factor(x$removed$reason, levels = c("overlong", "degenerate warp")))
  nk <- NROW(x$warping$degenerate)
  kept <- if (nk) cli::pluralize("; {nk} degenerate warp{?s} kept by a fallback") else ""
  cli::cat_line(cli::pluralize(paste0(
    "  recordings: {x$n_input} in, {x$n_used} used ({rm[['overlong']]} over-long, ",
    "{rm[['degenerate warp']]} degenerate warp{?s} removed{kept})")))
  trimmed <- if (identical(s$motion, "trim")) "; recordings trimmed to the motion" else ""
  cli::cat_line(sprintf("  target length: %d frames at %g Hz; warping: %s%s", as.integer(x$target_length), x$rate,
                        x$warping$method, trimmed))
  if (!is.null(x$glove) && any(x$glove$channels$stuck)) {
    cli::cat_line("  stuck channels held constant: ", paste(x$glove$channels$channel[x$glove$channels$stuck], collapse = " "))
  }
  ve <- 100 * rowSums(model_var_explained(x))
  if (any(is.finite(ve))) {
    cli::cat_line(cli::pluralize("  variance explained by {s$ncomp} FPC{?s} per DoF: "),
                  sprintf("min %.1f%%, median %.1f%%, max %.1f%%", min(ve, na.rm = TRUE),
                          stats::median(ve, na.rm = TRUE), max(ve, na.rm = TRUE)))
  }
  cli::cat_line("  ", format_dependence(x))
  cli::cat_line(format_settings(s))
  dg <- format_degenerate(x$degenerate_data)
  if (length(dg)) cli::cat_line(dg)
  fb <- x$fallbacks
  if (nrow(fb) == 0L) {
    cli::cat_line("  fallbacks: none")
  } else {
    cli::cat_line("  fallbacks:")
    cli::cat_line("    ", fb$step, ifelse(is.na(fb$dof), "", paste0(" [", fb$dof, "]")), ": ", fb$reason)
  }
  invisible(x)
}

#' Summarise a grasp model
#'
#' @param object A `grasp_model` from [fit_grasp_model()].
#' @param ... Unused.
#' @return A data frame with one row per DoF: `dof`, the percentage of
#'   variance explained by each FPC (`FPC1`, `FPC2`, ...) and in total
#'   (`total`), the mixture used (`"mixture"`, `"single Gaussian"` or
#'   `"point mass"`) and the fallback reason. The recordings removed and the
#'   fallbacks are kept as attributes `removed` and `fallbacks` and printed;
#'   attribute `dependence_matrix` is the DoF x DoF correlation between the
#'   DoFs' first FPC scores the model generates with (the identity for the
#'   thesis' independent DoFs, `dependence = "independent"`).
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' summary(fit_grasp_model(g, seed = 1))
summary.grasp_model <- function(object, ...) {
  check_grasp_model(object, "object", "be summarised")
  ve <- 100 * model_var_explained(object)
  mix <- vapply(object$gmm, function(g) {
    if (isTRUE(g$point_mass)) "point mass" else if (isTRUE(g$fallback)) "single Gaussian" else "mixture"
  }, character(1))
  reason <- vapply(object$gmm, function(g) if (isTRUE(g$fallback)) gmm_reason(g) else NA_character_,
                   character(1))
  out <- data.frame(dof = object$dofs, as.data.frame(ve, row.names = NULL), total = rowSums(ve),
                    mixture = unname(mix), reason = unname(reason), stringsAsFactors = FALSE)
  rownames(out) <- NULL
  structure(out, class = c("summary_grasp_model", "data.frame"), grasp = object$grasp,
            removed = object$removed, fallbacks = object$fallbacks,
            n_used = object$n_used, n_input = object$n_input, target_length = object$target_length,
            warping = object$warping$method, dependence = format_dependence(object),
            dependence_matrix = dependence_matrix(object))
}

# One line on how a model joins its DoFs and guards its mixtures.
format_dependence <- function(model) {
  guard <- model$settings$mixture_guard %||% "none"
  n_guard <- sum(model$fallbacks$step %in% c("mixture_guard", "warp_mixture_guard"))
  g <- if (guard == "none") "no mixture guard" else
    sprintf("mixture guard %s (%d of %d mixtures one Gaussian)", guard, n_guard, length(model$dofs) + 1L)
  if (!joint_dependence(model)) {
    return(paste0("dependence: independent DoFs (the thesis' model); ", g))
  }
  if (identical(model$dependence$type, "kernel")) {
    kern <- model$dependence$kernel
    return(sprintf("dependence: kernel density over %d scores of %d recordings (bandwidth %.2f of the scores' shrunk covariance, shrinkage %.2f); %s",
                   nrow(kern$columns), kern$n, kern$bandwidth, kern$shrinkage, g))
  }
  R <- dependence_matrix(model)
  r <- abs(R[upper.tri(R)])
  cop <- model$dependence$copula
  sprintf("dependence: Gaussian copula over %d scores (shrinkage %.2f), |r| between DoFs' FPC1 median %.2f, max %.2f; %s",
          nrow(cop$columns), cop$shrinkage, stats::median(r), max(r), g)
}

#' @export
print.summary_grasp_model <- function(x, ...) {
  a <- attributes(x)
  cli::cat_line(cli::pluralize(
    "Grasp model {a$grasp}: {a$n_used} of {a$n_input} recording{?s} used, {a$target_length} frames, {a$warping} warping"))
  cli::cat_line(a$dependence %||% "")
  print(as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE), digits = 4, row.names = FALSE)
  rm <- attr(x, "removed")
  if (nrow(rm)) {
    cli::cat_line("Removed recordings:")
    print(rm, row.names = FALSE)
  }
  fb <- attr(x, "fallbacks")
  cli::cat_line(if (nrow(fb)) "Fallbacks:" else "Fallbacks: none")
  if (nrow(fb)) print(fb, row.names = FALSE)
  invisible(x)
}
