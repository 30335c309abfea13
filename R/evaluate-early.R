# How early can a grasp be recognised? Held out by subject: for each fold a
# recogniser is fitted on the other subjects and the held-out recordings
# are classified from their first frames, at times since the recording
# began and at fractions of each recording's own length.

#' Accuracy of early recognition against time and fraction of the motion
#'
#' Holds out each subject (or group of subjects) in turn, fits
#' [fit_grasp_recognizer()] on the others, and classifies the held-out
#' recordings from their first frames: after `ms` milliseconds since the
#' recording began (what a live stream knows), and after each fraction in
#' `fractions` of the recording's own length (for comparison with
#' whole-motion classifiers; a live stream does not know the fraction).
#' The work runs through `future.apply` (set a `future::plan()` to use several
#' cores), horizon by horizon: at each horizon every fold's discriminant is
#' fitted from the whole set's moments minus the fold's, the fit
#' [fit_grasp_recognizer()] would make on the fold's training recordings. A
#' progress bar (one step per horizon, through `progressr`) appears after
#' 2 s (in interactive sessions, or when you set progressr's handlers or
#' `progressr.enable`); `options(handmotion.progress = FALSE)` turns it off.
#' The folds are those of [evaluate_loso()]: by subject with two or
#' more subjects, else stratified folds of recordings (`split`); by default
#' one fold per subject up to 30 subjects, and 30 seeded groups of subjects
#' beyond that, so that the cost grows with the data, not with its square
#' (every fold's discriminant at every horizon passes over its training
#' recordings once).
#'
#' **Recordings that start at rest.** When the recordings are mostly still
#' (the rule of `fit_grasp_model(motion = "auto")`), time counts from the
#' motion's onset, as a live stream sees it: an onset detector fitted on
#' the recordings' joint speed (labels unused; see [find_motion()]) finds it
#' in every recording, so "after 300 ms" means 300 ms of motion.
#'
#' @param x A labelled [grasps()] object.
#' @param ms Times since the recording (or its motion) began, in
#'   milliseconds, or `NULL`.
#' @param fractions Fractions of each recording's length, or `NULL`. Each
#'   fold fits the recogniser's discriminants only at the horizons these
#'   need (a few for `ms` alone), the same fits [fit_grasp_recognizer()]
#'   makes at those horizons.
#' @param folds,seed,split As in [evaluate_loso()]: `folds` `NULL` is one
#'   fold per subject (at most 30 folds: with more subjects, 30 groups of
#'   subjects), or 5 folds of recordings.
#' @param ... Passed to [fit_grasp_recognizer()] (`at`, `horizon`).
#' @return A data frame of class `early_recognition` with columns `scale`
#'   (`"ms"` or `"fraction"`), `value`, `accuracy`, `n` (recordings) and
#'   `frames` (mean frames seen); attribute `scheme`. `autoplot()` draws
#'   accuracy against both scales.
#' @seealso [fit_grasp_recognizer()], [start_recognition()]
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 1:3, objects = 2, trials = 2, seed = 1)
#' er <- evaluate_early_recognition(g, ms = c(200, 400), fractions = c(0.5, 1))
#' er
#' ggplot2::autoplot(er)
evaluate_early_recognition <- function(x, ms = seq(100, 1000, by = 100), fractions = seq(0.1, 1, by = 0.1),
                                       folds = NULL, seed = 1, split = c("auto", "subject", "recording"), ...) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  if (!is.null(ms) && (!is.numeric(ms) || !length(ms) || anyNA(ms) || any(ms <= 0))) {
    hm_abort("{.arg ms} must be positive times in milliseconds, or {.code NULL}.", "bad_input",
             argument = "ms", call = call)
  }
  if (!is.null(fractions)) {
    fractions <- check_fractions(fractions, "fractions", call = call)
    if (any(fractions == 0)) {
      hm_abort("{.arg fractions} must be above 0: a recording is seen from its first frame.", "bad_input",
               argument = "fractions", call = call)
    }
  }
  if (is.null(ms) && is.null(fractions)) {
    hm_abort("Give {.arg ms}, {.arg fractions} or both: there is nothing to evaluate.", "bad_input",
             argument = "ms", call = call)
  }
  rec_args <- list(...)
  unknown <- setdiff(names(rec_args) %||% rep("", length(rec_args)), c("at", "horizon"))
  if (length(unknown)) {
    hm_abort("{.arg ...} is passed to {.fn fit_grasp_recognizer}, which takes {.arg at} and {.arg horizon}, not {.val {unknown}}.",
             "bad_input", argument = "...", call = call)
  }
  at <- check_fractions(rec_args$at %||% eval(formals(fit_grasp_recognizer)$at), "at", call = call)
  check_training_labels(x, call = call)
  old_rng <- save_rng()
  on.exit(restore_rng(old_rng), add = TRUE)
  groups <- make_folds(x, split, early_folds(x, split, folds), seed, call = call)
  # recordings that rest before the grasp: time counts from the onset a
  # detector finds in each recording (fitted on the joint speed of all of
  # them: labels are not used, so nothing of the held-out classes leaks)
  det <- if (resolve_motion(x, "auto") == "trim") fit_onset_detector(x)
  x <- from_onset(x, det)
  tests <- unname(lapply(groups, identity))
  all <- with_progress_shown(early_recognition_counts(x, tests, ms, fractions, at, rec_args$horizon, call))
  key <- paste(all$scale, all$value)
  agg <- do.call(rbind, lapply(split(all, factor(key, levels = unique(key))), function(d) {
    data.frame(scale = d$scale[1], value = d$value[1], accuracy = sum(d$correct) / sum(d$n),
               n = sum(d$n), frames = sum(d$frames) / sum(d$n), stringsAsFactors = FALSE)
  }))
  rownames(agg) <- NULL
  structure(agg, class = c("early_recognition", "data.frame"),
            scheme = attr(groups, "scheme"),
            classes = length(unique(x$meta$grasp)))
}

# The number of folds by default: leave-one-subject-out holds out each of S
# subjects, and each fold's fit passes over its ~N training recordings at
# every horizon, so its cost grows as S x N, the square of the data when
# more data means more subjects. Up to `max_folds` subjects (the default
# data's 30) that is kept; beyond, the subjects are dealt into `max_folds`
# seeded groups (the same held-out question on a few more subjects at a
# time), and ten times the subjects cost about ten times the time.
early_folds <- function(x, split, folds, max_folds = 30L) {
  if (!is.null(folds) || identical(split[1], "recording")) return(folds)
  n_subjects <- length(unique(stats::na.omit(x$meta$subject)))
  if (n_subjects > max_folds) max_folds else NULL
}

# The held-out counts of every fold (a logical test mask each) and view (a
# time or a fraction): correct predictions, recordings and frames seen.
# What each fold's recogniser would be is fitted horizon by horizon instead
# of fold by fold: at horizon h the features of every recording are built
# once, each fold's discriminant comes from the whole set's moments minus
# the fold's (lda_moments()), and only the folds whose held-out recordings
# are classified at h fit there. The predictions are those of
# fit_grasp_recognizer() on each fold's training recordings (to rounding:
# the moments are subtracted, not recomputed). Horizons run through
# future.apply in chunks, with one progress step per horizon.
early_recognition_counts <- function(x, tests, ms, fractions, at, horizon, call) {
  nf <- x$meta$n_frames
  truth <- as.character(x$meta$grasp)
  y <- x$meta$grasp
  levels <- if (is.factor(y)) levels(droplevels(y)) else sort(unique(as.character(y)))
  cls <- match(truth, levels)
  # per fold: its training labels checked as the recogniser checks them,
  # its horizon, and the frames each held-out recording is seen for at
  # every view (capped at the fold's horizon)
  folds <- lapply(tests, function(test) {
    check_training_labels(list(meta = list(grasp = y[!test])), call = call)
    H <- recognizer_horizon(list(meta = list(n_frames = nf[!test])), horizon, call)
    rows <- which(test)
    views <- c(lapply(ms, function(v) {
      list(scale = "ms", value = v, seen = rep(max(1L, as.integer(round(v * x$rate / 1000))), length(rows)))
    }), lapply(fractions, function(v) {
      list(scale = "fraction", value = v, seen = pmax(1L, as.integer(round(v * nf[rows]))))
    }))
    list(rows = rows, H = H, views = views,
         needed = sort(unique(pmin(unlist(lapply(views, `[[`, "seen")), H))))
  })
  horizons <- sort(unique(unlist(lapply(folds, `[[`, "needed"))))
  # one chunk per worker (each stacks the recordings once), the horizons
  # dealt out in turn so that every chunk has short and long ones
  workers <- if (requireNamespace("future", quietly = TRUE)) future::nbrOfWorkers() else 1L
  n_chunks <- min(length(horizons), max(1L, workers))
  chunks <- unname(split(horizons, rep_len(seq_len(n_chunks), length(horizons))))
  p <- hm_progressor(length(horizons))
  parts <- future.apply::future_lapply(chunks, function(hs) {
    prefix <- prefix_source(x)
    lapply(hs, function(h) {
      out <- early_horizon_predictions(prefix, h, at, cls, levels, folds)
      p(sprintf("horizon %d (%d frames)", h, max(horizons)))
      out
    })
  }, future.seed = TRUE)
  preds <- unlist(parts, recursive = FALSE)
  names(preds) <- unlist(chunks)
  # the counts of every fold and view from the predictions at each
  # recording's horizon
  do.call(rbind, lapply(seq_along(folds), function(f) {
    fo <- folds[[f]]
    do.call(rbind, lapply(fo$views, function(v) {
      h <- pmin(v$seen, fo$H)
      pred <- character(length(h))
      for (hh in unique(h)) {
        at_h <- h == hh
        pred[at_h] <- preds[[as.character(hh)]][[f]][at_h]
      }
      data.frame(scale = v$scale, value = v$value, correct = sum(pred == truth[fo$rows]),
                 n = length(h), frames = sum(v$seen))
    }))
  }))
}

# At one horizon: the predicted class of every held-out recording of every
# fold that needs this horizon (NULL for the others).
early_horizon_predictions <- function(prefix, h, at, cls, levels, folds) {
  F <- prefix_features(prefix, h, at)
  centre <- colMeans(F)
  Fc <- F - rep(centre, each = nrow(F))
  K <- length(levels)
  held <- lapply(folds, function(fo) lda_moments(Fc[fo$rows, , drop = FALSE], cls[fo$rows], K))
  total <- Reduce(lda_moments_plus, held)
  in_folds <- sort(unlist(lapply(folds, `[[`, "rows")))
  if (length(in_folds) < nrow(Fc)) {  # recordings never held out (no fold holds them)
    rest <- setdiff(seq_len(nrow(Fc)), in_folds)
    total <- lda_moments_plus(total, lda_moments(Fc[rest, , drop = FALSE], cls[rest], K))
  }
  lapply(seq_along(folds), function(f) {
    fo <- folds[[f]]
    if (!h %in% fo$needed) return(NULL)
    train <- setdiff(seq_len(nrow(Fc)), fo$rows)
    fit <- lda_from_moments(lda_moments_minus(total, held[[f]]), Fc, train, cls[train], levels, centre)
    top_class(fit$classes, shrunk_lda_scores(fit, F[fo$rows, , drop = FALSE]))
  })
}

#' @export
print.early_recognition <- function(x, ...) {
  k <- as.integer(attr(x, "classes"))
  cli::cat_line(cli::pluralize("<early_recognition> {k} class{?es}, held out: {attr(x, 'scheme')}"))
  d <- as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE)
  d$value <- format(d$value, drop0trailing = TRUE, scientific = FALSE)
  d$accuracy <- sprintf("%.1f%%", 100 * d$accuracy)
  d$frames <- round(d$frames, 1)
  print(d, row.names = FALSE)
  invisible(x)
}

#' @rdname evaluate_early_recognition
#' @param object An `early_recognition` result.
#' @export
#' @method autoplot early_recognition
autoplot.early_recognition <- function(object, ...) {
  d <- as.data.frame(unclass(object)[names(object)], stringsAsFactors = FALSE)
  d$axis <- factor(ifelse(d$scale == "ms", "time since the recording began (ms)", "fraction of the motion seen"),
                   levels = c("time since the recording began (ms)", "fraction of the motion seen"))
  ggplot2::ggplot(d, ggplot2::aes(.data$value, .data$accuracy)) +
    ggplot2::geom_hline(yintercept = 1 / attr(object, "classes"), linetype = "dotted", colour = "grey50") +
    ggplot2::geom_line(colour = "#2166ac") +
    ggplot2::geom_point(colour = "#2166ac") +
    # the panel strip, placed under the axis, is the x-axis title: time and
    # fraction need different titles when both are shown
    ggplot2::facet_wrap(~axis, scales = "free_x", strip.position = "bottom") +
    ggplot2::scale_y_continuous(labels = function(v) paste0(round(100 * v), "%"), limits = c(0, 1)) +
    ggplot2::labs(x = NULL, y = "held-out accuracy",
                  title = "Early grasp recognition",
                  subtitle = sprintf("%s; dotted: chance", attr(object, "scheme"))) +
    ggplot2::theme_minimal(base_size = 11) +
    ggplot2::theme(strip.placement = "outside", strip.text = ggplot2::element_text(size = 11))
}
