test_that("the slope-constrained kernel reproduces dtw's symmetricP05", {
  withr::local_seed(21)
  for (k in 1:4) {
    x <- matrix(stats::rnorm(37 * 3), 37)
    y <- matrix(stats::rnorm((30 + 8 * k) * 3), 30 + 8 * k)
    fast <- handmotion:::dtw_slope_pair(x, y, "fast")
    ref <- handmotion:::dtw_slope_pair(x, y, "reference")
    expect_identical(fast$index1, ref$index1)
    expect_identical(fast$index2, ref$index2)
    expect_equal(fast$distance, ref$distance, tolerance = 1e-12)
    # no frame of either series is matched more than three times in a row
    expect_lte(max(rle(fast$index1)$lengths), 3)
    expect_lte(max(rle(fast$index2)$lengths), 3)
  }
  # no path when one series is more than three times the other
  expect_error(handmotion:::dtw_slope_pair(x[1:5, ], y), "slope constraint")
})
