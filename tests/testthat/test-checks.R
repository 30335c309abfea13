test_that("the checkers name the argument and what was wrong", {
  f <- function(n = 1, engine = c("fast", "reference"), seed = NULL) {
    n <- check_whole(n, "n", max = 10)
    engine <- check_choice(engine, arg = "engine")
    check_seed(seed)
    list(n, engine)
  }
  expect_identical(f(), list(1L, "fast"))
  expect_identical(f(3, "reference", 2), list(3L, "reference"))
  cnd <- tryCatch(f(engine = "fsat"), handmotion_error = function(e) e)
  expect_identical(cnd$argument, "engine")
  expect_snapshot(error = TRUE, {
    f(n = 0)
    f(n = 1e10)
    f(n = 2.5)
    f(n = "a")
    f(engine = "fsat")
    f(engine = c("fast", "x"))
    f(seed = c(1, 2))
    f(seed = NA)
  })
})
