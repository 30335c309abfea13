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
#'    (kept as `alignment`) to the type's mean frame count `L`; a recording
#'    with a degenerate warp (one frame repeated over more than `max_stall * L`
#'    template frames, Figure 5.1) is kept with a slope-constrained DTW warp
#'    (see `degenerate_warps`; the thesis dropped it), and linear warping is
#'    used only if the alignment fails;
#' 3. functional PCA with `ncomp` components per DoF on the warped curves
#'    (`fpca_fit()`), with the variance each component explains;
#' 4. functional PCA with `warp_ncomp` components on the warping functions,
#'    which are kept in original frames so that one component captures the
#'    variation in duration;
#' 5. a `mixture_components`-component Gaussian mixture per DoF on the FPC scores, and one on
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
#' | | `ncomp` | `warp_ncomp` | `mixture_components` | `warping` | `fpc_scores` | `mixture_guard` |
#' |---|---|---|---|---|---|---|
#' | `"independent"` (the thesis) | 2 | 1 | 2 | `"dtw"` | `"trapezoid"` | `"none"` |
#' | `"copula"`, `"kernel"` | 4 | 1 | 1 | `"linear"` | `"least_squares"` | `"bic"` |
#'
#' Recordings trimmed to their motion (argument `motion`) are warped
#' linearly by default in either model: cut at their detected onset and end,
#' they are registered at both landmarks, which linear time normalisation
#' keeps. Dynamic time warping on top of it, with projections by the mean
#' warp, costs held-out accuracy there (on the twin's raw-count glove
#' protocol, six objects, one subject, 5-fold by recording: FPCA distance
#' 75% with DTW, 96% linear). Their mixtures are guarded by default in
#' either model (`mixture_guard = "bic"`): a real glove gives a few dozen
#' recordings a type and person, on which the thesis' two-component mixtures
#' fit slivers to a few outlying recordings (its Figure 5.6) that generate
#' odd grasps. On flexglove by participant folds the independent model's
#' generated grasps went from 1.28 to 1.21 times the real-vs-real MMD
#' (seeds 1-4); its classifiers do not read the mixtures. Recordings as
#' recorded (the thesis' data and its twin) keep the thesis' mixtures.
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
#'   `dependence = "independent"` (the thesis), 4 for `"copula"` and `"kernel"` (see
#'   Defaults).
#' @param warp_ncomp Number of FPCs of the warping functions. `NULL`
#'   (default): 1 (the thesis; with linear time normalisation the warps vary
#'   only by their duration, which one FPC carries exactly).
#' @param mixture_components Number of Gaussian components of each score
#'   mixture (`k` in development versions). `NULL`
#'   (default): 2 for the independent model (the thesis), 1 for the copula and kernel
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
#'   independent model (the thesis), `"linear"` for the copula and kernel models and for
#'   recordings trimmed to their motion (see Defaults).
#' @param max_stall Largest share of template frames a warp may spend on one
#'   original frame before the recording counts as degenerately warped (step
#'   2 of the description).
#' @param degenerate_warps What becomes of a recording whose DTW warp is
#'   degenerate. `"constrain"` (default): it is aligned again to the template
#'   (estimated without it) by DTW under Sakoe and Chiba's slope constraint
#'   (local slopes between 1/3 and 3, dtw's `symmetricP05`), so no frame is
#'   held over more than three template frames while the recording may still
#'   shift by any amount, or linearly if no such path exists; it stays in the
#'   model, listed in `warping$degenerate` (`id`, `stall`, `fallback`:
#'   `"slope"` or `"linear"`)
#'   and in `fallbacks`. Real glove recordings stall where the template
#'   holds still (the rest before and the hold after the grasp): there every
#'   path costs about the same and DTW's cheapest runs along one recording
#'   frame, then along the template's last frame; the slope constraint
#'   forbids that corner. `"drop"` is the thesis' rule (Figure 5.1, Table 5.1): such
#'   recordings are removed (listed in `removed`); [reproduce_thesis()] uses
#'   it. When most recordings of a type stall at once, the whole type is
#'   aligned by slope-constrained DTW barycenter averaging (recorded in
#'   `warping$step_pattern` and `fallbacks`). On a real 6-sensor glove (626
#'   recordings with rest and hold, 8 types) the thesis' rule dropped 13% of
#'   the recordings as recorded (8-25% per type) and 25% once trimmed to the
#'   motion; `"constrain"` keeps all but the over-long ones.
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
#'   inside the joint limits by default. `"kernel"` draws the joint vector of
#'   all those scores from a Gaussian kernel density on the training
#'   recordings' own vectors (a smoothed bootstrap: a training recording's
#'   scores plus Gaussian noise of covariance `h^2` times the scores'
#'   covariance, shrunk as the copula's correlation is). A type recorded on
#'   a few objects has clustered scores, one cluster per object; a Gaussian
#'   copula blurs them into one, the kernel density keeps them. The
#'   bandwidth `h` maximises the leave-one-out likelihood of the training
#'   vectors (over 0.05 to 1.5; print() shows it). It takes the copula
#'   model's defaults (see Defaults). On flexglove by participant folds its
#'   generated grasps are nearer the held-out participant (MMD 1.22 times
#'   real-vs-real, seeds 1-3, against 1.31 for the copula model;
#'   `vignette("natural-grasps")`); on the simulated data it scores about as
#'   the copula model does.
#' @param mixture_guard `"bic"` keeps a mixture of `mixture_components` only if every
#'   component holds at least `max(2 (d + 1), 0.05 n)` of the `n` recordings
#'   and its BIC beats one Gaussian's; otherwise one Gaussian replaces it
#'   (listed in `fallbacks` as `"mixture_guard"`). It removes the slivers
#'   fitted to two or three outlying recordings (the thesis' Figure 5.6).
#'   `"none"` fits the thesis' mixtures as they come. `NULL` (default):
#'   `"bic"` for the copula and kernel models (it matters there only with `mixture_components > 1`)
#'   and for recordings trimmed to their motion, `"none"` for the independent
#'   one on recordings as recorded (see Defaults).
#' @param fpc_scores How FPC scores integrate over time (`fpca_fit()`):
#'   `"trapezoid"`, fda.usc's rule as in the thesis, or `"least_squares"`,
#'   under which the scores are the least-squares coefficients of each curve
#'   on the FPCs, so mean plus FPCs times scores reconstructs the recording's
#'   final posture in full (the trapezoidal rule halves the weight of the end
#'   points, where grasps vary most). `NULL` (default): `"trapezoid"` for the
#'   independent model, `"least_squares"` for the copula and kernel models.
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
#' # the joint scores from a kernel density on the recordings' own (keeps clusters)
#' mk <- fit_grasp_model(g, seed = 1, dependence = "kernel")
#' mk
fit_grasp_model <- function(x, grasp = NULL, ncomp = NULL, warp_ncomp = NULL, mixture_components = NULL,
                            engine = c("fast", "reference"), overlong = c(iqr_mult = 3, median_mult = 1.5),
                            warping = NULL, max_stall = 0.25, seed = 1,
                            keep_data = TRUE, dependence = c("independent", "copula", "kernel"),
                            mixture_guard = NULL, fpc_scores = NULL, motion = c("auto", "trim", "as_recorded"),
                            residuals = NULL, degenerate_warps = c("constrain", "drop")) {
  call <- rlang::caller_env()
  # (an old `k = 2` would otherwise be taken for `keep_data` by partial matching)
  check_renamed_args(names(sys.call()), "fit_grasp_model", own = names(formals(fit_grasp_model)), call = call)
  check_grasps(x, call = call)
  dependence <- check_choice(dependence, arg = "dependence", call = call)
  # what NULL means depends on the model (see model_defaults)
  def <- model_defaults[[dependence]]
  # which settings the caller left to the defaults, for print()
  defaulted <- c(ncomp = is.null(ncomp), warp_ncomp = is.null(warp_ncomp),
                 mixture_components = is.null(mixture_components), warping = is.null(warping),
                 fpc_scores = is.null(fpc_scores), mixture_guard = is.null(mixture_guard),
                 residuals = is.null(residuals))
  motion_asked <- motion[1]
  ncomp <- check_whole(ncomp %||% def$ncomp, "ncomp", max = 50, call = call)
  mixture_components <- check_whole(mixture_components %||% def$mixture_components,
                                    "mixture_components", max = 50, call = call)
  warp_ncomp <- check_whole(warp_ncomp %||% def$warp_ncomp, "warp_ncomp", max = 50, call = call)
  engines <- resolve_engines(engine, call)
  if (!is.null(warping)) warping <- check_choice(warping, c("dtw", "linear"), arg = "warping", call = call)
  if (!is.null(mixture_guard)) mixture_guard <- check_choice(mixture_guard, c("none", "bic"), arg = "mixture_guard", call = call)
  fpc_scores <- check_choice(fpc_scores %||% def$fpc_scores, c("trapezoid", "least_squares"),
                             arg = "fpc_scores", call = call)
  max_stall <- check_number(max_stall, "max_stall", min = 0, max = 1, min_open = TRUE, call = call)
  degenerate_warps <- check_choice(degenerate_warps, c("constrain", "drop"), arg = "degenerate_warps", call = call)
  keep_data <- check_flag(keep_data, "keep_data", call = call)
  overlong <- as_overlong_rule(overlong, call = call)
  x <- select_one_type(x, grasp, call)
  # (every recording's motion found once, for the decision and the trim)
  resolved <- resolve_motion_found(x, motion, call = call)
  motion <- resolved$motion
  phases <- NULL
  if (motion == "trim") {
    trimmed <- with_motion_found(resolved$found, trim_motion(x))
    phases <- still_phases(x, attr(trimmed, "motion"))
    x <- trimmed
  }
  # recordings cut at their detected onset and end are registered at both;
  # linear time normalisation keeps that registration (see Defaults)
  warping <- warping %||% if (motion == "trim") "linear" else def$warping
  # and their mixtures are guarded: a real glove gives a few dozen
  # recordings a type and person, on which the thesis' two-component
  # mixtures fit slivers to a few recordings (its Figure 5.6) that generate
  # odd grasps (flexglove by participant folds, seeds 1-4: generated / real
  # MMD 1.28 -> 1.21; see Defaults)
  mixture_guard <- mixture_guard %||% if (motion == "trim") "bic" else def$mixture_guard
  residuals <- check_choice(residuals %||% "none", c("none", "resample"), arg = "residuals", call = call)
  settings <- list(ncomp = as.integer(ncomp), warp_ncomp = as.integer(warp_ncomp),
                   mixture_components = as.integer(mixture_components), overlong = overlong, warping = warping, max_stall = max_stall,
                   keep_data = keep_data, gmm_max_iter = gmm_model_max_iter,
                   dependence = dependence, mixture_guard = mixture_guard, fpc_scores = fpc_scores,
                   motion = motion, residuals = residuals, degenerate_warps = degenerate_warps,
                   defaulted = names(defaulted)[defaulted], motion_asked = motion_asked)
  model <- with_seed(seed, fit_grasp_model_impl(x, settings, engines, call, phases))
  warn_degenerate(model$degenerate_data,
                  sprintf("The model of grasp type \"%s\" rests on degenerate data:", model$grasp))
  model
}


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
    gmm[[j]] <- fit_mixture(fpca[[j]], settings$mixture_components, engines$gmm, settings$gmm_max_iter, guard)
    if (isTRUE(gmm[[j]]$fallback) && !isTRUE(fpca[[j]]$constant)) {
      fallbacks <- add_fallback(fallbacks, "mixture", dofs[j],
                                paste("single Gaussian:", gmm_reason(gmm[[j]])))
    }
    if (!is.null(gmm[[j]]$guard)) {
      fallbacks <- add_fallback(fallbacks, "mixture_guard", dofs[j], paste("single Gaussian:", gmm[[j]]$guard))
    }
  }
  warp_gmm <- fit_mixture(warp_fit, settings$mixture_components, engines$gmm, settings$gmm_max_iter, guard)
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
                   converged = (aln$converged %||% NA), engine = engines$align,
                   degenerate = prep$kept_degenerate,
                   step_pattern = aln$step_pattern %||% NA_character_),
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
