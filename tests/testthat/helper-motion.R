# Recordings with a planted rest, minimum-jerk reach and hold in raw counts,
# with sensor noise and rounding: the onsets and ends are known exactly.
plant_motion <- function(n_rec = 40, rate = 100, p = 12, noise = 1.5, seed = 1) {
  withr::with_seed(seed, {
    recs <- vector("list", n_rec)
    onset <- end <- integer(n_rec)
    for (i in seq_len(n_rec)) {
      n_rest <- sample(round(0.6 * rate):round(1.4 * rate), 1)
      n_mot <- sample(round(0.6 * rate):round(1.2 * rate), 1)
      n_hold <- sample(round(0.6 * rate):round(1.4 * rate), 1)
      tau <- seq(0, 1, length.out = n_mot)
      mj <- 10 * tau^3 - 15 * tau^4 + 6 * tau^5
      start <- stats::runif(p, 200, 400)
      amp <- stats::runif(p, 100, 400) * sample(c(-1, 1), p, TRUE)
      X <- rbind(matrix(start, n_rest, p, byrow = TRUE),
                 outer(mj, amp) + matrix(start, n_mot, p, byrow = TRUE),
                 matrix(start + amp, n_hold, p, byrow = TRUE))
      X <- round(X + matrix(stats::rnorm(length(X), 0, noise), nrow(X)))
      colnames(X) <- paste0("ch", seq_len(p))
      recs[[i]] <- X
      onset[i] <- n_rest + 1L
      end[i] <- n_rest + n_mot
    }
    list(g = grasps(recs, meta = data.frame(grasp = rep(c("a", "b"), length.out = n_rec)), rate = rate,
                    unit = "raw"),
         onset = onset, end = end)
  })
}

# The slow end-to-end checks run in `make test` (HANDMOTION_SLOW_TESTS=true),
# not in R CMD check.
slow_tests_enabled <- function() identical(Sys.getenv("HANDMOTION_SLOW_TESTS"), "true")

# The hand-marked flexglove recordings (fixtures/flexglove-motion.csv, or the
# held-out flexglove-motion-heldout.csv), read in place from the shared
# folder (skips without it): list(g, marks).
flexglove_marked <- function(file = "flexglove-motion.csv") {
  dir <- dirname(shared_file("data", "flexglove", "manifest.csv"))
  marks <- utils::read.csv(test_path("fixtures", file), comment.char = "#", stringsAsFactors = FALSE)
  recs <- lapply(marks$file, function(f) as.matrix(utils::read.csv(file.path(dir, f))))
  list(g = grasps(recs, meta = data.frame(grasp = marks$label, subject = marks$subject), rate = 33.3),
       marks = marks)
}

# Channels that carry no motion, planted beside a recording of `n` frames
# (shared by the tests and bench/bench-segment.R, which sources this file):
# white noise (`jitter1` in counts, `jitter2` unrounded), one-frame spikes
# of 400 counts (`spikes`, one every `spike_every` frames), a channel that
# changes by one count three times (`near`) and, with `contact` (a frame),
# `pads` pressure pads: noise at zero until contact, then a rise to 300
# counts.
noise_channels <- function(n, contact = NULL, pads = 1L, spike_every = 30L) {
  spikes <- 300 + round(stats::rnorm(n))
  hit <- sample(n, max(2L, n %/% spike_every))
  spikes[hit] <- spikes[hit] + 400
  near <- rep(200, n)
  near[sample(n, 3)] <- 201
  out <- cbind(jitter1 = round(500 + stats::rnorm(n, 0, 3)), jitter2 = 400 + stats::rnorm(n, 0, 10),
               spikes = spikes, near = near)
  if (is.null(contact)) return(out)
  pad <- vapply(seq_len(pads), function(k) {
    v <- pmax(0, round(stats::rnorm(n, 0, 0.7)))
    at <- contact:n
    v[at] <- v[at] + round(300 * (1 - exp(-seq_along(at) / 3)))
    v
  }, numeric(n))
  colnames(pad) <- if (pads == 1L) "pad" else paste0("pad", seq_len(pads))
  cbind(out, pad)
}

# The same recordings with the planted channels of noise_channels() (with
# `contact`, a frame per recording: one pressure pad).
with_noise_channels <- function(x, seed, contact = NULL) {
  recs <- withr::with_seed(seed, lapply(seq_along(x), function(i) {
    r <- x$recordings[[i]]
    cbind(r, noise_channels(nrow(r), contact[i]))
  }))
  grasps(recs, meta = x$meta, rate = x$rate, unit = "raw")
}

# The hand-marked recordings read as users read them: their files with the
# time column (the copy shipped in inst/extdata/flexglove), with the planted
# channels of noise_channels() if `seed` is given (planted on the frames as
# recorded, so they are resampled too), written to a temporary folder and
# read back by read_glove(time = "time_ms"), which resamples them onto one
# 33.3 Hz grid. The marks move onto the grid by their time stamps (grid
# frames, fractional): list(g, marks).
flexglove_marked_resampled <- function(file = "flexglove-motion.csv", seed = NULL) {
  src <- system.file("extdata", "flexglove", package = "handmotion")
  testthat::skip_if_not(dir.exists(src), "inst/extdata/flexglove is not installed")
  marks <- utils::read.csv(test_path("fixtures", file), comment.char = "#", stringsAsFactors = FALSE)
  tmp <- withr::local_tempdir(.local_envir = parent.frame())
  recs <- lapply(marks$file, function(f) as.matrix(utils::read.csv(file.path(src, f))))
  if (!is.null(seed)) {
    recs <- withr::with_seed(seed, lapply(recs, function(r) cbind(r, noise_channels(nrow(r)))))
  }
  for (i in seq_along(recs)) {
    dir.create(file.path(tmp, dirname(marks$file[i])), showWarnings = FALSE, recursive = TRUE)
    utils::write.csv(recs[[i]], file.path(tmp, marks$file[i]), row.names = FALSE)
  }
  profile <- glove_profile(data.frame(channel = colnames(recs[[1]])[-1]), name = "flexglove+planted",
                           unit = "raw")
  g <- suppressMessages(read_glove(tmp, glove = profile, time = "time_ms", recursive = TRUE))
  # ids are the relative paths where base names repeat, else the base names
  id <- sub("[.]csv$", "", marks$file)
  if (!all(id %in% g$meta$id)) id <- basename(id)
  g <- g[match(id, g$meta$id)]
  on_grid <- function(r, frame) 1 + (r[frame, "time_ms"] - r[1, "time_ms"]) / 1000 * g$rate
  marks$onset <- mapply(on_grid, recs, marks$onset)
  marks$end <- mapply(on_grid, recs, marks$end)
  list(g = g, marks = marks)
}

# The plain threshold the real-sensor checks compare with: the first frame
# where any channel has left its initial level (median of its first 3
# frames) by more than 20% of its range in the recording.
plain_onset <- function(X, share = 0.2) {
  base <- apply(X[1:3, , drop = FALSE], 2, stats::median)
  rng <- pmax(apply(X, 2, function(v) diff(range(v))), 1)
  w <- which(rowSums(abs(sweep(X, 2, base)) > share * rng) > 0)[1]
  if (is.na(w)) nrow(X) else w
}
