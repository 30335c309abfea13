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

test_that("positions, numeric choices and three-way flags go through the shared checkers", {
  # positions: whole numbers in 1..n come back as integers; a fraction, 0,
  # n + 1, NA or nothing is refused naming the argument (2.5 was truncated)
  expect_identical(check_indices(c(2, 5), 5, "frames", "frame"), c(2L, 5L))
  for (bad in list(2.5, 0, 6, NA_real_, numeric(), "2")) {
    cnd <- tryCatch(check_indices(bad, 5, "frames", "frame"), handmotion_error_bad_input = function(e) e)
    expect_identical(cnd$argument, "frames", label = describe_value(bad))
  }
  expect_error(check_indices(c(1, 2), 5, "recording", "recording", one = TRUE), class = "handmotion_error_bad_input")
  # a fractional DoF column to deactivate is refused; a whole one is that DoF
  ang <- matrix(10, 3, 16, dimnames = list(NULL, hust_dofs$name))
  expect_error(forward_kinematics(ang, deactivate = 2.5), class = "handmotion_error_bad_input")
  expect_identical(forward_kinematics(ang, deactivate = 2), forward_kinematics(ang, deactivate = hust_dofs$name[2]))
  # numeric choices: the number itself, not a string of it
  expect_identical(check_choice(0.5, c(0.1, 0.5, 1), "speed"), 0.5)
  expect_error(check_choice("0.5", c(0.1, 0.5, 1), "speed"), class = "handmotion_error_bad_input")
  expect_error(check_choice(c(",", ";"), c(",", ";"), "sep", whole = FALSE), class = "handmotion_error_bad_input")
  # NA passes a flag only where it means "decide for me"
  expect_identical(check_flag(NA, "recursive", allow_na = TRUE), NA)
  expect_error(check_flag(NA, "limits"), class = "handmotion_error_bad_input")
  expect_snapshot(error = TRUE, {
    check_indices(2.5, 5, "frames", "frame", where = " (recording \"r1\" has 5)")
    check_flag("yes", "recursive", allow_na = TRUE)
    check_choice("rad ", c("deg", "rad"), "unit", whole = FALSE, info = "Angles {in} degrees or radians.")
  })
})
