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
