# How fast the machine runs the report's kind of work right now, measured
# before the report starts (issue 42: `make demo` said "about 2.3 min" and
# took 4.9 min on a quiet machine, 11.5 min on a busy one). The cost model
# (report_step_model) is in CPU seconds of a reference machine, which the
# load of other jobs does not change; what the load changes is how much of
# a core the report gets. A short calibration (the package's own fit on a
# tiny data set: DTW, FPCA and the mixture EM, the kernels the report
# spends its time in) measures both: its CPU time against the reference
# machine's (how fast a core is) and its elapsed time against its CPU time
# (how much of a core one process gets). The load average says how many
# other jobs want the cores, which matters for the steps on two workers.

# The calibration's CPU seconds (the quickest of its timed rounds, two
# rounds' worth, installed -O2 build) on the machine and in the conditions
# report_step_model's seconds stand for: the 2-core development machine,
# quiet. Set from two quiet `make demo` runs (issue 42, 2026-11-28), where
# the model (scaled to an earlier quiet run of 4.9 min) says 4.9 min at the
# reference pace: the calibration read 0.186 s for a report of 5.3 min and
# 0.175 s for one of 6.3 min (the same work took 17% more CPU time in the
# second: the machine's own pace drifts, and a short test fit sees only part
# of it). The references that would have made each estimate exact,
# 0.186 x 4.9 / 5.3 = 0.172 and 0.175 x 4.9 / 6.3 = 0.136, average 0.155 s:
# those runs' estimates would have been 5.9 (+11%) and 5.5 min (-13%). By
# hand, fresh sessions on the same quiet machine read 0.171-0.187 s. (The
# earlier 0.22 s was a single timed pair's lowest reading at load 5.3. With
# it, a quiet run whose single pair read 0.31 s said 9.8 min and took 5.9,
# and the six rounds said 4.1 min for the run of 5.3 and 5.1 for the run of
# 6.3.)
pace_reference_cpu <- 0.155

# The pace now: `cpu` and `elapsed` seconds of the calibration, `speed`
# (reference CPU / CPU: above 1 a faster core), `share` (CPU / elapsed:
# the part of a core one process got), `load` (the 1-minute load average,
# NA where the system does not say), `others` (the other processes' use of
# the cores during the calibration, in cores, NA where /proc/stat is not
# there) and `cores`.
#
# The speed is the quickest of six rounds (two rounds' worth, in the unit of
# pace_reference_cpu): other jobs, a page-cache miss or the host taking the
# core can only slow a round down, and with one timed pair the same quiet
# machine read 82% and 125% of the reference speed in three consecutive
# runs (issue 42: the 82% run's first estimate said 9.8 min for a run of
# 5.9). The share is over all six.
machine_pace <- function() {
  g <- simulate_grasps(subjects = 2, grasps = c(17, 25), objects = 2, trials = 2, seed = 1)
  # (silent; one model at a time, in this process: fit_grasp_model() does
  # not go through the future plan, which the calibration must not change,
  # as a multisession plan would restart its workers)
  old <- options(handmotion.progress = FALSE)
  on.exit(options(old), add = TRUE)
  fit <- function() for (k in c(17, 25)) invisible(fit_grasp_model(g, grasp = k, seed = 1))
  fit()  # (the first call loads and compiles what the later ones reuse)
  busy <- cpu_busy_seconds()
  rounds <- vapply(1:6, function(r) {
    t0 <- proc.time()
    fit()
    t <- proc.time() - t0
    c(cpu = t[["user.self"]] + t[["sys.self"]], elapsed = t[["elapsed"]])
  }, numeric(2))
  total_cpu <- max(1e-3, sum(rounds["cpu", ]))
  cpu <- max(1e-3, 2 * min(rounds["cpu", ]))
  # (the rounds' elapsed over CPU, at least 1: a round's CPU can exceed its
  # elapsed time by a clock tick; as a ratio, so a CPU-bound run gives
  # exactly `cpu`, where cpu * elapsed / cpu came out one rounding below it)
  total_elapsed <- max(total_cpu, sum(rounds["elapsed", ]))
  stretch <- total_elapsed / total_cpu
  pace_summary(cpu, cpu * stretch, load_average(), parallel::detectCores(),
               others = (busy$after() - total_cpu) / total_elapsed)
}

# The pace from its measurements (separate, so tests can feed them).
pace_summary <- function(cpu, elapsed, load = NA_real_, cores = 2L, others = NA_real_) {
  list(cpu = cpu, elapsed = elapsed, speed = pace_reference_cpu / cpu, share = min(1, cpu / elapsed),
       load = load, others = others, cores = max(1L, as.integer(cores %||% 1L)))
}

# The CPU seconds all processes spent on every core (Linux's /proc/stat,
# whose first line counts in ticks of 1/100 s), from now: `after()` gives
# those spent since. after() is NA where /proc/stat cannot be read.
cpu_busy_seconds <- function() {
  read <- function() {
    v <- tryCatch(scan("/proc/stat", what = "", nlines = 1L, quiet = TRUE), error = function(e) NULL,
                  warning = function(w) NULL)
    if (length(v) < 9L || v[1] != "cpu") return(NA_real_)
    ticks <- suppressWarnings(as.numeric(v[-1]))
    # user nice system idle iowait irq softirq steal: busy is all but idle
    # and iowait (steal, the host's use of the core, is time we do not get)
    sum(ticks[c(1:3, 6:8)]) / 100
  }
  start <- read()
  list(after = function() read() - start)
}

# The 1-minute load average (Linux, macOS via /proc where mounted), or NA.
load_average <- function() {
  tryCatch(scan("/proc/loadavg", n = 1L, quiet = TRUE), error = function(e) NA_real_,
           warning = function(w) NA_real_)
}

# Seconds of elapsed time per CPU second of the cost model, for the steps in
# the main process and for those on `workers` workers: the core's speed, and
# the share of a core a process gets. The kernel divides the cores evenly
# between the processes that want to run, so the calibration's share s of a
# core says how much other work there is: as much as `cores / s - 1`
# processes that each want a whole core. Where it got a whole core (s of
# 0.95 or more: a few per cent are the calibration's own waits) the share
# cannot say how much less than `cores - 1` the others want, and the load
# average, capped there, says it. The load average is not the demand itself:
# it counts processes waiting on the disk, jobs that use a part of a core,
# and lags by a minute; taken as the demand ((load + workers) / cores) it
# made the parallel steps about 6 times as slow at load 4-6 on 2 cores
# where 2.3 times was measured (issue 42). `w` workers among that demand
# get `cores / (others + w)` of a core each, at most a whole one.
pace_factors <- function(pace, workers = 1L) {
  slow <- 1 / pace$speed
  others <- pace_other_demand(pace)
  w <- max(1L, workers)
  c(main = slow * max(1, (others + 1) / pace$cores), workers = slow * max(1, (others + w) / pace$cores))
}

# The other jobs' demand for the cores, in processes that each want a whole
# core (see pace_factors()).
#
# Where the calibration got a whole core, what the other jobs used of the
# cores meanwhile (`others`, /proc/stat) says it, not the load average: that
# average lags by a minute, so a job that has just finished (the setup
# before `make demo`, an earlier run) still counts as one that wants a core,
# and on a quiet machine the workers' steps were planned 1.5 times as slow.
pace_other_demand <- function(pace) {
  if (pace$share < 0.95) return(pace$cores / pace$share - 1)
  others <- pace$others
  known <- if (!is.na(others)) others else if (is.na(pace$load)) 0 else pace$load
  min(max(0, known), pace$cores - 1)
}

# Is the machine busy? Then the first estimate says so: a process gets
# less than 80% of a core, or other jobs use most of the cores ours do not
# need (measured, `others`; where it is not, the load average fills them).
pace_busy <- function(pace) {
  others <- pace$others
  pace$share < 0.8 ||
    if (!is.na(others)) others >= 0.8 * (pace$cores - 1) else isTRUE(pace$load >= pace$cores)
}

# The words of the first estimate's note on the machine.
pace_text <- function(pace) {
  others <- pace$others
  load <- if (!is.na(others)) {
    sprintf("other jobs using %.1f of %d cores, ", max(0, others), pace$cores)
  } else if (!is.na(pace$load)) {
    sprintf("load %.1f on %d cores, ", pace$load, pace$cores)
  } else ""
  if (pace_busy(pace)) {
    sprintf("the machine is busy (%sa test fit got %.0f%% of a core): the estimate allows for it, and the run takes longer than on a quiet machine",
            load, 100 * pace$share)
  } else {
    sprintf("%sa test fit ran at %.0f%% of the reference machine's speed", load, 100 * pace$speed)
  }
}
