# The package's main job on the embedded default data: simulate the HUST-like
# twin, fit all 33 grasp models, classify, and render the thesis reproduction
# report with its tables and figures into the folder given (default "output").
args <- commandArgs(trailingOnly = TRUE)
out <- if (length(args)) args[1] else "output"
report <- handmotion::reproduce_thesis(out)
cat("handmotion: report written to", normalizePath(report), "\n")
