# FPCA and GMM engines: the thesis' packages (reference) against our fast
# engines, side by side on a realistic subset -- the 16 DoFs of one grasp type
# (270 simulated recordings, time-normalised to 40 points) and their bivariate
# FPC score sets -- then the fast engines on the volume of a whole model fit
# (33 types x 16 DoFs: 528 FPCAs + 528 bivariate GMMs, 33 warp FPCAs + 33
# univariate GMMs).
# Targets: fast >= 100x the reference; the whole volume in a few seconds.
# Run from the repository root: Rscript bench/bench-engines.R (BENCH_QUICK=1: seconds)
source("bench/_common.R")

L <- 40
g <- simulate_grasps(grasps = 1, seed = 1, subjects = bq(30, 6))
# Linear time normalisation stands in for DTW here: the engines only see an
# n x L matrix per DoF.
resample <- function(x, L) {
  apply(x, 2, function(col) stats::approx(seq(0, 1, length.out = length(col)), col,
                                          seq(0, 1, length.out = L))$y)
}
curves <- lapply(recordings(g), resample, L = L)
per_dof <- lapply(seq_along(g$dofs), function(j) t(vapply(curves, function(x) x[, j], numeric(L))))
names(per_dof) <- g$dofs
if (bench_quick) per_dof <- per_dof[1:4]
warps <- t(vapply(recordings(g), function(x) {
  stats::approx(seq(0, 1, length.out = L), seq(1, nrow(x), length.out = L), seq(0, 1, length.out = L))$y
}, numeric(L)))
cat(sprintf("data: %d DoFs x %d curves x %d points (simulated grasp type 1)\n",
            length(per_dof), nrow(per_dof[[1]]), L))

# Seconds per call: `batch` calls are timed together (the clock ticks in
# milliseconds) and the fastest of `reps` batches is kept. The machine is
# shared, so the minimum is the figure least disturbed by other processes;
# both engines are timed the same way.
time_per_call <- function(expr_fun, reps, batch = 1L) {
  best <- Inf
  for (i in seq_len(reps)) {
    t0 <- proc.time()[["elapsed"]]
    for (b in seq_len(batch)) res <- expr_fun()
    best <- min(best, (proc.time()[["elapsed"]] - t0) / batch)
  }
  list(seconds = best, result = res)
}
cpu <- cpu_of

# ---- FPCA ------------------------------------------------------------------
cat("\nFPCA, 2 components per DoF (ms per call, fastest of 3 reference calls / 5 batches of 20 fast calls)\n")
fp <- data.frame(dof = names(per_dof), reference_ms = NA_real_, fast_ms = NA_real_,
                 max_diff = NA_real_)
fast_fits <- vector("list", length(per_dof))
for (j in seq_along(per_dof)) {
  Y <- per_dof[[j]]
  ref <- time_per_call(function() fpca_fit(Y, ncomp = 2, engine = "reference"), bq(3, 1))
  fast <- time_per_call(function() fpca_fit(Y, ncomp = 2, engine = "fast"), bq(5, 1), batch = bq(20, 5))
  fast_fits[[j]] <- fast$result
  fp$reference_ms[j] <- 1000 * ref$seconds
  fp$fast_ms[j] <- 1000 * fast$seconds
  fp$max_diff[j] <- max(abs(ref$result$components - fast$result$components),
                        abs(ref$result$scores - fast$result$scores),
                        abs(ref$result$var_explained - fast$result$var_explained))
}
print(fp, digits = 3, row.names = FALSE)
cat(sprintf("FPCA per call: reference %.1f ms, fast %.3f ms, ratio %.0fx (target >= 100x); max |difference| %.1e\n",
            mean(fp$reference_ms), mean(fp$fast_ms), mean(fp$reference_ms) / mean(fp$fast_ms),
            max(fp$max_diff)))
bench_record("FPCA per call, fast", mean(fp$fast_ms), "ms")
bench_record("FPCA per call, reference / fast", mean(fp$reference_ms) / mean(fp$fast_ms), "x")
cat(sprintf("variance explained by 2 FPCs: min %.2f%%, mean %.2f%%, max %.2f%%\n",
            100 * min(sapply(fast_fits, function(f) sum(f$var_explained))),
            100 * mean(sapply(fast_fits, function(f) sum(f$var_explained))),
            100 * max(sapply(fast_fits, function(f) sum(f$var_explained)))))

# ---- GMM -------------------------------------------------------------------
# mixtools takes seconds per bivariate fit, so the reference runs on the first
# few DoFs only; the fast engine on all 16.
n_ref <- as.integer(Sys.getenv("BENCH_GMM_REF_DOFS", bq("3", "1")))
cat(sprintf("\nBivariate 2-component GMM on the FPC scores, ms per call (1 reference call, fastest of 3 batches of 5 fast calls; reference on %d DoFs)\n", n_ref))
gm <- data.frame(dof = names(per_dof), reference_ms = NA_real_, fast_ms = NA_real_,
                 loglik_gain = NA_real_, fast_iter = NA_integer_, ref_iter = NA_integer_,
                 fast_fallback = NA, ref_fallback = NA)
for (j in seq_along(per_dof)) {
  S <- fast_fits[[j]]$scores
  fast <- time_per_call(function() gmm_fit(S, k = 2, engine = "fast"), 3, batch = 5)
  gm$fast_ms[j] <- 1000 * fast$seconds
  gm$fast_iter[j] <- fast$result$iterations
  gm$fast_fallback[j] <- fast$result$fallback
  if (j <= n_ref) {
    ref <- time_per_call(function() gmm_fit(S, k = 2, engine = "reference", seed = j), 1)
    gm$reference_ms[j] <- 1000 * ref$seconds
    gm$ref_iter[j] <- ref$result$iterations
    gm$ref_fallback[j] <- ref$result$fallback
    gm$loglik_gain[j] <- fast$result$loglik - ref$result$loglik
  }
}
print(gm, digits = 4, row.names = FALSE)
cat(sprintf("GMM per call: reference %.0f ms, fast %.2f ms, ratio %.0fx (target >= 100x); fast loglik - reference loglik: min %.2g\n",
            mean(gm$reference_ms, na.rm = TRUE), mean(gm$fast_ms),
            mean(gm$reference_ms, na.rm = TRUE) / mean(gm$fast_ms[seq_len(n_ref)]),
            min(gm$loglik_gain, na.rm = TRUE)))
bench_record("GMM per call, fast", mean(gm$fast_ms), "ms")
bench_record("GMM per call, reference / fast", mean(gm$reference_ms, na.rm = TRUE) / mean(gm$fast_ms[seq_len(n_ref)]), "x")

# ---- whole-model volume with the fast engines -------------------------------
cat("\nFast engines on the volume of a whole model fit (33 types x 16 DoFs)\n")
reps <- bq(33, 2)
t_fpca <- cpu(system.time(for (r in seq_len(reps)) for (Y in per_dof) fpca_fit(Y, ncomp = 2)))
t_gmm <- cpu(system.time(for (r in seq_len(reps)) for (f in fast_fits) gmm_fit(f$scores, k = 2)))
t_warp <- cpu(system.time(for (r in seq_len(reps)) {
  wf <- fpca_fit(warps, ncomp = 1)
  gmm_fit(wf$scores, k = 2)
}))
cat(sprintf("CPU: 528 FPCAs %.2f s, 528 bivariate GMMs %.2f s, 33 warp FPCAs + 33 univariate GMMs %.2f s: total %.2f s\n",
            t_fpca, t_gmm, t_warp, t_fpca + t_gmm + t_warp))
bench_record(sprintf("fast engines, %d types x %d DoFs, CPU", reps, length(per_dof)), t_fpca + t_gmm + t_warp, "s")
cat(sprintf("machine load average at the end: %s\n",
            tryCatch(paste(readLines("/proc/loadavg", warn = FALSE), collapse = " "),
                     error = function(e) "unknown")))
