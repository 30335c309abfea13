test_that("the constructor derives the views from the FPCA and the validator refuses broken shapes", {
  g <- planted_grasps(n = 12, p = 2, seed = 3)
  m <- fit_grasp_model(g, warping = "linear", seed = 1)
  for (j in seq_along(m$dofs)) {
    expect_equal(unname(model_scores(m)[, j, ]), unname(m$fpca[[j]]$scores))
    expect_equal(unname(model_basis(m)$mean[, j]), m$fpca[[j]]$mean)
    expect_equal(unname(model_var_explained(m)[j, ]), unname(m$fpca[[j]]$var_explained))
  }
  broken <- unclass(m)
  broken$fpca[[1]]$mean <- broken$fpca[[1]]$mean[-1]
  expect_error(validate_grasp_model(structure(broken, class = "grasp_model")), "fpca_shape_fault")
  broken <- unclass(m)
  broken$n_used <- broken$n_used - 1L
  expect_error(validate_grasp_model(structure(broken, class = "grasp_model")))
  broken <- unclass(m)
  broken$gmm <- broken$gmm[1]
  expect_error(validate_grasp_model(structure(broken, class = "grasp_model")))
  # a set names each model by its own type, once
  expect_error(new_grasp_models(list(a = m)))
  expect_error(new_grasp_models(stats::setNames(list(m, m), c(m$grasp, m$grasp))))
  expect_s3_class(new_grasp_models(stats::setNames(list(m), m$grasp)), "grasp_models")
})
