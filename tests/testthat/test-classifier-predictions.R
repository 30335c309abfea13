test_that("the temperature fit recovers a planted temperature, and shuffled labels give vague probabilities", {
  set.seed(4)
  n <- 6000
  d <- matrix(stats::runif(n * 3, 0, 10), n, 3, dimnames = list(NULL, c("a", "b", "c")))
  p <- distance_softmax(d, 2)
  y <- c("a", "b", "c")[apply(p, 1L, function(pr) sample.int(3L, 1L, prob = pr))]
  expect_equal(fit_temperature(d, y), 2, tolerance = 0.1)
  # labels unrelated to the distances: a large temperature, near-uniform probabilities
  t_shuffled <- fit_temperature(d, sample(y))
  expect_gt(t_shuffled, 20)
  expect_lt(max(distance_softmax(d, t_shuffled)), 0.5)
})

test_that("the softmax of distances is its definition, with ties, missing and infinite distances", {
  ref <- function(d, temperature) {
    s <- -d / temperature
    s[!is.finite(s)] <- -Inf
    top <- apply(s, 1L, max)
    p <- exp(s - top) / rowSums(exp(s - top))
    p[!is.finite(top), ] <- NA_real_
    p
  }
  set.seed(5)
  d <- matrix(round(stats::runif(40 * 4, 0, 5)), 40, 4)
  d[1, ] <- NA
  d[2, ] <- c(Inf, 1, 1, NA)
  d[3, ] <- c(-Inf, 0, 2, 3)
  expect_identical(distance_softmax(d, 0.7), ref(d, 0.7))
  expect_identical(distance_softmax(d[0, , drop = FALSE], 1), ref(d[0, , drop = FALSE], 1))
})
