# Degenerate data is fitted with the documented fallbacks, and said at the top
# level: a warning of family handmotion_warning_degenerate naming what was
# degenerate, the same rows in $degenerate_data, and a line in print().

degenerate_classes <- function(expr) {
  w <- NULL
  value <- withCallingHandlers(expr, handmotion_warning_degenerate = function(cnd) {
    w <<- cnd
    invokeRestart("muffleWarning")
  })
  list(value = value, warning = w)
}

test_that("warning classes sit under their family and the root", {
  expect_identical(warning_classes("one_frame"),
                   c("handmotion_warning_one_frame", "handmotion_warning_degenerate", "handmotion_warning"))
  expect_identical(warning_classes("read_failures"), c("handmotion_warning_read_failures", "handmotion_warning"))
})

test_that("a model of one-frame recordings says so", {
  g <- simulate_grasps(subjects = 3, grasps = 1, objects = 2, trials = 2, seed = 1)
  g$recordings <- lapply(g$recordings, function(r) r[1, , drop = FALSE])
  g$meta$n_frames[] <- 1L
  res <- degenerate_classes(fit_grasp_model(g, seed = 1))
  expect_s3_class(res$warning, "handmotion_warning_one_frame")
  expect_s3_class(res$warning, "handmotion_warning_linear_fallback")
  expect_true("one_frame" %in% res$value$degenerate_data$class)
  expect_identical(res$warning$degenerate_data, res$value$degenerate_data)
  expect_output(print(res$value), "degenerate data: 12 of 12 recordings have a single frame")
})

test_that("a model of identical recordings says so", {
  g <- simulate_grasps(subjects = 3, grasps = 1, objects = 2, trials = 2, seed = 1)
  g$recordings <- rep(g$recordings[1], length(g))
  names(g$recordings) <- g$meta$id
  g$meta$n_frames[] <- nrow(g$recordings[[1]])
  expect_warning(m <- fit_grasp_model(g, seed = 1), class = "handmotion_warning_identical_recordings")
  expect_output(print(m), "degenerate data: the recordings do not vary")
  # the set of models says it once, naming the type
  expect_warning(ms <- fit_grasp_models(g, seed = 1), "1 of the 1 grasp type models rests",
                 class = "handmotion_warning_identical_recordings")
  expect_output(print(ms), "degenerate data in 1 type: Large Diameter")
})

test_that("more FPCs than the curves' rank and too small mixtures are said", {
  g <- simulate_grasps(subjects = 2, grasps = 1, objects = 2, trials = 2, seed = 1)
  # the curves of every DoF are one shape times a factor: rank 1
  base <- g$recordings[[1]]
  for (i in seq_along(g)) g$recordings[[i]] <- base * i
  g$meta$n_frames[] <- nrow(base)
  res <- degenerate_classes(fit_grasp_model(g, ncomp = 3, mixture_components = 2, seed = 1))
  expect_s3_class(res$warning, "handmotion_warning_rank_deficient")
  expect_s3_class(res$warning, "handmotion_warning_small_mixture")
  expect_output(print(res$value), "degenerate data: more FPCs \\(3\\) than the rank")
})

test_that("ordinary data fits without a degenerate-data warning", {
  g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
  expect_no_warning(m <- fit_grasp_model(g, seed = 1))
  expect_identical(nrow(m$degenerate_data), 0L)
  expect_false(any(grepl("degenerate data", capture.output(print(m)))))
})

test_that("align_recordings() says when it aligned degenerate data", {
  set.seed(1)
  recs <- lapply(1:4, function(i) matrix(stats::rnorm(20), 10))
  expect_warning(al <- align_recordings(recs, window = 0), class = "handmotion_warning_zero_window")
  expect_output(print(al), "degenerate data: `window = 0`")
  nan <- lapply(1:4, function(i) matrix(NaN, 10, 2))
  res <- degenerate_classes(align_recordings(nan))
  expect_s3_class(res$warning, "handmotion_warning_non_finite")
  expect_s3_class(res$warning, "handmotion_warning_linear_fallback")
  expect_identical(res$value$method, "linear")
  expect_warning(align_recordings(lapply(1:3, function(i) matrix(1:2, 1))),
                 class = "handmotion_warning_one_frame")
  expect_warning(align_recordings(recs[1]), "fewer than 2 recordings",
                 class = "handmotion_warning_linear_fallback")
  expect_no_warning(align_recordings(recs))
})
