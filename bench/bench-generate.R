# Generation benchmark: throughput in grasps per second for batches, and the
# latency of a single grasp. Targets on the 2-core reference machine:
# 100,000 or more grasps per second in batches; 1 ms or less for one grasp.
# Run from the repository root: Rscript bench/bench-generate.R
pkgload::load_all(".", quiet = TRUE)

g <- simulate_grasps(subjects = 30, grasps = 14, seed = 1)       # one type: Tripod
m <- fit_grasp_model(g, seed = 1)
cat(sprintf("model: %s, %d DoFs, L = %d frames, fitted on %d recordings\n",
            m$grasp, length(m$dofs), m$target_length, m$n_used))

for (n in c(1000L, 10000L, 50000L)) {
  r <- bench::mark(generate(m, n = n, seed = 1), iterations = 5, check = FALSE, filter_gc = FALSE)
  sec <- as.numeric(r$median)
  cat(sprintf("batch of %6d: median %.3f s -> %9.0f grasps/s (target 100,000: %s)\n",
              n, sec, n / sec, if (n / sec >= 1e5) "met" else "MISSED"))
}
r <- bench::mark(generate(m, n = 10000L, seed = 1, warp = FALSE), iterations = 5, check = FALSE,
                 filter_gc = FALSE)
cat(sprintf("batch of  10000 without warp: %9.0f grasps/s\n", 10000 / as.numeric(r$median)))

one <- bench::mark(generate(m, n = 1L), iterations = 500, check = FALSE, filter_gc = FALSE)
lat <- as.numeric(one$median) * 1000
cat(sprintf("single grasp: median %.3f ms, 90th percentile %.3f ms (target 1 ms: %s)\n",
            lat, as.numeric(stats::quantile(as.numeric(one$time[[1]]), 0.9)) * 1000, if (lat <= 1) "met" else "MISSED"))

# projection throughput (the classifier's inner loop): recordings per second
x <- simulate_grasps(subjects = 30, grasps = 1:33, objects = 3, trials = 3, seed = 2)
pr <- bench::mark(project(m, x, details = FALSE), iterations = 3, check = FALSE, filter_gc = FALSE)
sec <- as.numeric(pr$median)
cat(sprintf("projection of %d recordings onto one model: %.3f s (%.0f recordings/s); x 33 models = %.1f s\n",
            length(x), sec, length(x) / sec, 33 * sec))

# Elapsed times above suffer when other jobs share the cores; CPU time of
# this process for the same batches, with the load average at the time:
for (n in c(1000L, 10000L)) {
  t <- system.time(for (i in 1:5) generate(m, n = n))
  cpu <- (t[["user.self"]] + t[["sys.self"]]) / 5
  cat(sprintf("batch of %6d: %.3f s CPU -> %9.0f grasps per CPU second\n", n, cpu, n / cpu))
}
cat("load average:", tryCatch(readLines("/proc/loadavg"), error = function(e) "unknown"), "\n")
