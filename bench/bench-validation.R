# What validating objects where they are used costs the default path
# (issue 34 item 8): check_grasps() validates a grasps set at every verb
# (fields, meta, ids, DoF columns, frame counts, finite values) and the
# model checks re-read a fitted set's parts before generate()/project()/
# classify(). Timed on the default data (simulate_grasps()), and classify()
# with the checks against classify() with them replaced by no-ops.
#   Rscript bench/bench-validation.R     (BENCH_QUICK=1: 2 subjects)
source("bench/_common.R")

g <- if (bench_quick) simulate_grasps(subjects = 2, seed = 1) else simulate_grasps()
ms <- suppressWarnings(fit_grasp_models(g, seed = 1))
ns <- asNamespace("handmotion")
reps <- bq(20L, 3L)
per_call <- function(f) {
  t0 <- proc.time()[["elapsed"]]
  for (i in seq_len(reps)) f()
  (proc.time()[["elapsed"]] - t0) / reps
}
t_grasps <- per_call(function() ns$check_grasps(g))
t_models <- per_call(function() ns$check_grasp_models(ms, "models", "classify"))
t_classify <- per_call(function() classify(ms, g))
# the same classify() with the checks as no-ops
noop <- function(x, ...) invisible(x)
saved <- list(validate_grasps = ns$validate_grasps, check_grasp_models = ns$check_grasp_models,
              model_parts_fault = ns$model_parts_fault)
unlockBinding("validate_grasps", ns); unlockBinding("check_grasp_models", ns); unlockBinding("model_parts_fault", ns)
assign("validate_grasps", noop, ns); assign("check_grasp_models", noop, ns); assign("model_parts_fault", function(model) NULL, ns)
t_classify_unchecked <- per_call(function() classify(ms, g))
for (nm in names(saved)) assign(nm, saved[[nm]], ns)

cat(sprintf("data: %d recordings, %d values; %d models\n", length(g), sum(lengths(g$recordings)), length(ms)))
cat(sprintf("check_grasps(default data):        %6.1f ms\n", 1000 * t_grasps))
cat(sprintf("model-set check (%d models):        %6.1f ms\n", length(ms), 1000 * t_models))
cat(sprintf("classify(), with checks:           %6.3f s\n", t_classify))
cat(sprintf("classify(), checks as no-ops:      %6.3f s  (checks: %+.1f%%)\n", t_classify_unchecked,
            100 * (t_classify / t_classify_unchecked - 1)))
bench_record("check_grasps on the default data", 1000 * t_grasps, "ms")
bench_record("model-set check before classify", 1000 * t_models, "ms")
bench_record("classify overhead of the checks", 100 * (t_classify / t_classify_unchecked - 1), "%")
