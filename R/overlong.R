# Removal of over-long recordings before time warping. Jeppsson (2017, 4.1.2)
# removed "any recorded grasp with significantly longer frame count than the
# rest" without stating a rule; ours is a documented robust outlier fence on
# the frame counts of one grasp type, so ordinary length variation survives
# and recordings that kept running after the grasp (2-3x as long) do not.

#' Rule for over-long recordings
#'
#' A recording is over-long when its frame count exceeds
#' `max(Q3 + iqr_mult * IQR, median_mult * median)` of the frame counts of its
#' grasp type. The IQR fence is robust to the over-long recordings themselves;
#' the median floor keeps a type whose lengths happen to be nearly equal (IQR
#' close to 0) from losing ordinary recordings.
#'
#' @param iqr_mult Multiple of the interquartile range added to the upper
#'   quartile (default 3, Tukey's "far out" fence).
#' @param median_mult Recordings shorter than this multiple of the median
#'   frame count are never removed (default 1.5).
#' @return An object of class `overlong_rule`: `list(iqr_mult, median_mult)`.
#' @seealso [find_overlong()]
#' @examples
#' overlong_rule()
#' overlong_rule(iqr_mult = 2)
#' @export
overlong_rule <- function(iqr_mult = 3, median_mult = 1.5) {
  call <- rlang::caller_env()
  overlong_check_mult(iqr_mult, "iqr_mult", call)
  overlong_check_mult(median_mult, "median_mult", call)
  structure(list(iqr_mult = iqr_mult, median_mult = median_mult),
            class = "overlong_rule")
}

#' @export
print.overlong_rule <- function(x, ...) {
  cat(sprintf("<overlong_rule> remove n > max(Q3 + %g * IQR, %g * median)\n",
              x$iqr_mult, x$median_mult))
  invisible(x)
}

#' Find over-long recordings
#'
#' Flags the recordings of one grasp type whose frame count is much longer
#' than the rest (see [overlong_rule()]), to be removed before time warping.
#' Call it once per grasp type and keep the ids it flags: the removal is part
#' of the model's record.
#'
#' @param n_frames Integer (or numeric) vector of frame counts, one per
#'   recording of one grasp type. Missing values are an error.
#' @param rule An [overlong_rule()].
#' @return A logical vector as long as `n_frames`, `TRUE` = remove; names are
#'   kept. `overlong_threshold()` gives the frame count above which recordings
#'   are removed.
#' @examples
#' n <- c(40, 42, 38, 45, 41, 39, 44, 43, 110)
#' find_overlong(n)
#' @export
find_overlong <- function(n_frames, rule = overlong_rule()) {
  call <- rlang::caller_env()
  n_frames > overlong_threshold_impl(n_frames, rule, call)
}

#' @noRd
overlong_threshold <- function(n_frames, rule = overlong_rule()) {
  overlong_threshold_impl(n_frames, rule, rlang::caller_env())
}

overlong_threshold_impl <- function(n_frames, rule, call) {
  if (!is.numeric(n_frames) || length(n_frames) == 0L) {
    hm_abort("{.arg n_frames} must be a non-empty numeric vector of frame counts, not {describe_value(n_frames)}.",
             "bad_input", argument = "n_frames", call = call)
  }
  if (!all(is.finite(n_frames))) {
    bad <- which(!is.finite(n_frames))
    hm_abort(c("{.arg n_frames} must not contain missing or infinite values.",
               x = "At position{cli::qty(length(bad))}{?s} {.val {bad}}."),
             "bad_input", argument = "n_frames", call = call)
  }
  if (!inherits(rule, "overlong_rule")) {
    hm_abort("{.arg rule} must be made by {.fn overlong_rule}.",
             "bad_input", argument = "rule", call = call)
  }
  q <- stats::quantile(n_frames, c(0.25, 0.5, 0.75), names = FALSE, type = 7)
  max(q[3] + rule$iqr_mult * (q[3] - q[1]), rule$median_mult * q[2])
}

overlong_check_mult <- function(x, arg, call) {
  if (!is.numeric(x) || length(x) != 1L || is.na(x) || x <= 0 || !is.finite(x)) {
    hm_abort("{.arg {arg}} must be one positive number, not {.val {x}}.",
             "bad_input", argument = arg, call = call)
  }
  invisible(x)
}
