# Progress of the long calls (issue 36): steps are counted through progressr,
# shown by the outermost call, and nothing at all when turned off.

count_progressions <- function(expr) {
  n <- 0L
  local_progress_listener()
  withr::with_options(list(handmotion.progress = getOption("handmotion.progress.test", TRUE),
                           progressr.enable = TRUE), {
    withCallingHandlers(expr, progression = function(p) {
      if (identical(p$type, "update")) n <<- n + 1L
    })
  })
  n
}

test_that("long calls count their steps: a fold, a horizon, a model, a type", {
  g <- simulate_grasps(subjects = 4, grasps = 1:3, objects = 1, trials = 2, seed = 1)
  # early recognition: one step per horizon its folds need (here 5 and 10 frames)
  expect_equal(count_progressions(evaluate_early_recognition(g, ms = c(100, 200), fractions = NULL)), 2L)
  expect_equal(count_progressions(ms <- fit_grasp_models(g, seed = 1, mixture_components = 1)), 3L)
  expect_equal(count_progressions(classify(ms, g)), 3L)
  expect_equal(count_progressions(evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 2),
                                                in_sample = FALSE)), 4L)
  # an outer long call counts; the calls inside it do not start a second count
  expect_equal(count_progressions(evaluate_loso(g, method = "fpca", fit_args = list(mixture_components = 1), folds = 2,
                                                in_sample = FALSE)), 2L)
})

test_that("progress is shown when asked (progressr.enable) and is silent when turned off", {
  g <- simulate_grasps(subjects = 3, grasps = 1:2, objects = 1, trials = 2, seed = 1)
  shown <- withr::with_options(list(handmotion.progress = TRUE, progressr.enable = TRUE, progressr.enable_after = 0), {
    capture.output(ms <- fit_grasp_models(g, seed = 1, mixture_components = 1), type = "message")
  })
  expect_match(paste(shown, collapse = ""), "100%")
  off <- withr::with_options(list(handmotion.progress = FALSE, progressr.enable = TRUE, progressr.enable_after = 0), {
    capture.output(invisible(fit_grasp_models(g, seed = 1, mixture_components = 1)), type = "message")
  })
  expect_length(off, 0L)
  expect_equal(withr::with_options(list(handmotion.progress.test = FALSE),
                                   count_progressions(classify(ms, g))), 0L)
})

test_that("inside the user's own with_progress() the updates reach the user's handler", {
  withr::local_options(handmotion.progress = TRUE)
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 2)
  seen <- 0L
  count <- function(p) if (inherits(p, "progression") && identical(p$type, "update")) seen <<- seen + 1L
  withCallingHandlers(
    progressr::with_progress(fit_grasp_models(g, warping = "linear", seed = 1),
                             handlers = progressr::handler_void(), enable = TRUE),
    progression = count)
  # one update per type reaches the user's with_progress() (the package adds none of its own)
  expect_equal(seen, 2L)
})

# A script run by Rscript into a log file, loading this build of the package.
script_log <- function(lines) {
  load <- if (pkgload::is_dev_package("handmotion")) {
    sprintf("suppressMessages(pkgload::load_all(%s, helpers = FALSE, quiet = TRUE))", deparse(pkgload::pkg_path()))
  } else {
    "library(handmotion)"
  }
  script <- withr::local_tempfile(fileext = ".R")
  log <- withr::local_tempfile(fileext = ".log")
  writeLines(c(load, "options(progressr.enable_after = 0)",
               "g <- simulate_grasps(subjects = 3, grasps = 1:3, objects = 1, trials = 2, seed = 1)",
               lines, "ms <- fit_grasp_models(g, seed = 1, mixture_components = 1)", "cat('fitted', length(ms), '\\n')"),
             script)
  status <- system2(file.path(R.home("bin"), "Rscript"), shQuote(script), stdout = log, stderr = log)
  expect_equal(status, 0L)
  paste(readLines(log, warn = FALSE), collapse = "\n")
}

test_that("a script's log gets no bar by default, and one when the user asks (progressr's conventions)", {
  skip_on_cran()
  # Rscript is not interactive: no bar unless asked
  quiet <- script_log(character(0))
  expect_match(quiet, "fitted 3", fixed = TRUE)
  expect_no_match(quiet, "|=", fixed = TRUE)
  expect_no_match(quiet, "100%", fixed = TRUE)
  # handlers chosen by the user, or progressr.enable: the bar is drawn
  expect_match(script_log('progressr::handlers("txtprogressbar")'), "100%", fixed = TRUE)
  expect_match(script_log("options(progressr.enable = TRUE)"), "100%", fixed = TRUE)
  # ... and handmotion.progress = FALSE turns it off
  expect_no_match(script_log(c('progressr::handlers("txtprogressbar")', "options(handmotion.progress = FALSE)")),
                  "100%", fixed = TRUE)
})

test_that("a fold on a worker counts nothing of its own: one step per fold reaches the caller", {
  # (the fold function marks its process as counted from outside, as a
  # multisession worker needs; here the plan is sequential, the same code)
  withr::local_options(handmotion.progress = TRUE)
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 2)
  ids <- character(0)
  as_listener(withr::with_options(list(progressr.enable = TRUE), withCallingHandlers(
    evaluate_loso(g, "fpca", fit_args = list(mixture_components = 1, warping = "linear"), in_sample = FALSE),
    progression = function(p) ids <<- c(ids, p$progressor_uuid))))
  expect_length(unique(ids), 1L)
})

test_that("a progressor carries nothing of its caller to the workers (issue 43)", {
  # progressors travel with every chunk of futures: one that closed
  # over its caller's frame shipped the whole data set to each worker
  shipped <- function(progress) {
    big <- numeric(1e6)   # 8 MB in the caller's frame
    withr::local_options(handmotion.progress = progress)
    p <- hm_progressor(3)
    length(serialize(p, NULL))
  }
  expect_lt(shipped(FALSE), 1e5)
  expect_lt(shipped(TRUE), 1e5)
})
