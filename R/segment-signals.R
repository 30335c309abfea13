# The signals that find a grasping motion, shared by find_motion(),
# cut_motion() and the recogniser's onset detector (fit_onset_detector()).
#
# Every threshold is in units of a channel's own noise, estimated from the
# recording itself, because real gloves mix channels that move a lot with
# channels that only jitter (loose sensors, pressure pads that stay at zero
# until contact, stuck channels): scaling by a channel's spread over the set,
# as before, made a jittery channel's noise look like motion, and quantiles of
# the speed, on short recordings that are mostly motion, put the "still" level
# inside the motion (flexglove: median rest 0.00 s).
#
#  * noise: sd of the white noise of a channel, from the median absolute
#    second difference (robust to the motion, which is smooth, and to spikes);
#    floored at half the smallest step between frames (quantisation: a
#    channel in counts that never changes has noise 0.5, not 0).
#  * smoothed channel: running median of 3 frames with Tukey's end rule
#    (stats::runmed(v, 3, endrule = "median"); removes one-frame spikes).
#  * departure: the smoothed channel minus its rest level (the median of the
#    first `motion_rest_s` seconds), in noise sds; the largest absolute value
#    it keeps for `motion_sustain` frames is how far the channel moves
#    ("move"; a spike of one or two frames moves nothing).
#  * rate: central difference over +-`motion_rate_s` seconds, in noise sds of
#    that difference.
#
# A channel "moves" when its move and its peak rate are at least `min_move`
# noise sds: a channel that only jitters, or carries spikes, or is nearly
# constant, never reaches it, so it can never start or end a motion. (No
# threshold is relative to the other channels: a clean pressure pad that
# jumps by hundreds of sds at contact must not silence the fingers.)

motion_rest_s <- 0.15       # rest window for the rest level
motion_rate_s <- 0.12       # half-width of the rate's central difference
motion_level_z <- 4         # a channel is at rest while within 4 noise sds of its rest level
motion_rate_z <- 6          # ... or moving while its rate exceeds 6 noise sds of the rate
motion_rate_share <- 0.05   # ... and 5% of its peak rate
motion_edge_share <- 0.3    # the motion is first sure where a channel has moved 30% of its move
motion_sustain <- 3L         # a departure counts once it lasts 3 frames (spikes last 1 or 2)

# Noise sd per column of a matrix (see above). `spacing`: for a recording
# resampled from its time stamps (read_glove(time =)), its recorded rate over
# the grid's rate (recorded frames per grid frame; NA: as recorded). Linear
# interpolation averages neighbouring samples, which shrinks the second
# differences (by 40% at equal rates) more than the noise of a frame (by
# 18%), so on the grid the noise looked smaller than a frame's and onsets
# came early (flexglove: 3.27 frames MAE on the grid against 2.90 as
# recorded). The noise is therefore read from second differences over the
# recorded spacing, scaled by what interpolation does to them and to a
# frame (resampled_mad()). The quantisation
# floor too: see quantum_floor().
channel_noise <- function(X, spacing = NA_real_) {
  X <- as_double_matrix(X)
  base <- .Call(hm_motion_base, X, 0L, noise_lag(spacing))
  noise_from_mad(X, base$mad, base$floor, spacing)
}

# Recorded frames between the points of a second difference: 1 as recorded,
# the recorded spacing on a resampled grid.
noise_lag <- function(spacing) if (is.finite(spacing)) max(1L, as.integer(round(1 / spacing))) else 1L

# The noise sd per column from the MAD of its second differences (computed in
# src/motion-signals.c; Inf for a channel too short to have one), scaled and
# floored as above. `floor`: the quantisation floor as recorded, per column
# (the same C pass); on a resampled grid it is read from the flat frames
# here (quantum_floor()).
noise_from_mad <- function(X, mad, floor, spacing) {
  resampled <- is.finite(spacing)
  scale <- if (resampled) resampled_mad(spacing, noise_lag(spacing)) else 1
  if (resampled) {
    floor <- vapply(seq_len(ncol(X)), function(j) {
      v <- X[, j]
      quantum_floor(v[is.finite(v)], resampled)
    }, numeric(1))
  }
  stats::setNames(pmax(mad / sqrt(6) / scale, floor), colnames(X))
}

as_double_matrix <- function(X) {
  X <- as.matrix(X)
  if (!is.double(X)) storage.mode(X) <- "double"
  X
}

# Half the smallest step between a channel's values (0.5 for a channel that
# never changes): the noise of quantisation, the floor of the noise (it
# binds on channels that mostly hold still, whose second differences are
# mostly 0). On a grid resampled by linear interpolation the steps are cut
# into fractions, and a channel that holds still differs from itself by
# rounding dust: a channel in counts that changed by one count three times
# had a noise of 1e-14 and "moved". There, in a channel that holds still
# most of the time (most frames equal to both neighbours: interpolated
# between equal samples), the values as recorded are read on those flat
# frames and the floor is half the smallest step between them (0.5 if they
# are all one value).
quantum_floor <- function(v, resampled) {
  tol <- 1e-9 * max(1, abs(v))
  d <- abs(diff(v))
  if (resampled) {
    flat <- which(c(FALSE, d <= tol) & c(d <= tol, FALSE))
    if (length(flat) > length(v) / 2) {
      steps <- diff(sort(unique(round(v[flat] / tol) * tol)))
      return(if (any(steps > tol)) min(steps[steps > tol]) / 2 else 0.5)
    }
  }
  if (any(d > tol)) min(d[d > tol]) / 2 else 0.5
}

# The MAD of lag-`lag` second differences of unit white noise sampled at one
# frame and linearly interpolated onto a grid of `spacing` recorded frames
# per grid frame, relative to the same without interpolation (sqrt(6) sds),
# divided by the sd of one interpolated frame (what the departures and rates
# are measured in: interpolation averages two samples, so a grid frame
# carries sqrt(2/3) of a sample's noise). The grid's phase against the
# samples drifts (real intervals jitter: 27 to 32 ms on flexglove), so the
# second differences are a mixture over a uniform phase; the MAD of that
# mixture is solved for. Memoised: a set has a few recorded rates.
resampled_mad <- function(spacing, lag) {
  key <- sprintf("%.6f/%d", spacing, lag)
  if (!is.null(resampled_mad_memo[[key]])) return(resampled_mad_memo[[key]])
  phase <- (seq_len(64) - 0.5) / 64
  sds <- vapply(phase, function(u) {
    at <- u + c(-lag, 0, lag) * spacing
    knots <- seq(floor(min(at)), ceiling(max(at)))
    w <- vapply(knots, function(k) sum(c(1, -2, 1) * pmax(0, 1 - abs(at - k))), numeric(1))
    sqrt(sum(w^2))
  }, numeric(1))
  half <- stats::uniroot(function(m) mean(2 * stats::pnorm(m / sds) - 1) - 0.5, c(1e-6, 10))$root
  point <- sqrt(mean((1 - phase)^2 + phase^2))
  resampled_mad_memo[[key]] <- half / (stats::qnorm(0.75) * sqrt(6)) / point
}
resampled_mad_memo <- new.env(parent = emptyenv())

# Per recording of a set, its `spacing` for channel_noise(): recorded frames
# per grid frame where read_glove(time =) resampled it (`recorded_rate` in
# the metadata), NA where the frames are as recorded.
recorded_spacing <- function(x) {
  r <- x$meta$recorded_rate
  if (is.null(r)) return(rep(NA_real_, length(x)))
  as.numeric(r) / x$rate
}

# Frames of the rest window and of the rate's half-width at `rate` Hz.
rest_frames <- function(rate) max(3L, round(motion_rest_s * rate))
rate_lag <- function(rate) max(1L, round(motion_rate_s * rate))

# Signed rate per column: central difference over +-lag frames (clamped at
# the ends), per frame.
channel_rate <- function(S, lag) {
  n <- nrow(S)
  ahead <- pmin(seq_len(n) + lag, n)
  behind <- pmax(seq_len(n) - lag, 1L)
  (S[ahead, , drop = FALSE] - S[behind, , drop = FALSE]) / pmax(ahead - behind, 1L)
}

# Everything find_motion() and detect_onset() read from one recording:
# smoothed channels, noise, departure from rest (noise sds), moves, rate and
# the rate's noise sd. `noise` may be given (a fitted detector's); `spacing`
# as for channel_noise().
motion_signals <- function(rec, rate, noise = NULL, spacing = NA_real_) {
  rec <- as_double_matrix(rec)
  # the running median of 3 frames (Tukey's end rule), the rest levels and
  # the noise's MAD, in one compiled pass (src/motion-signals.c)
  base <- .Call(hm_motion_base, rec, rest_frames(rate), noise_lag(spacing))
  S <- base$S
  if (is.null(noise)) noise <- noise_from_mad(rec, base$mad, base$floor, spacing)
  n <- nrow(S)
  lag <- rate_lag(rate)
  D <- (S - rep(base$rest, each = n)) / rep(noise, each = n)
  R <- channel_rate(S, lag) / rep(noise * sqrt(2) / (2 * lag), each = n)
  held <- sustained(abs(D))
  # (column maxima, as apply(, 2, max), and the walks below in C:
  # src/motion-walks.c)
  list(S = S, noise = noise, D = D, held = held, move = col_max(held), lag = lag, R = R,
       peak_rate = col_max(abs(R)))
}

# max() of each column of a double matrix.
col_max <- function(X) stats::setNames(.Call(hm_col_max, X), colnames(X))

# Per column, the smallest of each frame and the next `motion_sustain - 1`
# frames: the level a departure keeps for `motion_sustain` frames.
sustained <- function(A) {
  n <- nrow(A)
  out <- A
  for (k in seq_len(motion_sustain - 1L)) out <- pmin(out, A[pmin(seq_len(n) + k, n), , drop = FALSE])
  out
}

# Channels that move: a move of at least `min_move` noise sds, reached at a
# peak rate of at least `min_move` noise sds of the rate (a hold's slow creep
# can add up to a large move, but slowly).
moving_channels <- function(move, peak_rate, min_move) {
  move[!is.finite(move)] <- 0
  peak_rate[!is.finite(peak_rate)] <- 0
  which(move >= min_move & peak_rate >= min_move)
}

# The onset of a motion, walked back from frame `sure[j]` of each moving
# channel j (where it is surely moving): first back to where that channel is
# within `motion_level_z` noise sds of its rest level, then, from the earliest
# channel, further back while the channels that leave rest with it are still
# moving in the direction of their move (their pooled rate, weighting each
# channel by its move, above `motion_rate_z` and `motion_rate_share` of its
# peak). The second
# walk finds the slow start of a smooth reach that is still inside the noise
# band of any one channel. Returns the onset and the channel that starts it.
walk_back_onset <- function(sig, use, sure) {
  a <- .Call(hm_walk_back, abs(sig$D[, use, drop = FALSE]), as.integer(sure), rep(motion_level_z, length(use)))
  first <- which.min(a)
  # pool the channels that leave rest together with the first (within the
  # rate's half-width): a channel that starts later, such as a pressure pad
  # at contact, is still at rest there and would only dilute the rate
  lead <- which(a <= a[first] + sig$lag)
  dir <- sign(sig$D[cbind(sure[lead], use[lead])])
  w <- sig$move[use[lead]] / sqrt(sum(sig$move[use[lead]]^2))
  pooled <- as.numeric(sig$R[, use[lead], drop = FALSE] %*% (dir * w))
  thr <- max(motion_rate_share * max(pooled), motion_rate_z)
  t <- .Call(hm_walk_back, matrix(pooled), a[first], thr)
  list(onset = t, lead = use[first])
}

# The end of a motion: for each moving channel, from its last frame at half
# its peak rate forward while
# its rate stays above `motion_rate_z` noise sds and `motion_rate_share` of its
# peak; the latest of these. Slow creep while holding is not motion.
walk_forward_end <- function(sig, use) {
  r <- abs(sig$R[, use, drop = FALSE])
  # (each channel's peak rate, max(abs(R[, j])), as motion_signals() found it)
  pk <- unname(sig$peak_rate[use])
  from <- .Call(hm_last_at_least, r, 0.5 * pk)
  ends <- .Call(hm_walk_forward, r, from, pmax(motion_rate_share * pk, motion_rate_z))
  max(ends)
}

# The motion of one recording: list(start, end, found, status, lead).
motion_span <- function(rec, rate, min_move, min_still, spacing = NA_real_) {
  n <- nrow(rec)
  none <- function(status) list(start = 1L, end = n, found = FALSE, status = status, lead = NA_character_)
  if (n < 2L * rest_frames(rate)) return(none("too short"))
  sig <- motion_signals(rec, rate, spacing = spacing)
  use <- moving_channels(sig$move, sig$peak_rate, min_move)
  if (!length(use)) return(none("rest only"))
  sure <- .Call(hm_first_above, sig$held[, use, drop = FALSE], motion_edge_share * sig$move[use])
  on <- walk_back_onset(sig, use, sure)
  a <- on$onset
  b <- max(walk_forward_end(sig, use), a)
  # a still phase shorter than min_still is part of the motion
  if (a - 1L < min_still) a <- 1L
  if (n - b < min_still) b <- n
  list(start = as.integer(a), end = as.integer(b), found = TRUE, status = "motion",
       lead = colnames(rec)[on$lead] %||% as.character(on$lead))
}
