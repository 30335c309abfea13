# Honest evaluation of the classifiers. The thesis classified the very
# recordings its models were fitted on (in-sample), which flatters both
# schemes. Here each subject (or group of subjects) is held out in turn: the
# models are refitted without it and its recordings classified, so every
# prediction is for a hand the models never saw. Both numbers are returned.

#' Held-out evaluation of a grasp classifier: by subject or by recording
#'
#' **Folds for any design.** With recordings of two or more subjects
#' (`split = "auto"`, the default) each fold holds out whole subjects: for
#' each subject, refits the models of `method` on the recordings of all
#' other subjects and classifies the held-out subject's recordings; the pooled
#' predictions give a held-out confusion matrix. The in-sample figure of the
#' thesis (fit and classify the same recordings) is computed alongside, so
#' both can be reported.
#'
#' A full LOSO with `method = "fpca"` or `"weighted_fpca"` refits all grasp
#' models once per subject (30 times 33 models for HUST: about a minute on
#' two cores for the default data). Its folds fit one Gaussian to the scores
#' (`mixture_components = 1`, no EM) unless `fit_args` sets it. With
#' `fit_args = list(distance = "residual")` (the thesis' eq. 4.4, which reads
#' only the models' mean curves and FPCs) the predictions are those of the
#' thesis' two-component models; the default likelihood distance scores
#' the FPC scores by a kernel density of the training scores, which the
#' mixtures do not enter (except for a type of fewer than three recordings).
#' `folds = n` is the cheaper option:
#' subjects are split at random (seeded) into `n` groups and each group is
#' held out in turn (leave-one-group-of-subjects-out), so only `n` refits are
#' needed; it is still subject-independent, slightly pessimistic because each
#' fit sees fewer subjects.
#'
#' With one subject (or `split = "recording"`) the folds hold out
#' recordings instead: `folds` (default 5) stratified folds, each label's
#' recordings dealt evenly round them (seeded by `seed`, so repeatable).
#' The held-out accuracy comes with a 95% Wilson score interval
#' (`$accuracy_ci`).
#'
#' Folds run with `future.apply::future_lapply()` (set your own
#' `future::plan()`; none is set here) with `future.seed = TRUE`, and show a
#' progress bar, one step per fold, through `progressr` (after 2 s, in
#' interactive sessions or when you set its handlers or `progressr.enable`; its look
#' follows [progressr::handlers()]; `options(handmotion.progress = FALSE)`
#' turns it off).
#'
#' Bookkeeping, never silent: unlabelled recordings are not used (counted in
#' `$n_unlabelled`); recordings without a subject are never held out but are
#' used for training (`$n_no_subject`); a held-out type absent from a fold's
#' training data cannot be predicted correctly and is listed in
#' `$folds$missing_types`; a type whose model fails to fit in a fold is listed
#' in `$folds$unfitted_types`; a fold whose fit fails leaves its recordings
#' without prediction (`$folds$error`, warning).
#'
#' @param x A [grasps()] object with `grasp` and `subject` metadata.
#' @param method `"fpca"` ([fit_grasp_models()] + projection distance),
#'   or `"last_frame"`, `"discriminant"` or `"weighted_fpca"`
#'   ([fit_grasp_classifier()] with that `method`); or a function that fits
#'   any classifier of the family ([summary.grasp_classifier()]) on a
#'   [grasps()] object, called as `method(train, ...)` with `fit_args` as
#'   its further arguments (e.g. [fit_grasp_recognizer]); the result's
#'   `method` is then the function's name.
#' @param fit_args A list of arguments for the fitting function (e.g.
#'   `list(ncomp = 5)` for last-frame PCA: the `...` of [fit_grasp_classifier()]).
#' @param subjects Subjects to hold out (default: all). Other subjects are
#'   always in the training set.
#' @param folds By subject: `NULL` for one fold per subject (LOSO), or a
#'   number `n` of subject groups. By recording: the number of folds
#'   (`NULL`: 5).
#' @param in_sample Also compute the in-sample (thesis) confusion matrix.
#' @param seed Seed for the random grouping of subjects or recordings into
#'   `folds`.
#' @param split `"auto"` (by subject when `x` has two or more subjects, else
#'   by recording), `"subject"` or `"recording"`.
#' @return An object of class `grasp_evaluation`: a list with `method`,
#'   `scheme`, `split`, `confusion` (pooled held-out [grasp_confusion()]),
#'   `accuracy_ci` (95% interval of the held-out accuracy), `in_sample`
#'   (in-sample `grasp_confusion` or `NULL`), `accuracy` (named: `held_out`,
#'   `in_sample`), `per_subject` (data frame: `subject`, `fold`, `n`,
#'   `correct`, `accuracy`), `folds` (data frame: `fold`, `subjects`,
#'   `n_train`, `n_test`, `missing_types`, `unfitted_types` (types whose model
#'   failed to fit in the fold, see [fit_grasp_models()]), `error`), `predictions`,
#'   `n_unlabelled`, `n_no_subject`. `summary()` gives both sets of metrics.
#' @seealso [classify()], [grasp_confusion()]
#' @export
#' @examples
#' set.seed(1)
#' recs <- lapply(1:24, function(i) matrix(rnorm(10 * 16, mean = i %% 2 * 40), 10, 16))
#' g <- grasps(recs, meta = data.frame(grasp = rep(c("Tripod", "Ring"), 12),
#'                                     subject = rep(paste0("s", 1:6), each = 4)))
#' ev <- evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 2))
#' ev
#' evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 2), folds = 3)$accuracy
evaluate_loso <- function(x, method = c("fpca", "last_frame", "discriminant", "weighted_fpca"), fit_args = list(), subjects = NULL,
                          folds = NULL, in_sample = TRUE, seed = 1, split = c("auto", "subject", "recording")) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  # a fitter function: its name is the method's in the result
  label <- if (is.function(method)) {
    if (is.symbol(substitute(method))) as.character(substitute(method)) else "custom"
  }
  if (!is.function(method)) method <- check_choice(method, arg = "method", call = call)
  in_sample <- check_flag(in_sample, "in_sample", call = call)
  seed <- check_seed(seed, call = call)
  # future.seed switches the session to L'Ecuyer-CMRG; give the caller back
  # the RNG kind and stream they had.
  old_rng <- save_rng()
  on.exit(restore_rng(old_rng), add = TRUE)
  if (!is.list(fit_args)) {
    hm_abort("{.arg fit_args} must be a list of arguments, not {.obj_type_friendly {fit_args}}.",
             "bad_input", argument = "fit_args", call = call)
  }
  unlabelled <- is.na(x$meta$grasp)
  # said once here, not once per fold (fit_quietly())
  warn_short_recordings(x, action = "evaluated")
  warn_few_recordings(x)
  if (all(unlabelled)) {
    hm_abort("{.arg x} has no labelled recordings to evaluate.", "no_labels", argument = "x", call = call)
  }
  x <- x[!unlabelled]
  subj <- x$meta$subject
  groups <- make_folds(x, split, folds, seed, subjects = subjects, call = call)

  # (recordings without a motion are said once for the set, not by every
  # fold's fit and projection)
  runs <- say_no_motion_once({
    fold_results <- with_progress_shown({
      p <- hm_progressor(length(groups))
      future.apply::future_lapply(seq_along(groups), function(f) {
        # inside a fold the package's long calls count nothing: the fold is
        # the step (on a worker, each inner fit would send its own steps back)
        local_counted_outside()
        res <- run_fold(x, groups[[f]], method, fit_args)
        p(sprintf("fold %d of %d", f, length(groups)))
        res
      }, future.seed = TRUE)
    })
    cl <- if (in_sample) classify(fit_quietly(x, method, fit_args), x)
    list(folds = fold_results, in_sample = cl)
  }, length(x))
  fold_results <- runs$folds

  predictions <- do.call(rbind, lapply(seq_along(fold_results), function(f) {
    d <- fold_results[[f]]$predictions
    if (nrow(d) > 0L) d$fold <- f
    d
  }))
  fold_table <- do.call(rbind, lapply(seq_along(fold_results), function(f) {
    r <- fold_results[[f]]
    data.frame(fold = f, subjects = names(groups)[f], n_train = r$n_train,
               n_test = r$n_test, missing_types = paste(r$missing_types, collapse = ","),
               unfitted_types = paste(r$unfitted_types, collapse = ","),
               error = r$error %||% NA_character_, stringsAsFactors = FALSE)
  }))
  failed <- !is.na(fold_table$error)
  if (any(failed)) {
    hm_warn(c("Fitting failed in {sum(failed)} fold{?s}: {.val {fold_table$fold[failed]}}.",
              i = "Their recordings have no prediction; see {.field folds$error}."),
            "fold_failed")
  }
  lev <- label_order(unique(as.character(x$meta$grasp)), levels(x$meta$grasp))
  held <- new_confusion(predictions$truth, predictions$predicted, levels = lev)
  ins <- NULL
  if (in_sample) {
    cl <- runs$in_sample
    ins <- new_confusion(cl$predictions$truth, cl$predictions$predicted, levels = lev)
  }
  structure(list(method = label %||% method, scheme = attr(groups, "scheme"), split = attr(groups, "split"),
                 confusion = held, in_sample = ins,
                 accuracy = c(held_out = confusion_accuracy(held),
                              in_sample = if (is.null(ins)) NA_real_ else confusion_accuracy(ins)),
                 accuracy_ci = accuracy_interval(sum(diag(held$table)), held$n),
                 per_subject = per_subject_accuracy(predictions),
                 folds = fold_table, predictions = predictions,
                 n_unlabelled = sum(unlabelled),
                 n_no_subject = if (attr(groups, "split") == "subject") sum(is.na(subj)) else 0L),
            class = "grasp_evaluation")
}

# Fit without the held-out subjects and classify them; failures are returned,
# not thrown, so one bad fold does not lose the others.
run_fold <- function(x, test_rows, method, fit_args) {
  train <- x[!test_rows]
  test <- x[test_rows]
  missing_types <- setdiff(unique(as.character(test$meta$grasp)), unique(as.character(train$meta$grasp)))
  out <- list(n_train = length(train), n_test = length(test),
              missing_types = label_order(missing_types, levels(x$meta$grasp)), error = NULL)
  fit <- tryCatch(fit_quietly(train, method, fit_args), error = function(e) e)
  # a fold where no type could be fitted has nothing to classify with
  if (inherits(fit, "grasp_models") && !length(fitted_models(fit))) {
    reasons <- failed_types(fit)
    fit <- simpleError(paste0("no grasp type could be fitted (", reasons$grasp[1], ": ", reasons$message[1], ")"))
  }
  if (inherits(fit, "error")) {
    out$error <- cli::ansi_strip(conditionMessage(fit))
    out$predictions <- data.frame(id = test$meta$id, subject = test$meta$subject,
                                  truth = test$meta$grasp, predicted = NA_character_,
                                  distance = NA_real_, stringsAsFactors = FALSE)
    return(out)
  }
  # a type whose model could not be fitted in this fold is recorded in the
  # fold table (unfitted_types) rather than warned about once per fold
  cl <- withCallingHandlers(classify(fit, test),
                            handmotion_warning_projection_failed = function(w) invokeRestart("muffleWarning"))
  out$unfitted_types <- unique(cl$failures$model)
  p <- cl$predictions
  p$predicted <- as.character(p$predicted)
  out$predictions <- p
  out
}

# fit_classifier() without the warnings evaluate_loso() gives once for the
# whole set (short recordings, types with few recordings).
fit_quietly <- function(x, method, fit_args) {
  withCallingHandlers(fit_classifier(x, method, fit_args),
                      handmotion_warning_short_recordings = function(w) invokeRestart("muffleWarning"),
                      # (the last-frame classifier's own warning about its PCs has no `grasp` field: kept)
                      handmotion_warning_few_recordings = function(w) if (!is.null(w$grasp)) invokeRestart("muffleWarning"))
}

confusion_accuracy <- function(cm) if (cm$n > 0) sum(diag(cm$table)) / cm$n else NA_real_

per_subject_accuracy <- function(pred) {
  pred$subject[is.na(pred$subject)] <- "(no subject)"
  ok <- !is.na(pred$predicted) & as.character(pred$truth) == as.character(pred$predicted)
  ok[is.na(ok)] <- FALSE
  subj <- unique(pred$subject)
  out <- data.frame(subject = subj,
                    fold = pred$fold[match(subj, pred$subject)],
                    n = as.integer(tabulate(match(pred$subject, subj), length(subj))),
                    correct = as.integer(tapply(ok, factor(pred$subject, levels = subj), sum)),
                    stringsAsFactors = FALSE)
  out$accuracy <- out$correct / out$n
  out
}

#' @export
print.grasp_evaluation <- function(x, ...) {
  method <- switch(x$method, fpca = "FPCA projection-distance", last_frame = "last-frame PCA",
                   discriminant = "shrinkage-LDA", weighted_fpca = "weighted FPCA-distance", x$method)
  cli::cat_line("<grasp_evaluation> ", method, " classifier, ", x$scheme)
  ci <- fmt_pct(x$accuracy_ci %||% c(NA_real_, NA_real_))
  held_out <- fmt_pct(x$accuracy[["held_out"]])
  n <- as.integer(x$confusion$n)
  cli::cat_line(cli::pluralize(
    "  held-out accuracy:  {held_out} (95% CI {ci[1]} to {ci[2]}; {n} recording{?s}, {nrow(x$per_subject)} subject{?s})"))
  if (!is.null(x$in_sample)) {
    cli::cat_line("  in-sample accuracy: ", fmt_pct(x$accuracy[["in_sample"]]),
                  " (the thesis' figure: fit and classify the same recordings)")
  }
  acc <- x$per_subject$accuracy
  if (length(acc) > 1) {
    cli::cat_line("  per-subject held-out accuracy: ", fmt_pct(min(acc)), " to ", fmt_pct(max(acc)),
                  " (median ", fmt_pct(stats::median(acc)), ")")
  }
  # what a fold or recording could not do, each line only when it happened
  counts <- c(missing = sum(nzchar(x$folds$missing_types)), unfit = sum(nzchar(x$folds$unfitted_types)),
              failed = sum(!is.na(x$folds$error)), unpredicted = as.integer(x$confusion$n_missing_predicted),
              unlabelled = as.integer(x$n_unlabelled), no_subject = as.integer(x$n_no_subject))
  lines <- c(missing = "  {n} fold{?s} held out a type absent from training",
             unfit = "  {n} fold{?s} could not fit every type's model (see $folds$unfitted_types)",
             failed = "  {n} fold{?s} failed to fit",
             unpredicted = "  {n} recording{?s} without prediction",
             unlabelled = "  {n} unlabelled recording{?s} not used",
             no_subject = "  {n} recording{?s} without subject used for training only")
  for (what in names(counts)[counts > 0]) {
    n <- counts[[what]]
    cli::cat_line(cli::pluralize(lines[[what]]))
  }
  invisible(x)
}

#' Metrics of a grasp-classifier evaluation, held-out beside in-sample
#'
#' @param object A [evaluate_loso()] result.
#' @param ... Unused.
#' @return A data frame (class `grasp_evaluation_summary`) with columns
#'   `.metric`, `class`, `held_out` and `in_sample` (`NA` when the in-sample
#'   fit was not computed), the rows of [summary.grasp_confusion()]; the
#'   shares are stored as fractions and printed as percentages.
#' @export
#' @examples
#' set.seed(1)
#' recs <- lapply(1:24, function(i) matrix(rnorm(10 * 16, mean = i %% 2 * 40), 10, 16))
#' g <- grasps(recs, meta = data.frame(grasp = rep(c("Tripod", "Ring"), 12),
#'                                     subject = rep(paste0("s", 1:6), each = 4)))
#' summary(evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 2)))
summary.grasp_evaluation <- function(object, ...) {
  h <- as.data.frame(unclass(summary(object$confusion)))
  out <- data.frame(.metric = h$.metric, class = h$class, held_out = h$.estimate, stringsAsFactors = FALSE)
  out$in_sample <- if (is.null(object$in_sample)) NA_real_ else summary(object$in_sample)$.estimate
  # prints the shares as percentages (R/thesis-table-print.R)
  class(out) <- c("grasp_evaluation_summary", class(out))
  out
}

#' Heatmap of the held-out confusion matrix of an evaluation
#'
#' @param object An [evaluate_loso()] result.
#' @param ... Passed to [autoplot.grasp_confusion()] (e.g. `normalise = TRUE`).
#' @return A ggplot object.
#' @export
#' @method autoplot grasp_evaluation
#' @examples
#' set.seed(1)
#' recs <- lapply(1:24, function(i) matrix(rnorm(10 * 16, mean = i %% 2 * 40), 10, 16))
#' g <- grasps(recs, meta = data.frame(grasp = rep(c("Tripod", "Ring"), 12),
#'                                     subject = rep(paste0("s", 1:6), each = 4)))
#' ggplot2::autoplot(evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 2)))
autoplot.grasp_evaluation <- function(object, ...) {
  autoplot.grasp_confusion(object$confusion, ...) +
    ggplot2::labs(title = sprintf("Held-out (%s) confusion matrix", object$scheme))
}
