test_that("the copula model's defaults are the measured ones, each overridable", {
  g <- simulate_grasps(subjects = 6, grasps = 3, objects = 2, trials = 2, seed = 3)
  mc <- fit_grasp_model(g, seed = 1, dependence = "copula")
  st <- mc$settings
  expect_equal(list(st$ncomp, st$warp_ncomp, st$mixture_components, st$warping, st$fpc_scores, st$mixture_guard),
               list(4L, 1L, 1L, "linear", "least_squares", "bic"))
  expect_identical(mc$warping$method, "linear")
  expect_false("warping" %in% mc$fallbacks$step) # asked for, not fallen back on
  expect_true(all(vapply(mc$fpca, `[[`, character(1), "score_rule") == "least_squares"))
  mi <- fit_grasp_model(g, seed = 1)
  st <- mi$settings
  expect_equal(list(st$ncomp, st$warp_ncomp, st$mixture_components, st$warping, st$fpc_scores, st$mixture_guard),
               list(2L, 1L, 2L, "dtw", "trapezoid", "none"))
  m2 <- fit_grasp_model(g, seed = 1, dependence = "copula", ncomp = 2, fpc_scores = "trapezoid")
  expect_equal(c(m2$settings$ncomp, dim(model_scores(m2))[3]), c(2L, 2L))
  expect_identical(m2$fpca[[1]]$score_rule, "trapezoid")
  expect_error(fit_grasp_model(g, dependence = "copula", fpc_scores = "trapez"),
               class = "handmotion_error_bad_input")
})
