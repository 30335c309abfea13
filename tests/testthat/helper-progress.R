# The package shows progress bars of its long calls by default (R/progress.R);
# in the test run they would only clutter the output. test-progress.R turns
# them on where it tests them.
options(handmotion.progress = FALSE)
