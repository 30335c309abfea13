# The simulator's calibration, recomputed from the package's own outputs.
# data-raw/calibrate-simulator.R tunes the simulator's parameters until the
# pipeline run on the default data resembles the thesis' chapter 5; this file
# measures that resemblance independently: it runs the pipeline, computes every
# calibration target from the results, and only then lays the published values
# (thesis_results) beside them. The pipeline never sees a thesis number.

# How closely the default data reproduce the thesis' figures: runs the
# pipeline on `x` (by default simulate_grasps()) and recomputes each figure
# the simulator was calibrated against (Tables 5.1, 5.2, 5.7 and the two
# in-sample accuracies; with `held_out` also leave-subject-out accuracies).
# A maintainer's tool (data-raw/calibrate-simulator.R, the calibration tests);
# users read the outcome in ?simulate_grasps.
calibration_report <- function(x = NULL, models = NULL, last_frame = NULL, seed = 1,
                               held_out = FALSE, folds = 5) {
  call <- rlang::caller_env()
  held_out <- check_flag(held_out, "held_out", call = call)
  # (checked whether or not held_out uses it: a bad value is a mistake either way)
  folds <- check_whole(folds, "folds", min = 2, call = call)
  seed <- check_seed(seed, call = call)
  if (is.null(x)) x <- simulate_grasps()
  check_grasps(x, call = call)
  if (is.null(models)) models <- fit_grasp_models(x, seed = seed)
  if (!inherits(models, "grasp_models")) {
    hm_abort("{.arg models} must be a {.cls grasp_models} object from {.fn fit_grasp_models}, not {.obj_type_friendly {models}}.",
             "bad_input", argument = "models", call = call)
  }
  if (is.null(last_frame)) last_frame <- fit_grasp_classifier(x, method = "last_frame", k = 5)
  if (!inherits(last_frame, "last_frame_pca")) {
    hm_abort("{.arg last_frame} must be a {.cls last_frame_pca} object from {.code fit_grasp_classifier(method = \"last_frame\")}, not {.obj_type_friendly {last_frame}}.",
             "bad_input", argument = "last_frame", call = call)
  }
  ours <- calibration_measure(x, models, last_frame)
  loso <- NULL
  if (isTRUE(held_out)) {
    ev_lf <- evaluate_loso(x, "last_frame", fit_args = list(k = 5), folds = folds, seed = seed)
    ev_fp <- evaluate_loso(x, "fpca", fit_args = list(seed = seed), folds = folds, seed = seed)
    loso <- data.frame(classifier = c("last_frame", "fpca"),
                       in_sample = c(ours$accuracy[["last_frame"]], ours$accuracy[["fpca"]]),
                       held_out = unname(c(ev_lf$accuracy[["held_out"]], ev_fp$accuracy[["held_out"]])),
                       stringsAsFactors = FALSE)
    loso$lower <- loso$held_out < loso$in_sample
  }
  new_calibration_report(ours, loso)
}

# The calibration figures of one pipeline run, per type and overall. Used by
# calibration_report() and by data-raw/calibrate-simulator.R (no thesis value
# enters here).
calibration_measure <- function(x, models, last_frame) {
  s <- summary(models)
  cv <- cumulative_variance(last_frame)
  cl_fp <- classify(models, x)
  cl_lf <- classify(last_frame, x)
  types <- feix_order(unique(c(s$grasp, cv$grasp)))
  recall <- function(cl) {
    p <- cl$predictions
    ok <- as.character(p$truth) == as.character(p$predicted)
    ok[is.na(ok)] <- FALSE
    vapply(types, function(t) mean(ok[as.character(p$truth) == t]), numeric(1))
  }
  accuracy <- function(cl) {
    p <- cl$predictions[!is.na(cl$predictions$truth), ]
    mean(!is.na(p$predicted) & as.character(p$truth) == as.character(p$predicted))
  }
  per_type <- data.frame(grasp_id = match(types, feix_levels()), grasp = types,
                         target_frames = s$target_length[match(types, s$grasp)],
                         mean_var = s$mean_var[match(types, s$grasp)],
                         pc5 = cv$pc5[match(types, cv$grasp)],
                         recall_fpca = unname(recall(cl_fp)), recall_last_frame = unname(recall(cl_lf)),
                         stringsAsFactors = FALSE)
  list(types = per_type, accuracy = c(fpca = accuracy(cl_fp), last_frame = accuracy(cl_lf)),
       overall_mean_var = mean(per_type$mean_var, na.rm = TRUE))
}

# The tolerances of the calibration (issue 5): absolute, in the units of each
# figure (frames, percentage points, proportions).
calibration_tolerances <- function() {
  c(target_frames = 0, mean_var = 2, overall_mean_var = 1, pc5 = 0.05,
    accuracy_last_frame = 0.05, accuracy_fpca = 0.05)
}

new_calibration_report <- function(ours, loso = NULL) {
  th <- handmotion::thesis_results
  ty <- ours$types
  pick <- function(tab, col) tab[[col]][match(ty$grasp_id, tab$grasp_id)]
  ty$thesis_target_frames <- pick(th$table_5_1, "target_frames")
  ty$thesis_mean_var <- pick(th$table_5_2, "mean")
  ty$thesis_pc5 <- pick(th$table_5_7, "pc5")
  ty$thesis_recall_fpca <- pick(th$table_5_6_diagonal, "correct") / pick(th$table_5_6_diagonal, "total")
  ty$thesis_recall_last_frame <- pick(th$table_5_8_diagonal, "correct") / pick(th$table_5_8_diagonal, "total")
  ty <- ty[c("grasp_id", "grasp", "target_frames", "thesis_target_frames", "mean_var", "thesis_mean_var",
             "pc5", "thesis_pc5", "recall_fpca", "thesis_recall_fpca", "recall_last_frame",
             "thesis_recall_last_frame")]
  acc <- th$accuracy$accuracy[match(c("last_frame", "fpca"), th$accuracy$classifier)]
  tol <- calibration_tolerances()
  worst <- function(a, b) max(abs(a - b), na.rm = TRUE)
  targets <- data.frame(
    target = c("Table 5.1 target frames", "Table 5.2 mean variance per type", "Table 5.2 overall mean",
               "Table 5.7 pc5 per type", "Last-frame PCA accuracy", "FPCA accuracy"),
    ours = c(mean(ty$target_frames), mean(ty$mean_var), ours$overall_mean_var, mean(ty$pc5),
             ours$accuracy[["last_frame"]], ours$accuracy[["fpca"]]),
    thesis = c(mean(ty$thesis_target_frames), mean(ty$thesis_mean_var), mean(ty$thesis_mean_var),
               mean(ty$thesis_pc5), acc),
    tolerance = unname(tol),
    worst = c(worst(ty$target_frames, ty$thesis_target_frames), worst(ty$mean_var, ty$thesis_mean_var),
              abs(ours$overall_mean_var - mean(ty$thesis_mean_var)), worst(ty$pc5, ty$thesis_pc5),
              abs(ours$accuracy[["last_frame"]] - acc[1]), abs(ours$accuracy[["fpca"]] - acc[2])),
    stringsAsFactors = FALSE)
  # a small slack for floating point in the exact and rounded comparisons
  targets$ok <- !is.na(targets$worst) & targets$worst <= targets$tolerance + 1e-9
  structure(list(types = ty, targets = targets, held_out = loso), class = "calibration_report")
}

#' @export
print.calibration_report <- function(x, ...) {
  t <- x$targets
  cat(sprintf("<calibration_report> %d grasp type%s; %d of %d targets within tolerance\n",
              nrow(x$types), if (nrow(x$types) == 1) "" else "s", sum(t$ok), nrow(t)))
  show <- data.frame(target = t$target, ours = signif(t$ours, 4), thesis = signif(t$thesis, 4),
                     worst_diff = signif(t$worst, 3), tolerance = t$tolerance,
                     ok = ifelse(t$ok, "yes", "NO"), stringsAsFactors = FALSE)
  print(show, row.names = FALSE)
  if (!is.null(x$held_out)) {
    cat("Held-out (leave-subject-out) vs in-sample accuracy:\n")
    print(x$held_out, row.names = FALSE, digits = 3)
  }
  invisible(x)
}
