# The settings a grasp model takes when its arguments are left NULL, which
# depend on `dependence` (and the warping on trimming): one table, shown by
# print() of every fit (format_settings()) and documented in ?fit_grasp_model.

# The settings each model takes when its arguments are left NULL. The
# independent model is the thesis' (section 4.1); the copula model's were
# chosen by measurement on held-out subjects (vignette("natural-grasps") and
# NEWS): linear time normalisation keeps the timing in the curves, where the
# FPCs and the copula carry it with the rest, instead of in DTW warps that
# the inverse map cannot reproduce; least-squares scores reconstruct the
# final posture in full; four FPCs per DoF carry the mid-motion variation;
# one Gaussian per score is as good as two-component mixtures there at a
# fraction of the cost (the guard still applies with mixture_components > 1).
model_defaults <- list(
  independent = list(ncomp = 2L, warp_ncomp = 1L, mixture_components = 2L, warping = "dtw",
                     mixture_guard = "none", fpc_scores = "trapezoid"),
  copula = list(ncomp = 4L, warp_ncomp = 1L, mixture_components = 1L, warping = "linear",
                mixture_guard = "bic", fpc_scores = "least_squares"))
# the kernel model draws the FPC and warp scores as the copula model does
# (all at once), so it takes the copula's basis; its mixtures are fitted for
# print() and the independent marginals only
model_defaults$kernel <- model_defaults$copula

# The settings a model was fitted with, as print() shows them: those left
# to the defaults (which depend on `dependence` and, for the warping, on
# whether the recordings were trimmed; see ?fit_grasp_model, Defaults) apart
# from those the caller gave. Models fitted before the defaults were
# recorded show every setting as given.
format_settings <- function(settings) {
  keys <- c("ncomp", "warp_ncomp", "mixture_components", "warping", "fpc_scores", "mixture_guard",
            "residuals")
  val <- function(k) {
    v <- settings[[k]]
    if (is.character(v)) sprintf("\"%s\"", v) else format(v)
  }
  show <- function(ks) paste(vapply(ks, function(k) paste(k, "=", val(k)), character(1)), collapse = ", ")
  keys <- keys[vapply(keys, function(k) !is.null(settings[[k]]), logical(1))]
  dflt <- intersect(keys, settings$defaulted)
  given <- setdiff(keys, dflt)
  motion <- sprintf("motion = \"%s\"%s", settings$motion %||% "as_recorded",
                    if (identical(settings$motion_asked, "auto")) " (resolved from \"auto\")" else "")
  lines <- c(if (length(dflt)) sprintf("defaults for dependence = \"%s\"%s: %s", settings$dependence,
                                       if (identical(settings$motion, "trim")) " and trimmed recordings" else "",
                                       show(dflt)),
             sprintf("%s%s", if (length(given)) paste0("given: ", show(given), "; ") else "", motion))
  unlist(lapply(lines, strwrap, width = 0.9 * getOption("width"), indent = 2, exdent = 4))
}
