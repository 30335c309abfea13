# Finding the grasping motion on real sensors (issue 40): find_motion() on the
# 626 real flexglove recordings against 80 hand-marked onsets and ends
# (tests/testthat/fixtures/flexglove-motion.csv, see the .md beside it; and
# 20 more marked after tuning, flexglove-motion-heldout.csv), and on a
# simulated wide glove (15 raw channels at 100 Hz, 1.4 s of rest, 1 s of
# hold, one person, six objects) with 8 planted channels that carry noise but
# no motion (white noise, spikes, near-constant) or only rise at contact
# (pressure pads).
#
# The plain threshold beside it: the first frame where any channel has left
# its initial level (the median of its first 3 frames) by more than 20% of
# its range in the recording (on the wide glove: of the glove's own 15
# channels, as it cannot tell noise from motion).
#
# Run from the repository root:
#   Rscript bench/bench-segment.R     (BENCH_QUICK=1: the 80 marked flexglove recordings only,
#                                      2 objects x 6 trials on the wide glove)
# Needs /work/shared/data/flexglove (or $HANDMOTION_SHARED/data/flexglove); skips that part without it.

source("bench/_common.R")
# plain_onset() and noise_channels(): the tests' own, so that the bench and
# tests/testthat/test-segment*.R plant the same channels and compare with the
# same threshold
source("tests/testthat/helper-motion.R")
cat(sprintf("%s; load average %s on %d cores\n\n", bench_build, load_avg(), parallel::detectCores()))
timed <- function(expr) {
  t <- system.time(value <- force(expr))
  list(value = value, elapsed = t[["elapsed"]], cpu = t[["user.self"]] + t[["sys.self"]])
}

# --- flexglove -------------------------------------------------------------
fg <- file.path(Sys.getenv("HANDMOTION_SHARED", "/work/shared"), "data", "flexglove")
if (dir.exists(fg)) {
  fx <- utils::read.csv("tests/testthat/fixtures/flexglove-motion.csv", comment.char = "#", stringsAsFactors = FALSE)
  man <- utils::read.csv(file.path(fg, "manifest.csv"), stringsAsFactors = FALSE)
  if (bench_quick) man <- man[man$file %in% fx$file, ]  # the 80 marked recordings only (no held-out figure)
  read_one <- function(f) as.matrix(utils::read.csv(file.path(fg, f)))
  all <- grasps(lapply(man$file, read_one), meta = data.frame(grasp = man$label, subject = man$subject),
                rate = 33.3)
  run <- timed(find_motion(all))
  m <- run$value
  k <- match(fx$file, man$file)
  on_err <- m$start[k] - fx$onset
  end_err <- m$end[k] - fx$end
  plain <- vapply(all$recordings, plain_onset, numeric(1))
  cat(sprintf("flexglove: %d recordings, %d hand-marked (%d clear)\n", length(all), nrow(fx), sum(fx$clear)))
  cat(sprintf("  onset MAE  %.2f frames (clear ones %.2f), mean error %+.2f\n", mean(abs(on_err)),
              mean(abs(on_err[fx$clear])), mean(on_err)))
  cat(sprintf("  end MAE    %.2f frames (clear ones %.2f), mean error %+.2f\n", mean(abs(end_err)),
              mean(abs(end_err[fx$clear])), mean(end_err)))
  ho <- utils::read.csv("tests/testthat/fixtures/flexglove-motion-heldout.csv", comment.char = "#",
                        stringsAsFactors = FALSE)
  kh <- match(ho$file, man$file)
  if (!anyNA(kh)) {
    cat(sprintf("  held out (%d marked after tuning): onset MAE %.2f frames, end MAE %.2f frames\n", nrow(ho),
                mean(abs(m$start[kh] - ho$onset)), mean(abs(m$end[kh] - ho$end))))
    bench_record("flexglove held-out onset MAE (frames)", mean(abs(m$start[kh] - ho$onset)), "frames")
  }
  cat(sprintf("  hand marks' median rest %.2f s\n", stats::median(fx$onset - 1) / 33.3))
  cat(sprintf("  median rest: find_motion %.2f s, plain threshold %.2f s (%d recordings)\n",
              stats::median(m$rest) / 33.3, stats::median(plain - 1) / 33.3, length(all)))
  cat(sprintf("  found %d of %d (%s)\n", sum(m$found), nrow(m),
              paste(names(table(m$status)), table(m$status), collapse = ", ")))
  cat(sprintf("  find_motion() on %d recordings: %.2f s elapsed, %.2f s CPU\n\n", length(all), run$elapsed, run$cpu))
  bench_record("flexglove onset MAE (frames)", mean(abs(on_err)), "frames")
  bench_record("flexglove end MAE (frames)", mean(abs(end_err)), "frames")
  bench_record("flexglove median rest, find_motion", stats::median(m$rest) / 33.3, "s")
  bench_record("flexglove median rest, plain threshold", stats::median(plain - 1) / 33.3, "s")
  bench_record("flexglove share found", mean(m$found), "fraction")
  bench_record(sprintf("flexglove find_motion, %d recordings", length(all)), run$elapsed, "s")
} else {
  cat("flexglove not found at", fg, "- skipped\n\n")
}

# --- a simulated wide glove with noise-only channels -------------------------
objects <- c(bottle = 1, mug = 9, ball = 17, pen = 22, card = 28, key = 31)
raw <- simulate_grasps(subjects = 1, grasps = objects[seq_len(bq(6, 2))], objects = 1, trials = bq(28, 6),
                       rate = 100, glove = "resistive", rest = 1.4, hold = 1, plant_overlong = FALSE, seed = 3)
# the planted channels of the tests, with four pressure pads that rise at
# contact, 0.1 s before the motion ends, and a spike every 50 frames
planted <- withr::with_seed(40, Map(function(r, e) {
  cbind(r, noise_channels(nrow(r), contact = max(1L, e - 10L), pads = 4L, spike_every = 50L))
}, raw$recordings, raw$meta$motion_end))
wide <- grasps(planted, meta = raw$meta, rate = 100, unit = "raw")
run <- timed(find_motion(wide))
m <- run$value
bare <- find_motion(raw)
plain <- vapply(raw$recordings, plain_onset, numeric(1))
noise_ch <- setdiff(wide$dofs, raw$dofs)
cat(sprintf("wide glove: %d recordings of %d channels (%d glove + %d planted) at 100 Hz\n", length(wide),
            length(wide$dofs), length(raw$dofs), length(noise_ch)))
cat(sprintf("  onset MAE %.1f frames (%.3f s) against the planted onset; end MAE %.1f frames\n",
            mean(abs(m$start - raw$meta$motion_start)), mean(abs(m$start - raw$meta$motion_start)) / 100,
            mean(abs(m$end - raw$meta$motion_end))))
cat(sprintf("  on the glove's own 15 channels: onset MAE %.1f frames, end MAE %.1f frames (the pads settle after the fingers)\n",
            mean(abs(bare$start - raw$meta$motion_start)), mean(abs(bare$end - raw$meta$motion_end))))
cat(sprintf("  median rest: find_motion %.2f s, plain threshold %.2f s, planted %.2f s\n",
            stats::median(m$rest) / 100, stats::median(plain - 1) / 100, stats::median(raw$meta$motion_start - 1) / 100))
cat(sprintf("  onsets moved by the planted channels: %d of %d; motions led by a planted channel: %d; found %d\n",
            sum(m$start != bare$start), nrow(m), sum(m$lead %in% noise_ch), sum(m$found)))
cat(sprintf("  find_motion() on %d recordings: %.2f s elapsed, %.2f s CPU\n", length(wide), run$elapsed, run$cpu))
bench_record("wide glove onset MAE (s)", mean(abs(m$start - raw$meta$motion_start)) / 100, "s")
bench_record("wide glove median rest, find_motion", stats::median(m$rest) / 100, "s")
bench_record("wide glove median rest, plain threshold", stats::median(plain - 1) / 100, "s")
bench_record("wide glove onsets moved by noise channels", sum(m$start != bare$start), "recordings")
bench_record("wide glove find_motion", run$elapsed, "s")
