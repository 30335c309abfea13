# Ten times the data (issue 16): simulate_grasps(subjects = 300), 89,100
# recordings, simulated, fitted for all 33 types on 2 multisession workers
# and classified in-sample (FPCA distance), beside the default data
# (30 subjects) so that every figure comes with its 10x / 1x ratio (linear
# cost: 10). Targets on the 2-core machine: fit 30 s or less, main-process
# peak memory 4 GB or less. Also the EM iterations per mixture (SQUAREM-
# accelerated, the stopping rule per observation, and above 1000 points the
# starts race on a subsample: they grow far slower than the data).
# Also (issue 36) early recognition (in 10 subject groups at both sizes) and
# the naturalness evaluation of two model sets (fitted on the first two
# thirds of the subjects, reps = 5), with their 10x / 1x ratios (goal: 12
# or less, like classification).
# Peak memory is the kernel's high-water mark of resident memory (VmHWM),
# reset before each step (/proc/<pid>/clear_refs), for the main process and
# for each worker.
# Early recognition is timed as a user calls it, with its default folds:
# leave-one-subject-out on the default data's 30 subjects, and on 300
# subjects 30 groups of subjects (evaluate_early_recognition() holds out at
# most 30 folds; one fold per subject would make its cost grow as subjects
# x recordings).
# Run from the repository root: Rscript bench/bench-scale.R (BENCH_QUICK=1:
# three types, 3 against 30 subjects, seconds); `Rscript
# bench/bench-scale.R early` times only early recognition (simulated data,
# no fits; a few minutes).
source("bench/_common.R")

sizes <- c(x1 = bq(30, 3), x10 = bq(300, 30))
types <- bq(1:33, 1:3)
hwm_gb <- function(pid = Sys.getpid()) {
  f <- sprintf("/proc/%d/status", pid)
  if (!file.exists(f)) return(NA_real_)
  as.numeric(gsub("\\D", "", grep("^VmHWM", readLines(f), value = TRUE))) / 2^20
}
reset_hwm <- function(pids) {
  for (p in pids) try(cat("5\n", file = sprintf("/proc/%d/clear_refs", p)), silent = TRUE)
}

future::plan(future::multisession, workers = 2)
worker_pids <- function() {
  unique(vapply(lapply(1:2, function(i) future::future({ Sys.sleep(0.5); Sys.getpid() })),
                future::value, numeric(1)))
}
workers <- worker_pids()
# warm-up: the first fit in a fresh worker loads the package there
warm_up <- function() invisible(fit_grasp_models(simulate_grasps(subjects = 2, grasps = 1:2, seed = 9), seed = 1))
warm_up()

only_early <- "early" %in% commandArgs(trailingOnly = TRUE)
measure_early <- function(subjects) {
  g <- simulate_grasps(subjects = subjects, grasps = types)
  future::plan(forked, workers = 2)
  gc()
  t_early <- system.time(er <- evaluate_early_recognition(g, folds = early_folds))
  future::plan(future::sequential)
  c(recordings = length(g), early = t_early[["elapsed"]], early_cpu_main = cpu_of(t_early),
    folds = if (attr(er, "scheme") == "leave-one-subject-out") length(unique(g$meta$subject))
            else as.numeric(sub("^leave-group-out \\(([0-9]+) .*", "\\1", attr(er, "scheme"))))
}
measure <- function(subjects) {
  gc()
  reset_hwm(Sys.getpid())
  t_sim <- system.time(g <- simulate_grasps(subjects = subjects, grasps = types))
  mem_sim <- hwm_gb()
  gc()
  reset_hwm(c(Sys.getpid(), workers))
  t_fit <- system.time(ms <- fit_grasp_models(g, seed = 1))
  mem_fit <- hwm_gb()
  mem_workers <- max(vapply(workers, hwm_gb, numeric(1)))
  iters <- unlist(lapply(ms$models, function(m) {
    c(vapply(m$gmm, function(x) as.numeric(x$iterations), numeric(1)), m$warp$gmm$iterations)
  }))
  gc()
  reset_hwm(Sys.getpid())
  t_cl <- system.time(cl <- classify(ms, g))
  mem_cl <- hwm_gb()
  acc <- mean(as.character(cl$predictions$predicted) == as.character(cl$predictions$truth))
  # early recognition and the naturalness evaluation on forked workers (the
  # recordings are not copied to them); early recognition in `early_folds`
  # (default folds: leave-one-subject-out at 30 subjects, 30 groups of
  # subjects at 300)
  future::plan(forked, workers = 2)
  t_early <- system.time(evaluate_early_recognition(g, folds = early_folds))
  sn <- as.integer(sub("^S", "", g$meta$subject))
  train <- g[sn <= floor(2 * subjects / 3)]
  held <- g[sn > floor(2 * subjects / 3)]
  nat <- list(thesis = fit_grasp_models(train, seed = 1),
              copula = fit_grasp_models(train, seed = 1, dependence = "copula"))
  t_gen <- system.time(evaluate_generation(nat, held, train, reps = 5))
  future::plan(future::multisession, workers = 2)
  workers <<- worker_pids()
  warm_up()
  c(recordings = length(g), simulate = t_sim[["elapsed"]], fit = t_fit[["elapsed"]],
    fit_cpu_main = cpu_of(t_fit), classify = t_cl[["elapsed"]], iter_median = stats::median(iters),
    iter_mean = mean(iters), at_cap = sum(iters >= 5000), mem_simulate = mem_sim, mem_fit = mem_fit,
    mem_workers = mem_workers, mem_classify = mem_cl, accuracy = acc, early = t_early[["elapsed"]],
    early_cpu_main = cpu_of(t_early), generation = t_gen[["elapsed"]], generation_cpu_main = cpu_of(t_gen))
}
early_folds <- bq(NULL, 3L)
# ten times the recordings are 600 MB: more than future's default cap on
# what a worker is given (forked workers share it anyway)
options(future.globals.maxSize = Inf)
# (plan() reads its strategy unevaluated: name it here)
forked <- if (future::supportsMulticore()) future::multicore else future::multisession
if (only_early) {
  res <- vapply(sizes, measure_early, numeric(4))
  cat(sprintf("\n%-44s %10s %10s %10s\n", "", names(sizes)[1], names(sizes)[2], "ratio"))
  lab <- c(recordings = "recordings", folds = "folds (default)", early = "early recognition, 2 workers, elapsed (s)",
           early_cpu_main = "early recognition, CPU incl. workers (s)")
  for (f in names(lab)) cat(sprintf("%-44s %10.4g %10.4g %10.3g\n", lab[[f]], res[f, 1], res[f, 2], res[f, 2] / res[f, 1]))
  for (f in c("early", "early_cpu_main")) bench_record(paste0(lab[[f]], ", 10x / 1x"), res[f, 2] / res[f, 1], "x")
  r <- res["early", 2] / res["early", 1]
  cat(sprintf("\ncost growth of early recognition, 10x / 1x (goal 12 or less): %.1f elapsed (%s), %.1f CPU; load average %s\n",
              r, if (r <= 12) "met" else "MISSED", res["early_cpu_main", 2] / res["early_cpu_main", 1], format(load_avg())))
  quit(save = "no")
}
res <- vapply(sizes, measure, numeric(17))
future::plan(future::sequential)

labels <- c(recordings = "recordings", simulate = "simulate, elapsed (s)", fit = "fit, 2 workers, elapsed (s)",
            fit_cpu_main = "fit, main-process CPU (s)", classify = "classify in-sample, elapsed (s)",
            iter_median = "EM iterations per mixture, median", iter_mean = "EM iterations per mixture, mean",
            at_cap = "EM runs at the 5000 cap", mem_simulate = "peak memory, simulate (GB)",
            mem_fit = "peak memory, fit, main (GB)", mem_workers = "peak memory, fit, a worker (GB)",
            mem_classify = "peak memory, classify, main (GB)", accuracy = "in-sample accuracy",
            early = if (is.null(early_folds)) "early recognition, default folds, 2 workers, elapsed (s)"
                    else sprintf("early recognition, %d folds, 2 workers, elapsed (s)", early_folds),
            early_cpu_main = "early recognition, main-process CPU (s)",
            generation = "evaluate_generation(), 2 sets, reps 5, elapsed (s)",
            generation_cpu_main = "evaluate_generation(), CPU (s)")
cat(sprintf("\n%-38s %10s %10s %10s\n", "", names(sizes)[1], names(sizes)[2], "ratio"))
for (f in rownames(res)) {
  ratio <- res[f, 2] / res[f, 1]
  cat(sprintf("%-38s %10.4g %10.4g %10.3g\n", labels[[f]], res[f, 1], res[f, 2], ratio))
  unit <- if (grepl("GB", labels[[f]])) "GB" else if (grepl("(s)", labels[[f]], fixed = TRUE)) "s" else ""
  bench_record(paste0(labels[[f]], ", 10x"), res[f, 2], unit)
  if (!f %in% c("recordings", "accuracy")) bench_record(paste0(labels[[f]], ", 10x / 1x"), ratio, "x")
}
growth <- res[c("classify", "early", "generation"), 2] / res[c("classify", "early", "generation"), 1]
cat(sprintf("\ncost growth, 10x / 1x (goal 12 or less): classification %.1f (%s), early recognition %.1f (%s), naturalness evaluation %.1f (%s)\n",
            growth[1], if (growth[1] <= 12) "met" else "MISSED", growth[2], if (growth[2] <= 12) "met" else "MISSED",
            growth[3], if (growth[3] <= 12) "met" else "MISSED"))
cat(sprintf("\n10x fit %.1f s (target 30 s: %s); main-process peak %.2f GB (target 4 GB: %s); load average %s\n",
            res["fit", 2], if (res["fit", 2] <= 30) "met" else "MISSED",
            max(res[c("mem_simulate", "mem_fit", "mem_classify"), 2]),
            if (max(res[c("mem_simulate", "mem_fit", "mem_classify"), 2]) <= 4) "met" else "MISSED",
            format(load_avg())))
