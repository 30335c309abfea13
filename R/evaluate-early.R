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
#' Folds run through `future.apply` (set a `future::plan()` to use several
#' cores). The folds are those of [evaluate_loso()]: by subject with two or
#' more subjects, else stratified folds of recordings (`split`).
#'
#' **Recordings that start at rest.** When the recordings are mostly still
#' (the rule of `fit_grasp_model(motion = "auto")`), time counts from the
#' motion's onset, as a live stream sees it: an onset detector fitted on
#' each fold's training recordings (their joint speed; see [find_motion()])
#' finds it in every held-out recording, so "after 300 ms" means 300 ms of
#' motion.
#'
#' @param x A labelled [grasps()] object.
#' @param ms Times since the recording (or its motion) began, in
#'   milliseconds, or `NULL`.
#' @param fractions Fractions of each recording's length, or `NULL`. Each
#'   fold fits the recogniser's discriminants only at the horizons these
#'   need (a few for `ms` alone), the same fits [fit_grasp_recognizer()]
#'   makes at those horizons.
#' @param folds,seed,split As in [evaluate_loso()]: `folds` `NULL` is one
#'   fold per subject, or 5 folds of recordings.
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
  groups <- make_folds(x, split, folds, seed, call = call)
  p <- progressr::progressor(steps = length(groups))
  parts <- future.apply::future_lapply(seq_along(groups), function(f) {
    test <- groups[[f]]
    train <- x[!test]
    te <- x[test]
    # recordings that rest before the grasp: time counts from the onset the
    # training recordings' detector finds in each held-out recording
    det <- if (resolve_motion(train, "auto") == "trim") fit_onset_detector(train)
    train <- from_onset(train, det)
    te <- from_onset(te, det)
    # frames seen by every held-out recording at each time and fraction
    views <- c(lapply(ms, function(v) {
      list(scale = "ms", value = v,
           seen = rep(max(1L, as.integer(round(v * te$rate / 1000))), length(te$recordings)))
    }), lapply(fractions, function(v) {
      list(scale = "fraction", value = v, seen = pmax(1L, as.integer(round(v * te$meta$n_frames))))
    }))
    H <- recognizer_horizon(train, rec_args$horizon, call)
    # only the horizons these views need (a full recogniser fits all H)
    needed <- sort(unique(pmin(unlist(lapply(views, `[[`, "seen")), H)))
    rec <- recognizer_fit(train, check_training_labels(train, call = call), at, H, needed)
    truth <- as.character(te$meta$grasp)
    out <- do.call(rbind, lapply(views, function(v) {
      hit <- top_class(rec$classes, recognizer_scores(rec, te, v$seen)) == truth
      data.frame(scale = v$scale, value = v$value, correct = sum(hit), n = length(truth), frames = sum(v$seen))
    }))
    p(sprintf("fold %d of %d", f, length(groups)))
    out
  }, future.seed = TRUE)
  all <- do.call(rbind, parts)
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

#' @export
print.early_recognition <- function(x, ...) {
  cat(sprintf("<early_recognition> %d classes, held out: %s\n",
              attr(x, "classes"), attr(x, "scheme")))
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
