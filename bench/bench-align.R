# Benchmark of the time alignment (R/align.R, src/dtw.c): the C DTW against
# the reference package dtw, side by side, and DBA over grasp types.
# Run from the repository root:  Rscript bench/bench-align.R  (BENCH_QUICK=1: seconds)
source("bench/_common.R")
bench_test_helper("align-reference")  # dtw_align_pair(): the pairwise DTW with its engine choice

fmt <- function(sec) if (sec < 1e-3) sprintf("%.1f us", sec * 1e6) else if (sec < 1) sprintf("%.2f ms", sec * 1e3) else sprintf("%.2f s", sec)
med <- function(expr) {
  e <- substitute(expr)
  b <- eval(bquote(bench::mark(.(e), min_time = .(bq(1, 0.1)), check = FALSE, filter_gc = FALSE)),
            parent.frame())
  as.numeric(b$median)
}

cat("== Pairwise multivariate DTW, 45 x 16 against 40 x 16 ==\n")
set.seed(1)
x <- matrix(rnorm(45 * 16), 45)
y <- matrix(rnorm(40 * 16), 40)
stopifnot(identical(dtw_align_pair(x, y)[1:2], dtw_align_pair(x, y, engine = "reference")[1:2]))
t_fast <- med(dtw_align_pair(x, y))
t_ref <- med(dtw_align_pair(x, y, engine = "reference"))
cat(sprintf("  reference (dtw::dtw)   %s\n  fast (C)               %s\n  ratio reference / fast %.1fx\n\n",
            fmt(t_ref), fmt(t_fast), t_ref / t_fast))
bench_record("pairwise DTW, fast", t_fast * 1e3, "ms")
bench_record("pairwise DTW, reference / fast", t_ref / t_fast, "x")

cat("== DBA on one grasp type (type 1, over-long removed) ==\n")
g <- simulate_grasps(grasps = 1, subjects = bq(30, 6))
m <- g$meta
recs <- g$recordings[!find_overlong(m$n_frames)]
cat(sprintf("  %d recordings x %d DoFs\n", length(recs), ncol(recs[[1]])))
s1 <- system.time(al_fast <- align_recordings(recs))
s2 <- system.time(al_ref <- align_recordings(recs, engine = "reference"))
cat(sprintf("  fast       CPU %s (%d iterations, %d degenerate, method %s)\n",
            fmt(cpu_of(s1)), al_fast$iterations, nrow(al_fast$degenerate), al_fast$method))
cat(sprintf("  reference  CPU %s (%d iterations)\n", fmt(cpu_of(s2)), al_ref$iterations))
cat(sprintf("  ratio reference / fast (CPU) %.1fx; max |warp difference| %.2g\n\n",
            cpu_of(s2) / cpu_of(s1), max(abs(al_fast$warps - al_ref$warps))))
bench_record("DBA one type, reference / fast (CPU)", cpu_of(s2) / cpu_of(s1), "x")

cat("== All types, default settings, fast engine, sequential ==\n")
gall <- simulate_grasps(subjects = bq(30, 4), grasps = bq(1:33, 1:4))
mall <- gall$meta
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
cat(sprintf("  alignment of %d types (%d recordings): CPU %s, elapsed %s\n", length(types),
            length(gall), fmt(cpu_of(s_all)), fmt(s_all[["elapsed"]])))
cat(sprintf("  linear fallbacks: %d; over-long removed: %d; degenerate dropped: %d\n",
            sum(rows$linear), sum(rows$overlong), sum(rows$degenerate)))
bench_record(sprintf("align %d types, CPU", length(types)), cpu_of(s_all), "s")
