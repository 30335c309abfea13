test_that("the sign convention makes refits on subsets comparable", {
  g <- planted_grasps(n = 80, p = 3, seed = 20)
  full <- fit_grasp_model(g, warping = "linear", seed = 1)
  sub <- fit_grasp_model(g[seq(2, 80, by = 2)], warping = "linear", seed = 2)
  # the two fits may have different target lengths: compare on normalised time
  w <- full$fpca[[1]]$weights
  for (j in 1:3) for (c in 1:2) {
    on_full <- stats::approx(sub$argvals, model_basis(sub)$components[, j, c], xout = full$argvals)$y
    inner <- sum(model_basis(full)$components[, j, c] * on_full * w)
    expect_gt(inner, 0.9)
  }
})

test_that("the compiled curve spread is the R expressions it replaced, to the bit", {
  set.seed(21)
  for (n in c(1L, 2L, 7L, 300L)) {
    Y <- matrix(rnorm(n * 9, sd = 3) + 50, n, 9)
    got <- .Call(hm_curve_spread, Y)
    v <- if (n > 1L) sum(colSums((Y - rep(colMeans(Y), each = n))^2)) / (n - 1L) else NA_real_
    expect_identical(got, c(v, mean(Y^2)))
  }
  # a constant DoF has no variance: the zero-component stand-in
  fit <- fit_fpca_or_constant(matrix(2L, 5, 4), seq(0, 1, length.out = 4), 2, "fast")
  expect_true(fit$constant)
})
