# Benchmark of the HUST-like simulator: time to generate the full default set
# (30 subjects x 33 types x 3 objects x 3 trials = 8910 recordings) and a
# per-recording figure. Run from the package root:
#   Rscript bench/simulate-grasps.R   (BENCH_QUICK=1: 6 subjects, seconds)
source("bench/_common.R")

subjects <- bq(30, 6)
full <- bench::mark(simulate_grasps(subjects = subjects), iterations = bq(3, 1), check = FALSE, memory = FALSE)
small <- bench::mark(simulate_grasps(subjects = 3, grasps = 1:3), iterations = bq(10, 2), check = FALSE,
                     memory = FALSE)
g <- simulate_grasps(subjects = subjects)
frames <- sum(g$meta$n_frames)
med_full <- as.numeric(full$median)
cat(sprintf("full default set: %d recordings, %d frames, median %.2f s (goal < 3 s, limit 10 s)\n",
            length(g), frames, med_full))
cat(sprintf("  per recording: %.1f us; per frame: %.2f us\n", 1e6 * med_full / length(g), 1e6 * med_full / frames))
cat(sprintf("small set (3 subjects x 3 types x 3 x 3 = 81 recordings): median %.3f s\n",
            as.numeric(small$median)))
cat(sprintf("ratio full / small: %.1f (recordings ratio %.1f)\n",
            med_full / as.numeric(small$median), length(g) / 81))
cat(sprintf("ratio to the 10 s limit: %.2f\n", med_full / 10))
bench_record(sprintf("simulate %d recordings", length(g)), med_full, "s")
