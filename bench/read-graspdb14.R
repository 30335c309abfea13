# Reading speed of read_graspdb14(): (1) the largest real sample (the
# 6674-line calibration stream); (2) a directory of many files written by
# write_graspdb14() from simulated data (full: 5,000 files, about 1.5 million
# lines; issue 16 asks for 10 s or less). Beside it, on the same files,
# utils::read.table() and data.table::fread() one file at a time: floors
# that do no validation and no metadata.
# Run from the repository root: Rscript bench/read-graspdb14.R (BENCH_QUICK=1: seconds)
source("bench/_common.R")

# ---- one large real file ----
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
cat(sprintf("ratio read_graspdb14 / read.table: %.2f\n", med[1] / med[3]))
bench_record("read_graspdb14, lines per second", n_lines / med[1], "1/s")
bench_record("read_graspdb14 / read.table", med[1] / med[3], "x")

# ---- a directory of many files ----
# Six simulated recordings of the 16 DoFs end to end make one file (about
# 300 frames at 60 Hz, the length of a GraspDB14 trial); the 23 sensor
# columns repeat the first 7 DoFs, in radians.
n_files <- bq(5000, 150)
sim <- simulate_grasps(subjects = ceiling(n_files * 6 / 297), rate = 60, seed = 1)
sensors <- cyberglove_sensors$name
recs <- lapply(seq_len(n_files), function(i) {
  m <- do.call(rbind, sim$recordings[(i - 1) * 6 + 1:6])[, c(1:16, 1:7)] * pi / 180
  colnames(m) <- sensors
  m
})
k <- seq_len(n_files) - 1
meta <- data.frame(id = sprintf("r%05d", k), grasp = k %% 33 + 1, subject = sprintf("su%02d", k %/% 165 + 1),
                   object = graspdb14_objects$name[1], trial = k %% 165 + 1)
dir <- tempfile("bench-graspdb14-")
write_graspdb14(grasps(recs, meta = meta, dofs = sensors, rate = 60, unit = "rad"), dir)
rm(sim, recs)
files <- list.files(dir, full.names = TRUE)
dir_lines <- sum(vapply(files, function(p) length(readLines(p)), integer(1)))
reps <- bq(3, 1)
time_it <- function(expr) {
  expr <- substitute(expr)
  st <- lapply(seq_len(reps), function(i) system.time(eval(expr, parent.frame(3))))
  c(elapsed = vapply(st, `[[`, numeric(1), "elapsed"), cpu = vapply(st, cpu_of, numeric(1)))
}
t_read <- time_it(g <- read_graspdb14(dir))
stopifnot(length(g) == n_files, nrow(read_failures(g)) == 0L)
t_table <- time_it(for (p in files) utils::read.table(p))
t_fread <- time_it(for (p in files) data.table::fread(p, header = FALSE, showProgress = FALSE))
el <- function(t) t[grepl("^elapsed", names(t))]
cp <- function(t) t[grepl("^cpu", names(t))]
cat(sprintf("\n%d files, %d lines (%d repetitions; load average %s)\n", n_files, dir_lines, reps,
            format(load_avg())))
show <- function(name, t) {
  cat(sprintf("%-26s elapsed min %6.2f s, median %6.2f s; CPU median %6.2f s; %9.0f lines/s (min)\n",
              name, min(el(t)), stats::median(el(t)), stats::median(cp(t)), dir_lines / min(el(t))))
}
show("read_graspdb14(dir)", t_read)
show("read.table, file by file", t_table)
show("fread, file by file", t_fread)
cat(sprintf("ratio read_graspdb14 / read.table: %.2f (elapsed min), %.2f (CPU)\n",
            min(el(t_read)) / min(el(t_table)), stats::median(cp(t_read)) / stats::median(cp(t_table))))
cat(sprintf("ratio read_graspdb14 / fread:      %.2f (elapsed min), %.2f (CPU)\n",
            min(el(t_read)) / min(el(t_fread)), stats::median(cp(t_read)) / stats::median(cp(t_fread))))
bench_record("directory: files", n_files, "files")
bench_record("directory: lines", dir_lines, "lines")
bench_record("directory: read_graspdb14 elapsed (min)", min(el(t_read)), "s")
bench_record("directory: read_graspdb14 elapsed (median)", stats::median(el(t_read)), "s")
bench_record("directory: read_graspdb14 CPU (median)", stats::median(cp(t_read)), "s")
bench_record("directory: read_graspdb14, lines per second", dir_lines / min(el(t_read)), "1/s")
bench_record("directory: read_graspdb14 / read.table", min(el(t_read)) / min(el(t_table)), "x")
bench_record("directory: read_graspdb14 / fread", min(el(t_read)) / min(el(t_fread)), "x")
unlink(dir, recursive = TRUE)
