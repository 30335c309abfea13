test_that("largest-remainder rounding keeps the total exactly", {
  x <- c(40.4, 38.7, 45.2, 41.9, 36.1)
  n <- sim_round_to_total(x, 205)
  expect_equal(sum(n), 205L)
  expect_true(all(abs(n - x * 205 / sum(x)) < 1))
})
