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
