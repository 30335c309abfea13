# Recordings trimmed to their motion take the mixture guard by default in
# the thesis' independent model too; recordings as recorded keep the
# thesis' mixtures.

test_that("on trimmed recordings the thesis model's slivers are guarded away by default", {
  # 23 recordings of type "a" (planted rest, reach and hold); three of them
  # reach three times as far on every channel: the outliers a two-component
  # mixture fits a sliver to
  p <- plant_motion(n_rec = 46, p = 4, seed = 3)
  recs <- p$g$recordings
  a <- which(p$g$meta$grasp == "a")
  for (i in a[1:3]) {
    r <- recs[[i]]
    recs[[i]] <- round(sweep(sweep(r, 2, r[1, ]) * 3, 2, r[1, ], "+"))
  }
  g <- grasps(recs, meta = data.frame(grasp = p$g$meta$grasp), rate = 100, unit = "raw")
  n <- length(a)
  # unguarded, the mixtures of the DoFs give a component to (about) the
  # three outliers: under the guard's size rule, max(2 (d + 1), 5% of n) = 6
  thesis <- fit_grasp_model(g, grasp = "a", seed = 1, mixture_guard = "none")
  expect_equal(thesis$settings$motion, "trim")
  smallest <- vapply(thesis$gmm, function(m) min(m$weights) * n, numeric(1))
  expect_gte(sum(smallest < 6), 3)
  expect_true(all(lengths(lapply(thesis$gmm, `[[`, "weights")) == 2L))
  # by default the guard is on for trimmed recordings: one Gaussian each,
  # every replacement a recorded fallback, and print() says it was defaulted
  m <- fit_grasp_model(g, grasp = "a", seed = 1)
  expect_equal(m$settings$mixture_guard, "bic")
  expect_true("mixture_guard" %in% m$settings$defaulted)
  expect_true(all(lengths(lapply(m$gmm, `[[`, "weights")) == 1L))
  expect_setequal(m$fallbacks$dof[m$fallbacks$step == "mixture_guard"], g$dofs)
  expect_output(print(m), "mixture_guard = \"bic\"")
  # the same recordings as recorded keep the thesis' mixtures
  expect_equal(fit_grasp_model(g, grasp = "a", seed = 1, motion = "as_recorded")$settings$mixture_guard, "none")
})

test_that("the default data (as recorded) keeps the thesis' mixtures", {
  g <- simulate_grasps(subjects = 3, grasps = 1, objects = 2, trials = 2, seed = 1)
  m <- suppressWarnings(fit_grasp_model(g, seed = 1))
  expect_equal(m$settings$motion, "as_recorded")
  expect_equal(m$settings$mixture_guard, "none")
})
