test_that("recordings too short to model and types with one or two recordings are fitted with a classed warning naming them", {
  g <- bad_fixture()$g
  recs <- g$recordings
  recs[[2]] <- recs[[2]][1:2, ]
  short <- grasps(recs, meta = g$meta[c("id", "grasp", "subject", "object", "trial")], dofs = g$dofs)
  id <- g$meta$id[2]
  w <- expect_warning(fit_grasp_classifier(short), id, fixed = TRUE, class = "handmotion_warning_short_recordings")
  expect_s3_class(w, "handmotion_warning_degenerate")
  expect_warning(fit_grasp_recognizer(short), id, fixed = TRUE, class = "handmotion_warning_short_recordings")
  expect_warning(fit_grasp_model(short, grasp = 1, seed = 1), id, fixed = TRUE, class = "handmotion_warning_short_recordings")
  m <- bad_fixture()$m
  expect_warning(project(m, short), id, fixed = TRUE, class = "handmotion_warning_short_recordings")
  # a type with two recordings is fitted, said; one with one cannot be, said
  two <- g[c(1:2, 7:18)]
  w <- expect_warning(fit_grasp_classifier(two), "Large Diameter", class = "handmotion_warning_few_recordings")
  expect_identical(w$grasp, "Large Diameter")
  one <- g[c(1, 7:18)]
  got <- list()
  ms <- withCallingHandlers(fit_grasp_models(one, seed = 1), warning = function(w) {
    got[[length(got) + 1L]] <<- w
    invokeRestart("muffleWarning")
  })
  cls <- vapply(got, function(w) class(w)[1], "")
  expect_true(all(c("handmotion_warning_few_recordings", "handmotion_warning_model_failed") %in% cls))
  failed <- got[[which(cls == "handmotion_warning_model_failed")]]
  expect_identical(failed$grasp, "Large Diameter")
  expect_length(ms, 3L)
  # evaluate_loso() says it once, not once per fold
  got <- list()
  withCallingHandlers(evaluate_loso(two, method = "discriminant", in_sample = FALSE), warning = function(w) {
    got[[length(got) + 1L]] <<- w
    invokeRestart("muffleWarning")
  })
  expect_equal(sum(vapply(got, inherits, TRUE, "handmotion_warning_few_recordings")), 1L)
})
