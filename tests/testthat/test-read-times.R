test_that("uneven time stamps are resampled to a constant grid (planted signal recovered)", {
  dir <- withr::local_tempdir()
  set.seed(11)
  truth <- function(t) cbind(a = 500 + 100 * sin(2 * pi * 0.7 * t), b = 200 + 40 * t, c = 300)
  times <- list()
  for (i in 1:4) {
    # Arduino-like: a 10 ms first interval, then 25-35 ms
    dt <- c(10, stats::runif(79, 25, 35))
    t_ms <- 300 * i + cumsum(c(0, dt))
    times[[i]] <- t_ms
    write_timed(dir, sprintf("g%d/r%d.csv", i %% 2, i), t_ms, truth(t_ms / 1000))
  }
  g <- read_glove(dir, glove = tiny_glove(), time = "time_ms", pattern = "^(?<grasp>g\\d)/")
  # default rate: one over the median interval, pooled over the set
  expect_equal(g$rate, 1000 / stats::median(unlist(lapply(times, diff))))
  # (names do not repeat: the ids are the file names)
  for (k in seq_along(g)) {
    t_ms <- times[[as.integer(sub("^r", "", g$meta$id[k]))]]
    grid <- t_ms[1] / 1000 + (seq_len(g$meta$n_frames[k]) - 1) / g$rate
    expect_lte(max(grid), max(t_ms) / 1000 + 1e-9)
    expect_gt(max(grid), max(t_ms) / 1000 - 1 / g$rate)
    err <- abs(g$recordings[[k]] - truth(grid))
    # linear interpolation of a 0.7 Hz sine of amplitude 100 at <= 35 ms
    # spacing is off by at most h^2/8 * (2 pi 0.7)^2 * 100 = 0.30 counts;
    # the straight line and the constant come back exactly
    expect_lt(max(err[, "a"]), 0.3)
    expect_lt(max(err[, c("b", "c")]), 1e-9)
    expect_equal(g$meta$recorded_rate[k], 1000 / stats::median(diff(t_ms)))
  }
  expect_output(print(g), "resampled to")
  expect_output(print(summary(g)), "resampled to")
  # a given rate is the grid's; seconds from time_unit
  h <- read_glove(dir, glove = tiny_glove(), rate = 50, time = "time_ms", pattern = "^(?<grasp>g\\d)/")
  expect_identical(h$rate, 50)
  t1 <- times[[as.integer(sub("^r", "", h$meta$id[1]))]]
  expect_identical(h$meta$n_frames[1], as.integer(floor((max(t1) - min(t1)) / 20)) + 1L)
  sdir <- withr::local_tempdir()
  write_timed(sdir, "x/s1.csv", times[[1]] / 1000, truth(times[[1]] / 1000), header = c("t", "a", "b", "c"))
  s <- read_glove(sdir, glove = tiny_glove(), time = "t", time_unit = "s", recursive = TRUE)
  expect_equal(s$rate, 1000 / stats::median(diff(times[[1]])))
  expect_error(read_glove(sdir, glove = tiny_glove(), time = "t", recursive = TRUE),
               class = "handmotion_error_bad_input")
})

test_that("time stamps in files of their own (a timestamps folder) pair with the data files", {
  dir <- withr::local_tempdir()
  m <- matrix(c(0, 10, 20, 30, 5, 5, 5, 5, 1, 2, 3, 4), 4, 3)
  put <- function(rel, lines) write_fixture(dirname(file.path(dir, rel)), basename(rel), lines)
  data_lines <- c("a,b,c", apply(m, 1, paste, collapse = ","))
  put("cup/r1.csv", data_lines)
  put("pen/r1.csv", data_lines)
  put("timestamps/cup/r1.csv", c("time_ms", 100, 110, 130, 140))
  put("timestamps/pen/r1.csv", c("time_ms", 0, 20, 40, 60))
  g <- read_glove(dir, glove = tiny_glove(), time = "time_ms", timestamps = "timestamps",
                  pattern = "^(?<grasp>[^/]+)/")
  expect_identical(nrow(read_failures(g)), 0L)
  expect_identical(g$meta$id, c("cup/r1", "pen/r1"))
  # median interval over both files: 20 ms; cup's frames at 100, 110, 130, 140
  # come back at 100, 120, 140 (channel a is 0, 10, 20, 30 at those times)
  expect_equal(g$rate, 50)
  expect_equal(unname(g$recordings[[1]][, "a"]), c(0, 15, 30))
  expect_equal(unname(g$recordings[[2]][, "a"]), c(0, 10, 20, 30))
  expect_equal(g$meta$recorded_rate, c(1000 / 10, 1000 / 20))
  # a missing or short time stamp file: a failure naming the data file
  put("timestamps/pen/r1.csv", c("time_ms", 0, 20, 40))
  put("cup/r2.csv", data_lines)
  g <- suppressWarnings(read_glove(dir, glove = tiny_glove(), time = "time_ms", timestamps = "timestamps",
                                   pattern = "^(?<grasp>[^/]+)/"))
  f <- read_failures(g)
  expect_identical(g$meta$id, "cup/r1")
  expect_identical(sub(".*/([a-z]+/r\\d)\\.csv$", "\\1", f$file), c("cup/r2", "pen/r1"))
  expect_identical(f$class, c("handmotion_error_file_not_found", "handmotion_error_bad_time"))
  expect_error(read_glove(dir, glove = tiny_glove(), timestamps = "timestamps", recursive = TRUE),
               class = "handmotion_error_bad_input")
  expect_error(read_glove(dir, glove = tiny_glove(), time = "time_ms", timestamps = "nowhere", recursive = TRUE),
               class = "handmotion_error_file_not_found")
})
