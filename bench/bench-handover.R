# Hand-over reconstruction speed: frames reconstructed per second against a
# reference database of about 10,000 frames (target: >= 1,000 frames/s).
# Run from the repository root: Rscript bench/bench-handover.R
# The machine is shared: elapsed time depends on the load (printed), CPU time
# (user + system of this process) much less.
source("bench/_common.R")

g <- simulate_grasps(subjects = 10, grasps = bq(1:33, 1:3), objects = 1, trials = 1, seed = 11,
                     plant_overlong = FALSE)
subj <- unique(g$meta$subject)
ref <- g[g$meta$subject %in% subj[1:8]]
test <- g[!g$meta$subject %in% subj[1:8]]
n_ref <- sum(ref$meta$n_frames)
n_q <- sum(test$meta$n_frames)
cat(sprintf("reference: %d frames in %d recordings; query: %d frames in %d recordings (unseen subjects)\n",
            n_ref, length(ref), n_q, length(test)))

t_fit <- system.time(fit6 <- fit_handover(ref, n_markers = 6))[["elapsed"]]
cat(sprintf("fit_handover (6 markers, incl. ranking and forward kinematics of the reference): %.2f s elapsed\n", t_fit))
fit3 <- fit_handover(ref, n_markers = 3)
mk6 <- markers_from_angles(test, markers = fit6$markers)
mk3 <- markers_from_angles(test, markers = fit3$markers)

time_it <- function(f, reps = bq(3, 1)) {
  el <- cpu <- numeric(reps)
  for (i in seq_len(reps)) {
    t <- system.time(f())
    el[i] <- t[["elapsed"]]
    cpu[i] <- t[["user.self"]] + t[["sys.self"]]
  }
  c(elapsed = min(el), cpu = min(cpu))
}
row <- function(label, t) {
  cat(sprintf("%-40s %6.2f s elapsed = %6.0f frames/s (ratio to 1,000: %4.2f) | %6.2f s CPU = %6.0f frames/s\n",
              label, t[["elapsed"]], n_q / t[["elapsed"]], n_q / t[["elapsed"]] / 1000,
              t[["cpu"]], n_q / t[["cpu"]]))
}
cat("load average:", readLines("/proc/loadavg", warn = FALSE), "\n")
t6 <- time_it(function() predict(fit6, mk6))
row("reconstruct, 6 markers, neighbours = 256 (default)", t6)
bench_record("reconstruct, 6 markers, frames per CPU second", n_q / t6[["cpu"]], "1/s")
row("reconstruct, 3 markers, neighbours = 256", time_it(function() predict(fit3, mk3)))
fit6_128 <- fit_handover(ref, markers = fit6$markers, neighbours = 128)
row("reconstruct, 6 markers, neighbours = 128", time_it(function() predict(fit6_128, mk6)))
fit6_1024 <- fit_handover(ref, markers = fit6$markers, neighbours = 1024)
row("reconstruct, 6 markers, neighbours = 1024", time_it(function() predict(fit6_1024, mk6), reps = 1))
row("reconstruct from a grasps (incl. FK)", time_it(function() predict(fit6, test), reps = 1))

# the R transcription of the same regression (tests/testthat/helper-handover-reference.R), for the ratio
ref_env <- new.env(parent = asNamespace("handmotion"))
sys.source("tests/testthat/helper-handover-reference.R", envir = ref_env)
q <- do.call(rbind, mk6)
t_c <- time_it(function() lwr_predict(fit6$ref_x, fit6$ref_scores, q, 256, 1e-3, 1e-6))
t_r <- time_it(function() ref_env$lwr_predict_r(fit6$ref_x, fit6$ref_scores, q, 256, 1e-3, 1e-6),
               reps = 1)
cat(sprintf("LWR core, C engine vs R reference engine: %.2f s vs %.2f s CPU (speed-up %.1fx)\n",
            t_c[["cpu"]], t_r[["cpu"]], t_r[["cpu"]] / t_c[["cpu"]]))
bench_record("LWR core, R reference / C (CPU)", t_r[["cpu"]] / t_c[["cpu"]], "x")
cat("load average:", readLines("/proc/loadavg", warn = FALSE), "\n")
cat(sprintf("accuracy on the unseen subjects: 6 markers %.2f deg, 3 markers %.2f deg\n",
            handover_error(test, predict(fit6, test)), handover_error(test, predict(fit3, test))))
