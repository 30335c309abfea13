test_that("the mixtures run EM up to the model's cap before falling back", {
  g <- planted_grasps(n = 40, p = 2, seed = 3)
  m <- fit_grasp_model(g, seed = 1)
  expect_identical(m$settings$gmm_max_iter, 5000L)
  # a score cloud that needs more than 500 EM evaluations even accelerated
  # (two univariate components 1.2 SD apart): fitted, not a fallback
  X <- matrix(withr::with_seed(8, c(rnorm(150), rnorm(100, 1.2))))
  fit <- fit_mixture(list(scores = X, constant = FALSE), 2L, "fast")
  expect_false(fit$fallback)
  expect_gt(fit$iterations, 500)
  expect_true(gmm_fit(X)$fallback) # gmm_fit()'s own default cap of 500 falls back
})
