test_that("a fitted model whose parts were edited is refused by every verb, naming the part", {
  f <- bad_fixture()
  m <- f$m
  w <- m
  w$gmm[[1]]$weights[] <- NaN
  for (verb in list(function(x) generate(x, n = 2), function(x) project(x, f$g), function(x) summary(x),
                    function(x) autoplot(x))) {
    cnd <- expect_error(verb(w), "gmm", class = "handmotion_error_bad_model")
    expect_match(conditionMessage(cnd), "Large Diameter")
  }
  s <- f$ms
  s[[1]] <- w
  expect_error(classify(s, f$g), "DoF CMC1", class = "handmotion_error_bad_model")
  mean_nan <- m
  mean_nan$fpca[[2]]$mean[5] <- NaN
  expect_error(generate(mean_nan, n = 1), "fpca.*DoF ABD1", class = "handmotion_error_bad_model")
  no_warp <- m
  no_warp$warp <- NULL
  expect_error(project(no_warp, f$g), "warp", class = "handmotion_error_bad_model")
  no_rate <- m
  no_rate$rate <- NaN
  expect_error(generate(no_rate, n = 1), "rate", class = "handmotion_error_bad_model")
  # a set holding something that is not a model
  text <- unclass(f$ms)
  text$models[[2]] <- "x"
  class(text) <- class(f$ms)
  expect_error(classify(text, f$g), "models$models[[2]] (Small Diameter)", fixed = TRUE, class = "handmotion_error_bad_model")
  expect_error(generate(text, n = 1), "x$models[[2]]", fixed = TRUE, class = "handmotion_error_bad_model")
  # a set saved by an earlier version (the list of models, fields as attributes)
  old <- structure(f$ms$models, class = class(f$ms), temperature = 1)
  expect_error(predict(old, f$g), "earlier version", class = "handmotion_error_bad_model")
  hot <- unclass(f$ms)
  hot$temperature <- NaN
  class(hot) <- class(f$ms)
  expect_error(predict(hot, f$g, type = "prob"), "temperature", class = "handmotion_error_bad_model")
  # classifiers and the hand-over model
  clf <- f$clf
  clf$fit <- NULL
  expect_error(predict(clf, f$g), "no fit", class = "handmotion_error_bad_model")
  clf <- f$clf
  clf$at[2] <- NaN
  expect_error(predict(clf, f$g), "at", class = "handmotion_error_bad_model")
  clf <- f$clf
  clf$fit$members[[1]]$coef[1, 1] <- Inf
  cnd <- expect_error(classify(clf, f$g), "models$fit$members[[1]]$coef", fixed = TRUE, class = "handmotion_error_bad_model")
  expect_identical(cnd$argument, "models")
  ho <- fit_handover(f$g, n_markers = 3)
  q <- forward_kinematics(f$g[1], markers = ho$markers)[[1]]
  ho$rotation[1, 1] <- NaN
  expect_error(predict(ho, q), "object$rotation", fixed = TRUE, class = "handmotion_error_bad_model")
})
