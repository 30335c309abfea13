# Recognition benchmark: the discriminant classifier against MASS::lda (the
# reference package, same features) for fit and prediction; the early
# recogniser's fit and its per-frame update() cost (target: under 0.1 ms per
# frame for 33 types); the weighted FPCA distance against the thesis'.
#
# Run from the repository root:  Rscript bench/bench-recognition.R  (BENCH_QUICK=1: seconds)
source("bench/_common.R")

g <- simulate_grasps(subjects = bq(30, 4), grasps = bq(1:33, 1:6), seed = 1)
cat(sprintf("data: %d recordings, %d types, %d subjects\n", length(g),
            length(unique(g$meta$grasp)), length(unique(g$meta$subject))))
timed <- function(expr, reps = 1L) {
  t0 <- proc.time()[["elapsed"]]
  for (i in seq_len(reps)) value <- expr
  list(value = value, seconds = (proc.time()[["elapsed"]] - t0) / reps)
}

# discriminant vs MASS::lda on the same feature matrix
F <- handmotion:::classifier_features(g, seq(0, 1, by = 0.125))
y <- droplevels(factor(g$meta$grasp))
ours_fit <- timed(handmotion:::fit_shrunk_lda(F, y), bq(3L, 1L))
mass_fit <- timed(MASS::lda(F, y, prior = rep(1 / nlevels(y), nlevels(y))), bq(3L, 1L))
ours_pred <- timed(handmotion:::shrunk_lda_scores(ours_fit$value, F), 20L)
mass_pred <- timed(predict(mass_fit$value, F)$class, 20L)
agree <- mean(ours_fit$value$classes[max.col(ours_pred$value)] == as.character(mass_pred$value))
cat(sprintf("fit:     shrinkage LDA %.3f s, MASS::lda %.3f s  (MASS / ours = %.1fx)\n",
            ours_fit$seconds, mass_fit$seconds, mass_fit$seconds / ours_fit$seconds))
cat(sprintf("predict: shrinkage LDA %.3f s, MASS::lda %.3f s  (MASS / ours = %.1fx); same class for %.1f%%\n",
            ours_pred$seconds, mass_pred$seconds, mass_pred$seconds / ours_pred$seconds, 100 * agree))
bench_record("discriminant fit, MASS::lda / ours", mass_fit$seconds / ours_fit$seconds, "x")
bench_record("discriminant predict, MASS::lda / ours", mass_pred$seconds / ours_pred$seconds, "x")

# the early recogniser: fit, and one live update
rec <- timed(fit_grasp_recognizer(g))
cat(sprintf("fit_grasp_recognizer: %.1f s for %d horizons\n", rec$seconds, rec$value$horizon))
bench_record("fit_grasp_recognizer", rec$seconds, "s")
# held out by subject at the report's five times: each fold fits only the
# five horizons those need, instead of every horizon of a streaming recogniser
workers <- min(2L, future::availableCores())
old_plan <- future::plan(future::multisession, workers = workers)
early <- timed(evaluate_early_recognition(g, ms = c(100, 200, 300, 500, 1000), fractions = NULL))
future::plan(old_plan)
cat(sprintf("evaluate_early_recognition, %d folds at 5 times, %d workers: %.1f s; 300 ms: %.1f%%\n",
            length(unique(g$meta$subject)), workers, early$seconds,
            100 * early$value$accuracy[early$value$value == 300]))
bench_record("early recognition LOSO at 5 times, 2 workers", early$seconds, "s")
r <- g$recordings[[1]]
n_streams <- bq(300L, 20L)
t0 <- proc.time()
for (k in seq_len(n_streams)) {
  st <- start_recognition(rec$value)
  for (t in seq_len(nrow(r))) p <- update(st, r[t, ])
}
el <- (proc.time() - t0)[["elapsed"]]
per_frame <- 1000 * el / (n_streams * nrow(r))
cat(sprintf("update(): %.3f ms per frame (%d types; target 0.1 ms: %s)\n", per_frame,
            length(rec$value$classes), if (per_frame <= 0.1) "met" else "MISSED"))
bench_record("recognition update per frame", per_frame, "ms")

# the weighted FPCA distance against the thesis' distance (same models)
ms <- fit_grasp_models(g, seed = 1)
plain <- timed(classify(ms, g))
w <- timed(fit_grasp_classifier(g, method = "weighted_fpca", models = ms))
weighted <- timed(classify(w$value, g))
cat(sprintf("classify: thesis FPCA %.2f s, weighted FPCA %.2f s (+ %.2f s to learn the weights); ratio %.2fx\n",
            plain$seconds, weighted$seconds, w$seconds, weighted$seconds / plain$seconds))
bench_record("classify weighted FPCA / thesis FPCA", weighted$seconds / plain$seconds, "x")
