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

# The same recordings with planted channels that carry no motion: white noise
# (`jitter1` in counts, `jitter2` unrounded), one-frame spikes of 400 counts
# (`spikes`), a channel that changes by one count three times (`near`) and,
# with `pad = TRUE`, a pressure pad: noise at zero until `contact` (a frame
# per recording), then a rise to 300 counts.
with_noise_channels <- function(x, seed, contact = NULL) {
  recs <- withr::with_seed(seed, lapply(seq_along(x), function(i) {
    r <- x$recordings[[i]]
    n <- nrow(r)
    spikes <- 300 + round(stats::rnorm(n))
    hit <- sample(n, max(2L, n %/% 30))
    spikes[hit] <- spikes[hit] + 400
    near <- rep(200, n)
    near[sample(n, 3)] <- 201
    out <- cbind(r, jitter1 = round(500 + stats::rnorm(n, 0, 3)), jitter2 = 400 + stats::rnorm(n, 0, 10),
                 spikes = spikes, near = near)
    if (!is.null(contact)) {
      pad <- pmax(0, round(stats::rnorm(n, 0, 0.7)))
      at <- contact[i]:n
      pad[at] <- pad[at] + round(300 * (1 - exp(-seq_along(at) / 3)))
      out <- cbind(out, pad = pad)
    }
    out
  }))
  grasps(recs, meta = x$meta, rate = x$rate, unit = "raw")
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
