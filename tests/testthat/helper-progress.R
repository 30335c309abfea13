# The package shows progress bars of its long calls by default (R/progress.R);
# in the test run they would only clutter the output. test-progress.R turns
# them on where it tests them.
options(handmotion.progress = FALSE)

# Evaluate `expr` as an outer listener (reproduce_thesis()'s printer) hears
# it: the package's long calls count their steps and draw no bar of their own.
as_listener <- function(expr) {
  local_progress_listener()
  expr
}
