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
# index2 and distance as dtw_align_pair(). "fast" is src/dtw-slope.c,
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
       warps = pin_warp_ends(matrix(warps, 1L), nrow(x)), distance = path$distance)
}
