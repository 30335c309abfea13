test_that("a tapered segment's outline holds both end circles", {
  out <- tapered_outline(matrix(c(0, 0), 1), matrix(c(50, 0), 1), 10, 6)
  # the first half of the points on the distal circle, the second on the proximal one
  expect_equal(sqrt((out$x[1:10] - 50)^2 + out$y[1:10]^2), rep(6, 10))
  expect_equal(sqrt(out$x[11:20]^2 + out$y[11:20]^2), rep(10, 10))
  # joined by the outer tangents: the arcs end where the tangent from one circle touches the other
  a <- c(out$x[10], out$y[10]) - c(50, 0)
  b <- c(out$x[11], out$y[11])
  expect_equal(sum((b - c(out$x[10], out$y[10])) * a), 0, tolerance = 1e-9)
  expect_equal(range(out$x), c(-10, 56), tolerance = 0.03)
  # seen end on (both ends at one point), only the larger circle
  out <- tapered_outline(matrix(c(0, 0), 1), matrix(c(0, 0), 1), 10, 6)
  expect_equal(max(sqrt(out$x^2 + out$y^2)), 10, tolerance = 1e-9)
})
