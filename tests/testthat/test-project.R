test_that("projecting the training data of a linear-warp model returns its scores", {
  # all warps linear, so the normalised mean warp is the identity on each
  # recording's own frames: projection repeats the fit.
  g <- planted_grasps(n = 40, p = 3, seed = 41)
  m <- fit_grasp_model(g, warping = "linear", seed = 1)
  pr <- project(m, g)
  expect_s3_class(pr, "grasp_projection")
  expect_identical(pr$ids, g$meta$id)
  expect_equal(unname(pr$scores), unname(model_scores(m)), tolerance = 1e-6)
  expect_equal(unname(pr$warped[[5]]), unname(m$alignment$warped[5, , ]), tolerance = 1e-8)
  expect_equal(unname(pr$distance), sqrt(rowSums(pr$residual^2)), ignore_attr = TRUE)
  expect_identical(project(m, g), pr)
})

test_that("distance is eq. 4.4 over the hand, computed independently with apply_warp", {
  g <- planted_grasps(n = 40, p = 3, seed = 42)
  m <- fit_grasp_model(g, seed = 1)            # DTW: a non-linear mean warp
  x <- planted_grasps(n = 3, p = 3, seed = 43, len = 55)
  pr <- project(m, x)
  L <- m$target_length
  wbar <- warp_basis(m)$mean
  u <- (wbar - wbar[1]) / (wbar[L] - wbar[1])
  for (i in 1:3) {
    rec <- x$recordings[[i]]
    warp <- 1 + u * (nrow(rec) - 1)
    y <- apply_warp(rec, warp)
    expect_equal(unname(pr$warped[[i]]), unname(y), tolerance = 1e-8)
    res <- vapply(1:3, function(j) fpca_residual_norm(m$fpca[[j]], matrix(y[, j], 1)), 1)
    expect_equal(unname(pr$residual[i, ]), res, tolerance = 1e-8)
    expect_equal(unname(pr$distance[i]), sqrt(sum(res^2)), tolerance = 1e-8)
    # fitted = mean + FPCs x scores
    fit1 <- model_basis(m)$mean[, 1] + matrix(model_basis(m)$components[, 1, ], L) %*% pr$scores[i, 1, ]
    expect_equal(unname(pr$fitted[[i]][, 1]), drop(fit1), tolerance = 1e-8)
  }
})

test_that("a curve in the model's span is at distance 0, a foreign shape is far", {
  g <- planted_grasps(n = 40, p = 2, seed = 44)
  m <- fit_grasp_model(g, warping = "linear", seed = 1)
  inside <- generate(m, n = 5, seed = 1, warp = FALSE)
  # not exactly 0: fda.usc's components are orthonormal on the uniform rule,
  # projections use the trapezoidal rule (they differ at the two end points)
  expect_lt(max(project(m, inside)$distance), 1e-3)
  L <- m$target_length
  s <- seq(0, 1, length.out = L)
  odd <- cbind(30 * cos(3 * pi * s), 30 * sin(5 * pi * s))
  far <- grasps(list(odd), dofs = m$dofs)
  expect_gt(project(m, far)$distance, 5)
})

test_that("recordings of any length project, including a single frame", {
  g <- planted_grasps(n = 30, p = 2, seed = 45)
  m <- fit_grasp_model(g, warping = "linear", seed = 1)
  recs <- list(matrix(1:2, 1, 2), matrix(rnorm(6), 3, 2), g$recordings[[1]][rep(1:40, 3), ])
  pr <- project(m, grasps(recs, dofs = m$dofs))
  expect_equal(dim(pr$scores), c(3L, 2L, 2L))
  expect_true(all(is.finite(pr$distance)))
  expect_equal(unname(pr$warped[[1]]), matrix(c(1, 2), m$target_length, 2, byrow = TRUE))
})

test_that("a model set projects onto every model; DoF mismatch is a clear error", {
  a <- planted_grasps(n = 20, p = 2, grasp = "Ring", seed = 1)
  b <- planted_grasps(n = 20, p = 2, grasp = "Tripod", seed = 2, sep = 2)
  g <- grasps(c(a$recordings, b$recordings),
              meta = data.frame(id = paste0("x", 1:40), grasp = c(a$meta$grasp, b$meta$grasp)),
              dofs = a$dofs)
  ms <- fit_grasp_models(g, warping = "linear", seed = 1)
  prs <- project(ms, g)
  expect_named(prs, c("Tripod", "Ring"))
  expect_null(prs$Ring$fitted)
  expect_equal(prs$Ring$distance, project(ms$Ring, g)$distance)
  wrong <- grasps(list(matrix(0, 5, 3)), dofs = c("a", "b", "c"))
  expect_error(project(ms$Ring, wrong), class = "handmotion_error_bad_input")
  expect_error(project(ms$Ring, list()), class = "handmotion_error_bad_input")
  expect_snapshot(print(prs$Ring))
})
