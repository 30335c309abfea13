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
# classify() with the checks and with them as no-ops, interleaved (the
# median of paired runs is robust to the load drifting on a shared machine)
noop <- function(x, ...) invisible(x)
checked <- list(validate_grasps = ns$validate_grasps, check_grasp_models = ns$check_grasp_models,
                model_parts_fault = ns$model_parts_fault)
unchecked <- list(validate_grasps = noop, check_grasp_models = noop, model_parts_fault = function(model) NULL)
use <- function(fns) for (nm in names(fns)) {
  unlockBinding(nm, ns)
  assign(nm, fns[[nm]], ns)
  lockBinding(nm, ns)
}
time_once <- function() {
  t0 <- proc.time()[["elapsed"]]
  classify(ms, g)
  proc.time()[["elapsed"]] - t0
}
pairs <- t(vapply(seq_len(bq(10L, 2L)), function(i) {
  use(unchecked)
  off <- time_once()
  use(checked)
  c(on = time_once(), off = off)
}, numeric(2)))
t_classify <- stats::median(pairs[, "on"])
t_classify_unchecked <- stats::median(pairs[, "off"])
overhead <- stats::median(pairs[, "on"] / pairs[, "off"] - 1)

cat(sprintf("data: %d recordings, %d values; %d models\n", length(g), sum(lengths(g$recordings)), length(ms)))
cat(sprintf("check_grasps(default data):        %6.1f ms\n", 1000 * t_grasps))
cat(sprintf("model-set check (%d models):        %6.1f ms\n", length(ms), 1000 * t_models))
cat(sprintf("classify(), with checks:           %6.3f s\n", t_classify))
cat(sprintf("classify(), checks as no-ops:      %6.3f s  (median of paired ratios: %+.1f%%)\n",
            t_classify_unchecked, 100 * overhead))
bench_record("check_grasps on the default data", 1000 * t_grasps, "ms")
bench_record("model-set check before classify", 1000 * t_models, "ms")
bench_record("classify overhead of the checks", 100 * overhead, "%")
