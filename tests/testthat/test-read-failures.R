test_that("read_failures gives an empty report when nothing failed, and refuses what no reader returned", {
  f <- read_failures(grasps(list(matrix(0, 3, 2))))
  expect_identical(names(f), c("file", "line", "class", "message"))
  expect_equal(nrow(f), 0)
  expect_error(read_failures(list()), "reader", class = "handmotion_error_bad_input")
})

test_that("read_each_file collects classed failures and lets other errors through", {
  reader <- function(f) {
    if (f == "bad") abort_bad_file("broken {.file {f}}", "bad_field_count", file = f, line = 7)
    if (f == "bug") stop("a bug, not a bad file")
    toupper(f)
  }
  r <- read_each_file(c("a", "bad", "b"), reader)
  expect_identical(unlist(r$results), c("A", "B"))
  expect_identical(r$files, c("a", "b"))
  expect_identical(r$failures$file, "bad")
  expect_identical(r$failures$line, 7L)
  expect_identical(r$failures$class, "handmotion_error_bad_field_count")
  expect_match(r$failures$message, "broken")
  expect_error(read_each_file(c("a", "bug"), reader), "a bug")
})

test_that("the summary warning is classed, counts and names the failed files", {
  f <- data.frame(file = c("x/one{1}.txt", "x/two.txt"), line = c(3L, NA),
                  class = c("handmotion_error_non_numeric", "handmotion_error_empty_file"),
                  message = c("m1", "m2"))
  w <- expect_warning(warn_read_failures(f, total = 5), class = "handmotion_warning_read_failures")
  expect_match(conditionMessage(w), "2 of 5 files could not be read and were skipped")
  expect_match(conditionMessage(w), "one{1}.txt:3", fixed = TRUE)
  expect_identical(w$failures, f)
  w1 <- expect_warning(warn_read_failures(f[1, ], total = 2))
  expect_match(conditionMessage(w1), "1 of 2 files could not be read and was skipped")
  expect_silent(warn_read_failures(f[0, ], total = 2))
})
