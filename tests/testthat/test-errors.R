# The error-class hierarchy (?handmotion_errors) and the messages users read.

test_that("every specific class sits under one family and the root", {
  expect_identical(error_classes("truncated_line"),
                   c("handmotion_error_truncated_line", "handmotion_error_bad_file", "handmotion_error"))
  expect_identical(error_classes("unknown_grasp"),
                   c("handmotion_error_unknown_grasp", "handmotion_error_bad_input", "handmotion_error"))
  expect_identical(error_classes("too_few_recordings"),
                   c("handmotion_error_too_few_recordings", "handmotion_error_fit_failed", "handmotion_error"))
  expect_identical(error_classes("missing_dependency"),
                   c("handmotion_error_missing_dependency", "handmotion_error"))
  # a skeleton file's fault is both a skeleton and a file error, not a bad argument
  expect_identical(error_classes(c("bad_skeleton", "bad_file")),
                   c("handmotion_error_bad_skeleton", "handmotion_error_bad_file", "handmotion_error"))
  expect_false("bad_argument" %in% names(error_families))
})

test_that("errors from the public functions carry their family", {
  expect_error(find_overlong(c(40, NA, 42)), class = "handmotion_error_bad_input")
  expect_error(simulate_grasps(grasps = "No Such Grasp"), class = "handmotion_error_bad_input")
  bad <- withr::local_tempfile(fileext = ".xmlskel")
  writeLines("<skeleton><oops></skeleton>", bad)
  expect_error(read_skeleton(bad), class = "handmotion_error_bad_file")
  g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 2, seed = 1)
  expect_error(fit_grasp_model(g[1:2], ncomp = 2, warping = "linear"), class = "handmotion_error_fit_failed")
})

test_that("the checkers name the argument and what was wrong", {
  f <- function(n = 1, engine = c("fast", "reference"), seed = NULL) {
    n <- check_whole(n, "n", max = 10)
    engine <- check_choice(engine, arg = "engine")
    check_seed(seed)
    list(n, engine)
  }
  expect_identical(f(), list(1L, "fast"))
  expect_identical(f(3, "reference", 2), list(3L, "reference"))
  cnd <- tryCatch(f(engine = "fsat"), handmotion_error = function(e) e)
  expect_identical(cnd$argument, "engine")
  expect_snapshot(error = TRUE, {
    f(n = 0)
    f(n = 1e10)
    f(n = 2.5)
    f(n = "a")
    f(engine = "fsat")
    f(engine = c("fast", "x"))
    f(seed = c(1, 2))
    f(seed = NA)
  })
})

test_that("user-facing errors read well", {
  m <- fit_grasp_model(planted_grasps(n = 20, p = 2, seed = 2), warping = "linear", seed = 1)
  expect_snapshot(error = TRUE, {
    generate(m, n = -1)
    generate(m, n = 2, seed = "x")
    fit_grasp_model(planted_grasps(n = 20, p = 2), engine = "fastest")
    fit_grasp_models(planted_grasps(n = 20, p = 2), ncmop = 3)
    align_recordings(list(a = matrix(1:6, 3), b = "x"))
    simulate_grasps(subjects = 0)
  })
})
