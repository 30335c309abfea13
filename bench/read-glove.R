# Reading speed of read_glove() on the shipped real recordings
# (inst/extdata/flexglove: 626 files in 8 label folders, a time column,
# uneven frames resampled to one rate), the one-liner of ?read_glove. Beside
# it, on the same files, utils::read.csv() and data.table::fread() one file
# at a time: floors that do no validation, no labels and no resampling.
# Run from the repository root: Rscript bench/read-glove.R (BENCH_QUICK=1: two folders)
source("bench/_common.R")

dir <- system.file("extdata", "flexglove", package = "handmotion")
pattern <- "^(?<grasp>[^/]+)/(?<subject>P\\d)_(?<object>[a-z]+)_(?<trial>\\d+)$"
if (bench_quick) {
  # two label folders copied aside: the same code path on a quarter of the files
  quick <- file.path(tempdir(), "flexglove-quick")
  dir.create(quick, showWarnings = FALSE)
  file.copy(file.path(dir, c("Ventral", "Writing_Tripod")), quick, recursive = TRUE)
  dir <- quick
}
files <- list.files(dir, pattern = "\\.csv$", recursive = TRUE, full.names = TRUE)
res <- bench::mark(
  read_glove = read_glove(dir, glove = "flexglove", time = "time_ms", pattern = pattern),
  read.csv = lapply(files, utils::read.csv),
  fread = lapply(files, data.table::fread, showProgress = FALSE),
  check = FALSE, min_iterations = bq(3, 1), max_iterations = bq(5, 1)
)
print(res[, c("expression", "min", "median", "mem_alloc")])
med <- as.numeric(res$median)
g <- read_glove(dir, glove = "flexglove", time = "time_ms", pattern = pattern)
cat(sprintf("\n%d files, %d recordings read, %d failures; load average %s\n", length(files), length(g),
            nrow(read_failures(g)), format(load_avg())))
cpu <- system.time(read_glove(dir, glove = "flexglove", time = "time_ms", pattern = pattern))
cat(sprintf("read_glove: %.2f s median elapsed, %.2f s CPU (%.1f ms per file)\n", med[1],
            cpu_of(cpu), 1000 * med[1] / length(files)))
cat(sprintf("ratio read_glove / read.csv: %.2f; / fread: %.2f\n", med[1] / med[2], med[1] / med[3]))
bench_record("read_glove flexglove, seconds", med[1], "s")
bench_record("read_glove / read.csv", med[1] / med[2], "x")
bench_record("read_glove / fread", med[1] / med[3], "x")
