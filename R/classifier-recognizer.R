# Early recognition: which grasp is the hand making while it is still
# closing? A VR or teleoperation loop sees frames one at a time and never
# knows how long the grasp will last, so the features may only use the
# frames seen so far: the postures at fractions of them and how far each DoF
# has travelled. One shrinkage LDA (R/classifier-shrunk-lda.R) per horizon h (frames
# since the recording began) is trained on the first h frames of every
# training recording; a recording that ended before h is continued by its
# last posture, as a hand at rest would be.

#' Fit an early grasp recogniser
#'
#' Trains one discriminant per horizon `h = 1, ..., horizon` frames: each
#' training recording is cut after its first `h` frames (continued by its
#' last posture if it is shorter: the hand has stopped), described by the
#' postures at fractions `at` of those frames and by how far each DoF has
#' travelled so far (log of 1 + the sum of absolute changes), and a
#' shrinkage LDA (as in [fit_grasp_classifier()]) is fitted on the result.
#' Nothing about a recording's final length is used, so the recogniser can
#' classify a live stream: [start_recognition()] makes a stream to
#' `update()` frame by frame, and [predict.grasp_recognizer()] classifies
#' whole sets, from their first frames or whole. After `horizon` frames (by default
#' 95% of the training grasps have ended by then) the prediction stays that
#' of the first `horizon` frames: what follows is mostly a hand at rest.
#'
#' @param x A labelled [grasps()] object (the training recordings).
#' @param at Fractions of the frames seen so far at which the posture is
#'   taken (0 = the first frame, 1 = the newest).
#' @param horizon Number of horizons (frames) with their own discriminant;
#'   by default the 95th percentile of the training durations.
#' @return An object of class `grasp_recognizer`: `classes`, `levels` (of
#'   the training labels, carried by predictions), `at`, `dofs`,
#'   `rate`, `horizon`, `fits` (one discriminant per horizon) and `n`.
#' @seealso [start_recognition()], [evaluate_early_recognition()],
#'   [fit_grasp_classifier()] for complete recordings.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 5, grasps = 1:3, objects = 2, trials = 2, seed = 1)
#' rec <- fit_grasp_recognizer(g[g$meta$subject != "S05"])
#' rec
#' test <- g[g$meta$subject == "S05"]
#' # from the first 300 ms of every held-out recording
#' mean(predict(rec, test, ms = 300)$.pred_class == test$meta$grasp)
#' summary(rec)
fit_grasp_recognizer <- function(x, at = c(0, 0.25, 0.5, 0.75, 1), horizon = NULL) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  at <- check_fractions(at, "at", call = call)
  warn_short_recordings(x, action = "fitted")
  warn_few_recordings(x)
  # recordings that rest before the grasp are read from their motion onset
  det <- if (resolve_motion(x, "auto") == "trim") fit_onset_detector(x)
  x <- from_onset(x, det)
  y <- check_training_labels(x, call = call)
  recognizer_fit(x, y, at, recognizer_horizon(x, horizon, call), onset = det)
}

# The number of horizons: given, or the 95th percentile of the durations.
recognizer_horizon <- function(x, horizon, call) {
  H <- horizon %||% as.integer(ceiling(stats::quantile(x$meta$n_frames, 0.95, names = FALSE)))
  check_whole(H, "horizon", max = 1e4, call = call)
}

# The discriminants at `horizons`: every one of 1..H for a recogniser that
# streams; evaluate_early_recognition() fits only the horizons its held-out
# recordings are classified at (the others stay NULL, and such a recogniser
# never leaves it).
recognizer_fit <- function(x, y, at, H, horizons = seq_len(H), onset = NULL) {
  prefix <- prefix_source(x)
  fits <- vector("list", H)
  fits[horizons] <- lapply(horizons, function(h) fit_shrunk_lda(prefix_features(prefix, h, at), y))
  first <- fits[[horizons[1]]]
  new_grasp_recognizer(first$classes, grasp_levels(x), at, x$dofs, x$rate, H, fits, first$n, onset)
}

# The recogniser in the classifier family (R/classifier.R): its distance is
# minus the log posterior, so its temperature is 1. `onset`: the motion-onset
# detector new recordings are read from (NULL: from their first frame).
new_grasp_recognizer <- function(classes, levels, at, dofs, rate, horizon, fits, n, onset = NULL) {
  new_grasp_classifier(at = at, dofs = dofs, rate = rate, horizon = horizon, fits = fits, onset = onset,
                       classes = classes, levels = levels, n = n, temperature = 1, class = "grasp_recognizer")
}

# `seen`: frames seen of each recording of new_data, which predict() has
# already read from the motion's onset; without it (classify()) the whole
# recordings are read from their onset, as predict() reads them by default.
#' @export
classifier_distances.grasp_recognizer <- function(object, new_data, seen = NULL, ..., call = rlang::caller_env()) {
  check_trained_dofs(new_data, object$dofs, "recogniser", call = call)
  if (is.null(seen)) {
    new_data <- from_onset(new_data, object$onset)
    seen <- new_data$meta$n_frames
  }
  neg_log_posterior(recognizer_scores(object, new_data, seen))
}

#' @export
classifier_method.grasp_recognizer <- function(object) "recognizer"

#' @export
classifier_parts.grasp_recognizer <- function(object) c(NextMethod(), "at", "dofs", "horizon", "fits")

# What the features of every horizon are read from: the recordings stacked
# (frames x DoFs, as doubles) and the distance each DoF has travelled up to
# each frame, with each recording's first row and length. A recording cut
# after h frames and continued by its last posture (the hand has stopped)
# has its frame min(t, n) at time t and its travel up to min(h, n); nothing
# of size recordings x horizons x DoFs is built (the former prefix arrays
# took more time than the fits and n x H x p x 16 bytes of memory).
prefix_source <- function(x) {
  recs <- x$recordings
  nk <- vapply(recs, nrow, integer(1))
  S <- do.call(rbind, recs)
  storage.mode(S) <- "double"
  S <- unname(S)
  starts <- cumsum(nk) - nk
  travel <- matrix(0, nrow(S), ncol(S))
  # frame by frame over all recordings at once, in the order of the former
  # running sum (so the travel is the same to the last bit)
  for (t in seq_len(max(c(nk, 1L)))[-1L]) {
    r <- starts[nk >= t] + t
    travel[r, ] <- travel[r - 1L, , drop = FALSE] + abs(S[r, , drop = FALSE] - S[r - 1L, , drop = FALSE])
  }
  list(frames = S, travel = travel, starts = starts, n_frames = nk)
}

# Features at horizon h for the given recordings: the postures at fractions
# `at` of the h frames (ordered fraction-fastest: DoF 1 at every fraction,
# then DoF 2, ...), then the log travel of every DoF. Training and batch
# prediction both come through here; a live stream computes the same
# numbers incrementally (stream_features()).
prefix_features <- function(prefix, h, at, rows = seq_along(prefix$n_frames)) {
  n <- length(rows)
  p <- ncol(prefix$frames)
  ix <- fraction_index(h, at)
  nk <- prefix$n_frames[rows]
  st <- prefix$starts[rows]
  frame <- function(t) st + pmin(rep(t, each = n), nk)   # rows of frame t of every recording
  lo <- prefix$frames[frame(ix$lo), , drop = FALSE]
  hi <- prefix$frames[frame(ix$hi), , drop = FALSE]
  P <- lo * rep(1 - ix$w, each = n) + hi * rep(ix$w, each = n)
  # rows are (recording, fraction) with recording fastest: columns DoF-major
  dim(P) <- c(n, length(at) * p)
  cbind(P, log1p(prefix$travel[st + pmin(h, nk), , drop = FALSE]))
}

# The same features of one stream's frames seen so far (rows of `buf`).
stream_features <- function(buf, h, at, travel) {
  ix <- fraction_index(h, at)
  c(buf[ix$lo, , drop = FALSE] * (1 - ix$w) + buf[ix$hi, , drop = FALSE] * ix$w, log1p(travel))
}

# Frames seen of each recording of x (at least 1): the whole recording
# unless one of frames, ms and fraction says otherwise.
seen_frames <- function(x, frames, ms, fraction, call) {
  given <- !c(is.null(frames), is.null(ms), is.null(fraction))
  if (sum(given) > 1L) {
    hm_abort("Give at most one of {.arg frames}, {.arg ms} and {.arg fraction} (none: the whole recording).",
             "bad_input", argument = "frames", call = call)
  }
  n <- length(x$recordings)
  if (!any(given)) return(as.integer(x$meta$n_frames))
  if (given[1]) return(rep(check_whole(frames, "frames", max = 1e6, call = call), n))
  if (given[2]) {
    ms <- check_number(ms, "ms", min = 0, min_open = TRUE, call = call)
    return(rep(max(1L, as.integer(round(ms * x$rate / 1000))), n))
  }
  fraction <- check_number(fraction, "fraction", min = 0, max = 1, min_open = TRUE, call = call)
  pmax(1L, as.integer(round(fraction * x$meta$n_frames)))
}

# Log posteriors of recordings seen for `seen` frames each, from the same
# prefix arrays and features as the training (recordings grouped by horizon).
recognizer_scores <- function(object, x, seen) {
  s <- matrix(NA_real_, length(seen), length(object$classes),
              dimnames = list(x$meta$id, object$classes))
  seen <- pmin(seen, object$horizon) # past the horizon: the first `horizon` frames
  prefix <- prefix_source(x)
  for (h in unique(seen)) {
    rows <- which(seen == h)
    s[rows, ] <- shrunk_lda_scores(object$fits[[h]], prefix_features(prefix, h, object$at, rows))
  }
  s
}

#' @export
print.grasp_recognizer <- function(x, ...) {
  cli::cat_line(cli::pluralize(
    "<grasp_recognizer> {length(x$classes)} grasp type{?s}, {sum(x$n)} training recording{?s}, "),
    sprintf("horizons 1-%d frames (%.0f ms at %g Hz)", as.integer(x$horizon), 1000 * x$horizon / x$rate, x$rate))
  cli::cat_line("  features: postures at ", paste(signif(x$at, 3), collapse = ", "),
                " of the frames seen + travel per DoF; shrinkage LDA per horizon")
  invisible(x)
}

#' @rdname summary.grasp_classifier
#' @export
summary.grasp_recognizer <- function(object, ...) {
  last <- object$fits[[object$horizon]]
  classifier_summary_frame(object, log_prior = last$log_prior)
}
