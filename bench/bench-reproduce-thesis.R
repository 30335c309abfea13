# The package's main job, timed: reproduce_thesis() on the full default design
# (30 subjects x 33 types x 3 objects x 3 trials = 8910 recordings), once
# sequentially and once with 2 multicore workers (the `make demo` setting).
# Target on the 2-core reference machine: under 5 minutes (300 s).
# Run from the repository root: Rscript bench/bench-reproduce-thesis.R [sequential|multicore|both]
# BENCH_QUICK=1: a small design (4 subjects, 3 types, 2 folds), sequential only.
source("bench/_common.R")
# reproduce_thesis()'s arguments (the environment variables are read only by
# the vignette, so setting them here ran the full design in quick mode)
design <- if (bench_quick) list(subjects = 4, grasps = c(9, 17, 22), folds = 2) else list()
args <- commandArgs(trailingOnly = TRUE)
which <- if (length(args)) args[1] else if (bench_quick) "sequential" else "both"

run <- function(label) {
  out <- tempfile("report")
  cpu0 <- proc.time()
  t <- system.time(do.call(reproduce_thesis, c(list(out), design)))[["elapsed"]]
  cpu <- (proc.time() - cpu0)[["user.self"]]
  tim <- utils::read.csv(file.path(out, "tables", "timings.csv"))
  cat(sprintf("\n%s: %.1f s elapsed (%.1f s CPU in this process; target 300 s: %s)\n", label, t, cpu,
              if (t <= 300) "met" else "MISSED"))
  for (i in seq_len(nrow(tim))) cat(sprintf("  %-48s %7.1f s\n", tim$step[i], tim$seconds[i]))
  cat(sprintf("  outputs: %d tables, %d figures, report %.1f MB\n",
              length(list.files(file.path(out, "tables"))), length(list.files(file.path(out, "figures"))),
              file.size(file.path(out, "reproduce-thesis.html")) / 2^20))
  unlink(out, recursive = TRUE)
  t
}

if (which %in% c("sequential", "both")) {
  future::plan(future::sequential)
  t_seq <- run("sequential plan")
  bench_record("report, sequential, elapsed", t_seq, "s")
}
if (which %in% c("multicore", "both") && future::supportsMulticore()) {
  future::plan(future::multicore, workers = 2)
  t_par <- run("multicore plan, 2 workers")
  bench_record("report, 2 multicore workers, elapsed", t_par, "s")
  future::plan(future::sequential)
  if (exists("t_seq")) cat(sprintf("\nspeed-up with 2 workers: %.2fx\n", t_seq / t_par))
}
