# A model set is a member of the classifier family whose models are a field,
# read as the list of them (R/grasp-models-list.R).

test_that("a model set reads as the list of its models; $ reads fields and refuses a type, naming [[", {
  g <- simulate_grasps(subjects = 3, grasps = c(1, 9, 17), objects = 2, trials = 2, seed = 4)
  ms <- fit_grasp_models(g, seed = 1, mixture_components = 1)
  types <- names(ms$models)
  expect_s3_class(ms, "grasp_classifier")
  expect_identical(names(ms), types)
  expect_length(ms, 3L)
  expect_identical(ms$models[[types[2]]], ms[[types[2]]])
  expect_identical(ms[[2]], ms[[types[2]]])
  expect_identical(as.list(ms), ms$models)
  # lapply() and vapply() walk the models
  expect_identical(vapply(ms, function(m) m$grasp, ""), stats::setNames(types, types))
  expect_identical(ms$classes, types)
  expect_identical(unname(ms$n), vapply(types, function(t) as.integer(ms[[t]]$n_used), 1L, USE.NAMES = FALSE))
  err <- expect_error(eval(call("$", ms, as.name(types[1]))), class = "handmotion_error_bad_input")
  expect_match(conditionMessage(err), sprintf('x[["%s"]]', types[1]), fixed = TRUE)
  expect_null(ms$no_such_field)
  # a smaller set keeps the fields
  two <- ms[types[1:2]]
  expect_named(two, types[1:2])
  expect_identical(two$temperature, ms$temperature)
  expect_identical(two$levels, ms$levels)
  # replacing a model keeps the fields, and the set is checked again
  again <- ms
  again[[types[3]]] <- ms[[types[3]]]
  expect_identical(again, ms)
  expect_error(again[[types[3]]] <- ms[[types[1]]])
})
