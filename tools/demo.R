# The package's main job on the embedded default data: simulate the HUST-like
# twin, fit all 33 grasp models, classify, and render the thesis reproduction
# report with its tables and figures into the folder given (default "output").
args <- commandArgs(trailingOnly = TRUE)
out <- if (length(args)) args[1] else "output"
# Use both cores for the model fits and the held-out folds (the package itself
# never sets a future plan; the user, here the demo script, chooses it).
if (requireNamespace("future", quietly = TRUE) && future::supportsMulticore()) {
  future::plan(future::multicore, workers = min(2L, future::availableCores()))
}
# (reproduce_thesis() says step by step what it does and, at the end, where the report is)
# `make demo` renders its report afresh each time it is run, so it replaces
# the previous one on purpose (reproduce_thesis() itself refuses without
# overwrite = TRUE).
invisible(handmotion::reproduce_thesis(out, overwrite = TRUE))
