# A sixth classifier is one file against the family (R/classifier.R): here
# the whole of it is written in the test, through the family's constructor
# and one method of its one required generic, and every verb of the family
# then answers for it with no edit anywhere else.

# --- the sixth classifier: nearest centroid of the last frames --------------
# (In the package this would be R/<name>.R with `#' @export` on the method,
# which registers it; a test registers it by hand for its own duration.)

fit_nearest_centroid <- function(x) {
  last <- t(vapply(x$recordings, function(r) r[nrow(r), ], numeric(length(x$dofs))))
  y <- droplevels(as.factor(x$meta$grasp))
  centres <- rowsum(last, y) / as.vector(table(y))
  new_grasp_classifier(centres = centres, dofs = x$dofs,
                       classes = levels(y), levels = levels(x$meta$grasp), n = table(y),
                       temperature = 1, class = "nearest_centroid")
}

nearest_centroid_distances <- function(object, new_data, ..., call = rlang::caller_env()) {
  last <- t(vapply(new_data$recordings, function(r) r[nrow(r), ], numeric(length(object$dofs))))
  d <- sqrt(pmax(outer(rowSums(last^2), rowSums(object$centres^2), `+`) - 2 * last %*% t(object$centres), 0))
  dimnames(d) <- list(new_data$meta$id, object$classes)
  d
}

# Register an S3 method of the package's internal generic for the calling
# test only (what NAMESPACE's S3method() does for a file in R/).
local_classifier_method <- function(generic, class, fun, frame = parent.frame()) {
  ns <- asNamespace("handmotion")
  registerS3method(generic, class, fun, envir = ns)
  withr::defer(rm(list = paste(generic, class, sep = "."), envir = ns[[".__S3MethodsTable__."]]),
               envir = frame)
}

test_that("a sixth classifier written against the family answers every verb of the family", {
  local_classifier_method("classifier_distances", "nearest_centroid", nearest_centroid_distances)
  types <- c(1, 9, 17, 22)
  classes <- as.character(feix_levels()[types])
  train <- planted_types(types = types, subjects = 4, trials = 3, seed = 5)
  test <- planted_types(types = types, subjects = 2, trials = 2, seed = 5)
  test$meta$id <- paste0("new", seq_along(test$recordings))
  fit <- fit_nearest_centroid(train)
  expect_s3_class(fit, c("nearest_centroid", "grasp_classifier"), exact = TRUE)

  # predict(): the planted postures are far apart, so the nearest centroid is
  # the own type's, and the distances are the ones computed by hand
  cl <- predict(fit, test)
  expect_named(cl, ".pred_class")
  expect_identical(levels(cl$.pred_class), levels(train$meta$grasp))
  expect_gte(mean(as.character(cl$.pred_class) == as.character(test$meta$grasp)), 0.95)
  d <- predict(fit, test, type = "distance")
  own <- fit$centres[as.character(test$meta$grasp[3]), ]
  last3 <- test$recordings[[3]][nrow(test$recordings[[3]]), ]
  expect_equal(d[[paste0(".dist_", test$meta$grasp[3])]][3], sqrt(sum((last3 - own)^2)), tolerance = 1e-8)
  p <- predict(fit, test, type = "prob")
  expect_setequal(names(p), paste0(".pred_", classes))
  expect_equal(unname(rowSums(p)), rep(1, length(test)), tolerance = 1e-12)
  # probabilities are softmax(-distance / temperature) with its field
  expect_equal(unname(as.matrix(p)), unname(distance_softmax(as.matrix(d), 1)), tolerance = 1e-12)

  # print() and summary() of the parent: the family's fields
  expect_output(print(fit), "<nearest_centroid> grasp classifier: 4 classes, 48 training recordings")
  s <- summary(fit)
  expect_identical(names(s), c("grasp_id", "grasp", "n"))
  expect_identical(s$grasp, classes)
  expect_identical(s$grasp_id, as.integer(types))
  expect_identical(s$n, rep(12L, 4))

  # classify() infers the method from the class, and its confusion plots
  res <- classify(fit, test)
  expect_s3_class(res, "grasp_classification")
  expect_identical(res$method, "nearest_centroid")
  expect_output(print(res), "nearest_centroid distance")
  expect_equal(unname(res$distances), unname(as.matrix(d)))
  built <- ggplot2::ggplot_build(ggplot2::autoplot(res))
  expect_identical(sum(built$plot$data$n), length(test))

  # evaluate_loso() with the fitter: held out by subject, near-perfect on
  # planted types, and its summary and plot
  ev <- evaluate_loso(train, method = fit_nearest_centroid)
  expect_identical(ev$method, "fit_nearest_centroid")
  expect_gte(ev$accuracy[["held_out"]], 0.95)
  expect_identical(nrow(ev$per_subject), 4L)
  expect_output(print(ev), "fit_nearest_centroid classifier")
  expect_true(".metric" %in% names(summary(ev)))
  expect_s3_class(ggplot2::autoplot(ev), "ggplot")
})

test_that("the family's constructor refuses fields that do not agree", {
  ok <- list(classes = c("a", "b"), levels = c("a", "b", "c"), n = c(3, 4), class = "toy")
  expect_s3_class(do.call(new_grasp_classifier, ok), c("toy", "grasp_classifier"), exact = TRUE)
  expect_error(do.call(new_grasp_classifier, utils::modifyList(ok, list(levels = "a"))))
  expect_error(do.call(new_grasp_classifier, utils::modifyList(ok, list(classes = c("a", "a")))))
  expect_error(do.call(new_grasp_classifier, c(ok, temperature = -1)))
  expect_error(do.call(new_grasp_classifier, c(ok, list(1))))   # an unnamed field
})

test_that("something that is not a classifier, or the discriminant of an earlier version, is named", {
  train <- planted_types(types = c(1, 9), subjects = 3, trials = 3, seed = 6)
  expect_error(classify(list(a = 1), train), class = "handmotion_error_bad_input")
  old <- fit_grasp_classifier(train)
  class(old) <- "grasp_classifier"   # how earlier versions classed the discriminant
  expect_error(predict(old, train), class = "handmotion_error_bad_model")
  expect_snapshot(classify(old, train), error = TRUE)
})

test_that("every classifier is of the family and names its method", {
  train <- planted_types(types = c(1, 9, 17), subjects = 3, trials = 3, seed = 3)
  fits <- list(fpca = fit_grasp_models(train, seed = 1, mixture_components = 1),
               discriminant = fit_grasp_classifier(train),
               last_frame = fit_grasp_classifier(train, method = "last_frame", ncomp = 2),
               weighted_fpca = fit_grasp_classifier(train, method = "weighted_fpca", seed = 1),
               recognizer = fit_grasp_recognizer(train))
  for (m in names(fits)) {
    expect_s3_class(fits[[m]], "grasp_classifier")
    expect_identical(classifier_method(fits[[m]]), m)
    expect_identical(classify(fits[[m]], train)$method, m)
  }
  # the discriminant's class says what it is
  expect_identical(class(fits$discriminant), c("grasp_discriminant", "grasp_classifier"))
  # the methods classify() and evaluate_loso() take by name are one list:
  # the FPCA set's and fit_grasp_classifier()'s
  expect_identical(classify_methods(), eval(formals(evaluate_loso)$method))
  expect_setequal(classify_methods(), c("fpca", eval(formals(fit_grasp_classifier)$method)))
  # the recogniser classifies whole recordings as predict() does by default
  expect_identical(as.character(classify(fits$recognizer, train)$predictions$predicted),
                   as.character(predict(fits$recognizer, train)$.pred_class))
})
