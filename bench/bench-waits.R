# What a user waits for (issue 36), on the default data (seed 1: 30 subjects x
# 33 types, 8910 recordings), each beside the former R path where it is kept
# (tests/testthat/helper-*.R) so that the figures are also ratios:
# * classify(models, g), FPCA residual distance: target 1 s (the kernel reads
#   the recordings in place; the former path stacked them and built the warp
#   index in R); beside it the likelihood distance, the set's default;
# * evaluate_early_recognition(g), leave-one-subject-out, 2 workers: target 30 s;
# * evaluate_generation() of two model sets (thesis, copula; reps = 5), fitted
#   on subjects 1-20 and measured on 21-30: target 10 s (beside it the former
#   MMD test on one type's samples).
# Run from the repository root: Rscript bench/bench-waits.R (BENCH_QUICK=1:
# 4 subjects x 4 types, seconds).
source("bench/_common.R")
for (f in c("helper-project-reference.R", "helper-copula.R")) source(file.path("tests/testthat", f))

g <- simulate_grasps(subjects = bq(30, 4), grasps = bq(1:33, 1:4), seed = 1)
ms <- fit_grasp_models(g, seed = 1)
timed <- function(expr) {
  st <- system.time(value <- expr)
  list(value = value, elapsed = st[["elapsed"]], cpu = cpu_of(st))
}
best_of <- function(n, f) {
  runs <- lapply(seq_len(n), function(i) f())
  runs[[which.min(vapply(runs, `[[`, numeric(1), "elapsed"))]]
}
cat(sprintf("data: %d recordings, %d models\n", length(g), length(ms)))

# classification. Issue 36's target is the residual distance's (the thesis'
# eq. 4.4, which the former R path computes); the set's default distance is
# the likelihood (scores under the type's kernel density as well), timed
# beside it.
mr <- fit_grasp_models(g, seed = 1, distance = "residual")
cl <- best_of(3, function() timed(classify(mr, g)))
old <- timed(vapply(fitted_models(mr), function(m) project_reference(m, g)$distance * sqrt(m$target_length - 1),
                    numeric(length(g))))
same <- identical(as.character(cl$value$predictions$predicted),
                  colnames(old$value)[max.col(-old$value, ties.method = "first")])
cat(sprintf("classify, FPCA residual distance: %.2f s elapsed (%.2f s CPU; target 1 s: %s); former R path %.2f s (%.1fx); distances within %.1e relative, same predictions: %s\n",
            cl$elapsed, cl$cpu, if (cl$elapsed <= 1) "met" else "MISSED", old$elapsed, old$elapsed / cl$elapsed,
            max(abs(cl$value$distances - old$value) / old$value), same))
bench_record("classify FPCA, default data", cl$elapsed, "s")
bench_record("classify FPCA, former R path / kernel", old$elapsed / cl$elapsed, "x")
cll <- best_of(3, function() timed(classify(ms, g)))
cat(sprintf("classify, FPCA likelihood distance (the default): %.2f s elapsed (%.2f s CPU), %.1fx the residual's\n",
            cll$elapsed, cll$cpu, cll$elapsed / cl$elapsed))
bench_record("classify FPCA likelihood, default data", cll$elapsed, "s")

# early recognition on two workers (forked: the recordings are not copied)
workers <- min(2L, future::availableCores())
forked <- if (future::supportsMulticore()) future::multicore else future::multisession
future::plan(forked, workers = workers)  # (plan() reads its strategy unevaluated: named above)
er <- timed(evaluate_early_recognition(g))
future::plan("sequential")
cat(sprintf("evaluate_early_recognition, LOSO, %d workers: %.1f s elapsed (%.1f s CPU in the main process; target 30 s: %s); 1 s: %.1f%%\n",
            workers, er$elapsed, er$cpu, if (er$elapsed <= 30) "met" else "MISSED",
            100 * er$value$accuracy[er$value$scale == "ms" & er$value$value == 1000]))
bench_record("early recognition LOSO, 2 workers", er$elapsed, "s")

# naturalness of two model sets
sn <- as.integer(sub("^S", "", g$meta$subject))
cut_at <- floor(2 * max(sn) / 3)
train <- g[sn <= cut_at]
held <- g[sn > cut_at]
sets <- list(thesis = fit_grasp_models(train, seed = 1), copula = fit_grasp_models(train, seed = 1, dependence = "copula"))
ev <- timed(evaluate_generation(sets, held, train, reps = 5))
cat(sprintf("evaluate_generation, 2 sets, reps 5: %.1f s elapsed (%.1f s CPU; target 10 s: %s)\n",
            ev$elapsed, ev$cpu, if (ev$elapsed <= 10) "met" else "MISSED"))
bench_record("evaluate_generation, 2 sets, reps 5", ev$elapsed, "s")
# one type's MMD test, quadratic forms against the former indexing
ty <- held$meta$grasp == held$meta$grasp[1]
Z <- scale(generation_features(held[ty]))
Z[!is.finite(Z)] <- 0
bw <- stats::median(stats::dist(Z))
X <- Z[sample.int(nrow(Z), nrow(Z), replace = TRUE), , drop = FALSE] + 0.1
new <- best_of(3, function() timed(withr::with_seed(1, mmd_test(X, Z, bw))))
ref <- timed(withr::with_seed(1, mmd_test_reference(X, Z, bw)))
cat(sprintf("one MMD test (%d + %d recordings, 200 permutations): %.3f s, former %.3f s (%.1fx), same p-value: %s\n",
            nrow(X), nrow(Z), new$elapsed, ref$elapsed, ref$elapsed / max(new$elapsed, 1e-3),
            identical(new$value$p, ref$value$p)))
bench_record("MMD test, former / quadratic forms", ref$elapsed / max(new$elapsed, 1e-3), "x")
cat(sprintf("load average %s\n", format(load_avg())))
