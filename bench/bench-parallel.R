# Does the second core pay (issue 43)? fit_grasp_models() of the simulated
# data, sequentially and on two multisession workers, interleaved and
# repeated, at 1x (30 subjects, 8,910 recordings) and 10x (300 subjects,
# 89,100). Workers are started (and warmed up with one small fit) before
# the clock starts: a session pays that once, and it is printed apart.
# Prints each run's elapsed time, the main process's CPU and the workers'
# CPU, the load average, and the ratio two workers / sequential from the
# best of the repetitions (the least disturbed by other jobs on a shared
# machine). With BENCH_PREV_LIB=<library> the same runs of the build
# installed there (e.g. the previous release) are made beside, in turn.
#
# FAILS (non-zero exit) when two workers clearly cannot pay: their CPU (main
# process and both workers, median of the repetitions) at 1.9 times the
# sequential fit's or more (two cores at best halve the time, so a path
# that doubles the work is slower than one core whatever the load: issue
# 43's regression measured 1.9-2.0), or, on a machine quiet enough for
# elapsed times to mean something (load average below 1.5 on 2 cores
# during the runs), the best two-worker time above 1.2 times the best
# sequential time (a clear loss: with two repetitions of a 5 s fit the
# ratio moves by about a tenth between runs; a regressed build measured 1.11
# at 1x on the quiet CI machine; the goal of issue 43, 0.62 at 10x, is
# judged from the full run's figures); on a busy machine the elapsed ratio is printed, not
# judged. Either way, other models on two workers fail. Quick mode
# (CI): 1x only, two repetitions each; 1x is the smallest size at which
# two workers must win (about 8 s of fitting sequentially on a quiet machine).
# Run from the repository root: Rscript bench/bench-parallel.R
source("bench/_common.R")

sizes <- bq(c("1x" = 30, "10x" = 300), c("1x" = 30))
reps <- bq(3L, 2L)
allowed <- 1.2
cpu_allowed <- 1.9

# One build's runs, in a fresh R process (callr) whose library path puts
# `lib` first: a data frame of size, mode, rep, elapsed, main and worker CPU.
runs_of_build <- function(lib, sizes, reps) {
  callr::r(function(sizes, reps, dev) {
    if (nzchar(dev)) pkgload::load_all(dev, quiet = TRUE, helpers = FALSE) else library(handmotion)
    options(handmotion.progress = FALSE)
    cpu <- function(st) st[["user.self"]] + st[["sys.self"]]
    future::plan(future::multisession, workers = 2)
    on.exit(future::plan(future::sequential), add = TRUE)
    t_start <- system.time(invisible(suppressWarnings(
      fit_grasp_models(simulate_grasps(subjects = 2, grasps = 1:2, seed = 1), seed = 1))))[["elapsed"]]
    # the workers' own CPU, asked of each (the sleep keeps the two asks apart)
    worker_cpu <- function() {
      fs <- lapply(1:2, function(i) future::future({Sys.sleep(0.3); c(Sys.getpid(), sum(proc.time()[1:2]))}, seed = NULL))
      v <- vapply(fs, future::value, numeric(2))
      sum(v[2, ])
    }
    # the models without their own timings (the only part that differs between runs)
    sig_of <- function(ms) rlang::hash(lapply(ms$models, function(m) { if (is.list(m)) m$timing <- NULL; m }))
    out <- list()
    for (sz in names(sizes)) {
      g <- simulate_grasps(subjects = sizes[[sz]], seed = 7)
      for (r in seq_len(reps)) for (mode in c("sequential", "2 workers")) {
        if (mode == "sequential") {
          future::plan(future::sequential)
        } else {
          # plan() starts new workers after plan(sequential): load the
          # package in both before the clock starts, as a session that set
          # its plan once has it
          future::plan(future::multisession, workers = 2)
          invisible(future.apply::future_lapply(1:2, function(i) { loadNamespace("handmotion"); Sys.sleep(0.2) }))
        }
        w0 <- if (mode == "2 workers") worker_cpu() else 0
        load <- scan("/proc/loadavg", n = 1, quiet = TRUE)
        st <- system.time(ms <- suppressWarnings(fit_grasp_models(g, seed = 1)))
        w1 <- if (mode == "2 workers") worker_cpu() else 0
        if (r == 1L && mode == "sequential") sig <- sig_of(ms)
        out[[length(out) + 1L]] <- data.frame(
          size = sz, mode = mode, rep = r, elapsed = st[["elapsed"]], main_cpu = cpu(st),
          worker_cpu = w1 - w0, load = load,
          same = if (mode == "2 workers") identical(sig_of(ms), sig) else NA)
      }
      rm(g)
    }
    res <- do.call(rbind, out)
    attr(res, "start") <- t_start
    res
  }, args = list(sizes = sizes, reps = reps, dev = lib$dev %||% ""),
  libpath = c(lib$path, .libPaths()), show = FALSE)
}

builds <- list(this = list(path = if (grepl("installed", bench_build)) dirname(system.file(package = "handmotion")) else character(0),
                           dev = if (grepl("installed", bench_build)) "" else normalizePath(".")))
prev <- Sys.getenv("BENCH_PREV_LIB")
if (nzchar(prev)) builds$previous <- list(path = prev)

res <- list()
for (b in names(builds)) {
  r <- runs_of_build(builds[[b]], sizes, reps)
  r$build <- b
  cat(sprintf("%s build: workers started and warmed up in %.1f s (not timed below)\n", b, attr(r, "start")))
  res[[b]] <- r
}
all <- do.call(rbind, res)
cat(sprintf("\n%-9s %-5s %-11s %3s %9s %9s %11s %6s\n", "build", "size", "mode", "rep", "elapsed", "main CPU", "workers CPU", "load"))
for (i in seq_len(nrow(all))) {
  with(all[i, ], cat(sprintf("%-9s %-5s %-11s %3d %8.1fs %8.1fs %10.1fs %6.1f\n", build, size, mode, rep, elapsed,
                             main_cpu, worker_cpu, load)))
}
cat("\n")
verdict <- TRUE
for (b in names(builds)) for (sz in names(sizes)) {
  d <- all[all$build == b & all$size == sz, ]
  best_seq <- min(d$elapsed[d$mode == "sequential"])
  best_par <- min(d$elapsed[d$mode == "2 workers"])
  ratio <- best_par / best_seq
  # CPU the runs spent, beside: two workers' total against the sequential fit's
  cpu_ratio <- median(d$main_cpu[d$mode == "2 workers"] + d$worker_cpu[d$mode == "2 workers"]) /
    median(d$main_cpu[d$mode == "sequential"])
  same <- all(d$same[d$mode == "2 workers"])
  cat(sprintf("%s build, %s: best of %d: sequential %.1f s, 2 workers %.1f s: ratio %.2f (goal 0.62 or less; fails above %.1f on a quiet machine); CPU 2 workers / sequential %.2f (fails at %.1f); main process %.1f s CPU on 2 workers; same models: %s\n",
              b, sz, reps, best_seq, best_par, ratio, allowed, cpu_ratio, cpu_allowed,
              median(d$main_cpu[d$mode == "2 workers"]), same))
  if (b == "this") {
    bench_record(paste0("fit ", sz, ": 2 workers / sequential (best of ", reps, ")"), ratio, "x")
    bench_record(paste0("fit ", sz, ": CPU of 2 workers / sequential"), cpu_ratio, "x")
    bench_record(paste0("fit ", sz, ": sequential, best"), best_seq, "s")
    quiet <- max(d$load) < 1.5
    if (!quiet) cat(sprintf("  (elapsed ratio not judged: load average up to %.1f on 2 cores during the runs)\n", max(d$load)))
    if (cpu_ratio >= cpu_allowed || (quiet && ratio > allowed) || !same) verdict <- FALSE
  }
}
if (nzchar(prev)) for (sz in names(sizes)) {
  best <- function(b, m) min(all$elapsed[all$build == b & all$size == sz & all$mode == m])
  r <- best("this", "2 workers") / best("previous", "2 workers")
  cat(sprintf("%s, 2 workers: this build / previous build %.2f\n", sz, r))
  bench_record(paste0("fit ", sz, ": 2 workers, this build / previous"), r, "x")
}
cat(sprintf("load average at the end %s\n", format(load_avg())))
if (!verdict) {
  cat("bench-parallel: FAILED: two workers cost as much CPU as two sequential fits, or are slower than one on a quiet machine, or gave other models\n")
  quit(status = 1)
}
