# The per-type generative model of Jeppsson (2017, sections 2.2 and 4.1):
# over-long removal -> multivariate DTW to the type's mean length -> FPCA per
# DoF on the warped curves -> FPCA on the warping functions -> a Gaussian
# mixture per DoF on the FPC scores (and one on the warp scores).
# Everything removed or fallen back on the way is recorded in the model, never
# dropped silently: `removed` (recordings) and `fallbacks` (steps).

#' Fit the generative model of one grasp type
#'
#' Fits the model of Jeppsson (2017, eq. 2.5) to the recordings of one grasp
#' type:
#' 1. recordings whose frame count is significantly longer than the rest are
#'    removed by a documented rule (`overlong`, see Over-long recordings);
#' 2. the rest are aligned by multivariate dynamic time warping
#'    (kept as `alignment`) to the type's mean frame count `L`; recordings with
#'    a degenerate warp (one frame repeated over a long stretch, Figure 5.1)
#'    are dropped, and linear warping is used only if the alignment fails;
#' 3. functional PCA with `ncomp` components per DoF on the warped curves
#'    (`fpca_fit()`), with the variance each component explains;
#' 4. functional PCA with `warp_ncomp` components on the warping functions,
#'    which are kept in original frames so that one component captures the
#'    variation in duration;
#' 5. a `k`-component Gaussian mixture per DoF on the FPC scores, and one on
#'    the warp scores (`gmm_fit()`, with EM capped at 5000 iterations,
#'    recorded as `settings$gmm_max_iter`); when EM fails the mixture is
#'    replaced by a single Gaussian with the sample mean and covariance
#'    (Table 5.1).
#'
#' **Over-long recordings.** Jeppsson (2017, 4.1.2) removed "any recorded
#' grasp with significantly longer frame count than the rest" without a
#' rule; ours is a robust outlier fence: a recording is over-long when its
#' frame count exceeds `max(Q3 + iqr_mult * IQR, median_mult * median)` of the
#' frame counts of its grasp type. The IQR fence (`iqr_mult = 3`, Tukey's
#' "far out") is robust to the over-long recordings themselves; the median
#' floor (`median_mult = 1.5`) keeps a type whose lengths happen to be nearly
#' equal (IQR close to 0) from losing ordinary recordings. The removed ones
#' are listed in `removed`; `autoplot(x, type = "frame_counts")` draws them.
#'
#' **Sign convention.** Each DoF component is oriented so that its largest
#' projection onto the first three Legendre polynomials on the template time
#' (constant, ramp, parabola) is positive; unlike a rule on the integral alone
#' this stays stable for S-shaped components whose integral is near zero. The
#' warp component is oriented so that a positive score means a longer grasp.
#' Refits and subsets therefore give comparable models.
#'
#' A DoF that does not vary (all warped curves equal) cannot carry FPCs: its
#' components are set to zero, its scores to zero, its mixture to a point mass
#' at zero, and the DoF is listed in `fallbacks`. The same holds for warping
#' functions that do not vary (all recordings of one length, linear warps).
#'
#' **Degenerate data** is fitted with these fallbacks, and said: one-frame or
#' identical recordings, constant DoFs, more FPCs than the rank of the
#' curves, mixtures with more components than the recordings can carry and
#' the linear fallback of the alignment raise one warning of class
#' `handmotion_warning_degenerate` (see [handmotion_errors]), are listed in
#' `$degenerate_data` and shown by `print()`.
#'
#' **Defaults.** Arguments left `NULL` take the defaults of the chosen
#' `dependence`:
#'
#' | | `ncomp` | `warp_ncomp` | `k` | `warping` | `fpc_scores` | `mixture_guard` |
#' |---|---|---|---|---|---|---|
#' | `"independent"` (the thesis) | 2 | 1 | 2 | `"dtw"` | `"trapezoid"` | `"none"` |
#' | `"copula"` | 4 | 1 | 1 | `"linear"` | `"least_squares"` | `"bic"` |
#'
#' Recordings trimmed to their motion (argument `motion`) are warped
#' linearly by default in either model: cut at their detected onset and end,
#' they are registered at both landmarks, which linear time normalisation
#' keeps. Dynamic time warping on top of it, with projections by the mean
#' warp, costs held-out accuracy there (on the twin's raw-count glove
#' protocol, six objects, one subject, 5-fold by recording: FPCA distance
#' 75% with DTW, 96% linear).
#'
#' The copula model's were chosen by measurement on held-out subjects
#' ([evaluate_generation()], `vignette("natural-grasps")`): with DTW the
#' mid-motion posture of generated grasps varied a fifth less than recorded
#' (the aligned curves and warps cannot be mapped back to every recorded
#' frame, and truncated warps lose timing), with trapezoidal scores the final
#' posture a twelfth less; linear time normalisation, least-squares scores
#' and four FPCs per DoF remove most of both, and one Gaussian per score
#' joined by the copula (a multivariate Gaussian with shrunk correlation)
#' does as well as two-component mixtures there, at a fraction of the cost.
#'
#' @param x A [grasps()] object holding the recordings of one grasp type (or
#'   give `grasp` to select one type from a larger set).
#' @param grasp Optional grasp type (Feix name or id 1-33) to select from `x`.
#' @param ncomp Number of FPCs per DoF. `NULL` (default): 2 for
#'   `dependence = "independent"` (the thesis), 4 for `"copula"` (see
#'   Defaults).
#' @param warp_ncomp Number of FPCs of the warping functions. `NULL`
#'   (default): 1 (the thesis; with linear time normalisation the warps vary
#'   only by their duration, which one FPC carries exactly).
#' @param k Number of mixture components per score mixture. `NULL`
#'   (default): 2 for the independent model (the thesis), 1 for the copula
#'   model (see Defaults).
#' @param engine `"fast"` or `"reference"`, passed to the alignment, FPCA and
#'   mixture steps; or a named list such as
#'   `list(align = "fast", fpca = "reference", gmm = "reference")` to choose per
#'   step.
#' @param overlong The over-long rule, `c(iqr_mult = , median_mult = )` (see
#'   Over-long recordings; a left-out value keeps its default).
#' @param warping `"dtw"` aligns by dynamic time warping, with the linear
#'   fallback only when it fails; `"linear"` asks for linear warping of every
#'   recording (the thesis' fallback: time normalised to the template length,
#'   so the timing stays in the curves). `NULL` (default): `"dtw"` for the
#'   independent model (the thesis), `"linear"` for the copula model and for
#'   recordings trimmed to their motion (see Defaults).
#' @param max_stall Largest share of template frames a warp may spend on one
#'   original frame before the recording counts as degenerately warped (step
#'   2 of the description).
#' @param seed Seed of the mixture fits (default 1: like every handmotion
#'   verb that draws random numbers, a call repeats itself); the global RNG
#'   is restored afterwards. `NULL` uses the current RNG stream.
#' @param keep_data Keep the alignment (warped curves, warping functions,
#'   frame counts and degenerate warps) in the model, needed by
#'   [autoplot.grasp_model()] for the data layers and the alignment picture.
#'   Set to `FALSE` to keep models small.
#' @param dependence How the DoFs are joined. `"independent"` (default) is
#'   the thesis' model: each DoF's FPC scores and the warp scores are drawn
#'   from their own mixtures, so fingers do not move together (the thesis'
#'   own verdict, its chapter 6); [reproduce_thesis()] uses it. `"copula"`
#'   keeps every one of those marginal distributions and joins all FPC scores
#'   of all DoFs and the warp scores by a Gaussian copula: the correlation of
#'   their normal scores (from ranks), shrunk towards the identity by the
#'   analytic rule of Schafer and Strimmer (2005). Generated hands then move
#'   their fingers together as the recorded ones do
#'   ([evaluate_generation()] measures it), and [generate()] keeps them
#'   inside the joint limits by default.
#' @param mixture_guard `"bic"` keeps a `k`-component mixture only if every
#'   component holds at least `max(2 (d + 1), 0.05 n)` of the `n` recordings
#'   and its BIC beats one Gaussian's; otherwise one Gaussian replaces it
#'   (listed in `fallbacks` as `"mixture_guard"`). It removes the slivers
#'   fitted to two or three outlying recordings (the thesis' Figure 5.6).
#'   `"none"` fits the thesis' mixtures as they come. `NULL` (default):
#'   `"bic"` for the copula model (it matters there only with `k > 1`),
#'   `"none"` for the independent one.
#' @param fpc_scores How FPC scores integrate over time (`fpca_fit()`):
#'   `"trapezoid"`, fda.usc's rule as in the thesis, or `"least_squares"`,
#'   under which the scores are the least-squares coefficients of each curve
#'   on the FPCs, so mean plus FPCs times scores reconstructs the recording's
#'   final posture in full (the trapezoidal rule halves the weight of the end
#'   points, where grasps vary most). `NULL` (default): `"trapezoid"` for the
#'   independent model, `"least_squares"` for the copula model.
#' @param motion Recordings that rest before and hold after the grasp (as a
#'   data glove records them) are cut to the motion first ([trim_motion()]),
#'   so that alignment compares motions, not waiting: `"trim"` always,
#'   `"as_recorded"` never, `"auto"` (default) when the median recording is
#'   more than 35% still (rest plus hold, measured on up to 200 recordings;
#'   the thesis' recordings, cut to the motion, are not trimmed). Recordings
#'   projected on a trimmed model ([classify()], [predict()]) are trimmed the
#'   same way.
#' @param residuals What generation does with the variation the FPCs leave
#'   out: `"none"` (the thesis: a generated curve is the mean plus FPCs times
#'   scores) or `"resample"`: each generated grasp gets the residual curves
#'   (aligned curve minus its FPC reconstruction, all DoFs together) of a
#'   training recording drawn at random, so the generated grasps vary as
#'   much as the recordings, with their sensor noise and small corrections.
#'   `NULL` (default) is `"none"`: on the twin's glove protocol (one person,
#'   six objects, 5 folds by recording, 3 repetitions) resampling did not
#'   bring generated grasps closer to held-out recordings (MMD 1.23 times
#'   the real-vs-real distance with it, 1.06 without, thesis model; 1.26 and
#'   1.14 for the copula model).
#' @return An object of class `grasp_model`: a list with `grasp`, `grasp_id`,
#'   `dofs`, `rate`, `unit`, `target_length`, `argvals`, `n_input`, `n_used`,
#'   `ids` (recordings used), `removed` (data frame: `id`, `n_frames`, `reason`,
#'   `detail`), `warping` (method, fallback reason, engine, ...), `fpca` (one
#'   FPCA per DoF: `mean` and `components` on the template grid, `scores`
#'   n x ncomp, `var_explained`; each stored only there, [summary()] tabulates
#'   the variance explained), `gmm` (one Gaussian mixture per DoF), `warp`
#'   (the warp FPCA, scores and mixture), `sampler` (the mixtures' cumulative
#'   weights and covariance roots, derived from `gmm` and cached because
#'   rebuilding them would make a one-grasp [generate()] about four times
#'   slower), `fallbacks` (data frame: `step`, `dof`,
#'   `reason`), `settings`, `engine`, `timing` (seconds per step) and, with
#'   `keep_data`, `alignment` (a `grasp_alignment`: `warped` array n x L x p,
#'   `warps` n x L, `n_frames`, `degenerate`, `method`, ...),
#'   `dependence` (`type` and, for the copula, `copula`: its score columns,
#'   correlation `cor`, `shrinkage` and tabulated marginal quantiles),
#'   `limits` (the joint limits per DoF, the share of recorded frames outside
#'   them, and whether generation enforces them) and `degenerate_data`
#'   (data frame `class`, `message`; see Degenerate data).
#' @seealso [fit_grasp_models()] for every type at once, [generate()] and
#'   [project()] to project recordings onto a model, [autoplot.grasp_model()] to look at it.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' m
#' summary(m)
#' # fingers that move together
#' mc <- fit_grasp_model(g, seed = 1, dependence = "copula")
#' mc
fit_grasp_model <- function(x, grasp = NULL, ncomp = NULL, warp_ncomp = NULL, k = NULL,
                            engine = c("fast", "reference"), overlong = c(iqr_mult = 3, median_mult = 1.5),
                            warping = NULL, max_stall = 0.25, seed = 1,
                            keep_data = TRUE, dependence = c("independent", "copula"),
                            mixture_guard = NULL, fpc_scores = NULL, motion = c("auto", "trim", "as_recorded"),
                            residuals = NULL) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  dependence <- check_choice(dependence, arg = "dependence", call = call)
  # what NULL means depends on the model (see model_defaults)
  def <- model_defaults[[dependence]]
  ncomp <- check_whole(ncomp %||% def$ncomp, "ncomp", max = 50, call = call)
  k <- check_whole(k %||% def$k, "k", max = 50, call = call)
  warp_ncomp <- check_whole(warp_ncomp %||% def$warp_ncomp, "warp_ncomp", max = 50, call = call)
  engines <- resolve_engines(engine, call)
  if (!is.null(warping)) warping <- check_choice(warping, c("dtw", "linear"), arg = "warping", call = call)
  mixture_guard <- check_choice(mixture_guard %||% def$mixture_guard, c("none", "bic"),
                                arg = "mixture_guard", call = call)
  fpc_scores <- check_choice(fpc_scores %||% def$fpc_scores, c("trapezoid", "least_squares"),
                             arg = "fpc_scores", call = call)
  max_stall <- check_number(max_stall, "max_stall", min = 0, max = 1, min_open = TRUE, call = call)
  keep_data <- check_flag(keep_data, "keep_data", call = call)
  overlong <- as_overlong_rule(overlong, call = call)
  x <- select_one_type(x, grasp, call)
  check_grasps_finite(x, call = call)
  motion <- resolve_motion(x, motion, call = call)
  phases <- NULL
  if (motion == "trim") {
    trimmed <- trim_motion(x)
    phases <- still_phases(x, attr(trimmed, "motion"))
    x <- trimmed
  }
  # recordings cut at their detected onset and end are registered at both;
  # linear time normalisation keeps that registration (see Defaults)
  warping <- warping %||% if (motion == "trim") "linear" else def$warping
  residuals <- check_choice(residuals %||% "none", c("none", "resample"), arg = "residuals", call = call)
  settings <- list(ncomp = as.integer(ncomp), warp_ncomp = as.integer(warp_ncomp),
                   k = as.integer(k), overlong = overlong, warping = warping, max_stall = max_stall,
                   keep_data = keep_data, gmm_max_iter = gmm_model_max_iter,
                   dependence = dependence, mixture_guard = mixture_guard, fpc_scores = fpc_scores,
                   motion = motion, residuals = residuals)
  model <- with_seed(seed, fit_grasp_model_impl(x, settings, engines, call, phases))
  warn_degenerate(model$degenerate_data,
                  sprintf("The model of grasp type \"%s\" rests on degenerate data:", model$grasp))
  model
}

# The settings each model takes when its arguments are left NULL. The
# independent model is the thesis' (section 4.1); the copula model's were
# chosen by measurement on held-out subjects (vignette("natural-grasps") and
# NEWS): linear time normalisation keeps the timing in the curves, where the
# FPCs and the copula carry it with the rest, instead of in DTW warps that
# the inverse map cannot reproduce; least-squares scores reconstruct the
# final posture in full; four FPCs per DoF carry the mid-motion variation;
# one Gaussian per score is as good as two-component mixtures there at a
# fraction of the cost (the guard still applies with k > 1).
model_defaults <- list(
  independent = list(ncomp = 2L, warp_ncomp = 1L, k = 2L, warping = "dtw",
                     mixture_guard = "none", fpc_scores = "trapezoid"),
  copula = list(ncomp = 4L, warp_ncomp = 1L, k = 1L, warping = "linear",
                mixture_guard = "bic", fpc_scores = "least_squares"))

fit_grasp_model_impl <- function(x, settings, engines, call, phases = NULL) {
  t0 <- proc.time()[["elapsed"]]
  type <- as.character(x$meta$grasp[1])
  prep <- prepare_alignment(x, settings, engines, call)
  aln <- prep$alignment
  t_align <- proc.time()[["elapsed"]]

  n <- length(prep$ids)
  if (n < settings$ncomp + 1L) {
    hm_abort(c("Grasp type {.val {type}} has {n} usable recording{?s}; {settings$ncomp + 1L} or more are needed for {settings$ncomp} FPC{?s}.",
               i = if (nrow(prep$removed)) "Recordings in: {prep$n_input}; removed: {nrow(prep$removed)} ({.val {unique(prep$removed$reason)}})."),
             "too_few_recordings", grasp = type, call = call)
  }

  L <- aln$target_length
  dofs <- x$dofs
  p <- length(dofs)
  argvals <- seq(0, 1, length.out = L)
  fallbacks <- prep$fallbacks

  fpca <- vector("list", p)
  names(fpca) <- dofs
  for (j in seq_len(p)) {
    Y <- matrix(aln$warped[, , j], n, L)
    fpca[[j]] <- orient_components(fit_fpca_or_constant(Y, argvals, settings$ncomp, engines$fpca,
                                                        settings$fpc_scores))
    if (isTRUE(fpca[[j]]$constant)) {
      fallbacks <- add_fallback(fallbacks, "fpca", dofs[j], "constant DoF: no variation to model, FPCs set to zero")
    } else if (length(fpca[[j]]$notes)) {
      fallbacks <- add_fallback(fallbacks, "fpca_rank", dofs[j], paste(fpca[[j]]$notes, collapse = "; "))
    }
  }
  t_fpca <- proc.time()[["elapsed"]]
  # what the FPCs leave of each aligned curve, for generation to resample
  residuals <- if (identical(settings$residuals, "resample")) fpca_residual_curves(aln$warped, fpca)

  # Warping functions in original frames: one FPC carries the duration.
  warp_fit <- fit_fpca_or_constant(aln$warps, argvals, settings$warp_ncomp, engines$fpca,
                                   settings$fpc_scores)
  warp_fit <- orient_warp_fpca(warp_fit)
  if (isTRUE(warp_fit$constant)) {
    fallbacks <- add_fallback(fallbacks, "warp_fpca", NA_character_,
                              "warping functions do not vary: warp FPCs set to zero")
  }

  gmm <- vector("list", p)
  names(gmm) <- dofs
  guard <- settings$mixture_guard %||% "none"
  for (j in seq_len(p)) {
    gmm[[j]] <- fit_mixture(fpca[[j]], settings$k, engines$gmm, settings$gmm_max_iter, guard)
    if (isTRUE(gmm[[j]]$fallback) && !isTRUE(fpca[[j]]$constant)) {
      fallbacks <- add_fallback(fallbacks, "mixture", dofs[j],
                                paste("single Gaussian:", gmm_reason(gmm[[j]])))
    }
    if (!is.null(gmm[[j]]$guard)) {
      fallbacks <- add_fallback(fallbacks, "mixture_guard", dofs[j], paste("single Gaussian:", gmm[[j]]$guard))
    }
  }
  warp_gmm <- fit_mixture(warp_fit, settings$k, engines$gmm, settings$gmm_max_iter, guard)
  if (isTRUE(warp_gmm$fallback) && !isTRUE(warp_fit$constant)) {
    fallbacks <- add_fallback(fallbacks, "warp_mixture", NA_character_,
                              paste("single Gaussian:", gmm_reason(warp_gmm)))
  }
  if (!is.null(warp_gmm$guard)) {
    fallbacks <- add_fallback(fallbacks, "warp_mixture_guard", NA_character_,
                              paste("single Gaussian:", warp_gmm$guard))
  }
  t_gmm <- proc.time()[["elapsed"]]

  new_grasp_model(
    grasp = type,
    grasp_id = feix_ids(type),
    dofs = dofs, rate = x$rate, unit = x$unit,
    target_length = L, argvals = argvals,
    n_input = prep$n_input, n_used = n, ids = prep$ids,
    removed = prep$removed,
    warping = list(method = aln$method, fallback_reason = (aln$fallback_reason %||% NA_character_),
                   iterations = (aln$iterations %||% NA_integer_),
                   converged = (aln$converged %||% NA), engine = engines$align),
    fpca = fpca, gmm = gmm,
    warp = list(fpca = warp_fit, gmm = warp_gmm, constant = isTRUE(warp_fit$constant)),
    fallbacks = fallbacks,
    settings = settings, engine = engines,
    timing = c(align = t_align - t0, fpca = t_fpca - t_align, gmm = t_gmm - t_fpca,
               total = t_gmm - t0),
    limits = recorded_limits(x[prep$ids], dofs),
    levels = levels(x$meta$grasp), glove = x$glove, phases = phases, residuals = residuals,
    # what of the input was degenerate (said at the top level by the caller)
    degenerate_data = model_degeneracies(list(fallbacks = fallbacks, dofs = dofs, settings = settings,
                                              stuck = stuck_channels(x),
                                              warp = list(constant = isTRUE(warp_fit$constant))),
                                         stats::setNames(x$meta$n_frames, x$meta$id)),
    # the alignment as the aligner returned it (warped curves, warping
    # functions, frame counts, degenerate warps): the model's data, kept once
    alignment = if (isTRUE(settings$keep_data)) aln
  )
}

# The one constructor of class "grasp_model": the fitted parts in (one FPCA
# and one mixture per DoF, the warp model), each stored once. The stacked
# views are derived when needed (model_basis(), model_scores(),
# model_var_explained(): a few arrays of L x p x ncomp numbers, microseconds).
# Two derived parts are kept: the generation `sampler` (the mixtures'
# cumulative weights and covariance roots; rebuilding it costs about 1 ms,
# four times a one-grasp generate()) and the cross-DoF `dependence` (a fit of
# its own); nothing sets them apart from the mixtures and scores they come
# from.
new_grasp_model <- function(grasp, grasp_id, dofs, rate, unit, target_length, argvals, n_input, n_used,
                            ids, removed, warping, fpca, gmm, warp, fallbacks, settings, engine, timing,
                            limits, alignment = NULL, degenerate_data = empty_degenerate_notes(),
                            levels = feix_levels(), glove = NULL, phases = NULL, residuals = NULL) {
  model <- list(grasp = grasp, grasp_id = grasp_id, dofs = dofs, rate = rate, unit = unit,
                target_length = target_length, argvals = argvals, n_input = n_input, n_used = n_used,
                ids = ids, removed = removed, warping = warping, fpca = fpca, gmm = gmm, warp = warp, fallbacks = fallbacks, settings = settings, engine = engine,
                timing = timing)
  model$sampler <- build_sampler(model)
  model$dependence <- list(type = settings$dependence,
                           copula = if (settings$dependence == "copula") fit_score_copula(model))
  model$limits <- limits
  # the labels the model was fitted among (its own is `grasp`) and the glove
  # of its recordings, so generated grasps carry both
  model$levels <- levels
  model$glove <- glove
  model$phases <- phases
  model$residuals <- residuals
  model$degenerate_data <- degenerate_data
  model$alignment <- alignment
  validate_grasp_model(structure(model, class = "grasp_model"))
}

# Shapes that fit together: p DoFs, L template frames, n recordings used,
# ncomp FPCs per DoF; one FPCA and one mixture per DoF; the kept alignment
# (if any) holds exactly the recordings used.
validate_grasp_model <- function(x) {
  p <- length(x$dofs)
  L <- x$target_length
  n <- x$n_used
  q <- x$settings$ncomp
  stopifnot(
    is.character(x$grasp), length(x$grasp) == 1L,
    length(x$argvals) == L, n == length(x$ids), n <= x$n_input,
    identical(names(x$fpca), x$dofs), identical(names(x$gmm), x$dofs),
    all(vapply(x$fpca, inherits, logical(1), "fpca_fit")),
    all(vapply(x$gmm, inherits, logical(1), "gmm_fit")),
    is.null(fpca_shape_fault(x)), has_dim(model_scores(x), c(n, p, q)),
    inherits(x$warp$fpca, "fpca_fit"), length(x$warp$fpca$mean) == L,
    nrow(warp_basis(x)$components) == L, nrow(warp_basis(x)$scores) == n,
    is.data.frame(x$removed), is.data.frame(x$fallbacks), is.data.frame(x$degenerate_data),
    x$dependence$type %in% c("independent", "copula"),
    is.null(x$alignment) || (inherits(x$alignment, "grasp_alignment") && dim(x$alignment$warped)[1] == n)
  )
  x
}

has_dim <- function(a, d) length(dim(a)) == length(d) && all(dim(a) == d)

# Steps 1-2 (also used by the frame-PCA alternative): over-long removal, then
# alignment to the mean frame count, with degenerate warps dropped and a
# linear fallback if the aligner itself fails.
prepare_alignment <- function(x, settings, engines, call) {
  meta <- x$meta
  recs <- x$recordings
  type <- as.character(meta$grasp[1])
  removed <- empty_removed()
  fallbacks <- empty_fallbacks()
  long <- find_overlong(meta$n_frames, rule = settings$overlong)
  if (any(long)) {
    removed <- rbind(removed, data.frame(id = meta$id[long], n_frames = meta$n_frames[long],
                                         reason = "overlong", detail = NA_real_, stringsAsFactors = FALSE))
  }
  keep <- !long
  if (sum(keep) < 2L) {
    hm_abort(c("Grasp type {.val {type}} has {sum(keep)} recording{?s} left after over-long removal; alignment needs 2 or more.",
               i = "Recordings in: {length(recs)}."),
             "too_few_recordings", grasp = type, call = call)
  }
  recs <- recs[keep]
  L <- max(2L, as.integer(round(mean(meta$n_frames[keep]))))
  if (identical(settings$warping, "linear")) {
    aln <- align_linear_fallback(recs, L, engines$align, reason = "requested")
  } else {
    # (the model records degenerate data itself, see model_degeneracies())
    aln <- tryCatch(
      withCallingHandlers(
        align_recordings(recs, target_length = L, engine = engines$align, max_stall = settings$max_stall),
        handmotion_warning_degenerate = function(w) invokeRestart("muffleWarning")),
      error = function(e) e
    )
    if (inherits(aln, "error")) {
      reason <- paste("alignment failed:", cli::ansi_strip(conditionMessage(aln)))
      aln <- align_linear_fallback(recs, L, engines$align, reason = reason)
    }
  }
  if (identical(aln$method, "linear") && !identical(settings$warping, "linear")) {
    fallbacks <- add_fallback(fallbacks, "warping", NA_character_,
                              paste("linear warping:", (aln$fallback_reason %||% "unspecified")))
  }
  deg <- aln$degenerate
  if (!is.null(deg) && nrow(deg) > 0L) {
    removed <- rbind(removed, data.frame(id = as.character(deg$id),
                                         n_frames = meta$n_frames[match(deg$id, meta$id)],
                                         reason = "degenerate warp", detail = as.numeric(deg$stall),
                                         stringsAsFactors = FALSE))
  }
  ids <- dimnames(aln$warped)[[1]]
  if (is.null(ids)) ids <- setdiff(names(recs), removed$id)
  list(alignment = aln, ids = ids, removed = removed, fallbacks = fallbacks,
       n_input = length(x$recordings))
}

# FPCA of one set of curves, or a zero-component stand-in when the curves do
# not vary (a constant DoF or identical warps), so later steps never divide
# by a zero variance.
fit_fpca_or_constant <- function(Y, argvals, ncomp, engine, score_rule = "trapezoid") {
  # total variance over time points (colSums rather than apply(Y, 2, var):
  # this runs once per DoF and type)
  n <- nrow(Y)
  v <- if (n > 1L) sum(colSums((Y - rep(colMeans(Y), each = n))^2)) / (n - 1L) else NA_real_
  scale <- max(1, mean(Y^2))
  if (!is.finite(v) || v <= 1e-12 * scale) {
    return(new_fpca_fit(mean = colMeans(Y), components = matrix(0, ncol(Y), ncomp),
                        scores = matrix(0, n, ncomp), eigenvalues = rep(0, ncomp),
                        var_explained = rep(NA_real_, ncomp), argvals = argvals,
                        weights = fpca_weights(argvals, fpca_delta(argvals, range(argvals)), score_rule),
                        delta = fpca_delta(argvals, range(argvals)), rangeval = range(argvals),
                        engine = engine, notes = "constant: the curves do not vary",
                        constant = TRUE, score_rule = score_rule))
  }
  fit <- fpca_fit(Y, argvals = argvals, ncomp = ncomp, engine = engine, scores = score_rule)
  fit$constant <- FALSE
  fit
}

# Sign convention for the DoF components. fpca_fit() makes each component's
# integral positive, which is arbitrary for a component whose integral is
# near zero (an S-shaped second component): refits then flip it at random.
# Here each component is flipped so that its largest projection onto the
# first three Legendre polynomials on [0, 1] (constant, ramp, parabola) is
# positive: one of the three is always clearly non-zero, so the sign is
# stable across refits and subsets. Scores are flipped with it.
orient_components <- function(fit) {
  if (isTRUE(fit$constant)) return(fit)
  s <- (fit$argvals - min(fit$argvals)) / diff(range(fit$argvals))
  legendre <- cbind(1, sqrt(3) * (2 * s - 1), sqrt(5) * (6 * s^2 - 6 * s + 1))
  comps <- as.matrix(fit$components)
  proj <- crossprod(comps * fit$weights, legendre)        # ncomp x 3
  for (c in seq_len(ncol(comps))) {
    pick <- which.max(abs(proj[c, ]))
    if (proj[c, pick] < 0) {
      fit$components[, c] <- -fit$components[, c]
      fit$scores[, c] <- -fit$scores[, c]
    }
  }
  fit
}

# Sign convention for the warp FPC: a positive score means a longer grasp
# (the component is positive at the last template frame).
orient_warp_fpca <- function(fit) {
  if (isTRUE(fit$constant)) return(fit)
  comps <- as.matrix(fit$components)
  L <- nrow(comps)
  for (c in seq_len(ncol(comps))) {
    if (comps[L, c] < 0) {
      fit$components[, c] <- -fit$components[, c]
      fit$scores[, c] <- -fit$scores[, c]
    }
  }
  fit
}

# EM iteration cap of the models' mixtures. On strongly overlapping score
# clouds EM crawls: with gmm_fit()'s default of 500 the cap, not a failure,
# caused nearly all single-Gaussian fallbacks of the full default fit
# (fit_grasp_models(simulate_grasps(), seed = 1): 107 DoF and 26 warp
# mixtures at 500, 1 and 2 at 5000). mixtools' own default, which the thesis
# probably used, is 10000; with the compiled EM 5000 costs little, and the
# fallbacks left are real failures.
gmm_model_max_iter <- 5000L

# A mixture on the FPC scores, or a point mass at zero for a constant DoF;
# with guard = "bic", a mixture that does not describe the data (see
# guard_mixture()) is replaced by one Gaussian, its reason in $guard.
fit_mixture <- function(fpca, k, engine, max_iter = gmm_model_max_iter, guard = "none") {
  S <- as.matrix(fpca$scores)
  if (isTRUE(fpca$constant)) return(point_mass_gmm(ncol(S), engine, n = nrow(S)))
  if (is.null(max_iter)) max_iter <- gmm_model_max_iter # settings from before the cap existed
  fit <- gmm_fit(S, k = k, engine = engine, max_iter = max_iter)
  if (identical(guard, "bic")) guard_mixture(fit, S, engine) else fit
}

# The mixture guard (fit_grasp_model(mixture_guard = "bic")): a fit of k > 1
# components is kept only if every component holds at least
# max(2 (d + 1), 5% of n) recordings (its weight times n) and it has a lower
# BIC than one Gaussian; otherwise one Gaussian (the maximum-likelihood fit)
# replaces it, with the reason in $guard. Slivers fitted to two or three
# outlying recordings (the thesis' Figure 5.6) fail the size rule; a second
# component that only bends a unimodal cloud fails BIC.
guard_mixture <- function(fit, S, engine) {
  k <- length(fit$weights)
  if (k < 2L || isTRUE(fit$fallback)) return(fit)
  n <- nrow(S)
  d <- ncol(S)
  one <- gmm_fit(S, k = 1L, engine = engine)
  min_size <- max(2 * (d + 1), 0.05 * n)
  npar <- function(k) (k - 1) + k * d + k * d * (d + 1) / 2
  bic_k <- -2 * fit$loglik + npar(k) * log(n)
  bic_1 <- -2 * one$loglik + npar(1) * log(n)
  reason <- if (min(fit$weights) * n < min_size) {
    sprintf("smallest component holds %.1f recordings (< %.1f)", min(fit$weights) * n, min_size)
  } else if (!is.finite(bic_k) || bic_k >= bic_1) {
    sprintf("BIC prefers one Gaussian (%.1f vs %.1f for %d components)", bic_1, bic_k, k)
  }
  if (is.null(reason)) return(fit)
  one$guard <- reason
  one
}

point_mass_gmm <- function(d, engine, n = NA_integer_) {
  new_gmm_fit(weights = 1, means = matrix(0, 1, d), covs = array(0, c(d, d, 1)),
              loglik = NA_real_, iterations = 0L, converged = FALSE, fallback = TRUE,
              reason = "constant: point mass at zero", engine = engine, n = n, point_mass = TRUE)
}

gmm_reason <- function(fit) {
  r <- fit$reason
  if (is.null(r) || length(r) == 0L || is.na(r[1]) || !nzchar(r[1])) "EM failed" else as.character(r[1])
}

# Mean curves (L x p) and components (L x p x ncomp) of every DoF, laid out
# for vectorised generation and projection.
# The views of a model's per-DoF FPCAs that the kernels and methods read,
# stacked over DoFs: the basis (`mean` L x p, `components` L x p x ncomp),
# the training scores (n x p x ncomp) and the variance explained (p x ncomp).
model_basis <- function(model) {
  dofs <- model$dofs
  q <- model$settings$ncomp
  L <- model$target_length
  mean <- matrix(0, L, length(dofs), dimnames = list(NULL, dofs))
  comps <- array(0, c(L, length(dofs), q), dimnames = list(NULL, dofs, paste0("FPC", seq_len(q))))
  for (j in seq_along(dofs)) {
    mean[, j] <- model$fpca[[j]]$mean
    comps[, j, ] <- model$fpca[[j]]$components
  }
  list(mean = mean, components = comps)
}

model_scores <- function(model) {
  dofs <- model$dofs
  q <- model$settings$ncomp
  scores <- array(0, c(model$n_used, length(dofs), q), dimnames = list(model$ids, dofs, paste0("FPC", seq_len(q))))
  for (j in seq_along(dofs)) scores[, j, ] <- model$fpca[[j]]$scores
  scores
}

# The warping FPCA's views, as the kernels take them (stored once, in
# model$warp$fpca): mean (L), components (L x q) and scores (n x q).
warp_basis <- function(model) {
  f <- model$warp$fpca
  L <- model$target_length
  list(mean = as.numeric(f$mean), components = matrix(as.numeric(f$components), L),
       scores = matrix(as.numeric(f$scores), model$n_used))
}

model_var_explained <- function(model) {
  q <- model$settings$ncomp
  matrix(vapply(model$fpca, function(f) as.numeric(f$var_explained), numeric(q)),
         length(model$dofs), q, byrow = TRUE, dimnames = list(model$dofs, paste0("FPC", seq_len(q))))
}

# What in a model's FPCAs the kernels could not take (NULL when nothing): a
# model changed by hand gets a classed error naming it (see model_fault()),
# not a crash or an R error from model_basis().
fpca_shape_fault <- function(model, ncomp = model$settings$ncomp) {
  L <- model$target_length
  if (length(model$fpca) != length(model$dofs)) return("it does not hold one FPCA per DoF")
  for (j in seq_along(model$fpca)) {
    f <- model$fpca[[j]]
    if (!is.numeric(f$mean) || length(f$mean) != L) {
      return(sprintf("the FPCA mean of DoF %s does not have %d frames", model$dofs[j], L))
    }
    if (!is.numeric(f$components) || length(f$components) != L * ncomp) {
      return(sprintf("the FPCs of DoF %s are not %d frames x %d", model$dofs[j], L, ncomp))
    }
  }
  NULL
}

empty_removed <- function() {
  data.frame(id = character(), n_frames = integer(), reason = character(), detail = numeric(),
             stringsAsFactors = FALSE)
}

empty_fallbacks <- function() {
  data.frame(step = character(), dof = character(), reason = character(), stringsAsFactors = FALSE)
}

add_fallback <- function(fallbacks, step, dof, reason) {
  rbind(fallbacks, data.frame(step = step, dof = dof, reason = reason, stringsAsFactors = FALSE))
}

# engine: one of "fast"/"reference" for every step, or a named list per step.
resolve_engines <- function(engine, call) {
  steps <- c("align", "fpca", "gmm")
  choices <- c("fast", "reference")
  if (is.list(engine)) {
    bad <- setdiff(names(engine), steps)
    if (is.null(names(engine)) || length(bad)) {
      hm_abort(c("A list {.arg engine} must be named by step ({.val {steps}}).",
                 x = if (length(bad)) "Unknown step{?s}: {.val {bad}}."),
               "bad_input", argument = "engine", call = call)
    }
    out <- stats::setNames(as.list(rep("fast", 3)), steps)
    for (s in names(engine)) out[[s]] <- check_choice(engine[[s]], c("fast", "reference"), "engine", call = call)
    return(out)
  }
  if (is.character(engine) && identical(engine, choices)) engine <- "fast"
  e <- check_choice(engine, c("fast", "reference"), "engine", call = call)
  stats::setNames(as.list(rep(e, 3)), steps)
}

# Select the recordings of one type; refuse a set that mixes types.
select_one_type <- function(x, grasp, call) {
  if (!is.null(grasp)) {
    if (length(grasp) != 1L || is.na(grasp)) {
      hm_abort("{.arg grasp} must name one class label.", "bad_input", argument = "grasp", call = call)
    }
    g <- resolve_labels(grasp, levels(x$meta$grasp), "grasp", call = call)
    x <- x[!is.na(x$meta$grasp) & x$meta$grasp == g]
    if (length(x) == 0L) {
      hm_abort("No recordings of grasp type {.val {as.character(g)}} in {.arg x}.",
               "too_few_recordings", argument = "grasp", call = call)
    }
  }
  unlabelled <- is.na(x$meta$grasp)
  if (any(unlabelled)) {
    hm_abort(c("{sum(unlabelled)} of the {length(x)} recording{?s} in {.arg x} ha{?s/ve} no grasp type label.",
               i = "A model is fitted to the recordings of one labelled type; first unlabelled: {.val {x$meta$id[unlabelled][1]}}."),
             "no_labels", argument = "x", call = call)
  }
  types <- unique(as.character(x$meta$grasp))
  if (length(types) > 1L) {
    hm_abort(c("{.arg x} holds {length(types)} grasp types; {.fn fit_grasp_model} fits one.",
               i = "Types: {.val {types}}.",
               i = "Give {.arg grasp}, or use {.fn fit_grasp_models} for every type."),
             "multiple_grasps", argument = "x", call = call)
  }
  x
}

#' @export
print.grasp_model <- function(x, ...) {
  cat(sprintf("<grasp_model> %s%s: %d DoFs x %d FPCs + %d warp FPC%s, %d-component mixtures\n",
              x$grasp, if (!is.na(x$grasp_id)) sprintf(" (type %d)", x$grasp_id) else "",
              length(x$dofs), x$settings$ncomp, x$settings$warp_ncomp,
              if (x$settings$warp_ncomp == 1) "" else "s", x$settings$k))
  rm <- table(factor(x$removed$reason, levels = c("overlong", "degenerate warp")))
  cat(sprintf("  recordings: %d in, %d used (%d over-long, %d degenerate warps removed)\n",
              x$n_input, x$n_used, rm[["overlong"]], rm[["degenerate warp"]]))
  cat(sprintf("  target length: %d frames at %g Hz; warping: %s%s\n", x$target_length, x$rate,
              x$warping$method, if (identical(x$settings$motion, "trim")) "; recordings trimmed to the motion" else ""))
  if (!is.null(x$glove) && any(x$glove$channels$stuck)) {
    cat(sprintf("  stuck channels held constant: %s\n", paste(x$glove$channels$channel[x$glove$channels$stuck], collapse = " ")))
  }
  ve <- 100 * rowSums(model_var_explained(x))
  if (any(is.finite(ve))) {
    cat(sprintf("  variance explained by %d FPCs per DoF: min %.1f%%, median %.1f%%, max %.1f%%\n",
                x$settings$ncomp, min(ve, na.rm = TRUE), stats::median(ve, na.rm = TRUE),
                max(ve, na.rm = TRUE)))
  }
  cat("  ", format_dependence(x), "\n", sep = "")
  dg <- format_degenerate(x$degenerate_data)
  if (length(dg)) cat(dg, sep = "\n")
  if (nrow(x$fallbacks) == 0L) {
    cat("  fallbacks: none\n")
  } else {
    cat("  fallbacks:\n")
    fb <- x$fallbacks
    cat(paste0("    ", fb$step, ifelse(is.na(fb$dof), "", paste0(" [", fb$dof, "]")), ": ", fb$reason,
               collapse = "\n"), "\n", sep = "")
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
  if (!identical(model$dependence$type, "copula")) {
    return(paste0("dependence: independent DoFs (the thesis' model); ", g))
  }
  R <- dependence_matrix(model)
  r <- abs(R[upper.tri(R)])
  cop <- model$dependence$copula
  sprintf("dependence: Gaussian copula over %d scores (shrinkage %.2f), |r| between DoFs' FPC1 median %.2f, max %.2f; %s",
          nrow(cop$columns), cop$shrinkage, stats::median(r), max(r), g)
}

#' @export
print.summary_grasp_model <- function(x, ...) {
  cat(sprintf("Grasp model %s: %d of %d recordings used, %d frames, %s warping\n",
              attr(x, "grasp"), attr(x, "n_used"), attr(x, "n_input"), attr(x, "target_length"),
              attr(x, "warping")))
  cat(attr(x, "dependence") %||% "", "\n", sep = "")
  print(as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE), digits = 4, row.names = FALSE)
  rm <- attr(x, "removed")
  if (nrow(rm)) {
    cat("Removed recordings:\n")
    print(rm, row.names = FALSE)
  }
  fb <- attr(x, "fallbacks")
  cat(if (nrow(fb)) "Fallbacks:\n" else "Fallbacks: none\n")
  if (nrow(fb)) print(fb, row.names = FALSE)
  invisible(x)
}
