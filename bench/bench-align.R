# Benchmark of the time alignment (R/align.R, src/dtw.c).
# Run from the repository root:  Rscript bench/bench-align.R
#
# pkgload::load_all() compiles src/ with -O0 (debug), which is not what users
# get from an installed package (R's CFLAGS, -O2). So besides the load_all
# build, this script compiles an optimised copy of src/*.c into a temporary
# directory and points the package's two DTW routines at it; the figures for
# "fast (-O2)" are the ones to compare with the speed target (all 33 types,
# ~260 recordings each, well under 8 s sequentially).
pkgload::load_all(".", quiet = TRUE)
ns <- asNamespace("handmotion")

build_optimised <- function() {
  dir <- file.path(tempdir(), "hmopt")
  dir.create(dir, showWarnings = FALSE)
  file.copy(file.path("src", c("dtw.c", "init.c")), dir, overwrite = TRUE)
  # init.c's R_init_handmotion is not called for a DLL named hmopt, so the
  # symbols are found by name
  old <- setwd(dir); on.exit(setwd(old))
  out <- system2(file.path(R.home("bin"), "R"), c("CMD", "SHLIB", "-o", "hmopt.so", "dtw.c"),
                 stdout = TRUE, stderr = TRUE)
  dll <- dyn.load(file.path(dir, paste0("hmopt", .Platform$dynlib.ext)))
  list(pair = getNativeSymbolInfo("hm_dtw_pair", dll),
       batch = getNativeSymbolInfo("hm_dtw_batch", dll), log = out)
}
use_symbols <- function(pair, batch) {
  unlockBinding("hm_dtw_pair", ns); assign("hm_dtw_pair", pair, envir = ns)
  unlockBinding("hm_dtw_batch", ns); assign("hm_dtw_batch", batch, envir = ns)
}
debug_syms <- list(pair = get("hm_dtw_pair", ns), batch = get("hm_dtw_batch", ns))
opt <- build_optimised()

# The machine may be shared: report CPU time (user + system of this process)
# beside elapsed time, and the load average, so figures stay comparable.
cpu <- function(st) st[["user.self"]] + st[["sys.self"]]
load_avg <- function() tryCatch(scan("/proc/loadavg", n = 1, quiet = TRUE), error = function(e) NA)
cat(sprintf("load average at start: %s on %d cores\n\n", format(load_avg()), parallel::detectCores()))
fmt <- function(sec) if (sec < 1e-3) sprintf("%.1f us", sec * 1e6) else if (sec < 1) sprintf("%.2f ms", sec * 1e3) else sprintf("%.2f s", sec)
med <- function(expr, min_time = 1) {
  e <- substitute(expr)
  b <- eval(bquote(bench::mark(.(e), min_time = .(min_time), check = FALSE, filter_gc = FALSE)),
            parent.frame())
  as.numeric(b$median)
}

cat("== Pairwise multivariate DTW, 45 x 16 against 40 x 16 ==\n")
set.seed(1)
x <- matrix(rnorm(45 * 16), 45)
y <- matrix(rnorm(40 * 16), 40)
stopifnot(identical(dtw_align_pair(x, y)[1:2], dtw_align_pair(x, y, engine = "reference")[1:2]))
use_symbols(debug_syms$pair, debug_syms$batch)
t_fast_dbg <- med(dtw_align_pair(x, y))
use_symbols(opt$pair, opt$batch)
t_fast <- med(dtw_align_pair(x, y))
t_fast_raw <- med(handmotion:::dtw_pair_fast(x, y, NULL))
t_ref <- med(dtw_align_pair(x, y, engine = "reference"))
cat(sprintf("  reference (dtw::dtw)       %s\n", fmt(t_ref)))
cat(sprintf("  fast, load_all -O0 build   %s\n", fmt(t_fast_dbg)))
cat(sprintf("  fast, -O2 build            %s  (bare .Call: %s)\n", fmt(t_fast), fmt(t_fast_raw)))
cat(sprintf("  ratio reference / fast     %.1fx\n\n", t_ref / t_fast))

cat("== DBA on one grasp type (simulate_grasps(), type 1, over-long removed) ==\n")
g <- simulate_grasps(grasps = 1)
m <- grasp_meta(g)
recs <- g$recordings[!find_overlong(m$n_frames)]
cat(sprintf("  %d recordings x %d DoFs, %d-%d frames\n", length(recs), ncol(recs[[1]]),
            min(m$n_frames), max(m$n_frames[!find_overlong(m$n_frames)])))
s1 <- system.time(al_fast <- align_recordings(recs))
s2 <- system.time(al_ref <- align_recordings(recs, engine = "reference"))
t1 <- cpu(s1); t2 <- cpu(s2)
cat(sprintf("  fast (-O2)      CPU %s, elapsed %s  (%d iterations, %d degenerate, method %s)\n",
            fmt(t1), fmt(s1[["elapsed"]]), al_fast$iterations, nrow(al_fast$degenerate), al_fast$method))
cat(sprintf("  reference       CPU %s, elapsed %s  (%d iterations)\n", fmt(t2), fmt(s2[["elapsed"]]),
            al_ref$iterations))
cat(sprintf("  ratio reference / fast (CPU)  %.1fx; max |warp difference| %.2g\n\n", t2 / t1,
            max(abs(al_fast$warps - al_ref$warps))))

cat("== All 33 types, default settings, fast (-O2), sequential ==\n")
t_sim <- system.time(gall <- simulate_grasps())[["elapsed"]]
mall <- grasp_meta(gall)
types <- levels(droplevels(mall$grasp))
rows <- vector("list", length(types))
s_all <- system.time(for (i in seq_along(types)) {
  idx <- which(mall$grasp == types[i])
  long <- find_overlong(mall$n_frames[idx])
  al <- align_recordings(gall$recordings[idx[!long]])
  rows[[i]] <- data.frame(overlong = sum(long), degenerate = nrow(al$degenerate),
                          linear = al$method == "linear", iterations = al$iterations)
})
rows <- do.call(rbind, rows)
cat(sprintf("  (simulating 8910 recordings took %s)\n", fmt(t_sim)))
cat(sprintf("  alignment of 33 types: CPU %s, elapsed %s (load average now %s)\n",
            fmt(cpu(s_all)), fmt(s_all[["elapsed"]]), format(load_avg())))
cat(sprintf("  linear fallbacks: %d; over-long removed: %d; degenerate dropped: %d (per type %d-%d)\n",
            sum(rows$linear), sum(rows$overlong), sum(rows$degenerate),
            min(rows$degenerate), max(rows$degenerate)))
use_symbols(debug_syms$pair, debug_syms$batch)
