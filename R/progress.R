# Progress of the package's long calls (issue 36: no wait without a
# reason). Every loop that can take more than a couple of seconds (the fits
# per type, the folds, the horizons, the models a set of recordings is
# projected on) counts its steps with a progressr progressor, which also
# works from future workers. The outermost long call shows them, so a user
# sees progress without setting anything up:
#
# * `options(handmotion.progress = FALSE)` turns it off (nothing is
#   signalled or shown);
# * the bar is progressr's: `progressr::handlers("cli")` (or any other
#   handler) chooses how it looks, `progressr::handlers(list())` shows none;
# * it appears only after 2 s (progressr's `progressr.enable_after`, unless
#   the user set it), so quick calls stay quiet;
# * inside a call that already shows progress (reproduce_thesis(), or an
#   outer long call of the package) inner calls only count their steps.

progress_wanted <- function() isTRUE(getOption("handmotion.progress", TRUE))

# Evaluate `expr` showing the progress of the package's progressors in it.
with_progress_shown <- function(expr) {
  if (!progress_wanted() || isTRUE(getOption("handmotion.progress_listener")) || inside_with_progress()) {
    return(expr)
  }
  opts <- list(handmotion.progress_listener = TRUE)
  if (is.null(getOption("progressr.enable_after"))) opts$progressr.enable_after <- 2
  old <- options(opts)
  on.exit(options(old), add = TRUE)
  progressr::with_progress(expr, handlers = progressr::handlers(), enable = TRUE,
                           delay_stdout = FALSE, delay_conditions = character(0))
}

# A progressor of `steps` steps for the calling function, or a function that
# does nothing when progress is off or another progressor of the package is
# already counting (progressr draws one bar at a time: the outermost long
# step counts, the steps inside it do not).
hm_progressor <- function(steps, envir = parent.frame()) {
  if (!progress_wanted() || isTRUE(progress_state$active) || steps < 1) return(function(...) invisible(NULL))
  progress_state$active <- TRUE
  # (the release function itself goes into the caller's on.exit, as withr's
  # defer() does it)
  do.call(base::on.exit, list(as.call(list(progress_release)), add = TRUE), envir = envir)
  progressr::progressor(steps = steps, envir = envir)
}

progress_state <- new.env(parent = emptyenv())
progress_state$active <- FALSE

progress_release <- function() progress_state$active <- FALSE

# Is the call inside the user's own progressr::with_progress()? Then the
# progress goes to the user's handlers: a second with_progress() here would
# catch (and muffle) every update before it reached them.
inside_with_progress <- function() {
  wp <- progressr::with_progress
  n <- sys.nframe()
  for (i in seq_len(max(0L, n - 1L))) if (identical(sys.function(i), wp)) return(TRUE)
  FALSE
}
