# Benchmark of the classifiers and their evaluation (run from the repo root:
#   Rscript bench/classify.R
# BENCH_QUICK=1: 2 subjects x 6 types). Prints timings, the
# in-sample (thesis-style) and held-out accuracies of both classifiers on
# simulated HUST-like data, and the full leave-one-subject-out of the FPCA
# classifier on the default data on two workers.
source("bench/_common.R")

subjects <- as.integer(Sys.getenv("HM_BENCH_SUBJECTS", bq("6", "3")))
folds <- as.integer(Sys.getenv("HM_BENCH_FOLDS", "3"))
types <- bq(1:33, 1:6)
g <- simulate_grasps(subjects = subjects, grasps = types, objects = 1, trials = 2, seed = 1)
cat(sprintf("data: %d recordings, %d types, %d subjects\n", length(g), length(types), subjects))

timed <- function(expr) {
  t0 <- proc.time()[["elapsed"]]
  value <- expr
  list(value = value, seconds = proc.time()[["elapsed"]] - t0)
}

fit <- timed(fit_grasp_models(g, seed = 1))
cl_fpca <- timed(classify(fit$value, g))
lf_fit <- timed(fit_grasp_classifier(g, method = "last_frame", ncomp = 5))
cl_lf <- timed(classify(lf_fit$value, g))
acc <- function(cl) {
  p <- cl$predictions
  mean(as.character(p$predicted) == as.character(p$truth), na.rm = TRUE)
}
cat(sprintf("fit_grasp_models (33 types):        %7.2f s\n", fit$seconds))
cat(sprintf("classify, FPCA (%d x 33 projections): %7.2f s  (%.2f ms per recording x model)\n",
            length(g), cl_fpca$seconds, 1000 * cl_fpca$seconds / (length(g) * 33)))
cat(sprintf("fit_grasp_classifier(last_frame): %7.3f s\n", lf_fit$seconds))
cat(sprintf("classify, last frame:               %7.3f s\n", cl_lf$seconds))
cat(sprintf("ratio FPCA / last-frame (fit + classify): %.0f\n",
            (fit$seconds + cl_fpca$seconds) / (lf_fit$seconds + cl_lf$seconds)))
bench_record(sprintf("classify FPCA, %d recordings x %d models", length(g), length(fit$value)), cl_fpca$seconds, "s")
bench_record("classify FPCA / last-frame (fit + classify)",
             (fit$seconds + cl_fpca$seconds) / (lf_fit$seconds + cl_lf$seconds), "x")
cat(sprintf("in-sample accuracy: FPCA %.1f%%, last-frame PCA %.1f%%\n",
            100 * acc(cl_fpca$value), 100 * acc(cl_lf$value)))
print(distance_minima(distance_table(cl_fpca$value)))

ev_lf <- timed(evaluate_loso(g, "last_frame", fit_args = list(ncomp = 5)))
cat(sprintf("LOSO last-frame (%d folds): %.2f s; held-out %.1f%% vs in-sample %.1f%%\n",
            subjects, ev_lf$seconds, 100 * ev_lf$value$accuracy[["held_out"]],
            100 * ev_lf$value$accuracy[["in_sample"]]))
ev_fp <- timed(evaluate_loso(g, "fpca", fit_args = list(seed = 1), folds = folds, in_sample = FALSE))
cat(sprintf("grouped folds FPCA (%d folds): %.1f s; held-out %.1f%% vs in-sample %.1f%%\n",
            folds, ev_fp$seconds, 100 * ev_fp$value$accuracy[["held_out"]], 100 * acc(cl_fpca$value)))

# The full leave-one-subject-out of the FPCA classifier on the default data
# (30 folds, each refitting the 33 models without one subject), on two
# workers through the future framework (issue target: 60 s). Beside it, one
# fold refitted with the thesis' two-component mixtures, which the FPCA
# distance never reads (evaluate_loso() fits mixture_components = 1 for it): same predictions.
full <- simulate_grasps(subjects = bq(30, 4), grasps = bq(1:33, 1:4), seed = 1)
workers <- min(2L, future::availableCores())
old_plan <- future::plan(future::multisession, workers = workers)
ev_full <- timed(evaluate_loso(full, "fpca", fit_args = list(seed = 1), in_sample = FALSE))
future::plan(old_plan)
held <- full$meta$subject == full$meta$subject[1]
one_fold <- function(m) timed(fit_grasp_models(full[!held], seed = 1, mixture_components = m))$seconds
fold_k1 <- one_fold(1)
fold_k2 <- one_fold(2)
cat(sprintf("full FPCA LOSO, %d recordings, %d folds, %d workers: %.1f s (target 60 s); held out %.1f%%\n",
            length(full), length(unique(full$meta$subject)), workers, ev_full$seconds,
            100 * ev_full$value$accuracy[["held_out"]]))
cat(sprintf("one fold's refit, sequential: %.2f s with mixture_components = 1, %.2f s with the thesis' 2 (%.1fx)\n",
            fold_k1, fold_k2, fold_k2 / fold_k1))
bench_record(sprintf("full FPCA LOSO, %d folds, %d workers", length(unique(full$meta$subject)), workers),
             ev_full$seconds, "s")
bench_record("FPCA LOSO fold refit, 2 / 1 mixture components", fold_k2 / fold_k1, "x")
