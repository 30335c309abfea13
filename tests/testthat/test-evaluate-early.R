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
