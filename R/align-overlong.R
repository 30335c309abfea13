# Removal of over-long recordings before time warping. Jeppsson (2017, 4.1.2)
# removed "any recorded grasp with significantly longer frame count than the
# rest" without stating a rule; ours is a documented robust outlier fence on
# the frame counts of one grasp type, so ordinary length variation survives
# and recordings that kept running after the grasp (2-3x as long) do not.

# The rule as an object (class overlong_rule): a recording is over-long when
# its frame count exceeds max(Q3 + iqr_mult * IQR, median_mult * median) of
# the frame counts of its grasp type (documented under fit_grasp_model()'s
# `overlong`).
overlong_rule <- function(iqr_mult = 3, median_mult = 1.5) {
  call <- rlang::caller_env()
  check_number(iqr_mult, "iqr_mult", min = 0, min_open = TRUE, call = call)
  check_number(median_mult, "median_mult", min = 0, min_open = TRUE, call = call)
  as_overlong_rule(c(iqr_mult = iqr_mult, median_mult = median_mult), call = call)
}

#' @export
print.overlong_rule <- function(x, ...) {
  cli::cat_line(sprintf("<overlong_rule> remove n > max(Q3 + %g * IQR, %g * median)", x$iqr_mult, x$median_mult))
  invisible(x)
}

# TRUE for the recordings of one grasp type whose frame count is over the
# rule's threshold (removed before time warping).
find_overlong <- function(n_frames, rule = overlong_rule()) {
  call <- rlang::caller_env()
  n_frames > overlong_threshold_impl(n_frames, rule, call)
}

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

# The `overlong` argument of the verbs: a named numeric c(iqr_mult =,
# median_mult =) (either may be left out: its default is used), a rule
# object, or NULL where `allow_null` (no removal).
as_overlong_rule <- function(x, allow_null = FALSE, arg = "overlong", call = rlang::caller_env()) {
  if (is.null(x) && allow_null) return(NULL)
  if (inherits(x, "overlong_rule")) return(x)
  known <- c("iqr_mult", "median_mult")
  if (!is.numeric(x) || !length(x) || is.null(names(x)) || !all(names(x) %in% known) ||
      anyDuplicated(names(x))) {
    hm_abort(c("{.arg {arg}} must be a named number vector {.code c(iqr_mult = 3, median_mult = 1.5)}{if (allow_null) ' or NULL' else ''}.",
               x = "Got {describe_value(x)}."), "bad_input", argument = arg, call = call)
  }
  x <- as.list(x)
  rule <- list(iqr_mult = x$iqr_mult %||% 3, median_mult = x$median_mult %||% 1.5)
  check_number(rule$iqr_mult, "iqr_mult", min = 0, min_open = TRUE, call = call)
  check_number(rule$median_mult, "median_mult", min = 0, min_open = TRUE, call = call)
  structure(rule, class = "overlong_rule")
}

