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
    }
  }
})

test_that("a recording of three frames or fewer is not smoothed", {
  X <- matrix(c(1, 5, 2, 0, 0, 9), 3)
  got <- .Call(handmotion:::hm_motion_base, X, 3L, 1L)
  expect_identical(got$S, X)
  expect_identical(got$mad, c(Inf, Inf))
})

test_that("channel noise recovers a planted white-noise sd", {
  set.seed(4)
  n <- 4000
  X <- cbind(smooth = 100 * sin(seq_len(n) / 300) + rnorm(n, sd = 2), quiet = rnorm(n, sd = 0.5))
  expect_equal(unname(handmotion:::channel_noise(X)), c(2, 0.5), tolerance = 0.05)
})
