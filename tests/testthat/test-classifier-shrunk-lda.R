test_that("the shrinkage LDA is the Bayes rule on Gaussian classes", {
  set.seed(3)
  D <- 6
  mu <- rbind(rep(0, D), c(2, rep(0, D - 1)), c(0, 2, rep(0, D - 2)))
  S <- 0.5^abs(outer(1:D, 1:D, "-"))
  U <- chol(S)
  draw <- function(n) {
    y <- factor(sample(c("a", "b", "c"), n, TRUE))
    list(X = mu[as.integer(y), ] + matrix(stats::rnorm(n * D), n) %*% U, y = y)
  }
  tr <- draw(6000)
  te <- draw(3000)
  fit <- fit_shrunk_lda(tr$X, tr$y)
  expect_lt(fit$shrinkage, 0.01) # many recordings: nothing to shrink
  pred <- fit$classes[max.col(shrunk_lda_scores(fit, te$X))]
  # the true posterior with known means and covariance
  Si <- solve(S)
  true <- sapply(1:3, function(k) {
    d <- sweep(te$X, 2, mu[k, ])
    -0.5 * rowSums((d %*% Si) * d)
  })
  expect_gt(mean(pred == c("a", "b", "c")[max.col(true)]), 0.98)
  # with few recordings per feature the correlation is shrunk, and the fit stays usable
  few <- draw(40)
  X <- cbind(few$X, matrix(stats::rnorm(40 * 20), 40))
  fit_few <- fit_shrunk_lda(X, few$y)
  expect_gt(fit_few$shrinkage, 0.05)
  expect_true(all(is.finite(shrunk_lda_scores(fit_few, X))))
})
