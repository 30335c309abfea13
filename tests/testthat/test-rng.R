test_that("with_seed leaves the global RNG untouched", {
  set.seed(42); before <- .Random.seed
  x <- with_seed(1, runif(3))
  expect_identical(.Random.seed, before)
  expect_identical(x, with_seed(1, runif(3)))
})

test_that("rnorm_matrix() takes its n * p draws in one call, by column or by row", {
  # the simulator's fixed draw order depends on it: the same values as the
  # stream's next n * p standard normals, in the layout asked for
  z <- with_seed(3, stats::rnorm(12))
  expect_identical(with_seed(3, rnorm_matrix(4, 3)), matrix(z, 4, 3))
  expect_identical(with_seed(3, rnorm_matrix(4, 3, byrow = TRUE)), t(matrix(z, 3, 4)))
  # and it leaves the stream where n * p draws leave it
  expect_identical(with_seed(3, {rnorm_matrix(4, 3); stats::runif(1)}),
                   with_seed(3, {stats::rnorm(12); stats::runif(1)}))
})

test_that("draw_blocks() gives the numbers of one call per block, in order", {
  # the simulator's draw order depends on it: one draw of n * sum(widths)
  # cut into blocks equals the stream's separate calls, block after block
  one <- with_seed(5, draw_blocks(stats::runif, 4, c(a = 1, b = 3, c = 1)))
  sep <- with_seed(5, list(a = stats::runif(4), b = matrix(stats::runif(12), 4), c = stats::runif(4)))
  expect_identical(one, sep)
  z <- with_seed(6, draw_blocks(stats::rnorm, 3, c(x = 2, y = 1)))
  expect_identical(z, with_seed(6, list(x = rnorm_matrix(3, 2), y = stats::rnorm(3))))
  # no rows: empty blocks of the right kind, and the stream untouched
  e <- with_seed(7, {b <- draw_blocks(stats::runif, 0, c(u = 1, v = 2)); list(b, stats::runif(1))})
  expect_identical(e, with_seed(7, list(list(u = numeric(0), v = matrix(numeric(0), 0, 2)), stats::runif(1))))
})
