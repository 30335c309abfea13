test_that("the extremes of the motion are recovered, spikes aside, and tell apart a preshape", {
  g <- overshoot_types(n_per = 4)
  E <- extreme_features(g)
  first <- g$dofs[1]
  expect_identical(colnames(E)[c(1, 17)], paste0(first, c(".min", ".max")))
  tripod <- g$meta$grasp == "Tripod"
  # the planted 15 above (Tripod) or below (Ring) a DoF at rest (noise sd 1)
  expect_true(all(abs(E[tripod, 17] - 15) < 3.5))
  expect_true(all(abs(E[!tripod, 1] + 15) < 3.5))
  # one frame's spike is not an extreme (flexglove's flex6 jumps to 886)
  spiked <- g
  spiked$recordings[[1]][20, 2] <- 900
  expect_lt(extreme_features(spiked)[1, 18], 100)
  # the running median of 3 frames, the ends the median of their three
  r <- spiked$recordings[[1]]
  ref <- apply(r, 2, function(v) {
    n <- length(v)
    vapply(seq_len(n), function(i) stats::median(v[min(max(i - 1, 1), n - 2) + 0:2]), numeric(1))
  })
  expect_equal(median3_channels(r), ref, ignore_attr = TRUE)

  train <- overshoot_types()
  test <- overshoot_types(seed = 2)
  cl <- fit_grasp_classifier(train)
  expect_gt(mean(as.character(predict(cl, test)$.pred_class) == test$meta$grasp), 0.95)
  # without the extremes (postures at the same fractions, log duration and
  # travel) the same discriminant misses the recordings whose moment falls
  # between fractions
  without <- function(x) cbind(motion_features(x, cl$at), travel_features(x))
  fit <- fit_subclass_lda(without(train), factor(train$meta$grasp), "equal", 1L)
  pred <- top_class(fit$types, subclass_lda_scores(fit, without(test)))
  expect_lt(mean(pred == test$meta$grasp), 0.85)
})
