# Real recordings are the judge (issue 40): every figure of the issue on
# flexglove (626 real recordings of a 6-flex-sensor glove, 2 participants,
# 8 grasp types, shipped in inst/extdata/flexglove with its MIT notice), in
# one table beside the published figures and the goals, with the default
# data's figures beside them where the issue asks that they hold.
#
# The published figures come from the data's source repository (its README:
# two-fold by participant, window-level, with 97 synthetic copies of
# participant 1 left in, so optimistic); they appear only as a comparison
# column, never in a computation.
#
# Run from the repository root after `R CMD INSTALL --no-multiarch .`:
#   Rscript bench/bench-real.R     (BENCH_QUICK=1: fewer repetitions and no
#                                   wide-glove simulation; the same folds)

source("bench/_common.R")
cat(sprintf("%s; load average %s on %d cores\n\n", bench_build, load_avg(), parallel::detectCores()))

rows <- list()
# One row of the table: the figure, ours, the published one (if any) and the goal.
report <- function(figure, value, unit, published = NA, goal = NA, better = c("higher", "lower"),
                   shown = figure) {
  better <- match.arg(better)
  met <- if (is.na(goal)) NA else if (better == "higher") value >= goal else value <= goal
  rows[[length(rows) + 1L]] <<- data.frame(figure = shown, ours = value, unit = unit,
                                           published = published, goal = goal,
                                           met = met, stringsAsFactors = FALSE)
  bench_record(figure, value, unit)
}
timed <- function(expr) {
  t <- system.time(value <- force(expr))
  list(value = value, elapsed = t[["elapsed"]], cpu = t[["user.self"]] + t[["sys.self"]])
}
# A timing row: the elapsed time is judged against the goal; the CPU time of
# this process is said beside it (on a busy machine elapsed time is inflated;
# with workers, their CPU is not in this process's).
report_time <- function(figure, t, goal = NA) {
  report(figure, t$elapsed, "s", goal = goal, better = "lower",
         shown = sprintf("%s (CPU %.2f s)", figure, t$cpu))
  bench_record(paste(figure, "CPU"), t$cpu, "s")
}

# --- reading ------------------------------------------------------------------
dir <- system.file("extdata", "flexglove", package = "handmotion")
rd <- timed(read_glove(dir, glove = "flexglove", time = "time_ms",
                       pattern = "^(?<grasp>[^/]+)/(?<subject>P\\d)_(?<object>[a-z]+)_(?<trial>\\d+)$"))
g <- rd$value
cat(sprintf("flexglove: %d recordings, %d channels, %d labels, participants %s; read in %.2f s\n",
            length(g), length(g$dofs), length(unique(g$meta$grasp)),
            paste(sort(unique(g$meta$subject)), collapse = "/"), rd$elapsed))
report("recordings read (of 626)", length(g), "n", goal = 626)
report_time("read 626 files", rd)

# --- segmentation ---------------------------------------------------------------
fm <- timed(find_motion(g))
m <- fm$value
# the plain threshold (as in bench/bench-segment.R): the first frame where any
# channel has left its initial level (the median of its first 3 frames) by
# more than a fifth of its range over the recording
plain_onset <- function(r) {
  dev <- abs(sweep(r, 2, apply(r[1:3, , drop = FALSE], 2, stats::median)))
  rng <- apply(r, 2, function(v) diff(range(v)))
  hit <- which(apply(sweep(dev, 2, pmax(rng, 1e-9), "/") > 0.2, 1, any))
  if (length(hit)) hit[1] else 1L
}
plain <- vapply(g$recordings, plain_onset, integer(1))
report("median rest, find_motion() (s)", stats::median(m$rest) / g$rate, "s")
report("median rest, plain threshold (s)", stats::median(plain - 1) / g$rate, "s")
report("|median rest - plain threshold's| (s)",
       abs(stats::median(m$rest) - stats::median(plain - 1)) / g$rate, "s", goal = 0.3, better = "lower")
# the motion of 80 recordings marked by eye (tests/testthat/fixtures), in
# frame numbers of the files as recorded. First on those frames (the files'
# counts without their time column), then on the resampled grid of `g`
# (the marked frame's time stamp against the detected frame's time)
marks <- utils::read.csv("tests/testthat/fixtures/flexglove-motion.csv", comment.char = "#")
marked <- lapply(marks$file, function(f) as.matrix(utils::read.csv(file.path(dir, f))))
as_recorded <- grasps(lapply(marked, function(x) x[, -1]), rate = 33.3, unit = "raw",
                      meta = data.frame(id = marks$file, grasp = marks$label, subject = marks$subject))
mr <- find_motion(as_recorded)
report("onset MAE vs 80 hand marks (frames as recorded)", mean(abs(mr$start - marks$onset)), "frames",
       goal = 3, better = "lower")
report("end MAE vs 80 hand marks (frames as recorded)", mean(abs(mr$end - marks$end)), "frames")
grid_frame <- function(x, frame) 1 + (x[frame, "time_ms"] - x[1, "time_ms"]) / 1000 * g$rate
at <- match(sub("[.]csv$", "", marks$file), m$id)
report("onset MAE vs marks (resampled to 33.3 Hz)",
       mean(abs(m$start[at] - mapply(grid_frame, marked, marks$onset))), "frames")
report("end MAE vs marks (resampled to 33.3 Hz)",
       mean(abs(m$end[at] - mapply(grid_frame, marked, marks$end))), "frames")
report_time("find_motion(), 626 recordings", fm)

# --- models: alignment keeps the recordings, fitting is fast ---------------------
ft <- timed(fit_grasp_models(g, seed = 1))
ms <- ft$value
s <- summary(ms)
report("recordings used by the thesis model", sum(s$n_used) / sum(s$n_input), "fraction",
       goal = 0.95)
report_time("fit_grasp_models(), flexglove", ft, goal = 3)

# a stand-in for the second glove: 168 recordings of 23 raw channels, about
# 380 frames at 100 Hz (1.4 s of rest), one person, six objects
wide <- wide_glove(bq(6, 3), bq(28, 8))
wide_chan <- length(wide$dofs)
fw <- timed(fit_grasp_models(wide, seed = 1))
report_time(sprintf("fit_grasp_models(), %d x %d ch x %.0f frames (simulated)", length(wide), wide_chan,
                    mean(wide$meta$n_frames)), fw, goal = if (length(wide) >= 168) 3 else NA)

# --- classifiers: leave one participant out ------------------------------------
published <- c(fpca = NA, last_frame = NA, discriminant = NA, weighted_fpca = NA)
goal <- c(fpca = 0.75)
best <- 0
for (method in c("fpca", "last_frame", "discriminant", "weighted_fpca")) {
  ev <- timed(evaluate_loso(g, method = method, in_sample = FALSE))
  acc <- ev$value$accuracy[["held_out"]]
  best <- max(best, acc)
  report(sprintf("LOPO accuracy, %s", method), acc, "fraction",
         goal = if (method %in% names(goal)) goal[[method]] else NA)
  ps <- ev$value$per_subject
  for (k in seq_len(nrow(ps))) {
    report(sprintf("  %s, held-out %s", method, ps$subject[k]), ps$accuracy[k], "fraction")
  }
  report_time(sprintf("evaluate_loso(method = '%s')", method), ev, goal = 10)
}
er <- timed(evaluate_early_recognition(g, ms = c(300, 1000, 3000), fractions = 1))
acc_at <- function(scale, value) er$value$accuracy[er$value$scale == scale & er$value$value == value]
report("LOPO accuracy, recogniser (whole recording)", acc_at("fraction", 1), "fraction")
report("  recogniser after 300 ms of motion", acc_at("ms", 300), "fraction")
best <- max(best, acc_at("fraction", 1))
report_time("evaluate_early_recognition()", er, goal = 15)
report("LOPO accuracy, best classifier", best, "fraction", published = 0.80, goal = 0.85)
report("  published CNN-BiLSTM (window-level, optimistic)", NA, "fraction", published = 0.695)

# --- generation: generated against real grasps, by participant folds ------------
# (one seed's MMD ratio moves by about 0.05-0.1 with the seed on flexglove's
# two participants: the full run gives the mean of three seeds and their
# range, the quick run one seed)
gen_seeds <- bq(1:3, 1L)
gens <- lapply(gen_seeds, function(s) {
  timed(evaluate_generation(recordings = g, split = "subject", folds = 2, reps = bq(5, 2), seed = s))
})
ratios <- do.call(rbind, lapply(gens, function(x) {
  v <- x$value
  v[v$grasp == "overall" & v$metric == "mmd", c("model", "ratio")]
}))
for (mod in unique(ratios$model)) {
  r <- ratios$ratio[ratios$model == mod]
  report(sprintf("generated / real-vs-real MMD, %s", mod), mean(r), "x", goal = 1.25, better = "lower",
         shown = if (length(r) > 1L) sprintf("generated / real-vs-real MMD, %s (mean of seeds %s; %.2f-%.2f)",
                                              mod, paste(range(gen_seeds), collapse = "-"), min(r), max(r))
                 else sprintf("generated / real-vs-real MMD, %s (seed %d)", mod, gen_seeds))
}
oot <- unlist(lapply(gens, function(x) {
  x$value$generated[x$value$grasp == "overall" & x$value$metric == "outside_limits"]
}))
report("generated frames outside the sensors' range", max(oot), "fraction", goal = 0,
       better = "lower")

# --- the second glove's checks, on its simulated stand-in: 5 folds by recording ----
for (method in c("fpca", "discriminant")) {
  ev <- evaluate_loso(wide, method = method, in_sample = FALSE)
  report(sprintf("wide glove (simulated), 5 folds by recording, %s", method), ev$accuracy[["held_out"]],
         "fraction", goal = if (method == "fpca") 0.90 else 0.98)
}
wg <- evaluate_generation(recordings = wide, folds = 5, reps = bq(3, 1))
for (k in which(wg$grasp == "overall" & wg$metric == "mmd")) {
  report(sprintf("wide glove (simulated), generated / real MMD, %s", wg$model[k]), wg$ratio[k], "x",
         goal = 1.5, better = "lower")
}

tab <- do.call(rbind, rows)
fmt <- function(v, u) ifelse(is.na(v), "", ifelse(u == "fraction", sprintf("%.1f%%", 100 * v),
                                                  ifelse(u == "n", sprintf("%.0f", v), sprintf("%.2f %s", v, u))))
out <- data.frame(figure = tab$figure, ours = fmt(tab$ours, tab$unit),
                  published = fmt(tab$published, tab$unit), goal = fmt(tab$goal, tab$unit),
                  met = ifelse(is.na(tab$met), "", ifelse(tab$met, "yes", "NO")))
w <- vapply(out, function(v) max(nchar(c(v, ""))), integer(1))
w[] <- pmax(w, nchar(names(out)))
line <- function(v) cat(sprintf("%-*s  %*s  %*s  %*s  %s\n", w[1], v[1], w[2], v[2], w[3], v[3], w[4], v[4], v[5]))
cat("\n")
line(names(out))
for (i in seq_len(nrow(out))) line(unlist(out[i, ]))
