# Recordings without a motion are said once per call, for the caller's set,
# however many fits, folds and workers trim them.

# plant_motion()'s recordings with `rest_only` of them replaced by their own
# first frame held with sensor noise (no channel moves).
planted_with_rest_only <- function(rest_only, seed = 2) {
  p <- plant_motion(n_rec = 24, seed = seed)
  recs <- p$g$recordings
  withr::with_seed(seed, for (i in rest_only) {
    r <- recs[[i]]
    recs[[i]][] <- round(matrix(r[1, ], nrow(r), ncol(r), byrow = TRUE) + stats::rnorm(length(r), 0, 1.5))
  })
  grasps(recs, meta = data.frame(grasp = p$g$meta$grasp, subject = rep(c("s1", "s2"), each = 12)),
         rate = 100, unit = "raw")
}

# The no-motion messages `expr` lets through: a list of their conditions.
no_motion_messages <- function(expr) {
  said <- list()
  withCallingHandlers(expr, handmotion_message_no_motion = function(m) {
    said[[length(said) + 1L]] <<- m
    invokeRestart("muffleMessage")
  })
  said
}

test_that("say_no_motion_once() merges the messages of many trims into one for the set", {
  said <- no_motion_messages(say_no_motion_once({
    inform_no_motion(c("a", "b"), c("rest only", "too short"), 10)
    inform_no_motion("a", "rest only", 4)
    say_no_motion_once(inform_no_motion("c", "rest only", 2), 5)
    7
  }, 30))
  expect_length(said, 1)
  expect_equal(said[[1]]$ids, c("a", "b", "c"))
  expect_equal(said[[1]]$status, c("rest only", "too short", "rest only"))
  expect_match(conditionMessage(said[[1]]), "No motion found in 3 of 30 recordings")
  # nothing to say: nothing said, and the value comes back
  expect_length(no_motion_messages(expect_equal(say_no_motion_once(1 + 1, 3), 2)), 0)
})

test_that("fit_grasp_models() and evaluate_loso() name the rest-only recordings once, for the whole set", {
  g <- planted_with_rest_only(c(3, 8))
  # trim_motion() alone says them (both rest only, one per type)
  said <- no_motion_messages(trim_motion(g))
  expect_length(said, 1)
  expect_equal(said[[1]]$ids, g$meta$id[c(3, 8)])
  expect_equal(said[[1]]$status, rep("rest only", 2))
  # each type's fit and the temperature sample trim them again: one message
  said <- no_motion_messages(ms <- suppressWarnings(fit_grasp_models(g, motion = "trim", seed = 1)))
  expect_length(said, 1)
  expect_setequal(said[[1]]$ids, g$meta$id[c(3, 8)])
  expect_match(conditionMessage(said[[1]]), sprintf("in 2 of %d recordings", length(g)))
  # every fold's fit and projection, and the in-sample fit, trim them too
  said <- no_motion_messages(suppressWarnings(evaluate_loso(g, fit_args = list(motion = "trim"))))
  expect_length(said, 1)
  expect_setequal(said[[1]]$ids, g$meta$id[c(3, 8)])
})

test_that("no-motion messages relayed from workers are held back and said once too", {
  g <- planted_with_rest_only(c(3, 8))
  future::plan(future::multisession, workers = 2)
  on.exit(future::plan(future::sequential), add = TRUE)
  said <- no_motion_messages(suppressWarnings(fit_grasp_models(g, motion = "trim", seed = 1)))
  expect_length(said, 1)
  expect_setequal(said[[1]]$ids, g$meta$id[c(3, 8)])
})
