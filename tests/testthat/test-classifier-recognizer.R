# Early recognition: planted types that move alike for the first half of the
# motion and part only in the second half; a recogniser that used the
# recording's length or its future frames would see them apart too early.

test_that("the recogniser sees the types apart only once they part", {
  g <- late_types()
  test <- late_types(seed = 2)
  rec <- fit_grasp_recognizer(g)
  expect_s3_class(rec, "grasp_recognizer")
  expect_equal(rec$horizon, 40L)
  acc <- function(...) mean(predict(rec, test, ...)$.pred_class == test$meta$grasp)
  expect_lt(abs(acc(fraction = 0.4) - 0.5), 0.2)     # nothing to see yet: chance
  expect_gt(acc(fraction = 0.75), 0.95)              # parted
  expect_gt(acc(ms = 800), 0.95)                     # 40 frames at 50 Hz: the whole motion
  expect_gt(acc(frames = 200), 0.95)                 # past the horizon: the first 40 frames' prediction
  expect_identical(predict(rec, test), predict(rec, test, fraction = 1)) # by default the whole recording
  expect_output(print(rec), "horizons 1-40 frames")
})

test_that("streams and recognisers refuse bad input", {
  g <- late_types(n_per = 8)
  rec <- fit_grasp_recognizer(g, horizon = 10)
  st <- start_recognition(rec)
  expect_error(update(st, 1:3), "16 finite numbers", class = "handmotion_error_bad_input")
  expect_error(update(st, c(rep(1, 15), NA)), class = "handmotion_error_bad_input")
  expect_error(update(st, stats::setNames(rep(1, 16), rev(g$dofs))), "named", class = "handmotion_error_bad_input")
  expect_error(start_recognition(list()), class = "handmotion_error_bad_input")
  expect_error(predict(rec, g, ms = 100, frames = 3), "at most one", class = "handmotion_error_bad_input")
  expect_error(predict(rec, g, fraction = 1.5), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_recognizer(g, horizon = 0), class = "handmotion_error_bad_input")
})

test_that("the features and the shrinkage LDA equal the former prefix arrays and residual fit", {
  g <- late_types(n_per = 12, subjects = 4)
  # recordings of other lengths, one shorter than the horizons asked
  g <- grasps(unname(c(g$recordings, list(g$recordings[[1]][1:7, ], g$recordings[[2]][rep(1:40, 2), ]))),
              meta = data.frame(grasp = c(g$meta$grasp, "Tripod", "Ring"),
                                subject = c(g$meta$subject, "S01", "S02")), rate = 50)
  at <- c(0, 0.3, 1)
  old <- prefix_arrays_reference(g, 60)
  new <- prefix_source(g)
  for (h in c(1, 2, 7, 33, 60)) {
    expect_identical(prefix_features(new, h, at), prefix_features_reference(old, h, at))
  }
  F <- prefix_features(new, 20, at)
  F <- cbind(F, const = 3)   # a feature without variance is not whitened
  for (prior in c("equal", "data")) {
    a <- fit_shrunk_lda(F, g$meta$grasp, prior)
    b <- fit_shrunk_lda_reference(F, g$meta$grasp, prior)
    expect_equal(a$shrinkage, b$shrinkage, tolerance = 1e-9)
    expect_equal(a$coef, b$coef, tolerance = 1e-9)
    expect_equal(a$offset, b$offset, tolerance = 1e-9)
    expect_identical(a$classes, b$classes)
    expect_identical(a$n, b$n)
  }
  # the moments of a fold subtracted from the whole set's give the fit on the rest
  lev <- levels(factor(g$meta$grasp))
  cls <- as.integer(factor(g$meta$grasp))
  Fc <- F - rep(colMeans(F), each = nrow(F))
  fold <- g$meta$subject == "S02"
  sub <- lda_from_moments(lda_moments_minus(lda_moments(Fc, cls, 2), lda_moments(Fc[fold, ], cls[fold], 2)),
                          Fc, which(!fold), cls[!fold], lev, colMeans(F))
  direct <- fit_shrunk_lda_reference(F[!fold, ], g$meta$grasp[!fold])
  expect_equal(sub$coef, direct$coef, tolerance = 1e-9)
  expect_equal(sub$offset, direct$offset, tolerance = 1e-9)
  expect_equal(sub$shrinkage, direct$shrinkage, tolerance = 1e-9)
})
