# The fitted grasp classifiers behind one verb, fit_grasp_classifier(method = ):
# the thesis' last-frame PCA (R/classifier-last-frame.R), its proposed weighted FPCA
# distance (R/classifier-weighted-fpca.R) and, here, a discriminative classifier beyond
# the thesis (its chapter 6: the FPCA distance weighs every DoF and the whole
# motion alike, while grasp types differ in a few DoFs and mostly in the
# final posture). Linear discriminant analysis with a shrunk covariance
# (R/classifier-shrunk-lda.R) on the postures at fixed fractions of the motion and the
# log duration learns which DoFs and which moments separate the types, and
# gives class probabilities.

#' Fit a grasp classifier
#'
#' One verb for the fitted classifiers [classify()] ranks (the thesis' FPCA
#' distance needs no extra fit: [classify()] takes a [fit_grasp_models()]
#' result directly). `method` chooses the classifier; its arguments are
#' given in `...` (see below) and each method returns its own documented
#' class, a member of the classifier family `grasp_classifier` (see
#' [summary.grasp_classifier()]), which [classify()] and `predict()`
#' recognise:
#'
#' * `"discriminant"` (default, beyond the thesis; class `grasp_discriminant`):
#'   describes every recording by its posture (all DoFs) at `at` fractions of
#'   its own duration (linear interpolation between frames), its log duration,
#'   how far each DoF travels (log of 1 + the sum of its absolute
#'   frame-to-frame changes: two grasps can end alike after very different
#'   motions) and the extremes each DoF reaches over the whole recording (its
#'   smallest and largest value after a running median of 3 frames, so a
#'   one-frame spike is no extreme: the hand opening before it closes, a
#'   finger bending past where it rests, happen between fixed fractions of the
#'   motion), and fits linear discriminant analysis on those features: one
#'   Gaussian per grasp type with a covariance shared by all types, the pooled
#'   within-type correlation shrunk towards the identity by the analytic rule
#'   of Schäfer and Strimmer (2005) (no tuning parameter). Unlike the thesis'
#'   FPCA distance it weighs DoFs and moments by how well they separate the
#'   types, and it gives class probabilities ([predict.grasp_classifier()]).
#'   **Subclasses**: a type grasped round different objects (a can, a
#'   pineapple, a bottle) is several clusters of recordings whose mean lies
#'   between them, so each type is split into up to `subclasses` clusters by
#'   k-means (seeded) on its standardised features, at most one per five
#'   recordings; every cluster is a Gaussian with the shared covariance and a
#'   type's posterior is the sum of its clusters' (mixture discriminant
#'   analysis). `subclasses = "auto"` (default) fixes no number: it fits
#'   the discriminant with up to 1, 2, 4 and 6 clusters per type and averages
#'   their class probabilities (an ensemble; nothing is tuned, so nothing
#'   inside [evaluate_loso()] looks at the held-out fold); a number fits that
#'   one discriminant. `print()` and `summary()` show the clusters per type
#'   (of the finest fit). On the real flexglove recordings (6 flex sensors, 8
#'   types, 3 objects each, two participants, each classified by a fit on
#'   the other) subclasses lift the held-out accuracy from 71.6% (one
#'   Gaussian per type) to 85.0% (P1 80.7%, P2 90.9%); over k-means seeds
#'   1-10 the average is 84.8% (84.3% to 85.5%), where choosing the number
#'   by an inner cross-validation on the training participant swung from
#'   82.4% to 85.8% with the seed. The clusters are drawn with R's
#'   default generator whatever the caller's, so a fit inside
#'   [evaluate_loso()] (whose folds run under L'Ecuyer-CMRG) is the fit
#'   `fit_grasp_classifier()` gives on the same recordings.
#'   **Invariance**: LDA and the standardised k-means ignore any offset and
#'   scale of a feature, and a negative gain only swaps a DoF's extremes, so
#'   a per-channel offset or gain applied to every recording (another glove's
#'   calibration, counts or degrees, counts that fall as a finger bends)
#'   gives the same predictions (a gain exactly when travel is large against
#'   one unit). It is deliberately *not* invariant to a per-recording offset
#'   (each recording minus its own rest level, the median before its
#'   detected onset): on flexglove that costs 7.5 points (82.7% -> 75.2%,
#'   measured before the extremes), because the level of the recording
#'   itself tells the types apart. Nor to a per-participant one: flexglove's
#'   two participants rest within 5 counts of each other on every channel,
#'   so referring each participant's recordings to their own median rest
#'   level changes nothing (82.7%), and dividing them by their median range
#'   as well costs 2.3 points (that range depends on which types the
#'   participant recorded most); either would also make a recording's
#'   prediction depend on the other recordings given with it. Every
#'   recording must be labelled; at least two types with two recordings
#'   each.
#' * `"last_frame"` (thesis section 4.2, Tables 5.7 and 5.8; class
#'   `last_frame_pca`): for every grasp type, the last frames of its
#'   recordings, centred on the type's mean last frame, and their principal
#'   components (no scaling: all DoFs share the angle unit). A recording is
#'   scored against each type by the Euclidean distance between its last frame
#'   and that frame's projection on the type's first `ncomp` PCs
#'   ([predict.grasp_classifier()]). A type with `n` recordings has at most
#'   `n - 1` informative PCs; when `n - 1 < ncomp` it uses `n - 1` (0 for a single
#'   recording: distance to the mean), recorded in `$ncomp_used` and announced by
#'   a warning of class `handmotion_warning_few_recordings`. Unlabelled
#'   recordings are ignored and counted in `$n_unlabelled`.
#' * `"weighted_fpca"` (the thesis' own proposals, its chapter 6; class
#'   `weighted_fpca`): the FPCA distance with **time weights** on the
#'   template time (`time = "uniform"`, the thesis' norm, or `"end"`: rising
#'   linearly from 0 at the start to 2 at the end, mean 1; on the default data
#'   "end" does not help, see `vignette("recognition")`) and **per-type DoF
#'   weights**: for model *c*, each DoF's (time-weighted) residual norm `r_j`
#'   is scaled by its typical size on the type's own training recordings,
#'   `s2[c, j]` = mean of `r_j^2` over them, and the DoF's FPC scores `a_j`
#'   are scored by the type's own mixture `f_cj` (the one generation draws
#'   from). The distance is
#'   `sum_j (r_j^2 / s2[c, j] + log s2[c, j] - 2 log f_cj(a_j))`: minus twice
#'   the log-likelihood of the recording under the model (residual norms
#'   half-normal with the type's scales). A DoF that a type reproduces
#'   tightly weighs heavily for that type, one that varies a lot weighs
#'   little, and a recording whose projection needs scores the type never
#'   shows is far even when its residual is small. Each DoF's log density is
#'   floored at -50 (about ten standard deviations), so one degenerate
#'   mixture cannot veto a type alone.
#'
#' Evaluate any of them held out by subject with
#' `evaluate_loso(x, method = )`.
#'
#' @param x A labelled [grasps()] object (the training recordings).
#' @param method `"discriminant"`, `"last_frame"` or `"weighted_fpca"`.
#' @param ... Arguments of the method, by name:
#'   * `"discriminant"`: `at`, fractions of the motion (in `[0, 1]`) at which
#'     the posture is taken (default 0, 1/8, ..., 1, the best of 4, 8, 12 and
#'     16 equal steps held out by subject on the default data); `prior`,
#'     `"equal"` (default: every type equally likely a priori) or `"data"`
#'     (the training shares); `subclasses`, the largest number of clusters
#'     per type (a whole number: that number, 1 is one Gaussian per type) or
#'     `"auto"` (default: the average of the fits with 1, 2, 4 and 6, see
#'     above).
#'   * `"last_frame"`: `ncomp`, the number of PCs used (default 5, as the
#'     thesis); `grasps`, an optional subset of grasp types to fit (names or
#'     ids; all types present by default).
#'   * `"weighted_fpca"`: `models`, a [fit_grasp_models()] fit on `x`, or
#'     `NULL` (default) to fit one with one Gaussian per DoF for the scores
#'     (`mixture_components = 1`: on the default data, subjects 1-20 fitted and 21-30
#'     classified, it recognises 64.2% against 62.5% with the thesis' two
#'     components, at half the fitting cost); `time`, `"uniform"` (default) or
#'     `"end"`; any other argument is passed to [fit_grasp_models()] when
#'     `models` is `NULL`.
#' @return By `method`:
#'   * `"discriminant"`: class `grasp_discriminant`, a list with `classes`,
#'     `levels` (of the training labels, carried by predictions), `at`,
#'     `dofs`, `rate`, `prior`, `fit` (the discriminant of the subclasses:
#'     `members`, one fit per number of clusters, each with its coefficients,
#'     offsets, `shrinkage` and `type_of` (each subclass's type); `types`,
#'     `type_prior`, `subclasses` (the number given, or `"auto"`),
#'     `subclasses_used` (per type, of the finest member), `shrinkage` (per
#'     member) and `n` (per type)) and `n`
#'     (training recordings per type);
#'   * `"last_frame"`: class `last_frame_pca`, a list with `models` (one per
#'     type: `mean`, `rotation`, `sdev`, `cumvar`, `n`), `ncomp`, `ncomp_used` (named
#'     integer), `dofs` and `n_unlabelled`;
#'   * `"weighted_fpca"`: class `weighted_fpca`, a list with `models` (the
#'     `grasp_models`), `time` and `scale` (types x DoFs matrix of `s2`).
#'
#'   Each also has the fields of every classifier of the family: `classes`,
#'   `levels` (of the training labels, carried by predictions), `n`
#'   (training recordings per class) and `temperature` (of its
#'   probabilities, see [predict.grasp_models()]); each has `print()` and
#'   `summary()` methods; [classify()] ranks its distances.
#' @seealso [classify()], [predict.grasp_classifier()],
#'   [summary.grasp_classifier()], [evaluate_loso()], [fit_grasp_recognizer()]
#'   for recognition while the hand is still moving.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 6, grasps = 1:4, objects = 2, trials = 2, seed = 1)
#' train <- g[g$meta$subject != "S06"]
#' test <- g[g$meta$subject == "S06"]
#' cl <- fit_grasp_classifier(train)
#' cl
#' predict(cl, test)
#' head(predict(cl, test, type = "prob"))
#' classify(cl, test)
#' lf <- fit_grasp_classifier(train, method = "last_frame", ncomp = 2)
#' lf
#' classify(lf, test)
#' w <- fit_grasp_classifier(train, method = "weighted_fpca", seed = 1)
#' classify(w, test)
fit_grasp_classifier <- function(x, method = c("discriminant", "last_frame", "weighted_fpca"), ...) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  method <- check_choice(method, arg = "method", call = call)
  fitter <- classifier_fitter(method)
  warn_short_recordings(x, action = "fitted")
  warn_few_recordings(x)
  dots <- list(...)
  # weighted_fpca passes what it does not take itself on to fit_grasp_models(),
  # which passes what it does not take on to fit_grasp_model() (checked
  # against fit_grasp_models() alone, every model setting was refused)
  if (method == "weighted_fpca") {
    passed <- dots[!rlang::names2(dots) %in% c("models", "time", names(formals(fit_grasp_models)))]
    check_dots_for(passed, fit_grasp_model, "fit_grasp_model", exclude = c("x", "grasp"), call = call)
  } else {
    check_dots_for(dots, fitter, "fit_grasp_classifier", exclude = c("x", "call"), call = call)
  }
  # (recordings without a motion are said once, not by each type's fit)
  say_no_motion_once(fitter(x, ..., call = call), length(x))
}

classifier_fitter <- function(method) {
  switch(method, discriminant = fit_discriminant, last_frame = fit_last_frame_pca,
         weighted_fpca = fit_weighted_fpca)
}

# method = "discriminant"
fit_discriminant <- function(x, at = seq(0, 1, by = 0.125), prior = c("equal", "data"),
                             subclasses = "auto", call = rlang::caller_env()) {
  check_grasps(x, call = call)
  at <- check_fractions(at, "at", call = call)
  prior <- check_choice(prior, c("equal", "data"), arg = "prior", call = call)
  if (!identical(subclasses, "auto")) subclasses <- check_whole(subclasses, "subclasses", call = call)
  y <- check_training_labels(x, call = call)
  F <- classifier_features(x, at)
  fit <- fit_subclass_lda(F, y, prior, subclasses)
  new_grasp_discriminant(fit, at = at, dofs = x$dofs, rate = x$rate, prior = prior, levels = grasp_levels(x))
}

classifier_features <- function(x, at) cbind(motion_features(x, at), travel_features(x), extreme_features(x))

# The levels predictions carry: those of the training labels (all Feix
# types when they are a Feix factor), so predictions compare with labels.
grasp_levels <- function(x) {
  g <- x$meta$grasp
  if (is.factor(g)) levels(g) else sort(unique(as.character(g)))
}

# The discriminant in the classifier family (R/classifier.R): its distance
# is minus the log posterior, so its temperature is 1 (the softmax gives the
# posterior back).
new_grasp_discriminant <- function(fit, at, dofs, rate, prior, levels) {
  n <- stats::setNames(fit$n, fit$types)
  new_grasp_classifier(at = at, dofs = dofs, rate = rate, prior = prior, fit = fit,
                       classes = fit$types, levels = levels, n = n, temperature = 1,
                       class = "grasp_discriminant")
}

#' @export
classifier_distances.grasp_discriminant <- function(object, new_data, ..., call = rlang::caller_env()) {
  neg_log_posterior(classifier_log_posterior(object, new_data, call = call))
}

#' @export
classifier_method.grasp_discriminant <- function(object) "discriminant"

#' @export
classifier_parts.grasp_discriminant <- function(object) c(NextMethod(), "at", "dofs", "fit")

# Fractions of the motion: finite numbers in [0, 1], sorted, no duplicates.
check_fractions <- function(at, arg, call = rlang::caller_env()) {
  if (!is.numeric(at) || !length(at) || anyNA(at) || any(at < 0 | at > 1)) {
    hm_abort("{.arg {arg}} must be fractions of the motion: numbers in [0, 1], not {describe_value(at)}.", "bad_input",
             argument = arg, call = call)
  }
  sort(unique(as.numeric(at)))
}

# New recordings for a fitted classifier or recogniser: a grasps object with
# exactly the DoFs it was trained on, in that order.
check_trained_dofs <- function(x, dofs, what, call = rlang::caller_env()) {
  check_grasps(x, arg = "new_data", call = call, finite = FALSE)
  if (!identical(x$dofs, dofs)) {
    hm_abort(c("{.arg new_data} has other DoFs than the {what} was trained on.",
               i = "Trained on: {.val {dofs}}.", x = "Given: {.val {x$dofs}}."),
             "bad_input", argument = "new_data", call = call)
  }
  invisible(x)
}

# The grasp labels of a training set: every recording labelled, at least
# two types, at least two recordings each.
check_training_labels <- function(x, call = rlang::caller_env()) {
  y <- x$meta$grasp
  if (anyNA(y)) {
    hm_abort(c("{.arg x} has {sum(is.na(y))} unlabelled recording{?s}; a classifier is trained on labelled ones.",
               i = "Drop them first, e.g. {.code x[!is.na(x$meta$grasp)]}."),
             "bad_input", argument = "x", call = call)
  }
  y <- droplevels(as.factor(y))
  counts <- table(y)
  if (length(counts) < 2L) {
    hm_abort("{.arg x} holds {length(counts)} grasp type{?s}; a classifier needs at least two.",
             "bad_input", argument = "x", call = call)
  }
  if (any(counts < 2L)) {
    few <- names(counts)[counts < 2L]
    hm_abort("Grasp type{?s} {.val {few}} ha{?s/ve} fewer than two recordings in {.arg x}.",
             "bad_input", argument = "x", call = call)
  }
  y
}

# Log posteriors (rows: recordings of x, columns: types), after checking
# that x is what the classifier was trained on.
classifier_log_posterior <- function(object, x, call = rlang::caller_env()) {
  check_trained_dofs(x, object$dofs, "classifier", call = call)
  s <- subclass_lda_scores(object$fit, classifier_features(x, object$at))
  rownames(s) <- x$meta$id
  s
}

#' @export
print.grasp_discriminant <- function(x, ...) {
  cli::cat_line(cli::pluralize(
    "<grasp_discriminant> shrinkage LDA, {length(x$classes)} grasp type{?s}, {sum(x$n)} training recording{?s}"))
  at <- paste(signif(x$at, 3), collapse = ", ")
  cli::cat_line(cli::pluralize(paste(
    "  features: {length(x$dofs)} DoF{?s} at {length(x$at)} fraction{?s} of the motion ({at})",
    "+ log duration + travel and extremes per DoF")))
  cli::cat_line("  correlation shrinkage ", paste(sprintf("%.3f", x$fit$shrinkage), collapse = ", "), "; ",
                x$prior, " priors")
  used <- as.integer(x$fit$subclasses_used)
  range <- sprintf("%d to %d", min(used), max(used))
  cli::cat_line(if (identical(x$fit$subclasses, "auto")) {
    paste0("  subclasses per type: an average of the fits with up to ", paste(discriminant_subclass_choices, collapse = ", "),
           " (the finest uses ", range, ", ", sum(used), " in all)")
  } else {
    paste0("  subclasses per type: up to ", x$fit$subclasses, " (given); used ", range, " (", sum(used), " in all)")
  })
  invisible(x)
}

#' @rdname summary.grasp_classifier
#' @export
summary.grasp_discriminant <- function(object, ...) {
  classifier_summary_frame(object, log_prior = unname(object$fit$type_prior[object$classes]),
                           subclasses = unname(object$fit$subclasses_used[object$classes]))
}
