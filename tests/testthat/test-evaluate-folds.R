# Folds for any design: by subject, or stratified by recording.

test_that("stratified folds deal every label evenly, are seeded and repeatable", {
  lab <- factor(rep(c("a", "b", "c"), times = c(30, 12, 7)))
  f <- stratified_fold_ids(lab, 5, seed = 2)
  tab <- table(lab, f)
  expect_true(all(apply(tab, 1, function(r) max(r) - min(r) <= 1)))
  expect_lte(diff(range(table(f))), 1)
  expect_identical(f, stratified_fold_ids(lab, 5, seed = 2))
  expect_false(identical(f, stratified_fold_ids(lab, 5, seed = 3)))
})

test_that("make_folds splits by subject with two or more subjects, else by recording", {
  g <- simulate_grasps(subjects = 3, grasps = 1:2, objects = 1, trials = 2, seed = 1)
  f <- make_folds(g)
  expect_equal(attr(f, "split"), "subject")
  expect_length(f, 3)
  one <- g[g$meta$subject == "S01"]
  f1 <- make_folds(one, folds = 2)
  expect_equal(attr(f1, "split"), "recording")
  expect_true(all(Reduce(`+`, f1) == 1))   # every recording held out exactly once
  expect_error(make_folds(one, split = "subject"), class = "handmotion_error_too_few_subjects")
  expect_error(make_folds(one, folds = 1), class = "handmotion_error_bad_input")
})

test_that("one subject's recordings are evaluated by folds of recordings, with a confidence interval", {
  raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 3, card = 16, pen = 20), objects = 1, trials = 10,
                         rate = 50, glove = "resistive", rest = 0.8, hold = 0.8, seed = 5)
  ev <- evaluate_loso(raw, method = "discriminant")
  expect_equal(ev$split, "recording")
  expect_match(ev$scheme, "5-fold by recording")
  expect_equal(sum(ev$confusion$table), 30)
  ci <- ev$accuracy_ci
  expect_true(ci[["lower"]] <= ev$accuracy[["held_out"]] && ev$accuracy[["held_out"]] <= ci[["upper"]])
  expect_output(print(ev), "95% CI")
})

test_that("the Wilson interval covers a planted proportion at its nominal rate", {
  set.seed(11)
  hits <- vapply(1:2000, function(i) {
    k <- stats::rbinom(1, 60, 0.9)
    ci <- accuracy_interval(k, 60)
    ci[["lower"]] <= 0.9 && 0.9 <= ci[["upper"]]
  }, logical(1))
  expect_gt(mean(hits), 0.93)
  expect_lt(mean(hits), 0.975)
  expect_equal(unname(accuracy_interval(0, 0)), c(NA_real_, NA_real_))
})
