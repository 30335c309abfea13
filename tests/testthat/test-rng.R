test_that("with_seed leaves the global RNG untouched", {
  set.seed(42); before <- .Random.seed
  x <- with_seed(1, runif(3))
  expect_identical(.Random.seed, before)
  expect_identical(x, with_seed(1, runif(3)))
})
