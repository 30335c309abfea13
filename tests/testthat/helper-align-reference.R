# The R references of align.R's compiled steps (tests only; bench/bench-align.R
# sources this file): the pairwise DTW with its engine choice, the shape
# normalisation, the stall lengths and the linear-mean template. The package
# itself calls the compiled batch versions.

# Multivariate DTW of one recording against a template
#
# Dynamic time warping with the Euclidean distance between frames (across
# all DoFs) and the `symmetric2` step pattern (the dtw package's default:
# diagonal steps weigh the local distance twice).
#
# @param x Numeric matrix, frames x DoFs (the recording).
# @param template Numeric matrix, frames x DoFs, same number of columns.
# @param engine `"fast"` (the package's C implementation) or `"reference"`
#   ([dtw::dtw()]); both give the same path and distance.
# @param window `NULL` (no constraint) or a non-negative number: the
#   half-width, in template frames, of a band around the diagonal slanted
#   from (1, 1) to (n, L) (dtw's `"slantedband"` window).
# @return A list: `index1` (frames of `x`) and `index2` (frames of
#   `template`), integer vectors of equal length giving the warping path from
#   (1, 1) to (n, L), and `distance`, the accumulated cost (not normalised).
# @examples
# t1 <- seq(0, 1, length.out = 30); t2 <- seq(0, 1, length.out = 40)^1.5
# x <- cbind(a = sin(pi * t1), b = t1^2)
# y <- cbind(a = sin(pi * t2), b = t2^2)
# p <- dtw_align_pair(x, y)
# p$distance
# head(cbind(p$index1, p$index2))
dtw_align_pair <- function(x, template, engine = c("fast", "reference"), window = NULL) {
  call <- rlang::caller_env()
  engine <- check_choice(engine, arg = "engine", call = call)
  x <- as_numeric_matrix(x, "x", " (frames x DoFs)", call = call)
  template <- as_numeric_matrix(template, "template", " (frames x DoFs)", call = call)
  if (ncol(x) != ncol(template)) {
    hm_abort("{.arg x} has {ncol(x)} column{?s} but {.arg template} has {ncol(template)}.",
             "bad_input", argument = "template", call = call)
  }
  window <- check_number(window, "window", min = 0, allow_null = TRUE, call = call)
  res <- tryCatch(
    if (engine == "fast") dtw_pair_fast(x, template, window)
    else dtw_pair_reference(x, template, window),
    error = function(e) {
      hm_abort(c("DTW failed.", x = conditionMessage(e)), "alignment_failed",
               call = call)
    })
  res
}

dtw_pair_fast <- function(x, template, window) {
  .Call(hm_dtw_pair, x, template, window)
}

shape_normaliser <- function(x, k = 3L) {
  n <- nrow(x)
  k <- min(k, n)
  centre <- (colMeans(x[seq_len(k), , drop = FALSE]) +
               colMeans(x[(n - k + 1L):n, , drop = FALSE])) / 2
  sdev <- if (n > 1L) sqrt(colSums((x - rep(colMeans(x), each = n))^2) / (n - 1L)) else rep(0, ncol(x))
  floor <- 0.1 * max(sdev)
  if (!is.finite(floor) || floor <= 0) floor <- 1
  list(centre = centre, scale = pmax(sdev, floor))
}

# (rep() rather than sweep(): called once per recording, sweep's checks cost
# more than the arithmetic)
normalise_recording <- function(x, nm) {
  n <- nrow(x)
  (x - rep(nm$centre, each = n)) / rep(nm$scale, each = n)
}

stall_lengths_r <- function(warps) {
  L <- ncol(warps)
  if (L < 2L) return(rep(1L, nrow(warps)))
  same <- warps[, -1L, drop = FALSE] == warps[, -L, drop = FALSE]
  apply(same, 1L, function(s) {
    r <- rle(s)
    if (any(r$values)) max(r$lengths[r$values]) + 1L else 1L
  })
}

mean_linear_template_r <- function(recs, L) {
  acc <- matrix(0, L, ncol(recs[[1]]))
  for (x in recs) acc <- acc + warp_linear(x, L)
  acc / length(recs)
}

# Resample recording x to L frames, equally spaced in original time.
warp_linear <- function(x, L) {
  if (!is.matrix(x)) x <- as.matrix(x)
  apply_warp(x, linear_warp_function(nrow(x), L))
}
