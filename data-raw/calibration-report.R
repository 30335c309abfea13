# calibration_report(): how closely the default data reproduce the thesis'
# figures. A maintainer's tool of the simulator's calibration, not part of the
# installed package (issue 41: only what users need is installed).
# data-raw/calibrate-simulator.R sources it after pkgload::load_all(); the
# calibration tests (tests/testthat/test-calibration.R) source it through
# helper-calibration-report.R and skip where data-raw/ is absent. Its
# functions use the package's internals, so source it into an environment
# that sees them (load_all(), or a child of the namespace).
#
# The simulator's calibration, recomputed from the package's own outputs.
# data-raw/calibrate-simulator.R tunes the simulator's parameters until the
# pipeline run on the default data resembles the thesis' chapter 5; this file
# measures that resemblance independently: it runs the pipeline, computes every
# calibration target from the results, and only then lays the published values
# (thesis_results) beside them. The pipeline never sees a thesis number.

# How closely the default data reproduce the thesis' figures (internal: a
# maintainer's tool for data-raw/calibrate-simulator.R and the calibration
# tests; users read the outcome in ?simulate_grasps)
#
# Runs the pipeline on `x` (by default the package's default data,
# `simulate_grasps()`) and recomputes each figure the simulator was
# calibrated against (see the *Calibration* section of `?simulate_grasps`):
#
# * Table 5.1: the warping target length of every type (must equal the
#   thesis' exactly);
# * Table 5.2: the mean over DoFs of the variance explained by two FPCs, per
#   type (within 2 points) and overall (within 0.5 points);
# * Table 5.7: the cumulative variance of five last-frame PCs per type (within
#   0.05);
# * the in-sample accuracy of the last-frame PCA classifier (five PCs) and of
#   the FPCA classifier (within 4 points of the thesis' 64% and 35%, the
#   totals of the diagonals of Tables 5.8 and 5.6);
# * optionally (`held_out = TRUE`) the same two accuracies estimated by
#   leave-subject-out evaluation ([evaluate_loso()]), which must be lower than
#   the in-sample ones.
#
# Beside these tolerances it measures the *structure* the issue-14
# calibration aims at (element `structure`): the correlation of our per-type
# recalls with the thesis' (Tables 5.6 and 5.8, weighted by the confidence of
# each recovered diagonal: high 1, medium 1/2; aim at least 0.7), how many of
# the three groups of types the thesis names as hard to tell apart (section
# 5.2: adducted thumb, light tool and fixed hook; prismatic 4/3/2 finger and
# writing tripod; precision disk, precision sphere and tripod) have a
# confusion between two members among our ten largest off-diagonal cells of
# Table 5.6 (aim at least 2), and Table 5.3's four counts beside the thesis'
# (aim within 5 each). The thesis column of the confusion-group figure is
# measured on the thesis' own recovered Table 5.6 by the same rule: 1 of 3
# (its largest off-diagonal cells are types drawn to the palmar pinch
# model), so issue 14's aim of 2 asks more than the thesis' table shows.
#
# With `seeds`, the default data are simulated and the pipeline run once per
# seed; every figure is then the mean over seeds, each target also carries
# its spread over seeds (`sd`, `min`, `max` of ours, and `worst` the largest
# difference on any seed), a target is `ok` only if it holds for every seed,
# and `by_seed` lists each seed's figures.
#
# Fitting all 33 models of the default data takes a minute or more; pass
# already fitted `models` and `last_frame` to avoid refitting.
#
# @param x A labelled [grasps()] object; `NULL` simulates the default data.
# @param models A [fit_grasp_models()] result for `x`, or `NULL` to fit one
#   (with `seed`).
# @param last_frame A [fit_last_frame_pca()] result for `x` with `ncomp = 5`, or
#   `NULL` to fit one.
# @param seed Seed of the model fits.
# @param held_out Also run the leave-subject-out evaluations (slow for the
#   FPCA classifier: one refit of every model per fold).
# @param folds Number of subject groups held out in turn when `held_out`
#   (`NULL` for one fold per subject).
# @param seeds `NULL`, or several seeds of [simulate_grasps()]: run the
#   pipeline on the default data of each (then `x`, `models` and
#   `last_frame` must be `NULL`) and report the mean and spread over seeds.
#   Each seed takes a minute or more.
# @return An object of class `calibration_report`: a list with `types` (one
#   row per type: our `target_frames`, `mean_var`, `pc5`, `recall_fpca`,
#   `recall_last_frame`, each beside the thesis' value), `targets` (one row per
#   calibration target: `target`, `ours`, `thesis`, `tolerance`, `worst`
#   (largest absolute difference, for per-type targets) and `ok`; with
#   `seeds` also `sd`, `min`, `max`), `structure` (one row per structure
#   figure: `figure`, `ours`, `thesis`, `aim`, `ok`; with `seeds` also `sd`,
#   `min`, `max`), `by_seed` (with `seeds`: one row per seed and figure) and
#   `held_out` (data frame of held-out and in-sample accuracies, or `NULL`).
# @examples
# g <- simulate_grasps(subjects = 3, grasps = c(9, 22), objects = 2, trials = 2)
# rep <- calibration_report(g)
# rep$targets
calibration_report <- function(x = NULL, models = NULL, last_frame = NULL, seed = 1,
                               held_out = FALSE, folds = 5, seeds = NULL) {
  call <- rlang::caller_env()
  held_out <- check_flag(held_out, "held_out", call = call)
  # (checked whether or not held_out uses it: a bad value is a mistake either way)
  folds <- check_whole(folds, "folds", min = 2, call = call)
  seed <- check_seed(seed, call = call)
  if (!is.null(seeds)) {
    return(calibration_report_seeds(seeds, x, models, last_frame, seed, held_out, call))
  }
  if (is.null(x)) x <- simulate_grasps()
  check_grasps(x, call = call)
  if (is.null(models)) models <- fit_grasp_models(x, seed = seed, distance = "residual")
  if (!inherits(models, "grasp_models")) {
    hm_abort("{.arg models} must be a {.cls grasp_models} object from {.fn fit_grasp_models}, not {.obj_type_friendly {models}}.",
             "bad_input", argument = "models", call = call)
  }
  if (is.null(last_frame)) last_frame <- fit_grasp_classifier(x, method = "last_frame", ncomp = 5)
  if (!inherits(last_frame, "last_frame_pca")) {
    hm_abort("{.arg last_frame} must be a {.cls last_frame_pca} object from {.code fit_grasp_classifier(method = \"last_frame\")}, not {.obj_type_friendly {last_frame}}.",
             "bad_input", argument = "last_frame", call = call)
  }
  ours <- calibration_measure(x, models, last_frame)
  loso <- NULL
  if (isTRUE(held_out)) {
    ev_lf <- evaluate_loso(x, "last_frame", fit_args = list(ncomp = 5), folds = folds, seed = seed)
    ev_fp <- evaluate_loso(x, "fpca", fit_args = list(seed = seed, distance = "residual"), folds = folds, seed = seed)
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
  types <- label_order(unique(c(s$grasp, cv$grasp)))
  accuracy <- function(cl) {
    p <- cl$predictions[!is.na(cl$predictions$truth), ]
    mean(!is.na(p$predicted) & as.character(p$truth) == as.character(p$predicted))
  }
  per_type <- data.frame(grasp_id = match(types, feix_levels()), grasp = types,
                         target_frames = s$target_length[match(types, s$grasp)],
                         mean_var = s$mean_var[match(types, s$grasp)],
                         pc5 = cv$pc5[match(types, cv$grasp)],
                         recall_fpca = per_type_recall(cl_fp, types),
                         recall_last_frame = per_type_recall(cl_lf, types),
                         stringsAsFactors = FALSE)
  truth <- factor(as.character(cl_fp$predictions$truth), levels = types)
  confusion <- unclass(table(truth = truth,
                             predicted = factor(as.character(cl_fp$predictions$predicted), levels = types)))
  list(types = per_type, accuracy = c(fpca = accuracy(cl_fp), last_frame = accuracy(cl_lf)),
       overall_mean_var = mean(per_type$mean_var, na.rm = TRUE), confusion_fpca = confusion,
       minima = distance_minima(distance_table(cl_fp)))
}

# Share of each type's recordings in `types` that the classification `cl`
# gives their true type (a recording left unclassified counts as wrong).
per_type_recall <- function(cl, types) {
  p <- cl$predictions
  ok <- as.character(p$truth) == as.character(p$predicted)
  ok[is.na(ok)] <- FALSE
  unname(vapply(types, function(t) mean(ok[as.character(p$truth) == t]), numeric(1)))
}

confusion_groups_found <- function(conf, groups = thesis_confusion_groups(), top = 10L) {
  sum(confusion_groups_hit(conf, groups, top))
}

# The structure figures of one measurement (see calibration_report()).
calibration_structure <- function(ours) {
  th <- handmotion::thesis_results
  ty <- ours$types
  w <- function(conf) unname(c(high = 1, medium = 0.5, low = 0.25)[conf])
  recall_cor <- function(our, tab) {
    d <- tab[match(ty$grasp_id, tab$grasp_id), ]
    thesis <- d$correct / d$total
    ok <- is.finite(our) & is.finite(thesis)
    if (sum(ok) < 3L) return(NA_real_)
    stats::cov.wt(cbind(our[ok], thesis[ok]), wt = w(d$confidence[ok]) / sum(w(d$confidence[ok])),
                  cor = TRUE)$cor[1, 2]
  }
  cl <- th$table_5_3_claims
  claim <- function(nm) cl$thesis[cl$claim == nm]
  mn <- ours$minima
  data.frame(
    figure = c("Table 5.6 per-type recall, correlation with the thesis",
               "Table 5.8 per-type recall, correlation with the thesis",
               "Thesis confusion groups among our 10 largest off-diagonal cells (of 3)",
               "Table 5.3: models closest to their own type",
               "Table 5.3: types closest to their own model",
               "Table 5.3: both at once",
               "Table 5.3: types closest to the most attracting model"),
    ours = c(recall_cor(ty$recall_fpca, th$table_5_6_diagonal),
             recall_cor(ty$recall_last_frame, th$table_5_8_diagonal),
             confusion_groups_found(ours$confusion_fpca),
             mn$model_min_own_type, mn$type_min_own_model, mn$both, mn$n_attracted),
    thesis = c(1, 1, confusion_groups_found(thesis_confusion_fpca()), claim("model_min_own_type"),
               claim("type_min_own_model"), claim("both"), claim("n_attracted")),
    aim = c("at least 0.7", "at least 0.7", "at least 2", rep("within 5", 4)),
    stringsAsFactors = FALSE)
}

structure_ok <- function(st) {
  ifelse(st$aim == "at least 0.7", st$ours >= 0.7,
         ifelse(st$aim == "at least 2", st$ours >= 2, abs(st$ours - st$thesis) <= 5))
}

# calibration_report(seeds = ): one pipeline run per seed, then the mean and
# spread over seeds of every figure.
calibration_report_seeds <- function(seeds, x, models, last_frame, seed, held_out, call) {
  if (!is.null(x) || !is.null(models) || !is.null(last_frame)) {
    hm_abort("With {.arg seeds}, {.arg x}, {.arg models} and {.arg last_frame} must be {.code NULL}: each seed's default data are simulated and fitted.",
             "bad_input", argument = "seeds", call = call)
  }
  if (!is.numeric(seeds) || length(seeds) < 1L || anyNA(seeds) || any(seeds != round(seeds)) ||
      anyDuplicated(seeds)) {
    hm_abort("{.arg seeds} must be distinct whole numbers.", "bad_input", argument = "seeds", call = call)
  }
  if (isTRUE(held_out)) {
    hm_abort("{.arg held_out} is not available with {.arg seeds}; run it for one seed.", "bad_input",
             argument = "held_out", call = call)
  }
  reps <- lapply(seeds, function(s) {
    g <- simulate_grasps(seed = s)
    calibration_report(g, models = fit_grasp_models(g, seed = seed, distance = "residual"), last_frame = fit_last_frame_pca(g, ncomp = 5))
  })
  calibration_combine(reps, seeds)
}

# Mean and spread over several single-seed reports.
calibration_combine <- function(reps, seeds) {
  ty <- reps[[1]]$types
  num <- vapply(ty, is.numeric, logical(1)) & names(ty) != "grasp_id"
  cols <- function(f) do.call(cbind, lapply(reps, f))   # one column per seed
  for (nm in names(ty)[num]) ty[[nm]] <- rowMeans(cols(function(r) r$types[[nm]]))
  # element `el` of the first report with `ours` replaced by its mean over
  # seeds, its spread beside it, and `ok` only where every seed is ok
  over_seeds <- function(el) {
    tab <- reps[[1]][[el]]
    v <- cols(function(r) r[[el]]$ours)
    tab$ours <- rowMeans(v)
    tab$sd <- apply(v, 1L, stats::sd)
    tab$min <- apply(v, 1L, min)
    tab$max <- apply(v, 1L, max)
    tab$ok <- Reduce(`&`, lapply(reps, function(r) r[[el]]$ok))
    tab
  }
  tg <- over_seeds("targets")
  tg$worst <- apply(cols(function(r) r$targets$worst), 1L, max)
  st <- over_seeds("structure")
  by_seed <- do.call(rbind, lapply(seq_along(reps), function(i) {
    r <- reps[[i]]
    rbind(data.frame(seed = seeds[i], figure = r$targets$target, ours = r$targets$ours,
                     worst = r$targets$worst, ok = r$targets$ok, stringsAsFactors = FALSE),
          data.frame(seed = seeds[i], figure = r$structure$figure, ours = r$structure$ours,
                     worst = NA_real_, ok = r$structure$ok, stringsAsFactors = FALSE))
  }))
  structure(list(types = ty, targets = tg, structure = st, by_seed = by_seed, held_out = NULL,
                 seeds = seeds), class = "calibration_report")
}

# The tolerances of the calibration (issue 14): absolute, in the units of
# each figure (frames, percentage points, proportions).
calibration_tolerances <- function() {
  c(target_frames = 0, mean_var = 2, overall_mean_var = 0.5, pc5 = 0.05,
    accuracy_last_frame = 0.04, accuracy_fpca = 0.04)
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
  st <- calibration_structure(ours)
  st$ok <- !is.na(st$ours) & structure_ok(st)
  structure(list(types = ty, targets = targets, structure = st, by_seed = NULL, held_out = loso),
            class = "calibration_report")
}

print.calibration_report <- function(x, ...) {
  t <- x$targets
  multi <- !is.null(x$seeds)
  cat(sprintf("<calibration_report> %d grasp type%s%s; %d of %d targets within tolerance%s\n",
              nrow(x$types), if (nrow(x$types) == 1) "" else "s",
              if (multi) sprintf(", %d seeds (mean and spread over seeds)", length(x$seeds)) else "",
              sum(t$ok), nrow(t), if (multi) " on every seed" else ""))
  show <- data.frame(target = t$target, ours = signif(t$ours, 4), thesis = signif(t$thesis, 4),
                     worst_diff = signif(t$worst, 3), tolerance = t$tolerance,
                     ok = ifelse(t$ok, "yes", "NO"), stringsAsFactors = FALSE)
  if (multi) {
    show$sd <- signif(t$sd, 2)
    show$range <- sprintf("%s-%s", signif(t$min, 4), signif(t$max, 4))
  }
  print(show, row.names = FALSE)
  st <- x$structure
  if (!is.null(st)) {
    cat("Structure (per-type recalls, confusions, Table 5.3 counts):\n")
    sh <- data.frame(figure = st$figure, ours = signif(st$ours, 3), thesis = st$thesis, aim = st$aim,
                     ok = ifelse(st$ok, "yes", "NO"), stringsAsFactors = FALSE)
    if (multi) sh$range <- sprintf("%s-%s", signif(st$min, 3), signif(st$max, 3))
    print(sh, row.names = FALSE)
  }
  if (!is.null(x$held_out)) {
    cat("Held-out (leave-subject-out) vs in-sample accuracy:\n")
    print(x$held_out, row.names = FALSE, digits = 3)
  }
  invisible(x)
}
