# The thesis model on real and on wide glove recordings (issue 40): how many
# recordings it keeps per grasp type, with the thesis' rule for degenerate
# DTW warps (degenerate_warps = "drop", Figure 5.1) and with the default
# fallback ("constrain": a slope-constrained DTW warp), and how long fitting
# all models takes. Sequential, one core (plan(sequential)); CPU time beside
# elapsed time, since the machine may be shared.
#
# Data:
# * flexglove (real, $HANDMOTION_SHARED/data/flexglove: 626 recordings, 6 flex
#   sensors, ~33 Hz, 8 types, rest before and hold after each grasp), read
#   with read.csv; measured with motion = "auto" (trimmed by find_motion()),
#   with recordings trimmed by a plain threshold written here (so the figures
#   do not hang on find_motion()), and as recorded; the thesis model aligns
#   by DTW (warping = "dtw", which the trimmed default would replace by
#   linear time normalisation).
# * a wide simulated glove like a lab's second glove: one person, six
#   objects x 28 trials = 168 recordings of the resistive glove at 100 Hz,
#   1.4 s rest and 1.6 s hold, with 8 more channels (sums of neighbouring
#   channels plus sensor noise) for 23 channels of ~380 frames.
# Also: where the time goes on the wide set (Rprof, by function).
#
# Run from the repository root after `R CMD INSTALL --no-multiarch .`:
#   Rscript bench/bench-real-fit.R     (BENCH_QUICK=1: two types of each, seconds)

source("bench/_common.R")
future::plan(future::sequential)
cat(sprintf("%s; load average %s on %d cores\n\n", bench_build, load_avg(), parallel::detectCores()))

load_flexglove <- function(dir) {
  man <- utils::read.csv(file.path(dir, "manifest.csv"), stringsAsFactors = FALSE)
  recs <- lapply(man$file, function(f) as.matrix(utils::read.csv(file.path(dir, f))) * 1)
  names(recs) <- sub("[.]csv$", "", man$file)
  grasps(recs, meta = data.frame(grasp = man$label, subject = man$subject, object = man$object,
                                 stringsAsFactors = FALSE), rate = 33.3, unit = "raw")
}

# A plain threshold trim: keep the frames from where the recording first
# leaves its start posture to where it last differs from its end posture by
# more than `frac` of its largest such distance (channels scaled by their
# range), one frame of margin each side.
threshold_trim <- function(g, frac = 0.1) {
  recs <- lapply(g$recordings, function(x) {
    n <- nrow(x)
    sc <- rep(pmax(apply(x, 2, function(v) diff(range(v))), 1), each = n)
    a <- sqrt(rowSums(((x - rep(x[1, ], each = n)) / sc)^2))
    b <- sqrt(rowSums(((x - rep(x[n, ], each = n)) / sc)^2))
    s <- max(1, which(a > frac * max(a))[1] - 1)
    e <- min(n, max(which(b > frac * max(b))) + 1)
    if (e - s < 5) return(x)
    x[s:e, , drop = FALSE]
  })
  grasps(recs, meta = g$meta[, c("grasp", "subject", "object")], rate = g$rate, unit = g$unit)
}

kept_table <- function(label, x, ...) {
  rows <- list()
  for (dw in c("drop", "constrain")) {
    st <- system.time(ms <- suppressWarnings(fit_grasp_models(x, seed = 1, degenerate_warps = dw, ...)))
    s <- summary(ms)
    rows[[dw]] <- s
    fig <- sprintf("%s, %s", label, dw)
    cat(sprintf("%-52s %6.2f s elapsed, %6.2f s CPU; kept %d of %d (%.1f%%)\n", fig, st[["elapsed"]], cpu_of(st),
                sum(s$n_used), sum(s$n_input), 100 * sum(s$n_used) / sum(s$n_input)))
    bench_record(paste("fit s,", fig), st[["elapsed"]], "s")
    bench_record(paste("fit CPU s,", fig), cpu_of(st), "s")
    bench_record(paste("share kept,", fig), sum(s$n_used) / sum(s$n_input), "fraction")
  }
  d <- rows$drop
  k <- rows$constrain
  print(data.frame(grasp = d$grasp, n = d$n_input, overlong = d$n_overlong, kept_drop = d$n_used,
                   dropped = d$n_degenerate, kept_constrain = k$n_used, fallback = k$n_warp_fallback),
        row.names = FALSE)
  cat("\n")
}

dir <- file.path(Sys.getenv("HANDMOTION_SHARED", "/work/shared"), "data", "flexglove")
if (dir.exists(dir)) {
  flex <- load_flexglove(dir)
  if (bench_quick) flex <- flex[as.character(flex$meta$grasp) %in% unique(as.character(flex$meta$grasp))[1:2]]
  cat(sprintf("flexglove: %d recordings of %d channels, %d types\n\n", length(flex), length(flex$dofs),
              length(unique(flex$meta$grasp))))
  st <- system.time(ms <- fit_grasp_models(flex, seed = 1))
  cat(sprintf("%-52s %6.2f s elapsed, %6.2f s CPU (warping %s)\n\n", "flexglove, defaults", st[["elapsed"]],
              cpu_of(st), paste(unique(summary(ms)$warping), collapse = ", ")))
  bench_record("fit s, flexglove, defaults", st[["elapsed"]], "s")
  kept_table("flexglove, motion auto, DTW", flex, warping = "dtw")
  kept_table("flexglove, threshold-trimmed, DTW", threshold_trim(flex), motion = "as_recorded")
  kept_table("flexglove, as recorded, DTW", flex, motion = "as_recorded")
} else {
  cat("flexglove not found under", dir, "(set HANDMOTION_SHARED); skipped\n\n")
}

wide <- wide_glove(bq(6, 2), bq(28, 6))
cat(sprintf("wide simulated glove: %d recordings of %d channels, %d-%d frames\n\n", length(wide), length(wide$dofs),
            min(wide$meta$n_frames), max(wide$meta$n_frames)))
st <- system.time(ms <- fit_grasp_models(wide, seed = 1))
cat(sprintf("%-52s %6.2f s elapsed, %6.2f s CPU (warping %s; target 3 s)\n\n", "wide, defaults", st[["elapsed"]],
            cpu_of(st), paste(unique(summary(ms)$warping), collapse = ", ")))
bench_record("fit s, wide, defaults", st[["elapsed"]], "s")
kept_table("wide, motion auto, DTW", wide, warping = "dtw")
kept_table("wide, as recorded, DTW", wide, motion = "as_recorded")

# where the time goes: the DTW-aligned wide set as recorded
prof <- tempfile(fileext = ".out")
utils::Rprof(prof, interval = 0.01)
ms <- suppressWarnings(fit_grasp_models(wide, seed = 1, motion = "as_recorded"))
utils::Rprof(NULL)
steps <- colSums(t(vapply(ms, function(m) m$timing, numeric(4))))
cat("wide, as recorded: seconds by step (sum over types):", paste(names(steps), round(steps, 2), collapse = ", "), "\n")
cat(sprintf("  DBA iterations per type: %s\n",
            paste(vapply(ms, function(m) m$warping$iterations, integer(1)), collapse = " ")))
print(utils::head(summaryRprof(prof)$by.self, 8))
