three_types <- function() {
  parts <- list(planted_grasps(n = 20, p = 2, grasp = "Ring", seed = 1),
                planted_grasps(n = 20, p = 2, grasp = "Tripod", seed = 2),
                planted_grasps(n = 2, p = 2, grasp = "Lateral", seed = 3))
  grasps(unlist(lapply(parts, `[[`, "recordings"), recursive = FALSE),
         meta = data.frame(id = paste0("x", 1:42),
                           grasp = unlist(lapply(parts, function(p) as.character(p$meta$grasp)))),
         dofs = parts[[1]]$dofs)
}

# three_types() has a type of two recordings, which fit_grasp_models() warns
# about (and, with two FPCs, cannot fit): said once, in the first test
quiet_few <- function(expr) {
  suppressWarnings(expr, classes = c("handmotion_warning_few_recordings", "handmotion_warning_model_failed"))
}

strip_timing <- function(ms) {
  ms <- unclass(ms)
  for (i in seq_along(ms$models)) ms$models[[i]]$timing <- NULL
  ms
}

test_that("every type is fitted; a type that cannot be fitted is recorded, not fatal", {
  expect_warning(expect_warning(ms <- fit_grasp_models(three_types(), warping = "linear", seed = 1),
                                class = "handmotion_warning_model_failed"),
                 class = "handmotion_warning_few_recordings")
  expect_s3_class(ms, "grasp_models")
  # the failed type stays in the set, in its place, as a record of why
  expect_named(ms, c("Tripod", "Lateral", "Ring"))
  expect_s3_class(ms[["Lateral"]], "grasp_model_failed")
  expect_identical(ms[["Lateral"]]$class, "handmotion_error_too_few_recordings")
  expect_output(print(ms[["Lateral"]]), "grasp_model_failed")
  f <- failed_types(ms)
  expect_identical(f$grasp, "Lateral")
  expect_identical(f$class, "handmotion_error_too_few_recordings")
  expect_named(fitted_models(ms), c("Tripod", "Ring"))
  expect_s3_class(ms[["Ring"]], "grasp_model")
  expect_named(ms["ring"], "Ring")
  expect_named(ms[3], "Ring")
  # it survives subsetting and lapply(): it is an element, not an attribute
  expect_identical(failed_types(ms[c("Lateral", "Ring")])$grasp, "Lateral")
  expect_identical(vapply(lapply(ms, class), `[`, "", 1),
                   c(Tripod = "grasp_model", Lateral = "grasp_model_failed", Ring = "grasp_model"))
  expect_error(ms["Power Sphere"], class = "handmotion_error_bad_input")
  # generate() skips it, saying so, and refuses it by name
  expect_warning(gen <- generate(ms, n = 2, seed = 1), class = "handmotion_warning_model_failed")
  expect_setequal(as.character(unique(gen$meta$grasp)), c("Tripod", "Ring"))
  expect_error(generate(ms, grasps = "Lateral", seed = 1), class = "handmotion_error_model_failed")
  expect_error(generate(ms, grasps = "Lateral", seed = 1), class = "handmotion_error_fit_failed")
  expect_no_warning(generate(ms, grasps = "Ring", n = 1, seed = 1))
  only <- quiet_few(fit_grasp_models(three_types(), grasps = 14, warping = "linear", seed = 1))
  expect_named(only, "Tripod")
  expect_error(fit_grasp_models(three_types(), grasps = "Stick"),
               class = "handmotion_error_too_few_recordings")
})

test_that("summary is a tidy table with one row per type (Tables 5.1, 5.2)", {
  g <- three_types()
  recs <- g$recordings
  recs[[1]] <- rbind(recs[[1]], recs[[1]], recs[[1]])     # an over-long Ring
  g <- grasps(recs, meta = g$meta, dofs = g$dofs)
  ms <- quiet_few(fit_grasp_models(g, warping = "linear", seed = 1))
  s <- summary(ms)
  expect_s3_class(s, "data.frame")
  expect_identical(s$grasp, c("Tripod", "Lateral", "Ring"))
  expect_identical(s$grasp_id, c(14L, 16L, 31L))
  expect_identical(s$n_overlong, c(0L, NA, 1L))
  expect_identical(s$n_used, c(20L, NA, 19L))
  expect_identical(s$warping, c("linear", NA, "linear"))
  ok <- is.na(s$failed)
  expect_identical(ok, c(TRUE, FALSE, TRUE))
  expect_true(all(s$min_var[ok] <= s$median_var[ok] & s$median_var[ok] <= s$max_var[ok]))
  expect_true(all(s$min_var[ok] > 99))
  expect_match(s$failed[2], "usable recording")
  expect_snapshot(print(ms))
})

test_that("EM fallbacks are listed per type in the summary", {
  small <- planted_grasps(n = 5, p = 2, grasp = "Palmar Pinch", seed = 4)
  expect_warning(ms <- fit_grasp_models(small, warping = "linear", seed = 1), "Palmar Pinch",
                 class = "handmotion_warning_small_mixture")
  s <- summary(ms)
  expect_identical(s$em_fallback, "d1, d2")
  expect_identical(s$n_em_fallback, 2L)
})

test_that("the same seed gives identical models whatever the future plan", {
  skip_if_not_installed("future")
  g <- three_types()
  old <- future::plan(future::sequential)
  on.exit(future::plan(old), add = TRUE)
  seq_fit <- quiet_few(fit_grasp_models(g, seed = 7))
  again <- quiet_few(fit_grasp_models(g, seed = 7))
  expect_identical(strip_timing(again), strip_timing(seq_fit))
  if (future::supportsMulticore()) {
    future::plan(future::multicore, workers = 2)
    expect_identical(strip_timing(quiet_few(fit_grasp_models(g, seed = 7))), strip_timing(seq_fit))
  }
  # multisession workers load the installed package (as under R CMD check)
  installed <- nzchar(tryCatch(find.package("handmotion", lib.loc = .libPaths(), quiet = TRUE),
                               error = function(e) ""))
  skip_if_not(length(installed) == 1L && installed, "handmotion is not installed for workers")
  future::plan(future::multisession, workers = 2)
  expect_identical(strip_timing(quiet_few(fit_grasp_models(g, seed = 7))), strip_timing(seq_fit))
  # a real cluster: two PSOCK workers on this machine, as on other hosts
  cl <- parallel::makePSOCKcluster(2L)
  on.exit(parallel::stopCluster(cl), add = TRUE)
  future::plan(future::cluster, workers = cl)
  expect_identical(strip_timing(quiet_few(fit_grasp_models(g, seed = 7))), strip_timing(seq_fit))
  # a scheduler: batchtools jobs (run locally here; the shipped SLURM template
  # is for a cluster's scheduler)
  skip_if_not_installed("future.batchtools")
  withr::local_dir(withr::local_tempdir())
  future::plan(future.batchtools::batchtools_local)
  expect_identical(strip_timing(quiet_few(fit_grasp_models(g, seed = 7))), strip_timing(seq_fit))
})

test_that("the SLURM template is shipped and fills in with batchtools' fields", {
  tmpl <- system.file("templates", "slurm.tmpl", package = "handmotion")
  expect_true(nzchar(tmpl))
  text <- readLines(tmpl)
  expect_true(any(grepl("doJobCollection", text)))
  fields <- unlist(regmatches(text, gregexpr("(?<=<%= )[^ ]+", text, perl = TRUE)))
  expect_true(all(c("job.name", "log.file", "uri") %in% fields))
  expect_true(any(grepl("resources$walltime", text, fixed = TRUE)))
})

test_that("progress is reported through progressr, once per type", {
  # (as an outer listener such as reproduce_thesis() hears them; the call
  # itself would otherwise draw the bar: R/progress.R)
  withr::local_options(progressr.enable = TRUE, handmotion.progress = TRUE)
  n <- 0L
  withCallingHandlers(
    as_listener(quiet_few(fit_grasp_models(three_types(), warping = "linear", seed = 1))),
    progression = function(c) n <<- n + 1L
  )
  expect_gte(n, 3L)
})

test_that("simulated data: all types present fit, with their target lengths", {
  g <- simulate_grasps(subjects = 4, grasps = c(1, 9, 22), seed = 1)
  ms <- quiet_few(fit_grasp_models(g, seed = 1))
  expect_named(ms, c("Large Diameter", "Palmar Pinch", "Parallel Extension"))
  expect_equal(nrow(failed_types(ms)), 0L)
  expect_true(all(is.na(summary(ms)$failed)))
  s <- summary(ms)
  expect_true(all(s$target_length >= 10))
  expect_equal(s$n_used + s$n_overlong + s$n_degenerate, s$n_input)
})

test_that("fitting leaves the caller's RNG kind and stream untouched", {
  g <- simulate_grasps(subjects = 3, grasps = 1:2, objects = 1, trials = 2, seed = 1)
  set.seed(5)
  kind <- RNGkind()
  state <- .Random.seed
  quiet_few(fit_grasp_models(g, seed = 1))
  expect_identical(RNGkind(), kind)
  expect_identical(.Random.seed, state)
})

test_that("a cached fit resumes: only missing types are refitted, and the result is the uncached one", {
  g <- simulate_grasps(subjects = 4, grasps = c(1, 9, 17), objects = 2, trials = 2, seed = 2)
  cache <- withr::local_tempdir()
  full <- quiet_few(fit_grasp_models(g, seed = 5))
  first <- quiet_few(fit_grasp_models(g, seed = 5, cache = cache))
  files <- list.files(cache, full.names = TRUE)
  expect_length(files, 3L)
  strip <- function(ms) lapply(ms, function(m) m[setdiff(names(m), "timing")])
  expect_identical(strip(first), strip(full))
  # an "interrupted" fit: one type's file is missing
  gone <- names(full)[2]
  stem <- gsub("[^A-Za-z0-9]+", "-", gone)
  expect_true(file.remove(files[startsWith(basename(files), paste0(stem, "-"))]))
  fitted <- character()
  real <- fit_grasp_model
  local_mocked_internal("fit_grasp_model", function(x, ...) {
    fitted <<- c(fitted, as.character(x$meta$grasp[1]))
    real(x, ...)
  })
  resumed <- quiet_few(fit_grasp_models(g, seed = 5, cache = cache))
  expect_identical(fitted, gone)
  expect_identical(strip(resumed), strip(full))
  # other inputs never load a stale model
  fitted <- character()
  other <- quiet_few(fit_grasp_models(g, seed = 6, cache = cache))
  expect_setequal(fitted, names(full))
  expect_error(quiet_few(fit_grasp_models(g, seed = NULL, cache = cache)), class = "handmotion_error_bad_input")
})

test_that("the temperature's sample is scored by the classifier's own per-model step", {
  g <- simulate_grasps(subjects = 3, grasps = c(1, 9, 17), objects = 2, trials = 2, seed = 4)
  for (distance in c("likelihood", "residual")) {
    ms <- quiet_few(fit_grasp_models(g, seed = 1, mixture_components = 1, distance = distance))
    d <- fpca_distances(ms, g)$distances
    for (type in names(ms)) {
      # the same numbers, to the bit, whether a worker scores the sample (the
      # likelihood's terms apart until the set's residual scale is pooled)
      # or classify() does
      got <- finish_sample_distance(ms[[type]], sample_distance(ms[[type]], g, distance))
      expect_identical(got, unname(d[, type]))
    }
  }
  expect_null(sample_distance(ms[[1]], NULL, "likelihood"))
})
