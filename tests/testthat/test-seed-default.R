# One default for `seed`: every verb that draws random numbers defaults to
# seed = 1 (a call repeats itself); NULL draws from the session's stream.

test_that("every exported verb with a seed defaults to 1", {
  ns <- asNamespace("handmotion")
  funs <- c(getNamespaceExports("handmotion"),
            ls(ns, pattern = "^(generate|simulate|predict|project|summary)\\.", all.names = TRUE))
  seeds <- Filter(Negate(is.null), lapply(stats::setNames(funs, funs), function(f) {
    fn <- get(f, envir = ns)
    if (is.function(fn) && "seed" %in% names(formals(fn))) formals(fn)$seed
  }))
  # the verbs that draw (a scan that found none could not fail)
  expect_true(all(c("simulate_grasps", "fit_grasp_model", "fit_grasp_models", "generate.grasp_model",
                    "generate.grasp_models", "evaluate_loso") %in% names(seeds)))
  expect_equal(names(Filter(function(s) !identical(s, 1), seeds)), character(0))
})

test_that("generate() repeats itself by default; seed = NULL follows the session", {
  g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2)
  m <- fit_grasp_model(g)
  expect_identical(fit_grasp_model(g)$gmm, m$gmm)
  expect_identical(generate(m, n = 2)$recordings, generate(m, n = 2, seed = 1)$recordings)
  a <- withr::with_seed(5, generate(m, n = 2, seed = NULL))
  b <- withr::with_seed(5, generate(m, n = 2, seed = NULL))
  c <- withr::with_seed(6, generate(m, n = 2, seed = NULL))
  expect_identical(a$recordings, b$recordings)
  expect_false(identical(a$recordings, c$recordings))
})
