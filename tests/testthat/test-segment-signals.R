# src/motion-signals.c computes what find_motion() reads from a recording in
# one pass; these tests hold it to the R expressions it replaced, which are
# the definitions (stats::runmed(), median(), mad()).

test_that("the compiled smoothing, rest levels and noise MAD equal R's definitions", {
  set.seed(11)
  for (n in c(4L, 5L, 9L, 40L, 101L)) {
    X <- cbind(a = cumsum(rnorm(n)), b = round(rnorm(n) * 3), c = rep(2, n))
    X[sample(n, 1), 1] <- X[1, 1]                      # ties
    for (rest_n in c(3L, 4L, 5L)) for (lag in c(1L, 2L)) {
      got <- .Call(handmotion:::hm_motion_base, X, rest_n, lag)
      S <- apply(X, 2, function(v) as.numeric(stats::runmed(v, 3L, endrule = "median")))
      expect_identical(unname(got$S), unname(S))
      expect_identical(dimnames(got$S), dimnames(X))
      expect_identical(got$rest, unname(apply(S[seq_len(min(rest_n, n)), , drop = FALSE], 2, stats::median)))
      want <- apply(X, 2, function(v) {
        if (length(v) < 2L * lag + 2L) return(Inf)
        stats::mad(diff(v, lag = lag, differences = 2))
      })
      expect_identical(got$mad, unname(want))
      # the quantisation floor as recorded: quantum_floor() of each column
      expect_identical(got$floor, unname(apply(X, 2, quantum_floor, resampled = FALSE)))
    }
  }
})

test_that("a recording of three frames or fewer is not smoothed", {
  X <- matrix(c(1, 5, 2, 0, 0, 9), 3)
  got <- .Call(handmotion:::hm_motion_base, X, 3L, 1L)
  expect_identical(got$S, X)
  expect_identical(got$mad, c(Inf, Inf))
  expect_identical(got$floor, c(1.5, 4.5))
  # one value, or none finite: 0.5; steps below 1e-9 of the values do not count
  got <- .Call(handmotion:::hm_motion_base, cbind(c(NaN, 3, NA), c(1e12, 1e12 + 1e-4, 1e12 + 2)), 1L, 1L)
  expect_identical(got$floor, c(0.5, quantum_floor(c(1e12, 1e12 + 1e-4, 1e12 + 2), FALSE)))
  expect_identical(got$floor[2], 0.5)
})

test_that("channel noise recovers a planted white-noise sd", {
  set.seed(4)
  n <- 4000
  X <- cbind(smooth = 100 * sin(seq_len(n) / 300) + rnorm(n, sd = 2), quiet = rnorm(n, sd = 0.5))
  expect_equal(unname(handmotion:::channel_noise(X)), c(2, 0.5), tolerance = 0.05)
})

test_that("the compiled walks over channels are the R loops they replaced", {
  back <- function(x, t, thr) { while (t > 1L && x[t - 1L] > thr) t <- t - 1L; t }
  fwd <- function(x, e, thr) { while (e < length(x) && x[e + 1L] > thr) e <- e + 1L; e }
  set.seed(12)
  for (n in c(1L, 2L, 7L, 60L)) {
    X <- matrix(abs(rnorm(n * 5)) * 3, n, 5)
    thr <- c(0.5, 2, 3, 100, -1)
    start <- sample.int(n, 5, replace = TRUE)
    cols <- seq_len(5)
    expect_identical(.Call(hm_first_above, X, thr),
                     vapply(cols, function(j) which(X[, j] > thr[j])[1], integer(1)))
    expect_identical(.Call(hm_last_at_least, X, thr),
                     vapply(cols, function(j) { w <- which(X[, j] >= thr[j]); if (length(w)) max(w) else NA_integer_ }, integer(1)))
    expect_identical(.Call(hm_walk_back, X, start, thr),
                     vapply(cols, function(j) back(X[, j], start[j], thr[j]), integer(1)))
    expect_identical(.Call(hm_walk_forward, X, start, thr),
                     vapply(cols, function(j) fwd(X[, j], start[j], thr[j]), integer(1)))
    expect_identical(.Call(hm_col_max, X), apply(X, 2, max))
  }
  # max()'s missing values: NA before NaN
  X <- cbind(c(1, NaN, 3), c(NaN, NA, 2), c(-Inf, -5, -Inf))
  expect_identical(.Call(hm_col_max, X), apply(X, 2, max))
  expect_error(.Call(hm_walk_back, X, c(1L, 4L, 1L), c(0, 0, 0)), "frames")
  expect_error(.Call(hm_first_above, X, 1), "one value per column")
})
