test_that("the DTW path keeps the books: used + removed = input", {
  g <- planted_grasps(n = 25, p = 3, sep = 3, sd2 = 1, seed = 15)
  m <- fit_grasp_model(g, seed = 1)
  expect_true(m$warping$method %in% c("dtw", "linear"))
  expect_equal(m$n_used + nrow(m$removed), m$n_input)
  expect_equal(dim(model_scores(m)), c(m$n_used, 3L, 2L))
  expect_equal(dim(m$alignment$warped), c(m$n_used, m$target_length, 3L))
  expect_identical(rownames(m$alignment$warps), m$ids)
  # these planted recordings align by DTW: no warping fallback recorded
  expect_identical(m$warping$method, "dtw")
  expect_false("warping" %in% m$fallbacks$step)
  # when the alignment fails, linear warping is used, recorded and said
  local_failing_alignment()
  expect_warning(lin <- fit_grasp_model(g, seed = 1), class = "handmotion_warning_linear_fallback")
  expect_identical(lin$warping$method, "linear")
  expect_true("warping" %in% lin$fallbacks$step)
  expect_equal(lin$n_used + nrow(lin$removed), lin$n_input)
})
