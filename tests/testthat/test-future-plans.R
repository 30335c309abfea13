# The parallel entry points under every kind of future plan a user may set:
# sequential, multisession, a PSOCK cluster (as on other hosts) and a
# scheduler (future.batchtools, run locally). Same seed, same results; progress
# reaches the caller through progressr from every plan.

# Workers load the installed package (as under R CMD check); skip otherwise.
skip_without_installed_workers <- function() {
  skip_on_cran()
  skip_if_not_installed("future")
  installed <- nzchar(tryCatch(find.package("handmotion", lib.loc = .libPaths(), quiet = TRUE),
                               error = function(e) ""))
  skip_if_not(length(installed) == 1L && installed, "handmotion is not installed for workers")
}

# Run `expr` under each plan (a PSOCK cluster of two localhost workers for
# "cluster") and return the results by plan name.
under_plans <- function(expr, plans = c("sequential", "multisession", "cluster", "batchtools_local")) {
  expr <- substitute(expr)
  env <- parent.frame()
  old <- future::plan()
  on.exit(future::plan(old), add = TRUE)
  out <- list()
  for (p in plans) {
    if (p == "cluster") {
      cl <- parallel::makePSOCKcluster(2L)
      on.exit(parallel::stopCluster(cl), add = TRUE)
    }
    if (p == "batchtools_local") {
      if (!requireNamespace("future.batchtools", quietly = TRUE)) next
      # batchtools keeps its registry in the working directory
      withr::local_dir(withr::local_tempdir())
    }
    switch(p,
      sequential = future::plan(future::sequential),
      multisession = future::plan(future::multisession, workers = 2),
      cluster = future::plan(future::cluster, workers = cl),
      batchtools_local = future::plan(future.batchtools::batchtools_local))
    out[[p]] <- eval(expr, env)
  }
  out
}

# A progressr handler that counts the updates it is sent.
counting_handler <- function() {
  n <- 0L
  handler <- progressr::make_progression_handler("counter", enable = TRUE, reporter = list(
    update = function(config, state, progression, ...) n <<- n + 1L))
  list(handler = handler, count = function() n)
}

test_that("evaluate_loso() gives the same folds under every plan", {
  skip_without_installed_workers()
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 2)
  res <- under_plans(evaluate_loso(g, "last_frame", fit_args = list(ncomp = 2), seed = 3))
  expect_true(all(c("sequential", "multisession", "cluster") %in% names(res)))
  for (p in names(res)[-1]) expect_identical(res[[p]], res$sequential, label = p)
})

test_that("evaluate_generation() on models fitted under every plan gives the same table", {
  skip_without_installed_workers()
  g <- simulate_grasps(subjects = 6, grasps = c(1, 9), objects = 1, trials = 2, seed = 2)
  s <- as.integer(sub("\\D+", "", g$meta$subject))
  train <- g[s <= 4]
  held <- g[s > 4]
  res <- under_plans({
    ms <- fit_grasp_models(train, seed = 1, warping = "linear")
    evaluate_generation(ms, held, train, reps = 1, seed = 2)
  })
  for (p in names(res)[-1]) expect_identical(res[[p]], res$sequential, label = p)
})

test_that("a fit of trimmed recordings gives the same models on every plan (the motion found once travels)", {
  skip_without_installed_workers()
  planted <- plant_motion(n_rec = 24, p = 4, seed = 6)
  res <- under_plans({
    ms <- fit_grasp_models(planted$g, seed = 1)
    lapply(fitted_models(ms), function(m) m[setdiff(names(m), "timing")])
  }, plans = c("sequential", "multisession", "cluster"))
  expect_equal(res$sequential[[1]]$settings$motion, "trim")
  for (p in names(res)[-1]) expect_identical(res[[p]], res$sequential, label = p)
})

test_that("progress reaches a progressr handler from every plan: multisession, cluster, batchtools", {
  skip_without_installed_workers()
  skip_if_not_installed("progressr")
  # (the test helpers turn the package's progress off; here it is the subject)
  withr::local_options(handmotion.progress = TRUE)
  g <- planted_types(types = c(1, 17), subjects = 3, trials = 2)
  counts <- under_plans({
    h <- counting_handler()
    progressr::with_progress(fit_grasp_models(g, warping = "linear", seed = 1),
                             handlers = h$handler, enable = TRUE)
    fit_steps <- h$count()
    h <- counting_handler()
    progressr::with_progress(evaluate_loso(g, "last_frame", fit_args = list(ncomp = 2), in_sample = FALSE),
                             handlers = h$handler, enable = TRUE)
    c(fit = fit_steps, loso = h$count())
  })
  # one update per grasp type and one per fold, whatever the plan
  for (p in names(counts)) expect_identical(counts[[p]], c(fit = 2L, loso = 3L), label = p)
})
