# Fitting benchmark: all 33 per-type models on the full default simulated data
# (30 subjects x 33 types x 3 objects x 3 trials = 8910 recordings).
# Target on the 2-core reference machine: 30 s or less.
# Run from the repository root: Rscript bench/bench-fit.R
pkgload::load_all(".", quiet = TRUE)

t_sim <- system.time(g <- simulate_grasps())[["elapsed"]]
cat(sprintf("simulate_grasps(): %d recordings in %.2f s\n", length(g), t_sim))

run <- function(label) {
  tt <- system.time(ms <- fit_grasp_models(g, seed = 1))
  t <- tt[["elapsed"]]
  steps <- rowSums(vapply(unclass(ms), function(m) m$timing[c("align", "fpca", "gmm")], numeric(3)))
  cat(sprintf("%-28s %6.2f s for %d models (target 30 s: %s)\n", label, t, length(ms),
              if (t <= 30) "met" else "MISSED"))
  cat(sprintf("  time inside the fits: align %.2f s, fpca %.2f s, gmm %.2f s\n",
              steps[1], steps[2], steps[3]))
  # elapsed time is inflated when other jobs share the cores: CPU time of this
  # process (the main one; workers' CPU is not included) and the load average
  cat(sprintf("  CPU time of the main process %.2f s; load average %s\n",
              tt[["user.self"]] + tt[["sys.self"]],
              tryCatch(paste(utils::head(strsplit(readLines("/proc/loadavg"), " ")[[1]], 3), collapse = " "),
                       error = function(e) "unknown")))
  invisible(list(models = ms, seconds = t))
}

future::plan(future::sequential)
seq_run <- run("sequential plan:")
if (future::supportsMulticore()) {
  future::plan(future::multicore, workers = 2)
  par_run <- run("multicore plan, 2 workers:")
  same <- identical(lapply(unclass(seq_run$models), function(m) m[setdiff(names(m), "timing")]),
                    lapply(unclass(par_run$models), function(m) m[setdiff(names(m), "timing")]))
  cat(sprintf("  speed-up %.2fx; identical models to the sequential fit: %s\n",
              seq_run$seconds / par_run$seconds, same))
  future::plan(future::sequential)
}

s <- summary(seq_run$models)
ve <- unlist(lapply(unclass(seq_run$models), function(m) 100 * rowSums(m$var_explained)))
cat(sprintf("\nfitted types: %d of 33; failed: %d\n", nrow(s), nrow(attr(seq_run$models, "failed"))))
cat(sprintf("variance explained by 2 FPCs per DoF: min %.2f%%, median %.2f%%, mean %.2f%%, max %.2f%%\n",
            min(ve, na.rm = TRUE), stats::median(ve, na.rm = TRUE), mean(ve, na.rm = TRUE), max(ve, na.rm = TRUE)))
cat(sprintf("DoFs below 80%%: %d of %d\n", sum(ve < 80, na.rm = TRUE), length(ve)))
cat(sprintf("recordings used %d of %d (over-long %d, degenerate warps %d); linear warping in %d types; EM fallbacks on %d DoFs\n",
            sum(s$n_used), sum(s$n_input), sum(s$n_overlong), sum(s$n_degenerate),
            sum(s$warping == "linear"), sum(s$n_em_fallback)))
