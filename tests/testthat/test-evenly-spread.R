test_that("evenly_spread takes k indices from the first to the last, evenly, all of them when k >= n", {
  # planted: 1..10 in 4 picks are 1, 4, 7, 10 (steps of 3)
  expect_identical(evenly_spread(10, 4), c(1, 4, 7, 10))
  expect_identical(evenly_spread(5, 4), c(1, 2, 4, 5))
  expect_identical(evenly_spread(6, 6), as.numeric(1:6))
  expect_identical(evenly_spread(6, 100), as.numeric(1:6))
  expect_identical(evenly_spread(1, 3), 1)
  for (n in c(7, 50, 333)) for (k in c(2, 5, 30)) {
    i <- evenly_spread(n, k)
    expect_length(i, min(n, k))
    expect_identical(range(i), c(1, n))
    expect_true(all(diff(i) > 0))
    # evenly: gaps differ by at most one index
    if (length(i) > 2) expect_lte(diff(range(diff(i))), 1)
  }
})
