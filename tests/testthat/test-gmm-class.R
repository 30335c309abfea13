test_that("print reports the fit and any fallback", {
  expect_snapshot({
    print(gmm_fit(planted_mixture(1, 100, 0.6, c(5, 5))))
    print(gmm_fit(matrix(1, 5, 2)))
  })
})
