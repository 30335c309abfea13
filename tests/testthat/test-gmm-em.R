test_that("the compiled EM's entry point rejects bad input instead of crashing", {
  Y <- planted_groups(1, 50, 3, 2)
  design <- gmm_design(Y)
  state <- gmm_start_state(design, list(rep(1:2, 25)), 2L)
  em <- function(P = design$P, st = state, k = 2L, max_iter = 10L, tol = 1e-8, logdet0 = 0) {
    .Call(hm_gmm_em, P, st, k, max_iter, tol, logdet0)
  }
  expect_type(em(), "list")
  expect_error(em(P = design$P[, -1]), "monomials")
  expect_error(em(P = "a"), "double matrix")
  expect_error(em(P = as.vector(design$P)), "double matrix")
  expect_error(em(st = state[-1, , drop = FALSE]), "rows")
  expect_error(em(st = state * NA), "finite")
  expect_error(em(k = NA_integer_), "'k'")
  expect_error(em(k = 51L), "'k'")
  expect_error(em(k = 1:2), "single")
  expect_error(em(max_iter = 0L), "max_iter")
  expect_error(em(tol = NaN), "numbers")
  bad <- design$P
  bad[3, 2] <- Inf
  expect_error(em(P = bad), "finite")
})
