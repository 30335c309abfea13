# How natural are generated grasps? Each measure compares generated grasps
# with held-out recordings of new subjects, always beside the same measure
# for real recordings of the training subjects against the same held-out
# recordings, at the same sample size (every training recording against as
# many generated grasps, by default): different people grasp differently,
# so "as natural as recorded" means "no further from new subjects than the
# training subjects themselves are".

#' Measure how natural generated grasps are
#'
#' Generates grasps from each model set and compares them with held-out
#' recordings (ideally of subjects the models never saw), each measure beside
#' the same measure for real recordings of the training subjects against the
#' same held-out recordings at the same sample size (the real-vs-real
#' baseline). Per grasp type:
#'
#' * **discriminability** (`mmd`): the squared maximum mean discrepancy
#'   (Gretton et al. 2012, unbiased estimate) with a Gaussian kernel between
#'   the features of the two samples (at most 300 recordings of each, a random
#'   subsample beyond, as its cost grows with the square of the sample): the
#'   posture at 25%, 50%, 75% and 100%
#'   of the motion and the log duration, each standardised by the held-out
#'   recordings' spread; the kernel's bandwidth is the median distance
#'   between held-out recordings, the same for both comparisons. Unlike a
#'   test of means it sees the covariance: a sample whose fingers vary
#'   independently is far from one whose fingers vary together. Its
#'   permutation p-value (`mmd_p`, 200 permutations) is given too;
#' * **dependence** (`posture_cor_gap`, `velocity_cor_gap`): the mean over
#'   DoF pairs of `|r_held-out - r|`, where `r` is the correlation between two
#'   DoFs' final angles across recordings, or between their velocity
#'   profiles (the change over each tenth of the motion) within a recording,
#'   averaged over recordings;
#' * **recognisability** (`recognised`): the share classified as their own
#'   type by linear discriminant analysis (with a shrunk covariance, as in
#'   [fit_grasp_classifier()]) on the same features, trained on
#'   the training recordings of all types (real recordings only, never the
#'   model): for the generated grasps, and for the held-out recordings as the
#'   baseline;
#' * **plausibility** (`outside_limits`, `log_jerk`, `duration_ks`): the
#'   share of frames with a DoF outside the hand's joint limits (the DoFs the
#'   model's `limits` table enforces), the median over recordings of the log10
#'   mean squared jerk (third derivative, per second cubed), and the
#'   Kolmogorov-Smirnov distance of the durations from the held-out ones.
#'   For the first two the baseline is the held-out recordings' own value
#'   (the yardstick is "like real"), for the KS distance the training
#'   recordings' distance.
#'
#' Over-long recordings (the rule of [fit_grasp_model()]) are left out of both real
#' samples by default, with the threshold the models use (from each type's
#' training frame counts): the thesis' models are fitted without them, as
#' recordings that did not end with the grasp, so they are not part of what
#' generation should reproduce. How many were left out is kept in the
#' result's `excluded` attribute and printed; `overlong = NULL` keeps them.
#'
#' Every measure is averaged over `reps` repetitions (a fresh generated batch
#' each time and, with `n` smaller than the training recordings, a fresh
#' subsample of them, drawn before anything is generated, so every model set
#' is compared with the same real recordings). The `overall` rows
#' give the median over types (pooled shares for `recognised` and
#' `outside_limits`).
#'
#' **Folds.** Given `recordings` instead of `models` (and no `held_out`
#' or `training`), the evaluation makes its own held-out folds as
#' [evaluate_loso()] does (by subject with two or more subjects, else
#' stratified by recording; `split`, `folds`, `seed`), fits each model of
#' `fit` on each fold's training recordings, measures against its held-out
#' ones, and averages every measure over the folds.
#'
#' A progress bar (one step per grasp type, through `progressr`) appears
#' after 2 s (in interactive sessions, or when you set progressr's handlers
#' or `progressr.enable`); `options(handmotion.progress = FALSE)` turns it off.
#'
#' @param models A `grasp_models` set ([fit_grasp_models()]) or a named list
#'   of them to compare (e.g. `list(thesis = m1, copula = m2)`), with
#'   `held_out` and `training`; `NULL` with `recordings`.
#' @param held_out A [grasps()] object of held-out recordings of the modelled
#'   types.
#' @param training A [grasps()] object of the recordings the models were
#'   fitted on (the baseline's real recordings and the classifier's training
#'   data).
#' @param recordings Instead of `models`, `held_out` and `training`: a
#'   [grasps()] set of recordings to evaluate by folds (see Folds).
#' @param fit With folds: a named list of argument lists for
#'   [fit_grasp_models()], one per model compared (default: the thesis'
#'   independent model, the copula model and the kernel model).
#' @param split,folds With folds: as in [evaluate_loso()]: `folds = NULL`
#'   (default) is one fold per subject (5 folds by recording with one
#'   subject), a number `n` is `n` groups of subjects (or folds of
#'   recordings). Each fold fits every model of `fit`, so fewer folds
#'   (`folds = 2`) are much cheaper.
#' @param n Generated grasps (and training recordings) per type and
#'   repetition; by default every training recording of the type (over-long
#'   ones left out) against as many generated grasps. Both comparisons use
#'   the same sizes, so every measure is fair; the MMD estimate is unbiased
#'   whatever the sizes, and the larger samples make it steadier: with five
#'   folds of one person's recordings (a few held-out recordings a type) the
#'   MMD ratio of a model moved by 0.35-0.7 between seeds at the held-out size
#'   and by 0.2-0.4 at the training size (NEWS).
#'   A number `n` draws `n` training recordings at random in each repetition
#'   (at most all of them).
#' @param reps Repetitions averaged.
#' @param overlong The over-long rule of [fit_grasp_model()], `c(iqr_mult = ,
#'   median_mult = )`, whose over-long recordings are left out of the real
#'   samples (per type, threshold from the training
#'   recordings), or `NULL` to keep every recording.
#' @param seed Seed (the global RNG is restored afterwards).
#' @return A data frame of class `generation_evaluation` with columns `model`,
#'   `grasp` (a type, or `"overall"`), `family`, `metric`, `generated` (the
#'   measure for generated grasps), `baseline` (for real recordings),
#'   `better` (`"lower"` or `"higher"`) and `ratio` (`generated / baseline`).
#'   Attribute `excluded`: a data frame (`grasp`, `threshold`, `held_out`,
#'   `training`) of the over-long recordings left out per type.
#'   Print it for the overall rows; [autoplot()] draws generated against
#'   baseline for every type and measure.
#' @seealso [fit_grasp_model()] (`dependence`), [generate()] (`limits`).
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 6, grasps = 1:2, objects = 2, trials = 2, seed = 1)
#' train <- g[g$meta$subject <= "S04"]
#' test <- g[g$meta$subject > "S04"]
#' m <- fit_grasp_models(train, seed = 1, dependence = "copula")
#' ev <- evaluate_generation(m, test, train, reps = 2)
#' ev
#' # by folds, from the recordings
#' evaluate_generation(recordings = g, folds = 2, reps = 1, fit = list(copula = list(dependence = "copula")))
evaluate_generation <- function(models = NULL, held_out = NULL, training = NULL, n = NULL, reps = 5,
                                overlong = c(iqr_mult = 3, median_mult = 1.5), seed = 1,
                                fit = list(thesis = list(), copula = list(dependence = "copula"),
                                           kernel = list(dependence = "kernel")),
                                split = c("auto", "subject", "recording"), folds = NULL, recordings = NULL) {
  call <- rlang::caller_env()
  # two modes, two arguments: model sets with their held-out and training
  # recordings, or recordings alone (folds)
  if (inherits(models, "grasps")) {
    hm_abort(c("{.arg models} must be model sets, not a {.cls grasps} set of recordings.",
               i = "To evaluate recordings by folds, give them as {.arg recordings}."),
             "bad_input", argument = "models", call = call)
  }
  if (!is.null(recordings)) {
    if (!is.null(models) || !is.null(held_out) || !is.null(training)) {
      hm_abort("Give either {.arg recordings} (folds) or {.arg models} with {.arg held_out} and {.arg training}, not both.",
               "bad_input", argument = "recordings", call = call)
    }
    check_grasps(recordings, arg = "recordings", call = call)
    # (recordings without a motion are said once, not by each fold's fits)
    return(say_no_motion_once(evaluate_generation_folds(recordings, fit, split, folds, n, reps, overlong, seed, call),
                              length(recordings)))
  }
  sets <- if (inherits(models, "grasp_models")) stats::setNames(list(models), model_set_name(models)) else models
  if (!is.list(sets) || !length(sets) || !all(vapply(sets, inherits, logical(1), "grasp_models")) ||
      is.null(names(sets)) || any(!nzchar(names(sets)))) {
    hm_abort("{.arg models} must be a {.cls grasp_models} set or a named list of them.", "bad_input",
             argument = "models", call = call)
  }
  check_grasps(held_out, arg = "held_out", call = call)
  check_grasps(training, arg = "training", call = call)
  reps <- check_whole(reps, "reps", max = 1000, call = call)
  if (!is.null(n)) n <- check_whole(n, "n", min = 5, max = 1e5, call = call)
  seed <- check_seed(seed, call = call)
  overlong <- as_overlong_rule(overlong, allow_null = TRUE, call = call)
  # the types every set could fit (a failed type has nothing to generate)
  types <- Reduce(intersect, lapply(sets, function(s) names(fitted_models(s))))
  missing <- setdiff(types, as.character(unique(held_out$meta$grasp)))
  if (length(missing)) {
    hm_abort("{.arg held_out} has no recordings of {.val {missing}}.", "bad_input",
             argument = "held_out", call = call)
  }
  # channels that never move (a stuck sensor) have no correlation: they are
  # left out of the dependence measures, said once here
  flat <- held_out$dofs[find_stuck(c(held_out$recordings, training$recordings))]
  if (length(flat)) {
    hm_warn(c("{cli::qty(length(flat))}Channel{?s} {.val {flat}} {?is/are} constant in every recording: left out of the correlation measures.",
              i = "{cli::qty(length(flat))}The other measures use {?it/them} as recorded."), "constant_channels", channels = flat)
  }
  with_progress_shown(with_seed(seed, evaluate_generation_impl(sets, held_out, training, types, n, reps,
                                                               overlong)))
}

evaluate_generation_impl <- function(sets, held_out, training, types, n, reps, overlong) {
  lda <- fit_feature_lda(training)
  # one type per element, on the future plan's workers, each under its own
  # RNG stream drawn from the evaluation's seeded stream (as
  # fit_grasp_models() gives each type its own): the same figures under any
  # plan, and two workers share the types (the measures were all in the
  # main process: 12-13 s of the default data's evaluation of two sets;
  # 7-8 s on two workers)
  streams <- element_streams(sample.int(.Machine$integer.max, 1L), length(types))
  # (the models are stripped only to travel: in this process the copy would
  # cost about a second and save nothing)
  light <- if (ships_to_workers()) strip_for_generation else identity
  elements <- lapply(types, function(ty) {
    list(type = ty, held_out = held_out[held_out$meta$grasp == ty],
         training = training[training$meta$grasp == ty],
         models = lapply(sets, function(s) light(s[[ty]])))
  })
  p <- hm_progressor(length(types))
  res <- future_map_chunks(elements, generation_type_rows,
                           more = list(lda = lda, n = n, reps = reps, overlong = overlong, progress = p),
                           streams = streams,
                           work = vapply(elements, function(e) length(e$training) + length(e$held_out), numeric(1)))
  out <- do.call(rbind, lapply(res, `[[`, "rows"))
  out <- rbind(out, generation_overall(out))
  rownames(out) <- NULL
  excluded <- do.call(rbind, lapply(res, `[[`, "excluded"))
  structure(out, class = c("generation_evaluation", "data.frame"), excluded = excluded)
}

# A model as generation needs it: without the training alignment (the
# warped recordings, most of a model's bytes), which generate() does not
# read, so that a type's models travel to a worker light.
strip_for_generation <- function(m) {
  m$alignment <- NULL
  m
}

# One type's rows of the evaluation (every set's measures beside the
# real-vs-real baseline) and its over-long exclusions, under the type's own
# RNG stream (the training subsamples, the generated grasps and the MMD
# permutations all draw from it).
generation_type_rows <- function(.element, lda, n, reps, overlong, progress) {
  ty <- .element$type
  real_sets <- generation_real_samples(.element$held_out, .element$training, ty, n, reps, overlong)
  ho <- real_sets$held_out
  real <- real_sets$training
  n_ty <- length(real[[1]])
  models <- .element$models
  ref <- generation_reference(ho)
  base <- generation_measures(real, ref, lda, ty, models[[1]]$limits)
  base$recognised <- mean(lda_class(lda, ref$features) == ty)
  base$outside_limits <- limit_share(ho, models[[1]]$limits)
  base$log_jerk <- ref$log_jerk
  rows <- lapply(names(models), function(nm) {
    m <- models[[nm]]
    gen <- generate(m, n = n_ty * reps, seed = NULL)   # the type's stream
    gen <- lapply(seq_len(reps), function(r) gen[(r - 1L) * n_ty + seq_len(n_ty)])
    generation_rows(nm, ty, generation_measures(gen, ref, lda, ty, m$limits), base)
  })
  progress(sprintf("type %s", ty))
  list(rows = do.call(rbind, rows), excluded = real_sets$excluded)
}

# The real recordings of one type: held-out and training recordings without
# the over-long ones (threshold from the training frame counts, as the model
# has it), and the training sample: every recording (one sample), or `reps`
# subsamples of `n`.
generation_real_samples <- function(ho, tr, type, n, reps, overlong) {
  threshold <- if (is.null(overlong)) Inf else overlong_threshold(tr$meta$n_frames, overlong)
  long_ho <- ho$meta$n_frames > threshold
  long_tr <- tr$meta$n_frames > threshold
  ho <- ho[!long_ho]
  tr <- tr[!long_tr]
  # (by default every training recording: the same sample in each
  # repetition, so it is measured once; see `n` in ?evaluate_generation)
  n_ty <- min(n %||% length(tr), length(tr))
  list(held_out = ho,
       training = if (n_ty < length(tr)) lapply(seq_len(reps), function(r) tr[sample.int(length(tr), n_ty)]) else list(tr),
       excluded = data.frame(grasp = type, threshold = threshold, held_out = sum(long_ho),
                             training = sum(long_tr), stringsAsFactors = FALSE))
}

# Which way is better, and the family, of every measure.
generation_metrics <- data.frame(
  metric = c("mmd", "mmd_p", "posture_cor_gap", "velocity_cor_gap", "recognised", "outside_limits",
             "log_jerk", "duration_ks"),
  family = c("discriminability", "discriminability", "dependence", "dependence", "recognisability",
             "plausibility", "plausibility", "plausibility"),
  better = c("lower", "higher", "lower", "lower", "higher", "lower", "closer", "lower"),
  label = c("kernel MMD\u00b2", "MMD permutation p-value", "final-posture correlation gap",
            "velocity correlation gap", "recognised by LDA",
            "frames outside limits", "log jerk (smoothness)", "duration KS distance"),
  stringsAsFactors = FALSE)

# A lone model set is named after its dependence ("independent" is the
# thesis' model), so tables and legends say which model they show.
model_set_name <- function(models) {
  dep <- unique(vapply(fitted_models(models), function(m) m$dependence$type %||% "independent", character(1)))
  if (length(dep) == 1L) dep else "model"
}

generation_rows <- function(model, type, got, base) {
  mt <- generation_metrics
  data.frame(model = model, grasp = type, family = mt$family, metric = mt$metric,
             generated = unlist(got[mt$metric]), baseline = unlist(base[mt$metric]),
             better = mt$better, ratio = unlist(got[mt$metric]) / unlist(base[mt$metric]),
             stringsAsFactors = FALSE)
}

# Median over types per model and measure (the shares of recognised grasps
# and of frames outside the limits are means: every type has the same n).
generation_overall <- function(out) {
  keys <- unique(out[c("model", "metric")])
  rows <- lapply(seq_len(nrow(keys)), function(i) {
    d <- out[out$model == keys$model[i] & out$metric == keys$metric[i], ]
    # (over the types where the measure is defined: a type whose held-out
    # part is one recording has no MMD, and with it every fold of a small
    # set had no overall MMD at all, where the rows by type average the
    # folds that have one)
    f <- if (d$metric[1] %in% c("recognised", "outside_limits")) mean else stats::median
    g <- function(v) f(v[is.finite(v)])
    data.frame(model = d$model[1], grasp = "overall", family = d$family[1], metric = d$metric[1],
               generated = g(d$generated), baseline = g(d$baseline), better = d$better[1],
               ratio = g(d$generated) / g(d$baseline), stringsAsFactors = FALSE)
  })
  do.call(rbind, rows)
}

# What every comparison needs of the held-out recordings of one type.
generation_reference <- function(ho) {
  F <- generation_features(ho)
  centre <- colMeans(F)
  spread <- apply(F, 2, stats::sd)
  spread[!is.finite(spread) | spread == 0] <- 1
  Z <- sweep(sweep(F, 2, centre), 2, spread, "/")
  d <- as.vector(stats::dist(Z))
  list(features = F, centre = centre, spread = spread, Z = Z,
       bandwidth = stats::median(d[d > 0]) %||% 1,
       posture_cor = varying_cor(final_postures(ho)),
       velocity_cor = velocity_correlation(ho),
       durations = ho$meta$n_frames / ho$rate,
       log_jerk = stats::median(log_jerk(ho)))
}

# Measures of a list of samples (repetitions) of one type against the
# held-out reference, averaged over the repetitions.
generation_measures <- function(samples, ref, lda, type, limits) {
  one <- function(x) {
    F <- generation_features(x)
    Z <- sweep(sweep(F, 2, ref$centre), 2, ref$spread, "/")
    mmd <- mmd_test(mmd_subsample(Z), mmd_subsample(ref$Z), ref$bandwidth)
    list(mmd = mmd$mmd, mmd_p = mmd$p,
         posture_cor_gap = cor_gap(varying_cor(final_postures(x)), ref$posture_cor),
         velocity_cor_gap = cor_gap(velocity_correlation(x), ref$velocity_cor),
         recognised = mean(lda_class(lda, F) == type),
         outside_limits = limit_share(x, limits),
         log_jerk = stats::median(log_jerk(x)),
         duration_ks = ks_distance(x$meta$n_frames / x$rate, ref$durations))
  }
  res <- lapply(samples, one)
  stats::setNames(lapply(names(res[[1]]), function(k) mean(vapply(res, `[[`, numeric(1), k))),
                  names(res[[1]]))
}

# Posture at 25%, 50%, 75% and 100% of the motion and the log duration in
# seconds: one row per recording.
generation_features <- function(x) motion_features(x, c(0.25, 0.5, 0.75, 1))

final_postures <- function(x) {
  t(vapply(x$recordings, function(r) r[nrow(r), ], numeric(length(x$dofs))))
}

# Correlation between DoFs' velocity profiles within each recording,
# averaged over recordings (pairs undefined in a recording are skipped). The
# profile is the change of each angle over each tenth of the motion, so
# frame-to-frame sensor noise (which would decorrelate recorded velocities
# but not the smooth generated ones) does not enter. All recordings at once:
# each recording's profile columns are centred and scaled to unit length,
# so the sum over recordings of their correlation matrices is one cross
# product of the stacked profiles (a cor() per recording was a quarter of
# evaluate_generation()'s time); a DoF that does not move in a recording
# has no correlation there and is left out of that recording's count.
velocity_correlation <- function(x) {
  p <- length(x$dofs)
  recs <- x$recordings[vapply(x$recordings, nrow, integer(1)) >= 4L]
  out <- matrix(NA_real_, p, p, dimnames = list(x$dofs, x$dofs))
  if (!length(recs)) return(out)
  at <- seq(0, 1, by = 0.1)
  D <- do.call(rbind, lapply(recs, function(r) {
    pos <- 1 + at * (nrow(r) - 1)
    lo <- floor(pos)
    w <- pos - lo
    prof <- r[lo, , drop = FALSE] * (1 - w) + r[pmin(lo + 1L, nrow(r)), , drop = FALSE] * w
    diff(prof)
  }))
  m <- length(at) - 1L
  rec <- rep(seq_along(recs), each = m)
  D <- D - rowsum(D, rec, reorder = FALSE)[rec, , drop = FALSE] / m
  len <- sqrt(rowsum(D^2, rec, reorder = FALSE))
  ok <- len > 0 & is.finite(len)
  D <- D / len[rec, , drop = FALSE]
  D[!ok[rec, , drop = FALSE]] <- 0
  out[] <- crossprod(D) / crossprod(ok * 1)
  out
}

# Mean absolute difference of two correlation matrices over the DoF pairs
# defined in both.
cor_gap <- function(a, b) {
  d <- abs(a - b)[upper.tri(a)]
  mean(d[is.finite(d)])
}

# Log10 mean squared jerk (third difference, per second cubed) of every
# recording, from the recordings stacked: the third differences of the
# stacked frames are each recording's own wherever the four frames belong to
# one recording (each recording's diff(r, differences = 3), to rounding).
log_jerk <- function(x) {
  nk <- vapply(x$recordings, nrow, integer(1))
  out <- stats::setNames(rep(NA_real_, length(nk)), names(x$recordings))
  use <- nk >= 5L
  if (!any(use)) return(out)
  S <- do.call(rbind, x$recordings[use])
  # (the third difference in one pass: diff(S, differences = 3) copies S
  # three times and was a sixth of evaluate_generation()'s time)
  m <- nrow(S) - 3L
  j <- (S[4:nrow(S), , drop = FALSE] - S[seq_len(m), , drop = FALSE] -
          3 * (S[3:(m + 2L), , drop = FALSE] - S[2:(m + 1L), , drop = FALSE])) * x$rate^3
  n <- nk[use]
  rec <- rep(seq_along(n), n)
  # row t of j spans frames t..t+3: keep those inside one recording
  keep <- rec[seq_len(nrow(j))] == rec[seq_len(nrow(j)) + 3L]
  ss <- rowsum(rowSums(j[keep, , drop = FALSE]^2), rec[seq_len(nrow(j))][keep], reorder = FALSE)
  out[use] <- log10(ss[, 1] / ((n - 3) * ncol(S)))
  out
}

limit_share <- function(x, limits) {
  if (is.null(limits) || !nrow(limits)) return(NA_real_)
  limit_violations(x, limits[limits$enforced, , drop = FALSE])$frames
}

# Unbiased squared MMD with a Gaussian kernel of the given bandwidth, and
# its permutation p-value. The statistics of the observed split and of
# `permutations` random ones come from compiled code
# (src/mmd-permutations.c): the permutations are the same sample.int() draws
# from the session's stream as the R code before it made (which found the
# three kernel sums of each as quadratic forms of K with a 0/1 membership
# matrix, N^2 operations per permutation where n^2 / 2 additions suffice; it
# and the indexing before it were most of evaluate_generation()'s time), so
# the statistic agrees to rounding and the p-value is the same up to
# rounding ties.
mmd_test <- function(X, Y, bandwidth, permutations = 200L) {
  # a sample of one recording has no within-sample pair: no statistic (the
  # former R computation gave NaN and NA here; a type's held-out fold of one
  # recording on a small real set comes to this)
  if (nrow(X) < 2L || nrow(Y) < 2L) return(list(mmd = NaN, p = NA_real_))
  K <- exp(-squared_distances(rbind(X, Y)) / (2 * bandwidth^2))
  stat <- .Call(hm_mmd_permutations, K, nrow(X), as.integer(permutations))
  obs <- stat[1L]
  list(mmd = obs, p = (1 + sum(stat[-1L] >= obs)) / (1 + permutations))
}

# The MMD's cost is quadratic in the sample sizes (every pair, for every
# permutation); beyond `cap` recordings a sample enters through a random
# subsample of `cap`, so the evaluation of ten times the data costs about
# ten times as much. The default data (at most about 90 held-out recordings
# of a type) never reach it, and then no random number is drawn.
mmd_cap <- 300L
mmd_subsample <- function(Z, cap = mmd_cap) {
  if (nrow(Z) <= cap) return(Z)
  Z[sort(sample.int(nrow(Z), cap)), , drop = FALSE]
}

# All squared Euclidean distances between the rows of A, from one cross
# product (as.matrix(dist()) cost as much as the whole MMD test).
squared_distances <- function(A) {
  s <- rowSums(A^2)
  D <- -2 * tcrossprod(A) + s
  D <- t(D) + s
  D[D < 0] <- 0
  diag(D) <- 0
  D
}

# The two-sample Kolmogorov-Smirnov statistic: the largest gap between the
# two empirical distribution functions over the pooled values (what
# ks.test()$statistic gives, without the p-value and its tie warnings).
ks_distance <- function(a, b) {
  z <- sort(unique(c(a, b)))
  max(abs(findInterval(z, sort(a)) / length(a) - findInterval(z, sort(b)) / length(b)))
}

# The recognisability yardstick: the package's shrinkage LDA
# (R/shrunk-lda.R, equal priors) on generation_features() of all training
# recordings. It never sees a model, only real recordings.
fit_feature_lda <- function(training) {
  fit_shrunk_lda(generation_features(training), training$meta$grasp)
}

lda_class <- function(lda, F) {
  top_class(lda$classes, shrunk_lda_scores(lda, F))
}

#' @export
print.generation_evaluation <- function(x, ...) {
  need <- c("model", "grasp", "family", "metric", "generated", "baseline", "better")
  if (!all(need %in% names(x))) { # a subset of columns: a plain table
    print(as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE), ...)
    return(invisible(x))
  }
  ov <- as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE)
  ov <- ov[ov$grasp == "overall", setdiff(need, "grasp")]
  n_types <- length(setdiff(unique(x$grasp), "overall"))
  models <- unique(x$model)
  cli::cat_line(cli::pluralize(
    "<generation_evaluation> {n_types} grasp type{?s}, {cli::qty(models)}model{?s} {paste(models, collapse = ', ')}"))
  cli::cat_line("Overall (median over types; baseline = real recordings of the training subjects):")
  print(as.data.frame(ov), digits = 3, row.names = FALSE)
  ex <- attr(x, "excluded")
  if (is.data.frame(ex) && nrow(ex)) {
    cli::cat_line(sprintf("Over-long recordings left out of the real samples: %d held-out, %d training.",
                          sum(ex$held_out), sum(ex$training)))
  }
  invisible(x)
}

#' Plot a generation evaluation
#'
#' One panel per measure: each grasp type's value for generated grasps
#' against the real-vs-real baseline, one colour per model, with the diagonal
#' (as natural as real) dashed.
#'
#' @param object A `generation_evaluation` from [evaluate_generation()].
#' @param metric Measures to show (default: all but the p-value).
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 6, grasps = 1:2, objects = 2, trials = 2, seed = 1)
#' train <- g[g$meta$subject <= "S04"]
#' test <- g[g$meta$subject > "S04"]
#' m <- fit_grasp_models(train, seed = 1, dependence = "copula")
#' ggplot2::autoplot(evaluate_generation(m, test, train, reps = 2))
autoplot.generation_evaluation <- function(object, metric = NULL, ...) {
  d <- as.data.frame(object)
  d <- d[d$grasp != "overall", ]
  metric <- metric %||% setdiff(generation_metrics$metric, "mmd_p")
  d <- d[d$metric %in% metric, ]
  d$metric <- factor(generation_metrics$label[match(d$metric, generation_metrics$metric)],
                     levels = generation_metrics$label[match(metric, generation_metrics$metric)])
  ggplot2::ggplot(d, ggplot2::aes(.data$baseline, .data$generated, colour = .data$model)) +
    ggplot2::geom_abline(slope = 1, intercept = 0, linetype = "dashed", colour = "grey50") +
    ggplot2::geom_point(alpha = 0.75) +
    ggplot2::facet_wrap(~metric, scales = "free") +
    ggplot2::labs(x = "real recordings (training subjects vs held-out)",
                  y = "generated grasps (vs held-out)", colour = "model",
                  title = "How natural are generated grasps?",
                  subtitle = "one point per grasp type; on the dashed line = as natural as recorded") +
    ggplot2::theme_bw(base_size = 11)
}

# Correlation matrix of the columns of X, NA for pairs with a column that
# does not vary (where stats::cor() would warn "the standard deviation is
# zero" once per call: for a stuck glove channel, at every repetition).
varying_cor <- function(X) {
  p <- ncol(X)
  out <- matrix(NA_real_, p, p, dimnames = list(colnames(X), colnames(X)))
  v <- apply(X, 2, function(col) length(col) > 1L && stats::var(col) > 0)
  if (sum(v) >= 2L) out[v, v] <- stats::cor(X[, v, drop = FALSE])
  out
}

# evaluate_generation() by folds: fit each model of `fit` on every fold's
# training part, measure against its held-out part, average the measures.
evaluate_generation_folds <- function(x, fit, split, folds, n, reps, overlong, seed, call) {
  if (!is.list(fit) || !length(fit) || is.null(names(fit)) || any(!nzchar(names(fit))) ||
      !all(vapply(fit, is.list, logical(1)))) {
    hm_abort("{.arg fit} must be a named list of argument lists for {.fn fit_grasp_models}.",
             "bad_input", argument = "fit", call = call)
  }
  x <- x[!is.na(x$meta$grasp)]
  groups <- make_folds(x, split, folds, seed, call = call)
  p <- progressr::progressor(steps = length(groups))
  parts <- lapply(seq_along(groups), function(f) {
    tr <- x[!groups[[f]]]
    ho <- x[groups[[f]]]
    sets <- lapply(fit, function(a) suppressWarnings(do.call(fit_grasp_models, c(list(tr, seed = seed), a))))
    res <- withCallingHandlers(
      evaluate_generation(sets, ho, tr, n = n, reps = reps, overlong = overlong, seed = seed + f),
      handmotion_warning_constant_channels = function(w) invokeRestart("muffleWarning"))
    p(sprintf("fold %d of %d", f, length(groups)))
    res
  })
  flat <- x$dofs[find_stuck(x$recordings)]
  if (length(flat)) {
    hm_warn("{cli::qty(length(flat))}Channel{?s} {.val {flat}} {?is/are} constant in every recording: left out of the correlation measures.",
            "constant_channels", channels = flat)
  }
  all <- do.call(rbind, lapply(parts, function(d) as.data.frame(unclass(d)[names(d)], stringsAsFactors = FALSE)))
  keys <- unique(all[c("model", "grasp", "family", "metric", "better")])
  avg <- function(col) vapply(seq_len(nrow(keys)), function(i) {
    v <- all[[col]][all$model == keys$model[i] & all$grasp == keys$grasp[i] & all$metric == keys$metric[i]]
    mean(v, na.rm = TRUE)
  }, numeric(1))
  out <- keys
  out$generated <- avg("generated")
  out$baseline <- avg("baseline")
  out$ratio <- out$generated / out$baseline
  out <- out[c("model", "grasp", "family", "metric", "generated", "baseline", "better", "ratio")]
  rownames(out) <- NULL
  excluded <- do.call(rbind, lapply(parts, attr, "excluded"))
  structure(out, class = c("generation_evaluation", "data.frame"), excluded = excluded,
            scheme = attr(groups, "scheme"))
}
