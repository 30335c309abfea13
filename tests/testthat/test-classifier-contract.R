# One contract for every classifier the package fits (?predict.grasp_models):
# each is fitted on planted, well-separated types and checked alike.

# Every classifier handmotion fits, on the same training set.
all_classifiers <- function(train) {
  list(
    fpca = fit_grasp_models(train, seed = 1, mixture_components = 1),
    discriminant = fit_grasp_classifier(train),
    last_frame = fit_grasp_classifier(train, method = "last_frame", ncomp = 2),
    weighted_fpca = fit_grasp_classifier(train, method = "weighted_fpca", seed = 1),
    recognizer = fit_grasp_recognizer(train)
  )
}

test_that("every classifier answers predict() with classes, probabilities and distances alike", {
  types <- c(1, 9, 17, 22)
  train <- planted_types(types = types, subjects = 4, trials = 3, seed = 2)
  # new recordings of the same types (the planted postures are the seed's)
  test <- planted_types(types = types, subjects = 2, trials = 2, seed = 2)
  test$meta$id <- paste0("new", seq_along(test$recordings))
  classes <- as.character(feix_levels()[types])
  fits <- all_classifiers(train)
  # the package's fitting verbs, each one here (a new classifier joins this list)
  expect_setequal(names(fits), c("fpca", "discriminant", "last_frame", "weighted_fpca", "recognizer"))
  for (name in names(fits)) {
    fit <- fits[[name]]
    info <- paste("classifier:", name)
    cl <- predict(fit, test)
    expect_s3_class(cl, c("grasp_predictions", "data.frame"))
    expect_named(cl, ".pred_class")
    expect_identical(rownames(cl), test$meta$id, label = info)
    expect_identical(levels(cl$.pred_class), levels(train$meta$grasp), label = info)
    expect_gte(mean(as.character(cl$.pred_class) == as.character(test$meta$grasp)), 0.95, label = info)
    p <- predict(fit, test, type = "prob")
    expect_s3_class(p, "grasp_predictions")
    expect_setequal(names(p), paste0(".pred_", classes))
    expect_equal(unname(rowSums(p)), rep(1, length(test)), tolerance = 1e-12, label = info)
    # the most probable class is the predicted one, and well-separated types
    # give near-certain probabilities on the right one
    top <- sub("^\\.pred_", "", names(p))[max.col(as.matrix(p), ties.method = "first")]
    expect_identical(top, as.character(cl$.pred_class), label = info)
    own <- as.matrix(p)[cbind(seq_len(nrow(p)), match(paste0(".pred_", test$meta$grasp), names(p)))]
    expect_gt(stats::median(own), 0.99, label = info)
    d <- predict(fit, test, type = "distance")
    expect_setequal(names(d), paste0(".dist_", classes))
    near <- sub("^\\.dist_", "", names(d))[max.col(-as.matrix(d), ties.method = "first")]
    expect_identical(near, as.character(cl$.pred_class), label = info)
    # a recording that cannot be classified is NA, with its reason (grasps()
    # refuses a NaN; this one was put in after construction)
    bad <- test
    bad$recordings[[2]][3, 1] <- NaN
    pb <- suppressWarnings(predict(fit, bad))
    expect_true(is.na(pb$.pred_class[2]), label = info)
    expect_false(anyNA(pb$.pred_class[-2]), label = info)
    expect_named(attr(pb, "reasons"), test$meta$id[2])
    expect_match(attr(pb, "reasons"), "non-finite")
    expect_true(all(is.na(unlist(suppressWarnings(predict(fit, bad, type = "prob"))[2, ]))), label = info)
    # print() previews ten rows, not all; the classifier prints and summarises
    out <- utils::capture.output(print(p))
    expect_lt(length(out), 40L)
    expect_match(paste(out, collapse = "\n"), "more rows")
    expect_output(print(p[1:3, ]), "class probabilities of 3 recordings")
    expect_output(print(fit))
    # every summary begins with the family's columns: the class and its
    # training recordings (the FPCA set's n: those its model kept)
    s <- summary(fit)
    expect_s3_class(s, "data.frame")
    expect_identical(names(s)[1:3], c("grasp_id", "grasp", "n"), label = info)
    expect_identical(s$grasp, classes, label = info)
    expect_identical(s$grasp_id, as.integer(types), label = info)
    counts <- as.integer(table(train$meta$grasp)[classes])
    if (name == "fpca") expect_true(all(s$n <= counts & s$n >= counts - 2L), label = info)
    else expect_identical(s$n, counts, label = info)
    # bad arguments, classed
    expect_error(predict(fit, test, type = "raw"), class = "handmotion_error_bad_input")
    expect_error(predict(fit, test, foo = 1), class = "handmotion_error_bad_input")
    expect_error(predict(fit, list()), class = "handmotion_error_bad_input")
  }
})

test_that("the FPCA set's temperature is fitted and kept when the set is subset", {
  train <- planted_types(types = c(1, 9, 17), subjects = 3, trials = 3, seed = 3)
  ms <- fit_grasp_models(train, seed = 1, mixture_components = 1)
  expect_true(is.numeric(ms$temperature) && ms$temperature > 0)
  expect_identical(ms[1:2]$temperature, ms$temperature)
  expect_output(print(ms), "class probabilities: softmax")
  # a set built without a fit has no temperature: no probabilities, said so
  bare <- new_grasp_models(ms$models)
  expect_error(predict(bare, train, type = "prob"), class = "handmotion_error_bad_model")
  expect_s3_class(predict(bare, train), "grasp_predictions")
})

test_that("classify() is predict(type = 'distance') kept whole", {
  train <- planted_types(types = c(1, 9, 17), subjects = 3, trials = 3, seed = 3)
  lf <- fit_grasp_classifier(train, method = "last_frame", ncomp = 2)
  cl <- classify(lf, train)
  d <- predict(lf, train, type = "distance")
  expect_equal(unname(cl$distances), unname(as.matrix(d)))
  expect_identical(as.character(cl$predictions$predicted), as.character(predict(lf, train)$.pred_class))
})
