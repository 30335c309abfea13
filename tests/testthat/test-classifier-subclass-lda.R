# Planted truth for the discriminant's subclasses and for what the
# classifiers are invariant to.

# Two types, each grasped round two objects: type A ends at posture +d or -d
# on DoFs 1-2 (two objects), type B at (+d, -d) or (-d, +d). Each type's mean
# end posture is the origin for both, so one Gaussian per type cannot tell
# them apart; two subclasses per type can.
two_object_types <- function(n_per = 40, subjects = 4, d = 30, seed = 1) {
  planted_set(c("Tripod", "Ring"), n_per, subjects, seed, function(ty, i) {
    object <- i %% 2L
    end <- switch(ty, Tripod = if (object == 1L) c(d, d) else c(-d, -d),
                  Ring = if (object == 1L) c(d, -d) else c(-d, d))
    m <- sample(25:35, 1)
    s <- (1 - cos(pi * seq(0, 1, length.out = m))) / 2
    target <- c(40 + end, stats::rnorm(14, 40, 3))
    outer(s, target) + matrix(stats::rnorm(m * 16, 0, 1), m)
  })
}

test_that("subclasses tell apart types whose objects make them multimodal", {
  g <- two_object_types()
  test <- two_object_types(seed = 2)
  acc <- function(cl) mean(as.character(predict(cl, test)$.pred_class) == test$meta$grasp)
  one <- fit_grasp_classifier(g, subclasses = 1)
  auto <- fit_grasp_classifier(g)
  # one Gaussian per type is at chance (the types' means coincide)
  expect_lt(acc(one), 0.7)
  expect_gt(acc(auto), 0.95)
  # "auto" averages the fits with 1, 2, 4 and 6 subclasses, and says so;
  # its finest member found (at least) the two planted objects per type
  expect_identical(auto$fit$subclasses, "auto")
  expect_length(auto$fit$members, 4L)
  expect_true(all(summary(auto)$subclasses >= 2))
  expect_output(print(auto), "an average of the fits with up to 1, 2, 4, 6")
  P <- predict(auto, test, type = "prob")
  expect_equal(unname(rowSums(P)), rep(1, nrow(P)), tolerance = 1e-12)
})

test_that("the ensemble's probabilities are the average of its members'", {
  g <- two_object_types(n_per = 30, seed = 9)
  test <- two_object_types(n_per = 10, seed = 10)
  auto <- fit_grasp_classifier(g)
  prob <- function(cl) as.matrix(predict(cl, test, type = "prob"))
  members <- lapply(c(1, 2, 4, 6), function(k) prob(fit_grasp_classifier(g, subclasses = k)))
  expect_equal(prob(auto), Reduce(`+`, members) / 4, tolerance = 1e-10)
  # a number still means that number: one member, up to that many clusters
  two <- fit_grasp_classifier(g, subclasses = 2)
  expect_length(two$fit$members, 1L)
  expect_equal(unname(two$fit$subclasses_used), c(2L, 2L))
  expect_output(print(two), "up to 2 [(]given[)]")
})

test_that("the ensemble does not depend on the k-means seed where subclasses are planted", {
  g <- two_object_types(n_per = 30, seed = 11)
  test <- two_object_types(n_per = 20, seed = 12)
  F <- classifier_features(g, seq(0, 1, by = 0.125))
  Ft <- classifier_features(test, seq(0, 1, by = 0.125))
  acc <- vapply(1:5, function(seed) {
    fit <- fit_subclass_lda(F, factor(g$meta$grasp), "equal", "auto", seed = seed)
    mean(top_class(fit$types, subclass_lda_scores(fit, Ft)) == test$meta$grasp)
  }, numeric(1))
  # the planted two objects per type are found whatever the seed
  expect_true(all(acc > 0.95))
})

test_that("one subclass per type is the one-Gaussian shrinkage LDA", {
  g <- two_object_types(n_per = 12, seed = 3)
  cl <- fit_grasp_classifier(g, subclasses = 1)
  F <- classifier_features(g, cl$at)
  ref <- fit_shrunk_lda(F, factor(g$meta$grasp))
  s_ref <- shrunk_lda_scores(ref, F)
  s <- subclass_lda_scores(cl$fit, F)
  # both as normalised log posteriors
  s_ref <- s_ref - log_sum_exp_rows(s_ref)
  expect_equal(unname(s[, colnames(s_ref)]), unname(s_ref), tolerance = 1e-10)
})

test_that("a type too small to split stays one subclass, and that is recorded", {
  g <- two_object_types(n_per = 40, seed = 4)
  ring <- which(g$meta$grasp == "Ring")
  x <- g[g$meta$grasp == "Tripod" | seq_along(g) %in% ring[1:6]]
  cl <- fit_grasp_classifier(x, subclasses = 4)
  s <- summary(cl)
  expect_equal(s$subclasses[s$grasp == "Ring"], 1L)       # 6 recordings < 2 x 5
  expect_equal(s$subclasses[s$grasp == "Tripod"], 4L)
  expect_error(fit_grasp_classifier(x, subclasses = 0), class = "handmotion_error_bad_input")
})

# Two types with the same start and the same end posture on every DoF, told
# apart only by the shape of the motion: type "early" closes DoFs 1-4 in the
# first third, type "late" in the last third.
same_ends_types <- function(n_per = 30, subjects = 3, seed = 1) {
  planted_set(c("Tripod", "Ring"), n_per, subjects, seed, function(ty, i) {
    m <- sample(28:36, 1)
    u <- seq(0, 1, length.out = m)
    centre <- if (ty == "Tripod") 0.3 else 0.7
    s <- stats::plogis((u - centre) * 25)
    s <- (s - s[1]) / (s[m] - s[1])
    target <- c(rep(50, 4), stats::rnorm(12, 40, 3))
    outer(s, target) + matrix(stats::rnorm(m * 16, 0, 1), m)
  })
}

test_that("types with the same end posture are told apart by the shape of their motion", {
  g <- same_ends_types()
  test <- same_ends_types(seed = 2)
  # the last frames alone cannot separate them; the discriminant can
  lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
  acc <- function(cl) mean(as.character(predict(cl, test)$.pred_class) == test$meta$grasp)
  expect_lt(acc(lf), 0.75)
  expect_gt(acc(fit_grasp_classifier(g)), 0.95)
})

# What the classifiers are invariant to: the glove's calibration per channel.
# The same recordings read through another offset and gain per channel
# (counts of another glove, degrees instead of counts), for training and new
# recordings alike, give the same predictions.
recalibrated <- function(x, gain, offset) {
  x$recordings <- lapply(x$recordings, function(r) sweep(sweep(r, 2, gain, "*"), 2, offset, "+"))
  x
}

test_that("the discriminant is invariant to a per-channel offset and nearly to a gain", {
  g <- two_object_types(n_per = 30, seed = 5)
  test <- two_object_types(n_per = 10, seed = 6)
  set.seed(7)
  offset <- stats::runif(16, -200, 200)
  gain <- stats::runif(16, 0.5, 3)
  pred <- function(train, new, k) as.character(predict(fit_grasp_classifier(train, subclasses = k), new)$.pred_class)
  base <- pred(g, test, 2)
  # an offset leaves every feature's differences unchanged: identical
  expect_identical(pred(recalibrated(g, rep(1, 16), offset), recalibrated(test, rep(1, 16), offset), 2), base)
  # a gain rescales postures (LDA and the standardised k-means ignore that)
  # and shifts log travel by about log(gain): the same predictions here
  expect_identical(pred(recalibrated(g, gain, 0), recalibrated(test, gain, 0), 2), base)
  # counts that fall as a finger bends (flexglove): a negative gain swaps
  # each channel's smallest and largest value, a permutation of the features
  # that the discriminant ignores too
  expect_identical(pred(recalibrated(g, -gain, 0), recalibrated(test, -gain, 0), 2), base)
})

test_that("the weighted FPCA distance is invariant to a per-channel gain", {
  g <- same_ends_types(n_per = 16, subjects = 4)
  test <- same_ends_types(n_per = 6, subjects = 2, seed = 2)
  set.seed(8)
  gain <- stats::runif(16, 0.5, 3)
  pred <- function(train, new) as.character(predict(fit_grasp_classifier(train, method = "weighted_fpca", seed = 1),
                                                    new)$.pred_class)
  base <- pred(g, test)
  scaled <- pred(recalibrated(g, gain, 0), recalibrated(test, gain, 0))
  # its per-type DoF scales absorb any unit of a channel (up to the
  # mixture fits' rounding)
  expect_gte(mean(scaled == base), 0.95)
})
