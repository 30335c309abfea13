# Your own glove (issue 33): the costs a researcher with a data glove waits
# for, on the simulator's raw-count protocol shaped like a lab's study (one
# person, six objects, 28 trials each = 168 recordings of 15 raw channels at
# 100 Hz, about 1 s rest and 1 s hold around each grasp). Target: fitting all
# models for 168 recordings in 3 s or less. Also: finding the motion in every
# recording, calibrating, and the held-out FPCA evaluation (5 folds).
#
# Run from the repository root after `R CMD INSTALL --no-multiarch .`:
#   Rscript bench/bench-glove.R      (BENCH_QUICK=1: 2 objects x 6 trials, seconds)

source("bench/_common.R")
cat(sprintf("%s; load average %s on %d cores\n\n", bench_build, load_avg(), parallel::detectCores()))

objects <- c(bottle = 1, mug = 9, ball = 17, pen = 22, card = 28, key = 31)
raw <- simulate_grasps(subjects = 1, grasps = objects[seq_len(bq(6, 2))], objects = 1, trials = bq(28, 6),
                       rate = 100, glove = "resistive", rest = 1, hold = 1, stuck = "thumb_cross",
                       plant_overlong = FALSE, seed = 3)
time_it <- function(label, expr, target = NA) {
  t <- system.time(value <- force(expr))
  cat(sprintf("%-44s %6.2f s elapsed, %6.2f s CPU%s\n", label, t[["elapsed"]],
              t[["user.self"]] + t[["sys.self"]],
              if (is.na(target)) "" else sprintf("  (target %g s: %s)", target,
                                                  if (t[["elapsed"]] <= target) "met" else "NOT met")))
  bench_record(label, t[["elapsed"]], "s")
  invisible(value)
}

cat(sprintf("%d recordings of %d channels\n", length(raw), length(raw$dofs)))
m <- time_it("find_motion(), every recording", find_motion(raw))
time_it("calibrate(), nominal map", calibrate(raw))
ms <- time_it(sprintf("fit_grasp_models(), %d recordings", length(raw)), fit_grasp_models(raw, seed = 1), target = 3)
s <- summary(ms)
cat(sprintf("  recordings kept by the thesis model: %d of %d\n", sum(s$n_used), sum(s$n_input)))
bench_record("share kept", sum(s$n_used) / sum(s$n_input), "fraction")
ev <- time_it("evaluate_loso(method = 'fpca'), 5 folds", evaluate_loso(raw, method = "fpca", in_sample = FALSE))
cat(sprintf("  held-out FPCA accuracy: %.1f%% (95%% CI %.1f%% to %.1f%%)\n", 100 * ev$accuracy[["held_out"]],
            100 * ev$accuracy_ci[["lower"]], 100 * ev$accuracy_ci[["upper"]]))
bench_record("FPCA held-out accuracy", ev$accuracy[["held_out"]], "fraction")
