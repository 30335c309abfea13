# distance_effects() on tables built from planted effects: the split must give
# them back exactly, and the counts without effects must be the counts of the
# planted residual.

planted_table <- function(model, type, residual, level = 1) {
  n <- length(model)
  ids <- paste0("T", seq_len(n))
  tab <- exp(level + outer(model, type, `+`) + residual)
  dimnames(tab) <- list(model = ids, truth = ids)
  tab
}

# centred effects and a residual with zero row and column means (the
# two-way fit's residual), so the planted parts are the ones to recover
centred_residual <- function(n, sd, own) {
  r <- matrix(stats::rnorm(n * n, sd = sd), n) + diag(own, n)
  r <- sweep(r, 1L, rowMeans(r))
  sweep(r, 2L, colMeans(r))
}

test_that("distance_effects recovers planted model, type and pairwise effects", {
  withr::local_seed(14)
  n <- 8
  model <- stats::rnorm(n, sd = 0.3); model <- model - mean(model)
  type <- stats::rnorm(n, sd = 0.2); type <- type - mean(type)
  res <- centred_residual(n, sd = 0.1, own = -0.6)
  e <- distance_effects(planted_table(model, type, res, level = 2))
  expect_equal(e$level, 2, tolerance = 1e-12)
  expect_equal(unname(e$model), model, tolerance = 1e-12)
  expect_equal(unname(e$type), type, tolerance = 1e-12)
  expect_equal(unname(e$residual), res, tolerance = 1e-12)
  expect_equal(e$own, mean(diag(res)), tolerance = 1e-12)
  off <- res; diag(off) <- Inf
  expect_equal(e$closest_other$residual, apply(off, 1L, min), tolerance = 1e-12)
  expect_equal(e$closest_other$type, paste0("T", apply(off, 1L, which.min)))
})

test_that("type effects lower G1 only, model effects G2 only, and removing them restores the counts", {
  withr::local_seed(15)
  n <- 10
  # every model fits its own type clearly best: both counts are n
  res <- centred_residual(n, sd = 0.05, own = -0.5)
  flat <- distance_minima(planted_table(rep(0, n), rep(0, n), res))
  expect_equal(c(flat$model_min_own_type, flat$type_min_own_model), c(n, n))
  # one very easy type (low type effect) takes every other model's row minimum
  type <- c(-2, rep(2 / (n - 1), n - 1))
  tab <- planted_table(rep(0, n), type, res)
  expect_equal(distance_minima(tab)$model_min_own_type, 1)
  expect_equal(distance_minima(tab)$type_min_own_model, n)
  expect_equal(unname(distance_effects(tab)$counts["model_min_own_type_without_type_effects"]), n)
  # one generalist model (low model effect) takes every other type's column minimum
  tab <- planted_table(type, rep(0, n), res)
  expect_equal(distance_minima(tab)$model_min_own_type, n)
  expect_equal(distance_minima(tab)$type_min_own_model, 1)
  expect_equal(unname(distance_effects(tab)$counts["type_min_own_model_without_model_effects"]), n)
})

test_that("distance_effects puts the columns in the rows' order", {
  withr::local_seed(16)
  tab <- planted_table(c(-0.2, 0, 0.2), c(0.1, 0, -0.1), centred_residual(3, 0.05, -0.5))
  shuffled <- tab[, c(3, 1, 2)]
  expect_equal(distance_effects(shuffled)$residual, distance_effects(tab)$residual)
})

test_that("distance_effects refuses tables it cannot split", {
  tab <- planted_table(c(0, 0), c(0, 0), diag(-0.5, 2))
  expect_error(distance_effects(tab[, 1, drop = FALSE]), class = "handmotion_error_bad_input")
  other <- tab; colnames(other) <- c("T1", "X")
  expect_error(distance_effects(other), "same types", class = "handmotion_error_bad_input")
  bad <- tab; bad[1, 2] <- NA
  expect_error(distance_effects(bad), "missing, infinite or not positive", class = "handmotion_error_bad_input")
  bad[1, 2] <- 0
  expect_error(distance_effects(bad), class = "handmotion_error_bad_input")
})
