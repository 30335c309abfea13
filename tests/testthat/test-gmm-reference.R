test_that("the reference engine is reproducible under a seed and keeps the RNG", {
  skip_if_not_installed("mixtools")
  X <- planted_mixture(11, 60, 0.6, c(4, 2))
  set.seed(5)
  before <- .Random.seed
  a <- gmm_fit(X, engine = "reference", seed = 3)
  expect_identical(.Random.seed, before)
  b <- gmm_fit(X, engine = "reference", seed = 3)
  expect_identical(a$means, b$means)
  expect_identical(a$engine, "reference")
})
