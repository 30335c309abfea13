test_that("compiled k-means gives the R version's labels", {
  Y <- scale(planted_mixture(3, 300, 0.4, c(2, -1)))
  Y <- matrix(Y, nrow(Y))
  centres <- withr::with_seed(2, lapply(1:6, function(i) Y[sample.int(nrow(Y), 2 + i %% 3), ,
                                                         drop = FALSE]))
  fast <- gmm_kmeans_all(Y, centres)
  ref <- lapply(centres, function(cen) gmm_kmeans(Y, cen))
  expect_identical(fast, ref)
  y <- matrix(withr::with_seed(4, rnorm(50)))
  expect_identical(gmm_kmeans_all(y, list(y[1:2, , drop = FALSE])), list(gmm_kmeans(y, y[1:2, , drop = FALSE])))
})
