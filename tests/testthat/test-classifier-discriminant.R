# Planted truth for the discriminant classifier: types that differ only in
# the final angle of two DoFs, under noise in all 16, must be told apart.

final_dof_types <- function(n_per = 40, subjects = 8, sep = 12, seed = 1) {
  planted_set(c("Tripod", "Ring", "Stick"), n_per, subjects, seed, function(ty, i) {
    shift <- c(Tripod = 0, Ring = sep, Stick = -sep)[[ty]]
    m <- sample(25:35, 1)
    s <- seq(0, 1, length.out = m)
    target <- stats::rnorm(16, 40, 8)                   # every DoF varies a lot between recordings
    target[c(3, 7)] <- 40 + shift + stats::rnorm(2, 0, 2)
    outer(s, target) + matrix(stats::rnorm(m * 16, 0, 1), m)
  })
}

test_that("the discriminant finds the two DoFs that separate the types", {
  g <- final_dof_types()
  test <- final_dof_types(seed = 2)
  cl <- fit_grasp_classifier(g)
  expect_s3_class(cl, "grasp_classifier")
  acc <- mean(predict(cl, test)$.pred_class == test$meta$grasp)
  expect_gt(acc, 0.95)
  P <- predict(cl, test, type = "prob")
  expect_equal(unname(rowSums(P)), rep(1, nrow(P)), tolerance = 1e-12)
  expect_setequal(colnames(P), paste0(".pred_", c("Tripod", "Ring", "Stick")))
  expect_identical(rownames(P), test$meta$id)
  # classify() gives the same predictions as a grasp_classification
  res <- classify(cl, test)
  expect_s3_class(res, "grasp_classification")
  expect_equal(as.character(res$predictions$predicted), as.character(predict(cl, test)$.pred_class))
  expect_output(print(res), "shrinkage LDA")
  expect_output(print(cl), "3 grasp types")
})

test_that("evaluate_loso() takes the discriminant and holds out by subject", {
  g <- final_dof_types(n_per = 24, subjects = 6)
  ev <- evaluate_loso(g, method = "discriminant")
  expect_s3_class(ev, "grasp_evaluation")
  expect_equal(nrow(ev$per_subject), 6)
  expect_gt(ev$accuracy[["held_out"]], 0.9)
  expect_gte(ev$accuracy[["in_sample"]], ev$accuracy[["held_out"]] - 0.02)
  expect_output(print(ev), "shrinkage-LDA")
})

test_that("the classifier refuses what it cannot learn from or apply to", {
  g <- final_dof_types(n_per = 6)
  expect_error(fit_grasp_classifier(g[g$meta$grasp == "Tripod"]), "at least two", class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, at = c(0, 2)), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, prior = "flat"), class = "handmotion_error_bad_input")
  one <- g[c(1:6, 7)]
  expect_error(suppressWarnings(fit_grasp_classifier(one), classes = "handmotion_warning_few_recordings"),
               "fewer than two", class = "handmotion_error_bad_input")
  unl <- g
  unl$meta$grasp[1] <- NA
  expect_error(fit_grasp_classifier(unl), "unlabelled", class = "handmotion_error_bad_input")
  cl <- fit_grasp_classifier(g)
  other <- grasps(lapply(g$recordings[1:3], function(r) r[, 1:15]))
  expect_error(predict(cl, other), "other DoFs", class = "handmotion_error_bad_input")
  expect_error(predict(cl, g, type = "raw"), class = "handmotion_error_bad_input")
})

test_that("class probabilities print as <0.001 and >0.999 at the ends, the data keep the numbers", {
  g <- final_dof_types(n_per = 6)
  pr <- predict(fit_grasp_classifier(g), g[1:3], type = "prob")
  shown <- capture.output(print(pr))
  expect_false(any(grepl("e-[0-9]", shown)))
  near <- unlist(pr) < 5e-4 | unlist(pr) >= 1 - 5e-4
  if (any(near)) expect_true(any(grepl("<0.001|>0.999", shown)))
  expect_true(is.double(pr[[1]]))   # not rounded or formatted in the data
  expect_equal(rowSums(as.data.frame(pr)), rep(1, 3), tolerance = 1e-12, ignore_attr = TRUE)
})

test_that("fit_grasp_classifier(method = ) gives each method's documented class, which classify() follows", {
  g <- final_dof_types(n_per = 6)
  lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
  expect_s3_class(lf, "last_frame_pca")
  expect_equal(lf$ncomp, 2L)
  expect_identical(classify(lf, g)$method, "last_frame")
  w <- fit_grasp_classifier(g, method = "weighted_fpca", seed = 1)
  expect_s3_class(w, "weighted_fpca")
  expect_identical(classify(w, g)$method, "weighted_fpca")
  expect_identical(classify(fit_grasp_classifier(g), g)$method, "discriminant")
  # a method's arguments are checked against that method, by name
  expect_error(fit_grasp_classifier(g, ncomp = 2), "no argument", class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, method = "last_frame", prior = "data"), "no argument",
               class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, method = "weighted_fpca", at = 0.5), "no argument",
               class = "handmotion_error_bad_input")
  # weighted_fpca takes fit_grasp_models()'s arguments and the model settings it passes on
  wg <- fit_grasp_classifier(g, method = "weighted_fpca", seed = 1, mixture_guard = "bic", ncomp = 3)
  expect_equal(unique(vapply(unclass(wg$models$models), function(m) m$settings$ncomp, integer(1))), 3L)
  expect_error(fit_grasp_classifier(g, method = "lda"), "must be one of", class = "handmotion_error_bad_input")
  # classify() needs the fitted object and never refits
  expect_error(classify(g, g, method = "last_frame"), "must be fitted", class = "handmotion_error_bad_input")
  expect_error(classify(lf, g, method = "discriminant"), class = "handmotion_error_bad_input")
})
