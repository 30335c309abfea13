# Generation benchmark: throughput in grasps per second for batches of
# 1 to 100,000 grasps, the latency of a single grasp, and the memory of the
# largest batch. Targets on the 2-core reference machine: 100,000 or more
# grasps per second in batches; 1 ms or less for one grasp.
#
# Run from the repository root:  Rscript bench/bench-generate.R  (BENCH_QUICK=1: seconds)
#
# Throughput is given as grasps per elapsed second and per CPU second of
# this process: on a shared machine other jobs inflate elapsed time, CPU time
# is what generation itself costs. Batches are timed back to back, the
# previous batch dropped first, so each figure includes collecting the
# garbage of the batch before (what a loop of generate() calls pays).
source("bench/_common.R")
loadavg <- function() tryCatch(readLines("/proc/loadavg"), error = function(e) "unknown")

ms <- fit_grasp_models(simulate_grasps(grasps = c(11, 17), subjects = bq(30, 6)), seed = 1)
m <- ms[[1]]
cat(sprintf("model set: %s; first model %s: %d DoFs, L = %d frames, %d FPCs, %d-component mixtures\n",
            paste(vapply(ms, `[[`, "", "grasp"), collapse = ", "), m$grasp, length(m$dofs),
            m$target_length, m$settings$ncomp, m$settings$mixture_components))

# Throughput of f() (a batch of `size` grasps a call), called back to back
# for at least `min_time` seconds after one warm-up call: total grasps over
# total elapsed and total CPU time, so R's garbage collections are included
# in proportion (a median would hide them: one batch in several pays for a
# full collection).
throughput <- function(f, size, min_time = bq(1.5, 0.1), min_calls = bq(3L, 1L)) {
  x <- f()
  x <- NULL
  calls <- 0L
  t0 <- proc.time()
  repeat {
    x <- NULL
    x <- f()
    calls <- calls + 1L
    t1 <- proc.time() - t0
    if (calls >= min_calls && t1[["elapsed"]] >= min_time) break
  }
  c(elapsed = size * calls / t1[["elapsed"]], cpu = size * calls / (t1[["user.self"]] + t1[["sys.self"]]),
    reps = calls)
}

verdict <- function(rate) if (rate >= 1e5) "met" else "MISSED"
row <- function(label, size, r, target = size >= 1000) {
  cat(sprintf("%-38s %9.0f /s elapsed %9.0f /s CPU  (%6d calls)%s\n", label, r[["elapsed"]], r[["cpu"]],
              as.integer(r[["reps"]]),
              if (target) sprintf("  target 100,000: elapsed %s, CPU %s", verdict(r[["elapsed"]]),
                                  verdict(r[["cpu"]])) else ""))
}

cat("\nbatches from one model: generate(m, n = N)\n")
for (N in bq(c(1L, 10L, 100L, 1000L, 10000L, 100000L), c(1L, 1000L))) {
  r <- throughput(function() generate(m, n = N), N)
  row(sprintf("  N = %6d", N), N, r)
  bench_record(sprintf("one model, batch of %d, grasps per CPU second", N), r[["cpu"]], "1/s")
}
cat("batches from the model set (2 types): generate(ms, n = N / 2)\n")
for (N in bq(c(10L, 100L, 1000L, 10000L, 100000L), 1000L)) {
  row(sprintf("  N = %6d", N), N, throughput(function() generate(ms, n = N %/% 2L), N))
}
row("  N =  10000, one model, no warp", 10000L,
    throughput(function() generate(m, n = 10000L, warp = FALSE), 10000L))
# The R transcription of the kernel (tests/testthat/helper-generate-reference.R)
# on the same batch: what the native kernel buys.
ref_env <- new.env(parent = asNamespace("handmotion"))
sys.source("tests/testthat/helper-generate-reference.R", envir = ref_env)
ref <- throughput(function() ref_env$generate_reference(m, 10000L, NULL), 10000L)
row("  N =  10000, one model, R reference", 10000L, ref, target = FALSE)
nat <- throughput(function() generate(m, n = 10000L), 10000L)
bench_record("batch of 10000, native / R reference (CPU)", nat[["cpu"]] / ref[["cpu"]], "x")

cat("\nsingle grasp: generate(m, n = 1)\n")
one <- bench::mark(generate(m, n = 1L), iterations = bq(2000, 100), check = FALSE, filter_gc = FALSE,
                   memory = FALSE)
times <- as.numeric(one$time[[1]]) * 1000
cat(sprintf("  median %.3f ms, 90th percentile %.3f ms (target 1 ms: %s)\n",
            stats::median(times), stats::quantile(times, 0.9), if (stats::median(times) <= 1) "met" else "MISSED"))
bench_record("one grasp, median", stats::median(times), "ms")

# The copula model (dependence = "copula"): scores drawn jointly in R, joint
# limits on; the same targets (100,000 grasps/s in batches, 1 ms for one).
mc <- fit_grasp_models(simulate_grasps(grasps = c(11, 17), subjects = bq(30, 6)), seed = 1,
                       dependence = "copula")[[1]]
cat("\ncopula model (dependence = \"copula\", limits on)\n")
for (N in bq(c(1000L, 10000L, 100000L), 1000L)) {
  r <- throughput(function() generate(mc, n = N), N)
  row(sprintf("  N = %6d", N), N, r)
  bench_record(sprintf("copula model, batch of %d, grasps per CPU second", N), r[["cpu"]], "1/s")
}
r_thesis <- throughput(function() generate(m, n = bq(10000L, 1000L)), bq(10000L, 1000L))
r_cop <- throughput(function() generate(mc, n = bq(10000L, 1000L)), bq(10000L, 1000L))
cat(sprintf("  copula / thesis throughput (CPU), batch of %d: %.2f\n", bq(10000L, 1000L), r_cop[["cpu"]] / r_thesis[["cpu"]]))
bench_record("copula / thesis model throughput (CPU)", r_cop[["cpu"]] / r_thesis[["cpu"]], "x")
one_c <- bench::mark(generate(mc, n = 1L), iterations = bq(2000, 100), check = FALSE, filter_gc = FALSE,
                     memory = FALSE)
times_c <- as.numeric(one_c$time[[1]]) * 1000
cat(sprintf("  one grasp: median %.3f ms (target 1 ms: %s)\n", stats::median(times_c),
            if (stats::median(times_c) <= 1) "met" else "MISSED"))
bench_record("copula model, one grasp, median", stats::median(times_c), "ms")

# The memory of the largest batch, in a fresh R process: the collector's
# state (heap size) carries over from batch to batch, so the peak resident
# set is only fair from a clean start.
in_fresh_r <- function(code) {
  setup <- paste0("source('bench/_common.R'); ",
                  "ms <- fit_grasp_models(simulate_grasps(grasps = c(11, 17)), seed = 1); ")
  out <- system2(file.path(R.home("bin"), "Rscript"), c("-e", shQuote(paste0(setup, code))),
                 stdout = TRUE, stderr = TRUE, env = "BENCH_CSV=/dev/null")
  cat(out[!startsWith(out, "==")], sep = "\n")
}
# Streaming: many grasps in chunks through a callback, holding one chunk at a
# time (R's own memory count, gc "max used", over the baseline).
n_stream <- bq(1e6, 2e4)
invisible(gc(reset = TRUE))
base_mb <- sum(gc()[, 2])
frames <- 0
t_stream <- system.time(generate(ms, n = n_stream / 2, chunk = 5000, seed = 1,
                                 callback = function(chunk, i) frames <<- frames + sum(chunk$meta$n_frames)))
after <- gc()
peak_mb <- sum(after[, match("max used", colnames(after)) + 1L]) - base_mb
cat(sprintf("\nstreamed %s grasps in chunks of 5,000 per type: %.1f s elapsed (%.0f grasps/s), %.0f frames; R's peak %.0f MB over the baseline (all at once would hold ~%.0f MB)\n",
            format(n_stream, big.mark = ","), t_stream[["elapsed"]], n_stream / t_stream[["elapsed"]],
            frames, peak_mb, frames * length(m$dofs) * 8 / 2^20))
bench_record(sprintf("stream %g grasps, peak memory over baseline", n_stream), peak_mb, "MB")
bench_record(sprintf("stream %g grasps, grasps per second", n_stream), n_stream / t_stream[["elapsed"]], "1/s")

if (bench_quick) quit(save = "no")

# Memory: R's own accounting (gc() "max used" since a reset, over the
# baseline) and the process's peak resident set (VmHWM, reset through
# /proc/self/clear_refs where the kernel allows it).
cat("\nmemory of one batch of 100,000 grasps from the model set (fresh session)\n")
in_fresh_r(paste0(
  "rss_peak <- function() { v <- grep('^VmHWM', readLines('/proc/self/status'), value = TRUE); ",
  "as.numeric(gsub('[^0-9]', '', v)) / 1024 }; ",
  "base <- gc(reset = TRUE); base_mb <- sum(base[, 2]); rss0 <- rss_peak(); ",
  "reset_ok <- tryCatch({ writeLines('5', '/proc/self/clear_refs'); TRUE }, error = function(e) FALSE, warning = function(w) FALSE); ",
  "x <- generate(ms, n = 50000L, seed = 1); after <- gc(); ",
  "held <- sum(after[, 2]) - base_mb; peak <- sum(after[, match('max used', colnames(after)) + 1L]) - base_mb; ",
  "frames <- sum(x$meta$n_frames); ",
  "cat(sprintf('  %d grasps, %.1f frames on average, %d DoFs: %.0f MB of angles (8 bytes each)\\n', ",
  "length(x), frames / length(x), length(x$dofs), frames * length(x$dofs) * 8 / 2^20)); ",
  "cat(sprintf('  held by the result: %.0f MB; R\\'s peak count during generation: %.0f MB over the baseline ",
  "\\n', held, peak)); ",
  "cat(sprintf('  process peak resident set: %.0f MB, %.0f MB before the batch%s\\n', rss_peak(), rss0, ",
  "if (reset_ok) '' else ' (peak not resettable: since start)'))"))
cat("load average after:", loadavg(), "\n")
