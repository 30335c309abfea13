# A classification built straight from a known distance matrix, so the
# bookkeeping (argmin, Table 5.3 scaling, minima counts) is checked by hand.
known_classification <- function() {
  d <- rbind(r1 = c(1, 5, 9), r2 = c(4, 2, 9), r3 = c(6, 3, 7), r4 = c(NA, NA, NA))
  colnames(d) <- c("Large Diameter", "Palmar Pinch", "Tripod")
  meta <- data.frame(id = rownames(d), subject = c("a", "a", "b", "b"),
                     grasp = factor(c("Large Diameter", "Palmar Pinch", "Tripod", "Tripod"),
                                    levels = feix_levels()))
  new_classification(d, meta, "fpca", target_length = c(`Large Diameter` = 10, `Palmar Pinch` = 20,
                                                        Tripod = 50))
}

test_that("the closest model wins; rows without distances get NA", {
  cl <- known_classification()
  p <- cl$predictions
  expect_equal(as.character(p$predicted), c("Large Diameter", "Palmar Pinch", "Palmar Pinch", NA))
  expect_equal(p$distance, c(1, 2, 3, NA))
  expect_output(print(cl), "accuracy 66.7% \\(2 of 3")
  expect_output(print(cl), "1 recording without a prediction")
  cm <- grasp_confusion(cl)
  expect_equal(cm$levels, c("Large Diameter", "Palmar Pinch", "Tripod"))
  expect_equal(cm$n_missing_predicted, 1L)
  expect_equal(cm$table["Palmar Pinch", "Tripod"], 1L)
})

test_that("distance_table gives mean 100 * d / T per model (rows) and true type (cols)", {
  tab <- distance_table(known_classification())
  expect_equal(names(dimnames(tab)), c("model", "truth"))
  expect_equal(rownames(tab), c("Large Diameter", "Palmar Pinch", "Tripod"))
  # Tripod column: only r3 has distances (r4 is NA and is skipped)
  expect_equal(tab["Large Diameter", "Tripod"], 100 * 6 / 10)
  expect_equal(tab["Tripod", "Tripod"], 100 * 7 / 50)
  expect_equal(tab["Palmar Pinch", "Large Diameter"], 100 * 5 / 20)
})

test_that("distance_minima counts row and column minima as in the thesis' text", {
  tab <- matrix(c(1, 3, 2,
                  2, 1, 3,
                  4, 2, 5), 3, byrow = TRUE,
                dimnames = list(model = c("A", "B", "C"), truth = c("A", "B", "C")))
  # row minima: A->A (own), B->B (own), C->B; column minima: A->A, B->B, C->A
  m <- distance_minima(tab)
  expect_equal(m$model_min_own_type, 2L)
  expect_equal(m$type_min_own_model, 2L)
  expect_equal(m$both, 2L)
  expect_equal(m$models_never_min, 1L)
  expect_equal(m$most_attracting, "A")
  expect_equal(m$n_attracted, 2L)
})

test_that("last-frame classification is near 100% on planted well-separated types", {
  g <- planted_types(types = c(1, 9, 17, 22, 31), subjects = 4, trials = 3, seed = 5)
  cl <- classify(fit_grasp_classifier(g, method = "last_frame", ncomp = 5), g)
  expect_s3_class(cl, "grasp_classification")
  expect_equal(cl$method, "last_frame")
  expect_equal(dim(cl$distances), c(length(g), 5L))
  acc <- summary(grasp_confusion(cl))
  expect_gte(acc$.estimate[acc$.metric == "accuracy"], 0.98)
  # same result from a fitted model; the method follows from its class
  fit <- fit_grasp_classifier(g, method = "last_frame", ncomp = 5)
  expect_equal(classify(fit, g)$predictions, cl$predictions)
  expect_error(classify(fit, g, method = "fpca"), class = "handmotion_error_bad_input")
  expect_error(classify(list(), g), class = "handmotion_error_bad_input")
  expect_error(classify(fit, "not grasps"), class = "handmotion_error_bad_input")
})

test_that("classification of shuffled labels is not near 100% (the test can fail)", {
  g <- planted_types(types = c(1, 9, 17, 22, 31), subjects = 4, trials = 3, seed = 5)
  shuffled <- g
  shuffled$meta$grasp <- withr::with_seed(1, sample(g$meta$grasp))
  cl <- classify(fit_grasp_classifier(shuffled, method = "last_frame", ncomp = 5), g)
  acc <- mean(as.character(cl$predictions$predicted) == as.character(g$meta$grasp))
  expect_lt(acc, 0.6)
})

test_that("one-type data: every recording goes to the only type, accuracy 1", {
  g <- planted_types(types = 17, subjects = 3, trials = 3)
  cl <- classify(fit_grasp_classifier(g, method = "last_frame", ncomp = 2), g)
  expect_true(all(cl$predictions$predicted == "Index Finger Extension"))
  cm <- grasp_confusion(cl)
  expect_equal(cm$levels, "Index Finger Extension")
  expect_equal(summary(cm)$.estimate[1], 1)
})

test_that("FPCA classification is near 100% on planted well-separated types", {
  g <- planted_types(types = c(1, 9, 17, 22), subjects = 4, trials = 3, seed = 2)
  # the thesis' distance (eq. 4.4), checked against project() below; the
  # likelihood distance has its own tests (test-classifier-fpca-likelihood.R)
  ms <- fit_grasp_models(g, seed = 1, distance = "residual")
  cl <- classify(ms, g)
  expect_equal(cl$method, "fpca")
  expect_gte(mean(as.character(classify(fit_grasp_models(g, seed = 1), g)$predictions$predicted) ==
                   as.character(g$meta$grasp)), 0.95)
  expect_equal(colnames(cl$distances), names(ms))
  expect_equal(unname(cl$target_length), vapply(ms, function(m) m$target_length, numeric(1)),
               ignore_attr = TRUE)
  expect_gte(mean(as.character(cl$predictions$predicted) == as.character(g$meta$grasp)), 0.95)
  # the thesis' norm on frames 1..T_i: project()'s [0, 1] distance times
  # sqrt(T_i - 1), model by model
  tl <- cl$target_length
  pr <- project(ms, g)
  for (type in names(ms)) {
    expect_equal(unname(cl$distances[, type]), unname(pr[[type]]$distance) * sqrt(tl[[type]] - 1),
                 tolerance = 1e-12)
  }
  tab <- distance_table(cl)
  expect_equal(dim(tab), c(4L, 4L))
  # every model fits its own type best (diagonal is the row minimum)
  expect_equal(distance_minima(tab)$model_min_own_type, 4L)
  # a model set where one type failed to fit: recorded and warned, never hidden
  failed <- new_grasp_model_failed("Tripod", simpleError("too few recordings"))
  part <- new_grasp_models(c(ms$models[1:3], list(Tripod = failed)))
  expect_warning(clp <- classify(part, g), class = "handmotion_warning_projection_failed")
  expect_equal(clp$failures$model, "Tripod")
  expect_output(print(clp), "failed models: Tripod")
  one <- ms[1]
  cl1 <- classify(one, g)
  expect_true(all(cl1$predictions$predicted == "Large Diameter"))
})

test_that("summary, autoplot and as.data.frame of a classification", {
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 2, seed = 9)
  cl <- classify(fit_grasp_classifier(g, method = "last_frame", ncomp = 2), g)
  s <- summary(cl)
  expect_s3_class(s, "summary_grasp_confusion")
  expect_equal(s$.estimate[s$.metric == "accuracy"], 1)
  b <- ggplot2::ggplot_build(ggplot2::autoplot(cl))
  expect_equal(nrow(b$data[[1]]), 4)
  expect_equal(as.data.frame(cl), cl$predictions)
  expect_snapshot(print(grasp_confusion(cl)))
})

test_that("classify() needs fitted models and takes nothing else (it never fits silently)", {
  g <- simulate_grasps(subjects = 2, grasps = c(9, 17), objects = 1, trials = 2, seed = 1)
  expect_error(classify(g, g), class = "handmotion_error_bad_input")
  expect_snapshot(error = TRUE, classify(g, g, method = "last_frame"))
  lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
  expect_error(classify(lf, g, k = 3), class = "handmotion_error_bad_input")
  expect_error(classify(lf, g, method = "fpca"), class = "handmotion_error_bad_input")
})
