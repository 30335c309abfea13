test_that("density is a proper mixture density and loglik its log-sum", {
  X <- planted_mixture(9, 200, 0.5, c(3, 3))
  fit <- gmm_fit(X)
  g <- seq(-6, 9, by = 0.05)
  grid <- as.matrix(expand.grid(g, g))
  expect_equal(sum(gmm_density(fit, grid)) * 0.05^2, 1, tolerance = 1e-3)
  expect_equal(gmm_loglik(fit, X), sum(log(gmm_density(fit, X))), tolerance = 1e-10)
  dnorm2 <- function(x, m, S) {
    z <- sweep(x, 2, m)
    exp(-0.5 * rowSums((z %*% solve(S)) * z)) / (2 * pi * sqrt(det(S)))
  }
  manual <- fit$weights[1] * dnorm2(X[1:5, ], fit$means[1, ], fit$covs[, , 1]) +
    fit$weights[2] * dnorm2(X[1:5, ], fit$means[2, ], fit$covs[, , 2])
  expect_equal(gmm_density(fit, X[1:5, ]), manual, tolerance = 1e-10)
  expect_length(gmm_density(fit, c(0, 0)), 1)
  # far from the data the density underflows but the log-likelihood stays finite
  expect_true(is.finite(gmm_loglik(fit, rbind(c(60, 60)))))
})
