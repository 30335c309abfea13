# Where the grasping motion is. Real recordings start with the hand at rest
# and end holding the object; the thesis' recordings were cut to the motion.
# The signals (each channel's noise, departure from rest and rate, in noise
# sds) are in segment-signals.R, shared with cut_motion() and the recogniser's
# onset detector.

#' Find the grasping motion in recordings that rest before and hold after it
#'
#' `find_motion()` locates, in each recording, the frames of the grasping
#' motion between a rest phase before it and a hold phase after it.
#' `trim_motion()` cuts each recording to that motion (recordings without a
#' clear motion are kept whole and listed). `cut_motion()` cuts a continuous
#' stream into one recording per motion.
#'
#' Every channel is measured in units of its own noise (the robust sd of its
#' second differences, so a smooth motion does not count as noise), after a
#' running median of 3 frames that removes one-frame spikes. A channel
#' *moves* when it leaves its rest level (the median of the first 0.15 s) by
#' at least `min_move` noise sds for at least 3 frames, at a peak rate of at
#' least `min_move` noise sds; channels that only jitter, carry spikes or hardly change
#' never move, so they never start or end a motion, and a pressure pad that
#' rises at contact moves late and does not start it either. A recording
#' where no channel moves is reported as rest only.
#'
#' The motion starts where the first moving channel leaves the band of 4
#' noise sds around its rest level (found walking back from where it has
#' made 30% of its move), extended back while the moving channels together
#' are still moving in the direction of their move (their rate, pooled with
#' weights proportional to their moves, above 6 noise sds and 5% of its peak:
#' the slow start of a smooth reach). It ends where the last moving channel
#' slows below those rate levels after its last frame at half its peak rate
#' (slow creep while holding is not motion).
#'
#' Recordings that [read_glove()] resampled from their time stamps (metadata
#' column `recorded_rate`) have their noise estimated as recorded: linear
#' interpolation averages neighbouring samples and would make the noise look
#' smaller than the sensor's, so the second differences are scaled by what
#' interpolation does to white noise at that recorded rate, and the
#' quantisation floor is read on the values as recorded.
#'
#' @param x A [grasps()] object.
#' @param min_move How far, in noise sds, a channel must leave its rest level
#'   to count as moving.
#' @param min_still Shortest still phase, in seconds, at the start or end of
#'   a recording for it to count as rest or hold; shorter ones are kept as
#'   part of the motion.
#' @param min_motion,min_gap For `cut_motion()`: the shortest motion kept,
#'   and the shortest still gap that separates two motions, in seconds.
#' @return `find_motion()`: a data frame with one row per recording: `id`,
#'   `start` and `end` (first and last frame of the motion), `n_frames`,
#'   `rest` and `hold` (frames before and after it), `found`, `status`
#'   (`"motion"`, `"rest only"` where no channel moves, or `"too short"`
#'   under 0.3 s; then `found` is `FALSE`, `start` is 1 and `end` the last
#'   frame) and `lead` (the channel whose departure starts the motion).
#'   `trim_motion()`: the recordings cut to their motion, with metadata
#'   columns `trim_start`, `trim_end` (the frames kept, in the original
#'   recording) and `motion_status`, and the attribute `motion` (the
#'   `find_motion()` table); recordings without a motion are kept whole and
#'   named in a message. `cut_motion()`: one recording per motion, with
#'   `parent` (the stream's id), `trim_start` and `trim_end`.
#' @seealso [fit_grasp_model()] (argument `motion`), [segment_by_switch()]
#' @export
#' @examples
#' raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 3, pen = 20), objects = 1,
#'                        trials = 3, glove = "resistive", rest = 1, hold = 1, seed = 1)
#' m <- find_motion(raw)
#' cbind(m[c("id", "start", "end", "lead")], planted = raw$meta$motion_start)
#' trim_motion(raw)
find_motion <- function(x, min_move = 12, min_still = 0.1) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  check_some_recordings(x, what = "find motion in", call = call)
  min_move <- check_number(min_move, "min_move", min = 3, max = 1e6, call = call)
  min_still <- check_number(min_still, "min_still", min = 0, max = 60, call = call)
  # the recordings whose motion the fit around this call has found already
  # are read from its table (R/segment-found-once.R); the others are found
  known <- known_motion(x, min_move, min_still)
  todo <- which(is.na(known))
  rows <- Map(motion_span, x$recordings[todo], recorded_spacing(x)[todo], MoreArgs = list(
    rate = x$rate, min_move = min_move, min_still = max(1L, round(min_still * x$rate))))
  n <- x$meta$n_frames[todo]
  start <- vapply(rows, `[[`, integer(1), "start")
  end <- vapply(rows, `[[`, integer(1), "end")
  found <- data.frame(id = x$meta$id[todo], start = start, end = end, n_frames = n, rest = start - 1L,
                      hold = n - end, found = vapply(rows, `[[`, logical(1), "found"),
                      status = vapply(rows, `[[`, character(1), "status"),
                      lead = vapply(rows, `[[`, character(1), "lead"), stringsAsFactors = FALSE)
  if (length(todo) == length(x)) return(found)
  out <- motion_found$table[known, , drop = FALSE]
  out[todo, ] <- found
  rownames(out) <- NULL
  out
}

#' @rdname find_motion
#' @param ... For `trim_motion()`: passed to `find_motion()`.
#' @export
trim_motion <- function(x, ...) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  m <- find_motion(x, ...)
  recs <- Map(function(r, a, b) r[a:b, , drop = FALSE], x$recordings, m$start, m$end)
  meta <- x$meta
  meta$trim_start <- m$start
  meta$trim_end <- m$end
  meta$motion_status <- m$status
  if (any(!m$found)) inform_no_motion(m$id[!m$found], m$status[!m$found], nrow(m))
  out <- new_grasps(recs, meta, x$dofs, x$rate, x$unit, glove = x$glove)
  attr(out, "motion") <- m
  out
}

#' @rdname find_motion
#' @export
cut_motion <- function(x, min_motion = 0.3, min_gap = 0.3, min_move = 12) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  check_some_recordings(x, what = "cut", call = call)
  min_motion <- check_number(min_motion, "min_motion", min = 0, max = 600, call = call)
  min_gap <- check_number(min_gap, "min_gap", min = 0, max = 600, call = call)
  min_move <- check_number(min_move, "min_move", min = 3, max = 1e6, call = call)
  pieces <- list()
  meta_rows <- list()
  spacing <- recorded_spacing(x)
  for (i in seq_along(x)) {
    runs <- stream_runs(x$recordings[[i]], x$rate, min_move, round(min_gap * x$rate), round(min_motion * x$rate),
                        spacing[i])
    for (k in seq_len(nrow(runs))) {
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
    hm_abort("No motion found in {.arg x}: no channel's rate stands out from its noise.",
             c("no_segments", "bad_recording"), argument = "x", call = call)
  }
  meta <- do.call(rbind, meta_rows)
  new_grasps(pieces, meta, x$dofs, x$rate, x$unit, glove = x$glove)
}

# Every motion of a stream. There is no one rest level in a stream, so a
# channel moves when its peak rate reaches `min_move` noise sds; the activity is the root mean square of the moving
# channels' rates (noise sds), and a motion is a run above the rate level of
# find_motion() (6 noise sds, 5% of the activity's peak) that reaches twice
# it, joined across gaps shorter than `min_gap` frames, at least `min_len` long.
stream_runs <- function(rec, rate, min_move, min_gap, min_len, spacing = NA_real_) {
  empty <- data.frame(start = integer(), end = integer())
  if (nrow(rec) < 2L * rest_frames(rate)) return(empty)
  sig <- motion_signals(rec, rate, spacing = spacing)
  use <- moving_channels(sig$peak_rate, sig$peak_rate, min_move)
  if (!length(use)) return(empty)
  act <- sqrt(rowMeans(sig$R[, use, drop = FALSE]^2))
  lo <- max(motion_rate_share * max(act), motion_rate_z)
  r <- rle(act > lo)
  ends <- cumsum(r$lengths)
  starts <- ends - r$lengths + 1L
  on <- which(r$values)
  runs <- data.frame(start = starts[on], end = ends[on])
  runs <- runs[vapply(seq_len(nrow(runs)), function(k) any(act[runs$start[k]:runs$end[k]] > 2 * lo), logical(1)), ,
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

# Share of still frames (rest plus hold) above which "auto" trims a set: the
# twin of HUST, cut to the motion, has a median of about 16% (its last few
# frames hold); a glove recording with a second of rest and of holding
# around a one-second reach, about 65%.
motion_auto_share <- 0.35

# "auto", "trim" or "as_recorded" for a set: auto measures the median still
# share on up to 200 recordings, evenly spread (deterministic).
# (resolve_motion_found() also finds every recording's motion when the set
# is trimmed: R/segment-found-once.R)
resolve_motion <- function(x, motion, call = rlang::caller_env()) {
  resolve_motion_found(x, motion, call, find_all = FALSE)$motion
}
motion_auto_sample <- 200L

# "auto"'s decision from the find_motion() table of a set's sample.
auto_motion <- function(m) {
  if (stats::median((m$rest + m$hold) / m$n_frames) > motion_auto_share) "trim" else "as_recorded"
}

# What a model of trimmed recordings keeps of their still phases: the rest
# and hold lengths (frames) of every recording with the length of its motion
# between them (generation draws the three together: on flexglove a long
# motion comes with a short hold, r = -0.4, and rest and hold drawn apart
# from the motion made generated durations too spread, KS 0.29 against 0.20
# real-vs-real), the path of every rest and hold as deviations from the
# posture it leads into (the onset) or follows (the end), the motion's
# displacement (end posture less onset posture) that generation matches
# donors on, and the tremor per channel (the standard deviation of each
# channel about its mean within a still phase, pooled over the phases at
# least 3 frames long). A hold is no frozen posture: on flexglove the
# fingers relax back by about a tenth of the reach after it (the drift
# over the hold against the reach's displacement, slope -0.05 to -0.10),
# and holding the end posture with tremor alone put the postures at 75% and
# 100% of a recording 1.2-1.3 times as far from the other participant's.
still_phases <- function(x, motion) {
  p <- length(x$dofs)
  ss <- numeric(p)
  df <- 0
  n <- length(x)
  rest_path <- hold_path <- vector("list", n)
  displacement <- matrix(0, n, p, dimnames = list(NULL, x$dofs))
  for (i in seq_len(n)) {
    r <- x$recordings[[i]]
    rest_rows <- seq_len(motion$rest[i])
    hold_rows <- motion$end[i] + seq_len(motion$hold[i])
    for (rows in list(rest_rows, hold_rows)) {
      if (length(rows) < 3L) next
      seg <- r[rows, , drop = FALSE]
      ss <- ss + colSums(sweep(seg, 2, colMeans(seg))^2)
      df <- df + length(rows) - 1
    }
    onset <- r[motion$start[i], ]
    end <- r[motion$end[i], ]
    rest_path[[i]] <- unname(r[rest_rows, , drop = FALSE] - rep(onset, each = length(rest_rows)))
    hold_path[[i]] <- unname(r[hold_rows, , drop = FALSE] - rep(end, each = length(hold_rows)))
    displacement[i, ] <- end - onset
  }
  list(rest = as.integer(motion$rest), hold = as.integer(motion$hold),
       motion = as.integer(motion$end - motion$start + 1L),
       rest_path = rest_path, hold_path = hold_path, displacement = displacement,
       tremor = stats::setNames(if (df > 0) sqrt(ss / df) else numeric(p), x$dofs))
}

# --- onset detection for recognition -------------------------------------
# A recogniser of recordings that start at rest must know where the motion
# starts without seeing its end. The detector is fitted once on the training
# recordings (each channel's noise, the median over them, and the channels
# that move in most of them) and then reads a recording, or a live stream,
# from the start with find_motion()'s signals: the motion is sure once a
# moving channel has left its rest level by `min_move` noise sds, and its
# onset is walked back from there as in find_motion(). The rate is centred,
# so the detector looks `motion_rate_s` (0.12 s) ahead.
fit_onset_detector <- function(x, min_move = 12) {
  spacing <- recorded_spacing(x)
  per_recording <- matrix(unlist(Map(channel_noise, x$recordings, spacing), use.names = FALSE),
                          nrow = length(x$dofs))
  noise <- apply(per_recording, 1, stats::median)
  moving <- vapply(x$recordings, function(r) {
    sig <- motion_signals(r, x$rate, noise)
    seq_along(x$dofs) %in% moving_channels(sig$move, sig$peak_rate, min_move)
  }, logical(length(x$dofs)))
  share <- rowMeans(matrix(moving, nrow = length(x$dofs)))
  list(noise = noise, use = which(share >= 0.5), min_move = min_move, rate = x$rate)
}

# The onset frame of one recording by a fitted detector, NA while no moving
# channel has left its rest level by `min_move` noise sds.
detect_onset <- function(rec, det) {
  if (!length(det$use) || nrow(rec) < 3L) return(NA_integer_)
  sig <- motion_signals(rec, det$rate, det$noise)
  sure <- vapply(det$use, function(j) which(sig$held[, j] >= det$min_move)[1], integer(1))
  if (all(is.na(sure))) return(NA_integer_)
  keep <- !is.na(sure)
  walk_back_onset(sig, det$use[keep], sure[keep])$onset
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
