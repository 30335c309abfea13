# The rest and hold a model of trimmed recordings adds back at generation:
# planted lengths tied to the motion's, planted tremor, planted sensor range.

# Raw-count recordings (100 Hz) with a rest, a minimum-jerk reach and a hold
# whose length makes up the rest of a fixed 2 s after the rest, so a long
# motion has a short hold (correlation -1), and white tremor of known sd per
# channel before rounding. Two subjects rest at levels `offset` apart.
plant_phases <- function(n_rec = 80, tremor = c(1, 3), offset = 60, seed = 2) {
  withr::with_seed(seed, {
    p <- length(tremor)
    recs <- vector("list", n_rec)
    for (i in seq_len(n_rec)) {
      n_rest <- sample(40:80, 1)
      n_mot <- sample(50:110, 1)
      n_hold <- 200L - n_mot
      tau <- seq(0, 1, length.out = n_mot)
      mj <- 10 * tau^3 - 15 * tau^4 + 6 * tau^5
      start <- 600 + offset * (i %% 2) + stats::rnorm(p, 0, 5)
      amp <- -stats::runif(p, 250, 350)
      X <- rbind(matrix(start, n_rest, p, byrow = TRUE),
                 outer(mj, amp) + matrix(start, n_mot, p, byrow = TRUE),
                 matrix(start + amp, n_hold, p, byrow = TRUE))
      X <- round(X + matrix(stats::rnorm(length(X)), nrow(X)) * rep(tremor, each = nrow(X)))
      colnames(X) <- paste0("ch", seq_len(p))
      recs[[i]] <- X
    }
    grasps(recs, meta = data.frame(grasp = "a", subject = ifelse(seq_len(n_rec) %% 2, "S2", "S1")),
           rate = 100, unit = "raw")
  })
}

test_that("a model of trimmed recordings recovers the planted tremor within 20%", {
  g <- plant_phases()
  m <- fit_grasp_model(g, seed = 1, dependence = "copula")
  expect_equal(m$settings$motion, "trim")
  # rounding to counts adds a uniform error of variance 1/12
  expect_equal(unname(m$phases$tremor), sqrt(c(1, 3)^2 + 1 / 12), tolerance = 0.2)
  expect_length(m$phases$motion, length(g))
})

test_that("generated rest and hold follow the motion's length as in the recordings", {
  g <- plant_phases()
  for (dep in c("independent", "copula")) {
    m <- fit_grasp_model(g, seed = 1, dependence = dep)
    gen <- generate(m, n = 400, seed = 3)
    motion <- generate(m, n = 400, seed = 3, phases = FALSE)
    # the same draws, with and without the phases: what was added is rest + hold
    added <- gen$meta$n_frames - motion$meta$n_frames
    expect_true(all(added >= 0))
    # planted: motion + hold = 200 frames, so total = rest + 200 whatever the
    # motion; rest and hold drawn apart from the motion would spread the
    # totals by the motion's and the hold's spread too (about 2.4 times)
    expect_lt(stats::sd(gen$meta$n_frames), 1.5 * stats::sd(g$meta$n_frames))
    expect_lt(stats::cor(motion$meta$n_frames, added), -0.5)
  }
})

test_that("generated grasps never leave the recorded range of a raw-count sensor", {
  g <- plant_phases(tremor = c(4, 8))
  lo <- apply(do.call(rbind, g$recordings), 2, min)
  hi <- apply(do.call(rbind, g$recordings), 2, max)
  for (dep in c("independent", "copula")) {
    gen <- generate(fit_grasp_model(g, seed = 1, dependence = dep), n = 300, seed = 4)
    all_frames <- do.call(rbind, gen$recordings)
    expect_true(all(sweep(all_frames, 2, lo, `-`) >= 0))
    expect_true(all(sweep(all_frames, 2, hi, `-`) <= 0))
    expect_true(all(all_frames >= 0 & all_frames <= 1023))
  }
})

# A rest that drifts into the onset and a hold that settles back after the
# reach, by a planted share of how far each channel reached (as flexglove's
# fingers relax by about a tenth after the grasp).
plant_settling <- function(n_rec = 120, settle = -0.15, drift = 20, seed = 5) {
  withr::with_seed(seed, {
    p <- 2L
    recs <- lapply(seq_len(n_rec), function(i) {
      n_rest <- sample(40:60, 1)
      n_mot <- sample(60:90, 1)
      n_hold <- 120L
      tau <- seq(0, 1, length.out = n_mot)
      mj <- 10 * tau^3 - 15 * tau^4 + 6 * tau^5
      start <- 600 + stats::rnorm(p, 0, 5)
      amp <- -stats::runif(p, 150, 450)
      relax <- 1 - exp(-seq_len(n_hold) / 30)
      X <- rbind(outer(seq(-1, 0, length.out = n_rest + 1)[-(n_rest + 1)], rep(drift, p)) +
                   matrix(start, n_rest, p, byrow = TRUE),
                 outer(mj, amp) + matrix(start, n_mot, p, byrow = TRUE),
                 outer(relax, settle * amp) + matrix(start + amp, n_hold, p, byrow = TRUE))
      X <- X + matrix(stats::rnorm(length(X)), nrow(X))
      colnames(X) <- paste0("ch", seq_len(p))
      X
    })
    grasps(recs, meta = data.frame(grasp = rep("a", n_rec), subject = "S1"), rate = 100, unit = "raw")
  })
}

test_that("generated holds settle back and rests drift as the recordings' do", {
  g <- plant_settling()
  for (dep in c("independent", "copula")) {
    m <- fit_grasp_model(g, seed = 1, dependence = dep)
    expect_equal(m$settings$motion, "trim")
    gen <- generate(m, n = 300, seed = 3)
    motion <- generate(m, n = 300, seed = 3, phases = FALSE)
    first <- t(vapply(motion$recordings, function(r) r[1, ], numeric(2)))
    last <- t(vapply(motion$recordings, function(r) r[nrow(r), ], numeric(2)))
    end <- t(vapply(gen$recordings, function(r) r[nrow(r), ], numeric(2)))
    start <- t(vapply(gen$recordings, function(r) r[1, ], numeric(2)))
    for (j in 1:2) {
      # the hold settles back by the planted share of the generated reach
      # (what the detected end leaves of it: about 0.9 of the settling's
      # full size after 1.2 s, less the part inside the detected motion)
      reach <- last[, j] - first[, j]
      slope <- unname(stats::coef(stats::lm(I(end[, j] - last[, j]) ~ reach))[2])
      expect_gt(slope, -0.15 - 0.05)
      expect_lt(slope, -0.15 + 0.07)
      # the rest starts below the onset posture by the planted drift, within 5 counts
      expect_equal(mean(first[, j] - start[, j]), 20, tolerance = 5 / 20)
    }
  }
})
