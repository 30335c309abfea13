# Parsing speed of read_graspdb14() on the largest real sample (the 6674-line
# calibration stream), against utils::read.table() on the same file as a
# floor (read.table does no validation and no metadata).
# Run from the repository root: Rscript bench/read-graspdb14.R (BENCH_QUICK=1: seconds)
source("bench/_common.R")
f <- file.path("..", "shared", "data", "graspdb14", "00_calib-rad-su01.txt")
if (!file.exists(f)) f <- "/work/shared/data/graspdb14/00_calib-rad-su01.txt"
if (!file.exists(f)) {
  f <- system.file("extdata", "graspdb14", "00_calib-rad-su01.txt", package = "handmotion")
  cat("real sample absent; timing the small shipped example instead\n")
}
n_lines <- length(readLines(f))
res <- bench::mark(
  read_graspdb14 = read_graspdb14(f),
  parse_only = parse_graspdb14_content(f),
  read.table = utils::read.table(f),
  check = FALSE, min_iterations = bq(10, 2)
)
print(res[, c("expression", "min", "median", "mem_alloc")])
med <- as.numeric(res$median)
cat(sprintf("\n%s: %d lines\n", basename(f), n_lines))
cat(sprintf("read_graspdb14: %.3f s median (%.0f lines/s)\n", med[1], n_lines / med[1]))
cat(sprintf("ratio read_graspdb14 / read.table: %.1f\n", med[1] / med[3]))
bench_record("read_graspdb14, lines per second", n_lines / med[1], "1/s")
bench_record("read_graspdb14 / read.table", med[1] / med[3], "x")
