test_that("LOSO on a planted design: held-out accuracy <= in-sample, bookkeeping adds up", {
  # Large subject x type interaction: in-sample models absorb each subject's
  # personal postures, a held-out subject's are new.
  g <- planted_types(types = c(1, 9, 17, 22), subjects = 5, trials = 2, spread = 20,
                     subject_sd = 8, seed = 4)
  ev <- evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 3))
  expect_s3_class(ev, "grasp_evaluation")
  expect_equal(ev$scheme, "leave-one-subject-out")
  expect_equal(nrow(ev$folds), 5L)
  expect_equal(ev$confusion$n, length(g))
  expect_gte(ev$accuracy[["in_sample"]], 0.95)
  expect_lte(ev$accuracy[["held_out"]], ev$accuracy[["in_sample"]])
  expect_lt(ev$accuracy[["held_out"]], 0.95)   # the planted subject effect must show
  ps <- ev$per_subject
  expect_setequal(ps$subject, paste0("s", 1:5))
  expect_equal(sum(ps$correct) / sum(ps$n), ev$accuracy[["held_out"]])
  expect_true(all(ev$folds$n_train + ev$folds$n_test == length(g)))
  # each recording is predicted exactly once, by the fold that held out its subject
  expect_setequal(ev$predictions$id, g$meta$id)
  s <- summary(ev)
  expect_named(s, c(".metric", "class", "held_out", "in_sample"))
  expect_equal(s$held_out[s$.metric == "accuracy"], ev$accuracy[["held_out"]])
  expect_equal(s$in_sample[s$.metric == "accuracy"], ev$accuracy[["in_sample"]])
  # printed for a person: percentages, not raw fractions
  out <- capture.output(print(s))
  expect_true(any(grepl(sprintf("%.1f%%", 100 * ev$accuracy[["held_out"]]), out, fixed = TRUE)))
  expect_false(any(grepl("\\b0\\.[0-9]{4,}", out)))
})

test_that("well-separated types are recovered held-out too, and the result is reproducible", {
  g <- planted_types(types = c(1, 17, 22), subjects = 4, trials = 2, seed = 8)
  ev <- evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 2), folds = 2, seed = 3)
  expect_match(ev$scheme, "2 folds")
  expect_equal(nrow(ev$folds), 2L)
  expect_equal(sort(unlist(strsplit(ev$folds$subjects, ","))), paste0("s", 1:4))
  expect_gte(ev$accuracy[["held_out"]], 0.95)
  again <- evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 2), folds = 2, seed = 3)
  expect_equal(again$folds, ev$folds)
  expect_equal(again$predictions, ev$predictions)
})

test_that("a held-out type missing from training is reported, unlabelled data counted", {
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 3, seed = 2)
  only_s1 <- planted_types(types = 22, subjects = 1, trials = 3, seed = 3)
  only_s1$meta$id <- paste0("x", seq_along(only_s1$recordings))
  all <- grasps(c(g$recordings, only_s1$recordings),
                meta = rbind(g$meta, only_s1$meta)[c("id", "grasp", "subject")])
  all$meta$grasp[1] <- NA
  ev <- suppressWarnings(evaluate_loso(all, method = "last_frame", fit_args = list(ncomp = 2)))
  expect_equal(ev$n_unlabelled, 1L)
  expect_equal(ev$folds$missing_types[ev$folds$subjects == "s1"], "Parallel Extension")
  # the held-out Parallel Extension recordings cannot be right
  pe <- ev$predictions[ev$predictions$truth == "Parallel Extension", ]
  expect_true(all(pe$predicted != "Parallel Extension"))
  expect_output(print(ev), "absent from training")
  expect_output(print(ev), "1 unlabelled")
})

test_that("too few subjects and bad arguments give classed errors", {
  g <- planted_types(types = c(1, 17), subjects = 1, trials = 3)
  # one subject: folds by subject are refused, the default holds out recordings
  expect_error(evaluate_loso(g, "last_frame", split = "subject"), class = "handmotion_error_too_few_subjects")
  expect_equal(evaluate_loso(g, "last_frame", folds = 3, fit_args = list(ncomp = 1))$split, "recording")
  g2 <- planted_types(types = c(1, 17), subjects = 3, trials = 3)
  expect_error(evaluate_loso(g2, "last_frame", folds = 1), class = "handmotion_error_too_few_subjects")
  expect_error(evaluate_loso(g2, "last_frame", folds = 4), class = "handmotion_error_bad_input")
  expect_error(evaluate_loso(g2, "last_frame", subjects = "nobody"), class = "handmotion_error_bad_input")
  expect_error(evaluate_loso(g2, "last_frame", fit_args = 5), class = "handmotion_error_bad_input")
  expect_error(evaluate_loso(g2, "svm"))
})

test_that("a fold whose fit fails is recorded and its recordings left unpredicted", {
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 3)
  # ncomp = 20 is invalid for 16 DoFs: every refit fails
  expect_warning(ev <- evaluate_loso(g, "last_frame", fit_args = list(ncomp = 20), in_sample = FALSE),
                 class = "handmotion_warning_fold_failed")
  expect_true(all(!is.na(ev$folds$error)))
  expect_equal(ev$confusion$n_missing_predicted, length(g))
  expect_null(ev$in_sample)
})

test_that("the caller's RNG kind and stream are left untouched", {
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 2)
  withr::local_seed(42)
  before <- .Random.seed
  evaluate_loso(g, "last_frame", fit_args = list(ncomp = 2))
  expect_identical(.Random.seed, before)
})

test_that("progress is reported through progressr, one step per fold", {
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 2)
  # (as an outer listener such as reproduce_thesis() hears them; the call
  # itself would otherwise draw the bar: R/progress.R)
  withr::local_options(progressr.enable = TRUE, handmotion.progress = TRUE)
  steps <- 0
  withCallingHandlers(
    as_listener(evaluate_loso(g, "last_frame", fit_args = list(ncomp = 2), in_sample = FALSE)),
    progression = function(c) if (identical(c$type, "update")) steps <<- steps + 1
  )
  expect_equal(steps, 3)
})

test_that("FPCA LOSO runs on a small planted design: held-out <= in-sample", {
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 3, spread = 30, subject_sd = 6, seed = 6)
  # a third type with one recording per subject: 3 in-sample (enough for 2
  # FPCs), 2 in every fold (too few), so its model fails to fit in each fold
  rare <- planted_types(types = 22, subjects = 3, trials = 1, spread = 30, seed = 7)
  rare$meta$id <- paste0("rare", 1:3)
  g <- grasps(c(g$recordings, rare$recordings),
              meta = rbind(g$meta, rare$meta)[c("id", "grasp", "subject")])
  # (the thesis' distance: a type of three recordings has a degenerate
  # score Gaussian, which the likelihood distance reads)
  ev <- evaluate_loso(g, method = "fpca", fit_args = list(seed = 1, distance = "residual"))
  expect_equal(ev$method, "fpca")
  expect_equal(nrow(ev$folds), 3L)
  expect_true(all(is.na(ev$folds$error)))
  expect_equal(ev$folds$unfitted_types, rep("Parallel Extension", 3))
  expect_output(print(ev), "could not fit every type")
  rare_pred <- ev$predictions$predicted[ev$predictions$truth == "Parallel Extension"]
  expect_true(all(rare_pred != "Parallel Extension"))
  expect_gte(ev$accuracy[["in_sample"]], 0.9)
  expect_lte(ev$accuracy[["held_out"]], ev$accuracy[["in_sample"]])
})

test_that("FPCA folds fit one Gaussian to the scores: with the residual distance, the same predictions as the thesis' two", {
  g <- planted_types(types = c(1, 17, 22), subjects = 3, trials = 4, spread = 30, subject_sd = 6, seed = 8)
  ev1 <- evaluate_loso(g, method = "fpca", fit_args = list(seed = 1, distance = "residual"), in_sample = FALSE)
  ev2 <- evaluate_loso(g, method = "fpca", fit_args = list(seed = 1, mixture_components = 2, distance = "residual"),
                       in_sample = FALSE)
  expect_identical(ev1$predictions$predicted, ev2$predictions$predicted)
  expect_equal(ev1$predictions$distance, ev2$predictions$distance, tolerance = 1e-10)
})

test_that("printed evaluation and autoplot", {
  g <- planted_types(types = c(1, 9, 17, 22), subjects = 5, trials = 2, spread = 20,
                     subject_sd = 8, seed = 4)
  ev <- evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 3))
  expect_snapshot(print(ev))
  b <- ggplot2::ggplot_build(ggplot2::autoplot(ev))
  expect_equal(nrow(b$data[[1]]), 16)
  expect_equal(sum(as.numeric(b$data[[2]]$label[b$data[[2]]$label != ""])), length(g))
})
