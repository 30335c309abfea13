# Where the grasping motion is. Real recordings start with the hand at rest
# and end holding the object; the thesis' recordings were cut to the motion.
# The motion is found from the joint speed: every channel scaled by its
# spread over the set (so raw counts and degrees weigh alike and a stuck
# channel not at all), differentiated, combined into one speed per frame and
# smoothed; then a hysteresis threshold between the recording's still level
# and its peak speed finds where the motion starts and ends.

#' Find the grasping motion in recordings that rest before and hold after it
#'
#' `find_motion()` locates, in each recording, the frames of the grasping
#' motion between a rest phase before it and a hold phase after it.
#' `trim_motion()` cuts each recording to that motion (recordings without a
#' clear motion are kept whole and listed). `cut_motion()` cuts a continuous
#' stream into one recording per motion.
#'
#' The speed of frame `t` is the root mean square over channels of the
#' central difference of each channel divided by its spread (the
#' interquartile range of the channel over all recordings, so channels in
#' counts and in degrees weigh alike and constant channels not at all),
#' smoothed by a moving average of `smooth` seconds. With `still` the speed
#' while the hand is still (the 10% quantile of the recording's speed) and
#' `peak` its 98% quantile, the motion is where the speed exceeds `still +
#' high * (peak - still)`, extended on both sides while it exceeds `still +
#' low * (peak - still)` (hysteresis: tremor during rest and hold does not
#' start or end a motion, and the slow start of a reach is still counted).
#' `trim_motion()` keeps the span from the first onset to the last end, so a
#' grasp that pauses midway stays one grasp.
#'
#' @param x A [grasps()] object.
#' @param high,low The hysteresis thresholds, as fractions of the way from
#'   the still speed to the peak speed (`0 < low < high < 1`).
#' @param smooth Width of the moving average of the speed, in seconds.
#' @param min_still Shortest still phase, in seconds, at the start or end of
#'   a recording for it to count as rest or hold; shorter ones are kept as
#'   part of the motion.
#' @param min_motion,min_gap For `cut_motion()`: the shortest motion kept,
#'   and the shortest still gap that separates two motions, in seconds.
#' @return `find_motion()`: a data frame with one row per recording: `id`,
#'   `start` and `end` (first and last frame of the motion), `n_frames`,
#'   `rest` and `hold` (frames before and after it) and `found` (`FALSE`
#'   where no motion stands out from the still speed; then `start` is 1 and
#'   `end` the last frame). `trim_motion()`: the recordings cut to their
#'   motion, with metadata columns `trim_start` and `trim_end` (the frames
#'   kept, in the original recording) and the attribute `motion` (the
#'   `find_motion()` table). `cut_motion()`: one recording per motion, with
#'   `parent` (the stream's id), `trim_start` and `trim_end`.
#' @seealso [fit_grasp_model()] (argument `motion`), [segment_by_switch()]
#' @export
#' @examples
#' raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 3, pen = 20), objects = 1,
#'                        trials = 3, glove = "resistive", rest = 1, hold = 1, seed = 1)
#' m <- find_motion(raw)
#' cbind(m[c("id", "start", "end")], planted = raw$meta$motion_start)
#' trim_motion(raw)
find_motion <- function(x, high = 0.15, low = 0.03, smooth = 0.08, min_still = 0.1) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  check_some_recordings(x, what = "find motion in", call = call)
  high <- check_number(high, "high", min = 0, max = 1, min_open = TRUE, call = call)
  low <- check_number(low, "low", min = 0, max = high, min_open = TRUE, call = call)
  smooth <- check_number(smooth, "smooth", min = 0, max = 10, call = call)
  min_still <- check_number(min_still, "min_still", min = 0, max = 60, call = call)
  spread <- channel_spread(x)
  width <- smoothing_width(smooth, x$rate)
  rows <- lapply(seq_along(x), function(i) {
    s <- motion_speed(x$recordings[[i]], spread, width)
    motion_span(s, high, low, max(1L, round(min_still * x$rate)))
  })
  n <- x$meta$n_frames
  start <- vapply(rows, `[[`, integer(1), "start")
  end <- vapply(rows, `[[`, integer(1), "end")
  data.frame(id = x$meta$id, start = start, end = end, n_frames = n, rest = start - 1L,
             hold = n - end, found = vapply(rows, `[[`, logical(1), "found"), stringsAsFactors = FALSE)
}

#' @rdname find_motion
#' @param ... For `trim_motion()` and `cut_motion()`: passed to
#'   `find_motion()`.
#' @export
trim_motion <- function(x, ...) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  m <- find_motion(x, ...)
  recs <- Map(function(r, a, b) r[a:b, , drop = FALSE], x$recordings, m$start, m$end)
  meta <- x$meta
  meta$trim_start <- m$start
  meta$trim_end <- m$end
  out <- new_grasps(recs, meta, x$dofs, x$rate, x$unit, glove = x$glove)
  attr(out, "motion") <- m
  out
}

#' @rdname find_motion
#' @export
cut_motion <- function(x, min_motion = 0.3, min_gap = 0.3, high = 0.15, low = 0.03, smooth = 0.08) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  check_some_recordings(x, what = "cut", call = call)
  min_motion <- check_number(min_motion, "min_motion", min = 0, max = 600, call = call)
  min_gap <- check_number(min_gap, "min_gap", min = 0, max = 600, call = call)
  spread <- channel_spread(x)
  width <- smoothing_width(smooth, x$rate)
  pieces <- list()
  meta_rows <- list()
  for (i in seq_along(x)) {
    s <- motion_speed(x$recordings[[i]], spread, width)
    lv <- speed_levels(s, high, low)
    runs <- motion_runs(s, lv, round(min_gap * x$rate), round(min_motion * x$rate))
    for (k in seq_len(nrow(runs))) {
      runs$start[k] <- edge_extrapolate(s, runs$start[k], lv, forward = TRUE)
      runs$end[k] <- edge_extrapolate(s, runs$end[k], lv, forward = FALSE)
      id <- sprintf("%s-m%d", x$meta$id[i], k)
      pieces[[id]] <- x$recordings[[i]][runs$start[k]:runs$end[k], , drop = FALSE]
      row <- x$meta[i, , drop = FALSE]
      row$parent <- x$meta$id[i]
      row$id <- id
      row$trim_start <- runs$start[k]
      row$trim_end <- runs$end[k]
      meta_rows[[id]] <- row
    }
  }
  if (!length(pieces)) {
    hm_abort("No motion found in {.arg x}: the speed never stands out from its still level.",
             c("no_segments", "bad_recording"), argument = "x", call = call)
  }
  meta <- do.call(rbind, meta_rows)
  new_grasps(pieces, meta, x$dofs, x$rate, x$unit, glove = x$glove)
}

# Frames of the speed's moving average: `smooth` seconds, at least one.
smoothing_width <- function(smooth, rate) max(1L, round(smooth * rate))

# The spread of each channel over every frame of a set (interquartile range,
# else the range), zero for a constant channel.
channel_spread <- function(x) {
  X <- do.call(rbind, x$recordings)
  apply(X, 2, function(v) {
    q <- stats::quantile(v, c(0.25, 0.75), names = FALSE)
    if (q[2] > q[1]) q[2] - q[1] else diff(range(v))
  })
}

# Speed per frame: root mean square over the varying channels of the scaled
# central difference, smoothed by a centred moving average of `width` frames.
motion_speed <- function(rec, spread, width, lag = width %/% 2L) {
  n <- nrow(rec)
  use <- spread > 0
  if (n < 3L || !any(use)) return(rep(0, n))
  r <- sweep(rec[, use, drop = FALSE], 2, spread[use], "/")
  # central difference over +-lag frames (clamped at the ends): per-frame
  # differences of counts are mostly quantisation noise at high rates
  lag <- max(1L, lag)
  ahead <- pmin(seq_len(n) + lag, n)
  behind <- pmax(seq_len(n) - lag, 1L)
  d <- (r[ahead, , drop = FALSE] - r[behind, , drop = FALSE]) / (ahead - behind)
  s <- sqrt(rowMeans(d^2))
  if (width > 1L && n > width) {
    k <- rep(1 / width, width)
    f <- stats::filter(s, k, sides = 2)
    f[is.na(f)] <- s[is.na(f)]
    s <- as.numeric(f)
  }
  s
}

# Thresholds between the still level and the peak of a speed curve.
# The still level is the median of the slowest 30% of frames and its noise
# their spread; the low level stays 4 noise sds above the still level, so
# tremor during rest and hold does not pass for motion.
speed_levels <- function(s, high, low) {
  slow <- s[s <= stats::quantile(s, 0.3, names = FALSE)]
  still <- stats::median(slow)
  noise <- stats::mad(slow)
  peak <- stats::quantile(s, 0.98, names = FALSE)
  lo <- still + max(low * (peak - still), 4 * noise)
  list(still = still, peak = peak, hi = max(still + high * (peak - still), lo), lo = lo,
       clear = peak > 4 * still + 1e-12)
}

# The one motion of a recording: first crossing of the high level, walked back
# while above the low level; the same from the end.
motion_span <- function(s, high, low, min_still) {
  n <- length(s)
  lv <- speed_levels(s, high, low)
  above <- which(s > lv$hi)
  if (!lv$clear || !length(above)) return(list(start = 1L, end = n, found = FALSE))
  a <- above[1]
  while (a > 1L && s[a - 1L] > lv$lo) a <- a - 1L
  a <- edge_extrapolate(s, a, lv, forward = TRUE)
  b <- above[length(above)]
  while (b < n && s[b + 1L] > lv$lo) b <- b + 1L
  b <- edge_extrapolate(s, b, lv, forward = FALSE)
  # a still phase shorter than min_still is part of the motion
  if (a - 1L < min_still) a <- 1L
  if (n - b < min_still) b <- n
  list(start = as.integer(a), end = as.integer(b), found = TRUE)
}

# Every motion of a stream: runs above the low level of `lv` (speed_levels())
# that reach its high level, joined across gaps shorter than `min_gap`, at least `min_len` long.
motion_runs <- function(s, lv, min_gap, min_len) {
  empty <- data.frame(start = integer(), end = integer())
  if (!lv$clear) return(empty)
  r <- rle(s > lv$lo)
  ends <- cumsum(r$lengths)
  starts <- ends - r$lengths + 1L
  on <- which(r$values)
  runs <- data.frame(start = starts[on], end = ends[on])
  runs <- runs[vapply(seq_len(nrow(runs)), function(k) any(s[runs$start[k]:runs$end[k]] > lv$hi), logical(1)), ,
               drop = FALSE]
  if (!nrow(runs)) return(empty)
  joined <- runs[1, ]
  for (k in seq_len(nrow(runs))[-1]) {
    last <- nrow(joined)
    if (runs$start[k] - joined$end[last] - 1L < min_gap) joined$end[last] <- runs$end[k]
    else joined <- rbind(joined, runs[k, ])
  }
  joined <- joined[joined$end - joined$start + 1L >= min_len, , drop = FALSE]
  rownames(joined) <- NULL
  joined
}

# A smooth reach starts with a speed that grows like the square of the time
# since onset (minimum-jerk profiles), so the threshold crossing comes a few
# frames late. The square root of the speed above the still level rises
# linearly: fit a line to it on the rising edge (from the low-level crossing
# to half the peak) and take its zero as the onset; the same backwards for
# the end. The crossing is kept when the edge is too short to fit.
edge_extrapolate <- function(s, at, lv, forward = TRUE) {
  n <- length(s)
  half <- lv$still + 0.5 * (lv$peak - lv$still)
  idx <- if (forward) at:n else at:1
  stop_at <- which(s[idx] >= half)[1]
  if (is.na(stop_at) || stop_at < 3L) return(at)
  t <- idx[seq_len(stop_at)]
  y <- sqrt(pmax(s[t] - lv$still, 0))
  fit <- stats::lm.fit(cbind(1, t), y)
  b <- fit$coefficients
  if (anyNA(b) || (forward && b[2] <= 0) || (!forward && b[2] >= 0)) return(at)
  # never further back than half the edge (a minimum-jerk start lies a third
  # of it back): a shallow fit is not evidence of an early start
  reach <- (stop_at - 1L) %/% 2L
  t0 <- round(-b[1] / b[2])
  if (forward) as.integer(min(max(t0, 1, at - reach), at)) else as.integer(max(min(t0, n, at + reach), at))
}

# Share of still frames (rest plus hold) above which "auto" trims a set: the
# twin of HUST, cut to the motion, has a median of about 16% (its last few
# frames hold); a glove recording with a second of rest and of holding
# around a one-second reach, about 65%.
motion_auto_share <- 0.35

# "auto", "trim" or "as_recorded" for a set: auto measures the median still
# share on up to 200 recordings, evenly spread (deterministic).
resolve_motion <- function(x, motion, call = rlang::caller_env()) {
  motion <- check_choice(motion, c("auto", "trim", "as_recorded"), arg = "motion", call = call)
  if (motion != "auto") return(motion)
  if (length(x) == 0L) return("as_recorded")
  idx <- unique(round(seq(1, length(x), length.out = min(200L, length(x)))))
  m <- find_motion(x[idx])
  if (stats::median((m$rest + m$hold) / m$n_frames) > motion_auto_share) "trim" else "as_recorded"
}

# What a model of trimmed recordings keeps of their still phases: the rest
# and hold lengths (frames) of every recording with the length of its motion
# between them (generation draws the three together: on flexglove a long
# motion comes with a short hold, r = -0.4, and rest and hold drawn apart
# from the motion made generated durations too spread, KS 0.29 against 0.20
# real-vs-real), and the tremor per channel (the standard deviation of each
# channel about its mean within a still phase, pooled over the phases at
# least 3 frames long).
still_phases <- function(x, motion) {
  p <- length(x$dofs)
  ss <- numeric(p)
  df <- 0
  for (i in seq_along(x)) {
    r <- x$recordings[[i]]
    for (rows in list(seq_len(motion$rest[i]), motion$end[i] + seq_len(motion$hold[i]))) {
      if (length(rows) < 3L) next
      seg <- r[rows, , drop = FALSE]
      ss <- ss + colSums(sweep(seg, 2, colMeans(seg))^2)
      df <- df + length(rows) - 1
    }
  }
  list(rest = as.integer(motion$rest), hold = as.integer(motion$hold),
       motion = as.integer(motion$end - motion$start + 1L),
       tremor = stats::setNames(if (df > 0) sqrt(ss / df) else numeric(p), x$dofs))
}

# --- onset detection for recognition -------------------------------------
# A recogniser of recordings that start at rest must know where the motion
# starts without seeing its end. The detector is fitted once on the training
# recordings (channel spreads, and the median high and low speed levels of
# their motions) and then reads a recording, or a live stream, from the
# start: the motion starts where the speed first passes the high level,
# walked back to where it passed the low one. The speed is centred, so the
# detector looks `lag + width / 2` frames ahead (about 80 ms).
fit_onset_detector <- function(x, high = 0.15, low = 0.03, smooth = 0.08) {
  spread <- channel_spread(x)
  width <- smoothing_width(smooth, x$rate)
  lv <- lapply(x$recordings, function(r) speed_levels(motion_speed(r, spread, width), high, low))
  list(spread = spread, width = width, hi = stats::median(vapply(lv, `[[`, 0, "hi")),
       lo = stats::median(vapply(lv, `[[`, 0, "lo")), rate = x$rate)
}

# The onset frame of one recording by a fitted detector, NA when the speed
# never passes the high level.
detect_onset <- function(rec, det) {
  s <- motion_speed(rec, det$spread, det$width)
  a <- which(s > det$hi)[1]
  if (is.na(a)) return(NA_integer_)
  while (a > 1L && s[a - 1L] > det$lo) a <- a - 1L
  as.integer(a)
}

# Recordings cut to start at their detected onset (kept whole where none is
# found; a NULL detector changes nothing). Metadata column `onset`.
from_onset <- function(x, det) {
  if (is.null(det)) return(x)
  on <- vapply(x$recordings, detect_onset, integer(1), det = det)
  start <- ifelse(is.na(on), 1L, on)
  recs <- Map(function(r, a) r[a:nrow(r), , drop = FALSE], x$recordings, start)
  meta <- x$meta
  meta$onset <- on
  new_grasps(recs, meta, x$dofs, x$rate, x$unit, glove = x$glove)
}
