# A live recognition stream: the state a VR loop keeps between frames. It
# lives in an environment, so update() changes it in place and costs one
# feature vector and one discriminant per frame; it keeps the first
# `horizon` frames only (after them the prediction no longer changes).

#' Recognise a grasp frame by frame
#'
#' `start_recognition()` opens a stream on a fitted recogniser;
#' `update(stream, frame)` adds the newest frame (one value per DoF, in the
#' recogniser's DoF order and units) and returns the current class
#' probabilities. The stream is updated in place: keep calling `update()` on
#' the same object. `start_recognition()` again for the next grasp.
#'
#' @param recognizer A [fit_grasp_recognizer()] result.
#' @param object A stream from `start_recognition()`.
#' @param frame A numeric vector with one finite value per DoF (names, if
#'   given, must be the DoFs).
#' @param ... Not used.
#' @return `start_recognition()`: an object of class `grasp_stream`.
#'   `update()`: a named vector of class probabilities (summing to 1), with
#'   attributes `frames` (seen so far) and `ms`, of class
#'   `grasp_probabilities`: it prints with three decimals, `<0.001` and
#'   `>0.999` beyond them; the stored numbers are the model's own.
#' @seealso [fit_grasp_recognizer()], [evaluate_early_recognition()]
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 1:3, objects = 2, trials = 2, seed = 1)
#' rec <- fit_grasp_recognizer(g)
#' stream <- start_recognition(rec)
#' r <- g$recordings[[1]]
#' for (t in 1:10) p <- update(stream, r[t, ])
#' p  # three decimals; the stored values are the model's own
#' stream
start_recognition <- function(recognizer) {
  if (!inherits(recognizer, "grasp_recognizer")) {
    hm_abort("{.arg recognizer} must be made by {.fn fit_grasp_recognizer}, not {.obj_type_friendly {recognizer}}.",
             "bad_input", argument = "recognizer", call = rlang::caller_env())
  }
  check_fitted_parts(recognizer, "recognizer", call = rlang::caller_env())
  state <- new.env(parent = emptyenv())
  state$recognizer <- recognizer
  state$buffer <- matrix(0, recognizer$horizon, length(recognizer$dofs))
  state$h <- 0L
  state$travel <- numeric(length(recognizer$dofs))
  state$probs <- NULL
  # a recogniser of recordings that rest first waits for the motion's onset
  state$waiting <- !is.null(recognizer$onset)
  state$pending <- matrix(0, 0L, length(recognizer$dofs))
  structure(list(state = state), class = "grasp_stream")
}

#' @rdname start_recognition
#' @export
update.grasp_stream <- function(object, frame, ...) {
  st <- object$state
  rec <- st$recognizer
  p <- length(rec$dofs)
  if (!is.numeric(frame) || length(frame) != p || !all(is.finite(frame))) {
    hm_abort("{.arg frame} must hold {p} finite numbers (one per DoF: {.val {rec$dofs}}).",
             "bad_input", argument = "frame", call = rlang::caller_env())
  }
  if (!is.null(names(frame)) && !identical(names(frame), rec$dofs)) { # never reorder silently
    hm_abort("{.arg frame} is named but not by the recogniser's DoFs in order.", "bad_input",
             argument = "frame", call = rlang::caller_env())
  }
  if (isTRUE(st$waiting)) {
    # keep the last two seconds; once the motion starts, replay it from its onset
    keep <- max(2L, round(2 * rec$rate))
    st$pending <- utils::tail(rbind(st$pending, frame), keep)
    on <- if (nrow(st$pending) >= 3L) detect_onset(st$pending, rec$onset) else NA_integer_
    if (is.na(on)) {
      prior <- rep(1 / length(rec$classes), length(rec$classes))
      return(new_grasp_probabilities(stats::setNames(prior, rec$classes), frames = 0L, ms = 0, motion = FALSE))
    }
    st$waiting <- FALSE
    replay <- st$pending[on:nrow(st$pending), , drop = FALSE]
    st$pending <- NULL
    for (k in seq_len(nrow(replay))) out <- update.grasp_stream(object, replay[k, ])
    return(out)
  }
  h <- st$h + 1L
  st$h <- h
  # past the horizon the prediction is that of the first `horizon` frames
  if (h <= rec$horizon) {
    st$buffer[h, ] <- frame
    if (h > 1L) st$travel <- st$travel + abs(frame - st$buffer[h - 1L, ])
    f <- stream_features(st$buffer, h, rec$at, st$travel)
    st$probs <- softmax_rows(shrunk_lda_scores(rec$fits[[h]], matrix(f, 1L)))[1L, ]
  }
  probs <- st$probs
  new_grasp_probabilities(probs, frames = h, ms = 1000 * h / rec$rate, motion = TRUE)
}

#' @export
print.grasp_stream <- function(x, ...) {
  st <- x$state
  ms <- sprintf("%.0f", 1000 * st$h / st$recognizer$rate)
  top <- if (!is.null(st$probs)) utils::head(sort(st$probs, decreasing = TRUE), 3)
  likely <- if (length(top)) paste("; most likely:", paste(sprintf("%s %.0f%%", names(top), 100 * top), collapse = ", "))
  cli::cat_line(cli::pluralize("<grasp_stream> {st$h} frame{?s} seen ({ms} ms)"), likely)
  invisible(x)
}
