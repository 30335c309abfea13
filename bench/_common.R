# Shared set-up of every benchmark in bench/ (sourced first by each script;
# run from the repository root: `Rscript bench/<name>.R`, or `make bench` /
# `make bench-quick`). See bench/README.md for the conventions.
#
# * The installed package is timed (R's CFLAGS, -O2), as users get it; a
#   pkgload::load_all() build compiles C at -O0 and is used, with a note, only
#   when handmotion is not installed or the sources changed since (make bench
#   installs first, so this is the exception).
# * BENCH_QUICK=1: small sizes and few repetitions, seconds per script. CI runs
#   this mode so that a benchmark that breaks fails CI. The figures of a quick
#   run are not comparable with a full run's and are recorded as mode "quick".
# * Every figure goes through bench_record(), which prints nothing and appends
#   one row (commit, date, mode, benchmark, figure, value, unit) to a CSV:
#   $BENCH_CSV, or bench/results/<benchmark>.csv, so figures can be compared
#   between commits.

bench_quick <- identical(Sys.getenv("BENCH_QUICK"), "1")
# no progress bars in the figures printed (R/progress.R)
options(handmotion.progress = FALSE)

# The size to use: `full` normally, `quick` under BENCH_QUICK=1.
bq <- function(full, quick) if (bench_quick) quick else full

bench_name <- local({
  args <- commandArgs(trailingOnly = FALSE)
  f <- sub("^--file=", "", grep("^--file=", args, value = TRUE))
  if (length(f)) sub("[.]R$", "", basename(f[1])) else "interactive"
})

bench_load <- function() {
  installed <- nzchar(system.file(package = "handmotion"))
  current <- FALSE
  if (installed) {
    # the installed build is current when it was built from these sources
    # (setup.sh stores the same hash at install time)
    stamp <- file.path(system.file(package = "handmotion"), "source-hash")
    here <- tryCatch(system2("bash", "tools/source-hash.sh", stdout = TRUE, stderr = FALSE),
                     error = function(e) "")
    current <- file.exists(stamp) && identical(readLines(stamp, warn = FALSE)[1], here[1])
  }
  if (installed && current) {
    suppressPackageStartupMessages(library(handmotion))
    # benchmarks time internal steps too (handmotion:::name without the
    # prefix): the namespace's functions, not its bookkeeping objects (a copy
    # of .__NAMESPACE__. on the search path confuses packages such as fda.usc)
    ns <- asNamespace("handmotion")
    keep <- Filter(function(n) !startsWith(n, "."), ls(ns, all.names = TRUE))
    attach(mget(keep, envir = ns), name = "handmotion:internals", warn.conflicts = FALSE)
    "installed package (-O2)"
  } else {
    pkgload::load_all(".", quiet = TRUE)
    "pkgload::load_all() build (C at -O0; install first for representative figures)"
  }
}
bench_build <- bench_load()

bench_commit <- tryCatch(system2("git", c("rev-parse", "--short", "HEAD"), stdout = TRUE,
                                 stderr = FALSE)[1], error = function(e) NA_character_)

bench_csv <- function() {
  f <- Sys.getenv("BENCH_CSV")
  if (!nzchar(f)) f <- file.path("bench", "results", paste0(bench_name, ".csv"))
  dir.create(dirname(f), recursive = TRUE, showWarnings = FALSE)
  f
}

# Record one figure (a number with its unit; ratios have unit "x").
bench_record <- function(figure, value, unit) {
  row <- data.frame(commit = bench_commit %||% NA_character_,
                    date = format(Sys.time(), "%Y-%m-%d %H:%M:%S", tz = "UTC"),
                    mode = if (bench_quick) "quick" else "full", benchmark = bench_name,
                    figure = figure, value = signif(as.numeric(value), 6), unit = unit)
  f <- bench_csv()
  utils::write.table(row, f, sep = ",", row.names = FALSE, col.names = !file.exists(f),
                     append = file.exists(f), qmethod = "double")
  invisible(value)
}

`%||%` <- function(a, b) if (is.null(a) || length(a) == 0L || is.na(a[1])) b else a

# CPU time of a system.time() result, and the load average: the machine may
# be shared, so figures come with both.
cpu_of <- function(st) st[["user.self"]] + st[["sys.self"]] + sum(st[c("user.child", "sys.child")], na.rm = TRUE)
load_avg <- function() tryCatch(scan("/proc/loadavg", n = 1, quiet = TRUE), error = function(e) NA)

cat(sprintf("== %s (%s mode; %s; load average %s on %d cores)\n", bench_name,
            if (bench_quick) "quick" else "full", bench_build, format(load_avg()),
            parallel::detectCores()))

# Attach a test helper (tests/testthat/helper-<name>.R): the R references and
# test-only wrappers live there, not in the package, and some benchmarks time
# them beside the compiled step. Evaluated in a child of the namespace, so
# they reach the package's internals as in the tests.
bench_test_helper <- function(name) {
  env <- new.env(parent = asNamespace("handmotion"))
  sys.source(file.path("tests", "testthat", paste0("helper-", name, ".R")), envir = env)
  attach(env, name = paste0("handmotion:helper-", name), warn.conflicts = FALSE)
  invisible(env)
}

# Evaluate `expr` with the R transcription of the batch EM
# (tests/testthat/helper-gmm-reference.R, the tests' reference; not in the
# package) in place of the compiled one, to time what compiling it bought.
with_r_em <- function(expr) {
  ns <- asNamespace("handmotion")
  ref <- new.env(parent = ns)
  sys.source(file.path("tests", "testthat", "helper-gmm-reference.R"), envir = ref)
  compiled <- ns$gmm_em_batch
  locked <- bindingIsLocked("gmm_em_batch", ns)
  if (locked) unlockBinding("gmm_em_batch", ns)
  assign("gmm_em_batch", ref$gmm_em_batch_r, envir = ns)
  on.exit({
    assign("gmm_em_batch", compiled, envir = ns)
    if (locked) lockBinding("gmm_em_batch", ns)
  })
  expr
}

# A wide simulated glove like a lab's second glove (issue 40): one person, six
# objects, 100 Hz, 1.4 s rest and 1.6 s hold; the resistive glove's 15 channels
# plus 8 derived ones (neighbour means with sensor noise) for 23 channels of
# about 380 frames. `types` objects, `trials` each.
wide_glove <- function(types, trials) {
  objects <- c(bottle = 1, mug = 9, ball = 17, pen = 22, card = 28, key = 31)[seq_len(types)]
  g <- simulate_grasps(subjects = 1, grasps = objects, objects = 1, trials = trials, rate = 100,
                       glove = "resistive", rest = 1.4, hold = 1.6, plant_overlong = FALSE, seed = 3)
  set.seed(4)
  recs <- lapply(g$recordings, function(x) {
    extra <- (x[, 1:8] + x[, 2:9]) / 2
    extra <- extra + stats::rnorm(length(extra), sd = 2)
    colnames(extra) <- paste0("extra", 1:8)
    cbind(x, extra)
  })
  grasps(recs, meta = g$meta[, c("grasp", "subject", "object")], rate = 100, unit = "raw")
}

