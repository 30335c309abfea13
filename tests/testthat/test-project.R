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
  expect_warning(pr <- project(m, grasps(recs, dofs = m$dofs)), class = "handmotion_warning_short_recordings")
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
  expect_equal(prs$Ring$distance, project(ms[["Ring"]], g)$distance)
  wrong <- grasps(list(matrix(0, 5, 3)), dofs = c("a", "b", "c"))
  expect_error(project(ms[["Ring"]], wrong), class = "handmotion_error_bad_input")
  expect_error(project(ms[["Ring"]], list()), class = "handmotion_error_bad_input")
  expect_snapshot(print(prs$Ring))
})

test_that("the kernel's projection equals the former R path (stacked, warp index in R) to rounding", {
  # a DTW model (non-linear mean warp), recordings of 1, 2 and many frames,
  # integer storage, DoFs in another order than the model's, and time weights
  g <- planted_grasps(n = 30, p = 3, seed = 46)
  m <- fit_grasp_model(g, seed = 1)
  x <- planted_grasps(n = 12, p = 3, seed = 47, len = 33)
  recs <- c(x$recordings, list(matrix(5, 1, 3), matrix(c(1, 2, 3, 4, 5, 6), 2, 3),
                               matrix(1:30, 10, 3), x$recordings[[1]][rep(1:33, 4), , drop = FALSE]))
  recs <- unname(lapply(recs, function(r) r[, 3:1, drop = FALSE]))
  x <- grasps(recs, dofs = rev(m$dofs))
  tw <- seq(0, 2, length.out = m$target_length)
  for (weights in list(NULL, tw)) {
    ref <- project_reference(m, x, time_weights = weights)
    got <- project_recordings(m, x, details = TRUE, time_weights = weights)
    expect_equal(unname(got$scores), ref$scores, tolerance = 1e-12)
    expect_equal(unname(got$residual), ref$residual, tolerance = 1e-12)
    expect_equal(unname(got$distance), ref$distance, tolerance = 1e-12)
    expect_equal(unname(do.call(rbind, got$warped)), ref$warped, tolerance = 1e-12)
    only <- project_recordings(m, x, details = FALSE, distance_only = TRUE, time_weights = weights)
    expect_identical(only$distance, got$distance)
  }
})

test_that("classify()'s FPCA distances equal the former R path on a model set", {
  g <- simulate_grasps(subjects = 4, grasps = c(1, 9, 17), objects = 2, trials = 2, seed = 2)
  # the thesis' eq. 4.4 residual distance, which the former R path computed
  ms <- fit_grasp_models(g, seed = 1, distance = "residual")
  cl <- classify(ms, g)
  ref <- vapply(fitted_models(ms), function(m) project_reference(m, g)$distance * sqrt(m$target_length - 1),
                numeric(length(g)))
  expect_equal(unname(cl$distances), unname(ref), tolerance = 1e-12)
})
