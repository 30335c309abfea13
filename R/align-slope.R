# The fallback warp of a recording whose DTW warp is degenerate (R/align.R,
# degenerate_warps = "constrain"): DTW under Sakoe and Chiba's slope
# constraint P = 1/2 (the dtw package's symmetricP05), whose local slopes lie
# between 1/3 and 3. Symmetric2 DTW may hold one recording frame over any
# number of template frames: where the template holds still (the rest before
# and the hold after a grasp) every path costs about the same, and the
# cheapest runs along the one best-matching recording frame, then along the
# template's last frame (an L-shaped path, the degenerate warp). Under the
# slope constraint a frame matches at most three template frames in a row,
# so the warp cannot stall, yet it may shift by any amount (unlike a band
# around the diagonal, which would cap the shift of a long or short rest).

# dtw::symmetricP05 as its table: pattern, di (recording), dj (template),
# weight (-1 marks each pattern's origin).
slope_pattern <- matrix(c(
  1, 1, 3, -1,  1, 0, 2, 2,  1, 0, 1, 1,  1, 0, 0, 1,
  2, 1, 2, -1,  2, 0, 1, 2,  2, 0, 0, 1,
  3, 1, 1, -1,  3, 0, 0, 2,
  4, 2, 1, -1,  4, 1, 0, 2,  4, 0, 0, 1,
  5, 3, 1, -1,  5, 2, 0, 2,  5, 1, 0, 1,  5, 0, 0, 1), ncol = 4, byrow = TRUE)

# The slope-constrained path of recording x against the template: index1,
# index2 and distance as dtw_pair_reference(). "fast" is src/dtw-slope.c,
# "reference" the dtw package (same path).
dtw_slope_pair <- function(x, template, engine = "fast") {
  if (engine == "fast") return(.Call(hm_dtw_pattern, x, template, slope_pattern))
  args <- list(x, template, step.pattern = dtw::symmetricP05, keep.internals = FALSE)
  if (ncol(x) > 1L) args$dist.method <- "Euclidean"
  r <- do.call(dtw::dtw, args)
  list(index1 = as.integer(r$index1), index2 = as.integer(r$index2), distance = r$distance)
}

# One recording's alignment to the template from a path: its warped frames
# (mean of the frames matched to each template frame), warping function
# (mean original frame, ends pinned) and distance, shaped as one row of
# dba_run()'s result.
path_alignment <- function(x, path, L) {
  cnt <- tabulate(path$index2, L)
  s <- rowsum(x[path$index1, , drop = FALSE], path$index2, reorder = TRUE)
  warps <- rowsum(path$index1, path$index2, reorder = TRUE)[, 1] / cnt
  list(warped = array(s / cnt, c(1L, L, ncol(x))),
       warps = pin_warp_ends(matrix(warps, 1L), nrow(x)), distance = path$distance,
       sum = unname(s), count = cnt)
}

# DTW barycenter averaging under the slope constraint, for a type whose
# template is suspect (most of its symmetric2 warps stalled: long rests and
# holds, where symmetric2 DBA only cycles through restarts). The same
# iteration as dba_run(), from `template`; a recording without a
# slope-constrained path (more than three times shorter or longer than the
# template) is left out of the template and warped linearly (`linear`).
dba_run_slope <- function(recs, template, engine, max_iter, tol) {
  L <- nrow(template)
  p <- ncol(template)
  align_all <- function(template) {
    lapply(recs, function(x) {
      path <- tryCatch(dtw_slope_pair(x, template, engine), error = function(e) NULL)
      if (!is.null(path)) path_alignment(x, path, L)
    })
  }
  res <- align_all(template)
  iterations <- 0L
  converged <- FALSE
  changes <- numeric(0)
  while (iterations < max_iter) {
    ok <- !vapply(res, is.null, logical(1))
    if (sum(ok) < 2L) break
    updated <- Reduce(`+`, lapply(res[ok], `[[`, "sum")) / Reduce(`+`, lapply(res[ok], `[[`, "count"))
    if (!all(is.finite(updated))) stop("the DBA template became non-finite")
    change <- sqrt(sum((updated - template)^2)) / max(sqrt(sum(template^2)), .Machine$double.eps)
    template <- updated
    changes <- c(changes, change)
    iterations <- iterations + 1L
    converged <- change < tol
    res <- align_all(template)
    if (converged) break
  }
  linear <- vapply(res, is.null, logical(1))
  if (sum(!linear) < 2L) stop("fewer than 2 recordings have a slope-constrained path")
  for (k in which(linear)) {
    x <- recs[[k]]
    wl <- linear_warp_function(nrow(x), L)
    res[[k]] <- list(warped = array(apply_warp(x, wl), c(1L, L, p)), warps = matrix(wl, 1L),
                     distance = NA_real_)
  }
  warped <- array(0, c(length(recs), L, p))
  for (k in seq_along(recs)) warped[k, , ] <- res[[k]]$warped[1L, , ]
  list(warped = warped, warps = do.call(rbind, lapply(res, `[[`, "warps")),
       distance = vapply(res, `[[`, numeric(1), "distance"), template = template,
       iterations = iterations, converged = converged, changes = changes, linear = linear)
}

# The whole type aligned by slope-constrained DBA (dba_run_slope()) from the
# linear mean, when dba_with_drops() found its template suspect (`fit$suspect`:
# most recordings stalled at once). Every recording that stalled under
# symmetric2 is listed in `degenerate` with fallback "slope" (or "linear"
# when it has no slope-constrained path); all are kept.
slope_dba_fit <- function(fit, recs, L, engine, max_iter, tol) {
  run <- dba_run_slope(recs, mean_linear_template(recs, L), engine, max_iter, tol)
  deg <- rbind(fit$degenerate, fit$suspect)
  deg <- deg[!duplicated(deg$id), , drop = FALSE]
  deg$fallback <- ifelse(run$linear[match(deg$id, names(recs))], "linear", "slope")
  extra <- setdiff(names(recs)[run$linear], deg$id)
  if (length(extra)) {
    deg <- rbind(deg, data.frame(id = extra, stall = NA_integer_,
                                 n_frames = vapply(recs[extra], nrow, integer(1)),
                                 fallback = "linear", stringsAsFactors = FALSE))
  }
  rownames(deg) <- NULL
  list(run = run, kept = seq_along(recs), degenerate = deg, dropped_warps = fit$dropped_warps,
       iterations = fit$iterations + run$iterations, converged = run$converged,
       changes = c(fit$changes, run$changes), step_pattern = "symmetricP05")
}
