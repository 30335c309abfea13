# A fit finds every recording's motion once; find_motion() reads what the
# fit around it has found, for those recordings only.

test_that("find_motion() reads a known table for its recordings and finds the others", {
  p <- plant_motion(n_rec = 6, p = 4, seed = 5)
  g <- p$g
  m <- find_motion(g)
  # a table with planted spans (not what the detector finds) for recordings 1-4
  known <- m[1:4, ]
  known$start <- 2L
  known$end <- known$n_frames - 1L
  got <- with_motion_found(known, find_motion(g))
  expect_equal(got$start, c(rep(2L, 4), m$start[5:6]))
  expect_equal(got$end[5:6], m$end[5:6])
  expect_equal(got$id, g$meta$id)
  expect_equal(names(got), names(m))
  # not read: other settings, a recording of another length under the id,
  # and outside the call
  expect_equal(with_motion_found(known, find_motion(g, min_move = 20))$start, find_motion(g, min_move = 20)$start)
  longer <- known
  longer$n_frames[1] <- longer$n_frames[1] + 1L
  expect_equal(with_motion_found(longer, find_motion(g))$start[1:2], c(m$start[1], 2L))
  expect_equal(find_motion(g), m)
  # NULL keeps what is known
  expect_equal(with_motion_found(known, with_motion_found(NULL, find_motion(g)))$start[1], 2L)
})

test_that("a fit of trimmed recordings looks at each recording once, with the same models", {
  p <- plant_motion(n_rec = 24, p = 4, seed = 6)
  looked <- 0L
  span <- motion_span
  local_mocked_internal("motion_span", function(...) {
    looked <<- looked + 1L
    span(...)
  })
  ms <- fit_grasp_models(p$g, seed = 1)
  expect_equal(ms[[1]]$settings$motion, "trim")
  expect_equal(looked, length(p$g))
  # the same fit with every recording's motion found afresh at each step
  local_mocked_internal("known_motion", function(x, ...) rep(NA_integer_, length(x)))
  looked <- 0L
  fresh <- fit_grasp_models(p$g, seed = 1)
  expect_gt(looked, 2L * length(p$g))
  strip <- function(s) lapply(fitted_models(s), function(m) m[setdiff(names(m), "timing")])
  expect_identical(strip(ms), strip(fresh))
})
