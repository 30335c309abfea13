# Planted truth for the thesis' proposed fix: two types whose 14 other DoFs
# wander in ways two FPCs cannot follow (a large residual for every model,
# different from model to model), and which differ only in the timing of two
# DoFs that both types reproduce tightly. The thesis' distance adds the
# residuals of all DoFs alike, so the small, consistent difference drowns;
# the weighted distance scales each DoF by the type's own spread there.

two_dof_types <- function(n_per = 30, seed = 1) {
  planted_set(c("Tripod", "Ring"), n_per, subjects = 5, seed, function(ty, i) {
    m <- 30L
    s <- seq(0, 1, length.out = m)
    close <- (1 - cos(pi * s)) / 2
    r <- outer(close, stats::rnorm(16, 40, 5))
    for (j in setdiff(1:16, c(3, 7))) {
      r[, j] <- r[, j] + 10 * sin(2 * pi * stats::runif(1, 1, 3) * s + stats::runif(1, 0, 2 * pi))
    }
    shape <- if (ty == "Tripod") close else close^1.4
    r[, c(3, 7)] <- outer(shape, 40 + stats::rnorm(2, 0, 1))
    r + matrix(stats::rnorm(m * 16, 0, 0.3), m)
  })
}

test_that("the weighted distance tells apart types the thesis' distance cannot", {
  train <- two_dof_types()
  test <- two_dof_types(seed = 2)
  # the thesis' distance (eq. 4.4, residuals only) is the one that cannot
  m <- fit_grasp_models(train, seed = 1, distance = "residual")
  acc <- function(cl) mean(as.character(cl$predictions$predicted) == as.character(cl$predictions$truth))
  plain <- acc(classify(m, test))
  w <- fit_grasp_classifier(train, method = "weighted_fpca", models = m)
  weighted <- acc(classify(w, test))
  # over training seeds 1-3 (fresh test sets): plain 0.57-0.65, weighted 0.88-1
  expect_lt(plain, 0.75)
  expect_gt(weighted, 0.85)
  expect_gt(weighted - plain, 0.2)
  # the DoFs that separate the types get the weight: their scores are tight
  expect_s3_class(w, "weighted_fpca")
  expect_equal(dim(w$scale), c(2L, 16L))
  expect_output(print(w), "per-type DoF weights")
  expect_output(print(classify(w, test)), "weighted FPCA distance")
})

test_that("time weights reweigh the residual norm towards the end of the motion", {
  expect_equal(distance_time_weights(5, "uniform"), rep(1, 5))
  v <- distance_time_weights(5, "end")
  expect_equal(v, c(0, 0.5, 1, 1.5, 2))
  expect_equal(mean(v), 1)
  # a residual only at the start counts for nothing with end weights
  t <- seq(0, 1, length.out = 21)
  Y <- outer(stats::rnorm(30), sin(pi * t))
  fit <- fpca_fit(Y, argvals = t, ncomp = 1)
  bump <- sin(pi * t) * 0 + c(5, rep(0, 20))
  expect_gt(fpca_residual_norm(fit, bump), 0)
  expect_lt(fpca_residual_norm(fit, bump, distance_time_weights(21, "end")),
            1e-3 * fpca_residual_norm(fit, bump))
})

test_that("evaluate_loso() refits the weighted distance per fold, and bad input is refused", {
  g <- two_dof_types(n_per = 20)
  ev <- evaluate_loso(g, method = "weighted_fpca", fit_args = list(seed = 1), folds = 2)
  expect_gt(ev$accuracy[["held_out"]], 0.75) # half the subjects to train on
  expect_output(print(ev), "weighted FPCA-distance")
  expect_error(fit_grasp_classifier(g, method = "weighted_fpca", time = "start"), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, method = "weighted_fpca", models = list()), class = "handmotion_error_bad_input")
  m <- fit_grasp_models(g, seed = 1)
  expect_error(fit_grasp_classifier(g[g$meta$grasp == "Ring"], method = "weighted_fpca", models = m), class = "handmotion_error_bad_input")
})
