# Early recognition: planted types that move alike for the first half of the
# motion and part only in the second half; a recogniser that used the
# recording's length or its future frames would see them apart too early.

late_types <- function(n_per = 36, subjects = 6, seed = 1) {
  planted_set(c("Tripod", "Ring"), n_per, subjects, seed, function(ty, i) {
    m <- 40L
    s <- seq(0, 1, length.out = m)
    common <- outer(s, stats::rnorm(16, 30, 3))                   # both types close alike ...
    part <- outer(pmax(0, (s - 0.5) / 0.5), c(rep(0, 15), if (ty == "Tripod") 25 else -25)) # ... then DoF 16 parts
    common + part + matrix(stats::rnorm(m * 16, 0, 0.5), m)
  })
}

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

# The class probabilities of the first recording, named by class.
first_probs <- function(rec, x, frames) {
  p <- predict(rec, x, frames = frames, type = "prob")
  stats::setNames(unlist(p[1, ]), sub("^\\.pred_", "", names(p)))
}

test_that("a stream updated frame by frame gives the batch prediction of the frames seen", {
  g <- late_types(n_per = 20)
  rec <- fit_grasp_recognizer(g, horizon = 30)
  r <- g$recordings[[5]]
  st <- start_recognition(rec)
  expect_output(print(st), "0 frames seen")
  for (t in seq_len(nrow(r))) {
    p <- update(st, r[t, ])
    if (t %in% c(1, 7, 30, 40)) {
      pb <- first_probs(rec, g[5], t)
      expect_equal(p[names(pb)], pb, tolerance = 1e-10, ignore_attr = TRUE)
    }
  }
  expect_equal(attr(p, "frames"), 40L)
  expect_equal(attr(p, "ms"), 800)
  expect_equal(sum(p), 1, tolerance = 1e-12)
  expect_output(print(st), "40 frames seen \\(800 ms\\); most likely")
  # past the horizon (30 frames) the prediction is the first 30 frames'
  p30 <- first_probs(rec, g[5], 30)
  for (t in 1:100) p <- update(st, r[nrow(r), ] + 50)
  expect_equal(attr(p, "frames"), 140L)
  expect_equal(p[names(p30)], p30, tolerance = 1e-10, ignore_attr = TRUE)
})

test_that("probabilities print with three decimals and bounded ends, the numbers kept", {
  expect_identical(format_probability(c(1, 1 - 1e-12, 1.715671e-21, 0, 0.5, 0.9994, 0.0006, NA)),
                   c(">0.999", ">0.999", "<0.001", "<0.001", "0.500", "0.999", "0.001", NA))
  g <- late_types(n_per = 8)
  rec <- fit_grasp_recognizer(g, horizon = 10)
  st <- start_recognition(rec)
  r <- g$recordings[[1]]
  for (t in 1:10) p <- update(st, r[t, ])
  expect_s3_class(p, "grasp_probabilities")
  out <- capture.output(print(p))
  expect_false(any(grepl("e-|e\\+", out)))
  expect_match(out, "after 10 frames (200 ms)", fixed = TRUE, all = FALSE)
  # the stored values are the model's own, not the printed ones
  expect_identical(as.vector(unclass(p)), as.vector(st$state$probs))
  # the README's most likely types print the same way (a subset keeps the class)
  top <- head(sort(p, decreasing = TRUE), 3)
  expect_s3_class(top, "grasp_probabilities")
  expect_identical(as.vector(unclass(top)), utils::head(sort(as.vector(unclass(p)), decreasing = TRUE), 3))
  expect_false(any(grepl("e-|e\\+", capture.output(print(top)))))
  expect_equal(sum(p), 1, tolerance = 1e-12)
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

test_that("early recognition is evaluated held out by subject, against time and fraction", {
  g <- late_types(n_per = 18, subjects = 6)
  er <- evaluate_early_recognition(g, ms = c(200, 800), fractions = c(0.25, 1))
  expect_s3_class(er, "early_recognition")
  expect_equal(er$scale, c("ms", "ms", "fraction", "fraction"))
  expect_equal(er$n, rep(36L, 4))
  expect_equal(er$frames, c(10, 40, 10, 40))
  expect_lt(er$accuracy[er$scale == "fraction" & er$value == 0.25], 0.8)
  expect_gt(er$accuracy[er$scale == "ms" & er$value == 800], 0.9)
  expect_equal(attr(er, "scheme"), "leave-one-subject-out")
  expect_output(print(er), "held out: leave-one-subject-out")
  expect_s3_class(ggplot2::autoplot(er), "ggplot")
  grouped <- evaluate_early_recognition(g, ms = 400, fractions = 1, folds = 3)
  expect_equal(attr(grouped, "scheme"), "leave-group-out (3 folds of subjects)")
  expect_error(evaluate_early_recognition(g, ms = -1), class = "handmotion_error_bad_input")
  expect_error(evaluate_early_recognition(g, fractions = 0), class = "handmotion_error_bad_input")
  expect_error(evaluate_early_recognition(g, ms = NULL, fractions = NULL), class = "handmotion_error_bad_input")
  expect_error(evaluate_early_recognition(g, ms = 100, horizont = 5), "horizont",
               class = "handmotion_error_bad_input")
  # without subjects the folds hold out recordings; folds by subject are refused
  nosub <- g
  nosub$meta$subject <- NA
  expect_error(evaluate_early_recognition(nosub, split = "subject"), class = "handmotion_error_too_few_subjects")
  byrec <- evaluate_early_recognition(nosub, ms = 800, fractions = NULL, folds = 3)
  expect_match(attr(byrec, "scheme"), "3-fold by recording")
  expect_equal(byrec$n, 36L)
})

test_that("by default early recognition holds out each subject, in at most 30 folds", {
  # 30 subjects: one fold each; 31: 30 seeded groups of subjects, the same
  # evaluation as asking for 30 folds (the cost grows with the data, not
  # with subjects x data)
  g <- simulate_grasps(subjects = 31, grasps = c(1, 17), objects = 1, trials = 1, seed = 2)
  thirty <- g[g$meta$subject != "S31"]
  expect_equal(attr(evaluate_early_recognition(thirty, ms = 400, fractions = NULL), "scheme"),
               "leave-one-subject-out")
  er <- evaluate_early_recognition(g, ms = 400, fractions = NULL)
  expect_equal(attr(er, "scheme"), "leave-group-out (30 folds of subjects)")
  expect_identical(er, evaluate_early_recognition(g, ms = 400, fractions = NULL, folds = 30))
  expect_equal(er$n, length(g))
  expect_match(attr(evaluate_early_recognition(g, ms = 400, fractions = NULL, split = "recording"),
                    "scheme"), "5-fold by recording")
})

test_that("fitting only the horizons a fold needs changes no prediction", {
  g <- late_types(n_per = 18, subjects = 4)
  er <- evaluate_early_recognition(g, ms = c(100, 600), fractions = 0.5, at = c(0, 1))
  expect_equal(er$scale, c("ms", "ms", "fraction"))
  ms_only <- evaluate_early_recognition(g, ms = c(100, 600), fractions = NULL, at = c(0, 1))
  expect_equal(ms_only$accuracy, er$accuracy[1:2])
  # the same counts from full recognisers, one per held-out subject
  subj <- unique(g$meta$subject)
  correct <- rowSums(vapply(subj, function(s) {
    test <- g$meta$subject == s
    rec <- fit_grasp_recognizer(g[!test], at = c(0, 1))
    te <- g[test]
    hits <- function(...) sum(predict(rec, te, ...)$.pred_class == te$meta$grasp)
    c(hits(ms = 100), hits(ms = 600), hits(fraction = 0.5))
  }, numeric(3)))
  expect_equal(er$accuracy, correct / length(g))
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
