# Planted truth: ordinary frame counts with ~12% coefficient of variation
# around a median, plus a few recordings 2-3x the median (as the simulator
# plants them). The rule must flag exactly the planted ones.
plant_lengths <- function(n = 270, n_long = 4, centre = 42, cv = 0.12) {
  ordinary <- round(stats::rnorm(n - n_long, centre, cv * centre))
  long <- round(centre * stats::runif(n_long, 2, 3))
  lengths <- c(ordinary, long)
  planted <- c(rep(FALSE, n - n_long), rep(TRUE, n_long))
  o <- sample.int(n)
  list(n = lengths[o], planted = planted[o])
}

test_that("find_overlong flags exactly the planted over-long recordings", {
  withr::local_seed(11)
  for (rep in 1:200) {
    n <- sample(c(30, 120, 270), 1)
    # "a few": up to ~5% of a type (the thesis removed about ten of ~270)
    d <- plant_lengths(n = n, n_long = sample(0:ceiling(0.05 * n), 1),
                       centre = sample(32:54, 1))
    expect_identical(find_overlong(d$n), d$planted)
  }
})

test_that("the rule is max(Q3 + iqr_mult * IQR, median_mult * median)", {
  n <- c(10, 20, 30, 40, 50)            # Q1 20, median 30, Q3 40, IQR 20
  expect_equal(overlong_threshold(n), max(40 + 3 * 20, 1.5 * 30))
  expect_equal(overlong_threshold(n, overlong_rule(iqr_mult = 0.5, median_mult = 1)), 50)
  expect_equal(overlong_threshold(n, overlong_rule(iqr_mult = 0.1, median_mult = 2)), 60)
  # equal lengths: IQR 0, the median floor protects ordinary recordings
  n_eq <- c(rep(40, 20), 41, 59, 61)
  expect_identical(find_overlong(n_eq), n_eq > 60)
  # boundary: exactly at the threshold is kept
  expect_false(find_overlong(c(10, 20, 30, 40, 50, 100))[6])
})

test_that("find_overlong keeps names and handles tiny inputs", {
  n <- c(a = 40, b = 41, c = 120, d = 39, e = 42)
  expect_identical(names(find_overlong(n)), names(n))
  expect_identical(unname(find_overlong(n)), c(FALSE, FALSE, TRUE, FALSE, FALSE))
  expect_false(find_overlong(40))
  expect_identical(find_overlong(c(40L, 44L)), c(FALSE, FALSE))
})

test_that("bad input gives classed errors", {
  expect_error(find_overlong(c(40, NA, 42)), class = "handmotion_error_bad_input")
  expect_error(find_overlong(character(0)), class = "handmotion_error_bad_input")
  expect_error(find_overlong(1:5, rule = list(iqr_mult = 3)), class = "handmotion_error_bad_input")
  expect_error(overlong_rule(iqr_mult = -1), class = "handmotion_error_bad_input")
  expect_error(overlong_rule(median_mult = c(1, 2)), class = "handmotion_error_bad_input")
})

test_that("overlong_rule prints its formula", {
  expect_snapshot(print(overlong_rule(iqr_mult = 2.5)))
})
