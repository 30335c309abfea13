# Planted truth: curves = known mean + known orthonormal components x scores
# with an exactly known covariance + small noise, on [0, 1].
planted_curves <- function(n = 200, L = 41, sd = c(5, 2), noise = 0.05, seed = 1) {
  t <- seq(0, 1, length.out = L)
  # sqrt(2) sin(r pi t) are orthonormal in L2[0, 1] and, vanishing at both
  # ends, exactly orthonormal under the trapezoidal rule on this grid. The
  # second and third mix sin(2 pi t) and sin(3 pi t) so that no component
  # integrates to zero (the sign convention then has a clear answer).
  s <- sqrt(2) * cbind(sin(pi * t), sin(2 * pi * t), sin(3 * pi * t))
  phi <- cbind(s[, 1], 0.6 * s[, 2] + 0.8 * s[, 3], 0.8 * s[, 2] - 0.6 * s[, 3])
  withr::with_seed(seed, {
    xi <- matrix(rnorm(n * 2), n, 2)
    xi <- sweep(xi, 2, colMeans(xi))
    # whiten, then scale: the scores' covariance (1/n) is exactly diag(sd^2)
    if (n > 2) xi <- xi %*% solve(chol(crossprod(xi) / n)) %*% diag(sd)
    E <- matrix(rnorm(n * L, sd = noise), n, L)
  })
  mu <- 20 + 30 * t^2
  Y <- matrix(mu, n, L, byrow = TRUE) + xi %*% t(phi[, 1:2]) + E
  list(Y = Y, t = t, phi = phi, xi = xi, mu = mu, sd = sd)
}

# Largest principal angle (radians) between the spans of two L x k bases
# under the inner product with weights w.
principal_angle <- function(A, B, w) {
  orth <- function(M) {
    G <- crossprod(M, M * w)
    M %*% solve(chol(G))
  }
  cosines <- svd(crossprod(orth(A), orth(B) * w))$d
  acos(min(1, min(cosines)))
}

test_that("FPCA recovers a planted subspace, variance proportions and scores", {
  p <- planted_curves()
  fit <- fpca_fit(p$Y, argvals = p$t, ncomp = 2)
  expect_s3_class(fit, "fpca_fit")
  expect_equal(dim(fit$components), c(41, 2))
  expect_equal(dim(fit$scores), c(200, 2))
  # subspace within 0.01 rad; each component within 0.01 rad of its truth
  expect_lt(principal_angle(fit$components, p$phi[, 1:2], fit$weights), 0.01)
  for (r in 1:2) {
    expect_lt(principal_angle(fit$components[, r, drop = FALSE], p$phi[, r, drop = FALSE],
                              fit$weights), 0.01)
  }
  # eigenvalues 25 and 4 (1/n convention) within 1%; proportions within 0.002
  expect_equal(fit$eigenvalues[1:2], p$sd^2, tolerance = 0.01)
  expect_equal(unname(fit$var_explained), p$sd^2 / sum(p$sd^2), tolerance = 0.002)
  # scores are the planted scores up to the sign of each component
  for (r in 1:2) expect_gt(abs(cor(fit$scores[, r], p$xi[, r])), 0.999)
  expect_equal(fit$mean, p$mu, tolerance = 0.01)
  expect_equal(fit$argvals, p$t)
})

test_that("the fast engine equals fda.usc::fdata2pc to 1e-8", {
  skip_if_not_installed("fda.usc")
  check_same <- function(fast, ref) {
    expect_equal(fast$components, ref$components, tolerance = 1e-8)
    expect_equal(fast$scores, ref$scores, tolerance = 1e-8)
    expect_equal(fast$var_explained, ref$var_explained, tolerance = 1e-8)
    expect_equal(fast$eigenvalues, ref$eigenvalues, tolerance = 1e-8)
    expect_equal(fast$mean, ref$mean, tolerance = 1e-12)
  }
  p <- planted_curves(n = 40, L = 25, noise = 0.5)
  check_same(fpca_fit(p$Y, p$t, ncomp = 3), fpca_fit(p$Y, p$t, ncomp = 3, engine = "reference"))
  # uneven grid on another range, more points than curves
  t2 <- sort(c(2, 9, withr::with_seed(3, runif(28, 2, 9))))
  Y2 <- withr::with_seed(4, matrix(rnorm(12 * 30), 12) + outer(rnorm(12, sd = 3), sin(t2)))
  check_same(fpca_fit(Y2, t2), fpca_fit(Y2, t2, engine = "reference"))
  # an fdata object in, its grid used
  fd <- fda.usc::fdata(p$Y, argvals = p$t)
  check_same(fpca_fit(fd), fpca_fit(p$Y, p$t, engine = "reference"))
  # the reference engine really is fdata2pc: the same components up to sign
  # (fdata2pc normalises them under the uniform weight delta^2)
  pc <- suppressWarnings(fda.usc::fdata2pc(fd, ncomp = 2))
  ref_comps <- t(pc$rotation$data)
  ours <- fpca_fit(fd, engine = "reference")
  expect_equal(abs(colSums(ours$components * ref_comps)) * ours$delta^2, c(1, 1),
               tolerance = 1e-10, ignore_attr = TRUE)
})

test_that("the sign convention makes each component integrate positive and is stable", {
  p <- planted_curves()
  fit <- fpca_fit(p$Y, p$t)
  expect_true(all(colSums(fit$components * fit$weights) > 0))
  # row permutation: same components, permuted scores
  perm <- withr::with_seed(9, sample(nrow(p$Y)))
  fit_p <- fpca_fit(p$Y[perm, ], p$t)
  expect_equal(fit_p$components, fit$components, tolerance = 1e-10)
  expect_equal(fit_p$scores, fit$scores[perm, ], tolerance = 1e-10)
  # subsets of the same population give components pointing the same way
  for (rows in list(1:120, 81:200, seq(1, 200, by = 3))) {
    sub <- fpca_fit(p$Y[rows, ], p$t)
    agreement <- colSums(sub$components * fit$components * fit$weights)
    expect_true(all(agreement > 0.99))
  }
  # a component with zero integral is oriented by its largest-magnitude value
  w <- rep(1, 4)
  expect_equal(fpca_sign(c(-3, 1, 1, 1), w), -1)
  expect_equal(fpca_sign(c(3, -1, -1, -1), w), 1)
  expect_equal(fpca_sign(c(-1, 2, 0, 0), w), 1)
  expect_equal(fpca_sign(c(1, -2, 0, 0), w), -1)
})

test_that("projection, reconstruction and residual norms use the fit's inner product", {
  p <- planted_curves()
  fit <- fpca_fit(p$Y, p$t)
  expect_equal(fpca_project(fit, p$Y), fit$scores, tolerance = 1e-10, ignore_attr = TRUE)
  expect_equal(dim(fpca_project(fit, p$Y[1, ])), c(1, 2))
  # a new curve: mean + 3 phi1 - 2 phi2 + 0.5 phi3 (phi3 outside the model)
  s <- unname(sign(colSums(fit$components * p$phi[, 1:2] * fit$weights)))
  g <- p$mu + 3 * p$phi[, 1] - 2 * p$phi[, 2] + 0.5 * p$phi[, 3]
  sc <- fpca_project(fit, g)
  expect_equal(as.numeric(sc), c(3, -2) * s, tolerance = 0.02)
  expect_equal(s, c(1, 1), ignore_attr = TRUE)
  expect_equal(fpca_residual_norm(fit, g), 0.5, tolerance = 0.02)
  rec <- fpca_reconstruct(fit, sc)
  expect_equal(dim(rec), c(1, 41))
  expect_equal(sqrt(sum((g - rec[1, ])^2 * fit$weights)), fpca_residual_norm(fit, g),
               tolerance = 1e-10)
  # curves in the model's span have almost no residual (not exactly none:
  # like fdata2pc, components are unit-norm under uniform weights while inner
  # products use the trapezoidal rule, which differ at the two end points)
  in_span <- fpca_reconstruct(fit, fit$scores)
  expect_lt(max(fpca_residual_norm(fit, in_span)), 1e-5 * max(abs(fit$scores)))
  # residual norm of the training curves is about the noise level
  expect_lt(mean(fpca_residual_norm(fit, p$Y)), 0.06)
})

test_that("degenerate inputs give zero components with recorded notes, not errors", {
  t <- seq(0, 1, length.out = 10)
  const <- matrix(3, 6, 10)
  for (engine in c("fast", "reference")) {
    fit <- fpca_fit(const, t, engine = engine)
    expect_equal(fit$components, matrix(0, 10, 2), ignore_attr = TRUE)
    expect_equal(fit$scores, matrix(0, 6, 2), ignore_attr = TRUE)
    expect_true(all(is.na(fit$var_explained)))
    expect_length(fit$eigenvalues, 0)
    expect_match(fit$notes, "do not vary")
    expect_equal(fpca_residual_norm(fit, const), rep(0, 6))
  }
  # n = 2: one non-trivial component
  p <- planted_curves(n = 2, noise = 0)
  for (engine in c("fast", "reference")) {
    fit <- fpca_fit(p$Y, p$t, engine = engine)
    expect_equal(unname(fit$var_explained), c(1, 0))
    expect_equal(fit$components[, 2], rep(0, 41), ignore_attr = TRUE)
    expect_match(fit$notes, "component 2: zero variance")
  }
  # ncomp above n - 1 and above L: padded with zero components
  fit <- fpca_fit(planted_curves(n = 5)$Y[, 1:3], ncomp = 6)
  expect_equal(dim(fit$components), c(3, 6))
  expect_equal(sum(abs(fit$components[, 4:6])), 0)
  expect_equal(sum(fit$var_explained), 1, tolerance = 1e-12)
  expect_equal(fit$argvals, c(0, 0.5, 1))
})

test_that("bad inputs raise classed errors naming the argument", {
  p <- planted_curves(n = 10)
  Y <- p$Y
  Y[3, 7] <- NA
  expect_error(fpca_fit(Y), class = "handmotion_error_bad_input")
  expect_error(fpca_fit(Y), "curve 3, point 7")
  expect_error(fpca_fit(p$Y, argvals = 1:3), class = "handmotion_error_bad_input")
  expect_error(fpca_fit(p$Y, argvals = rev(p$t)), class = "handmotion_error_bad_input")
  expect_error(fpca_fit(p$Y, ncomp = 0), class = "handmotion_error_bad_input")
  expect_error(fpca_fit("a"), class = "handmotion_error_bad_input")
  fit <- fpca_fit(p$Y, p$t)
  expect_error(fpca_project(fit, p$Y[, -1]), class = "handmotion_error_bad_input")
  expect_error(fpca_reconstruct(fit, matrix(0, 2, 3)), class = "handmotion_error_bad_input")
  expect_error(fpca_project(list(), p$Y), class = "handmotion_error_bad_input")
})

test_that("print shows the variance explained and notes", {
  p <- planted_curves(n = 2, noise = 0)
  expect_snapshot(print(fpca_fit(p$Y, p$t)))
})
