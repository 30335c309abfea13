test_that("switch_segments finds the planted runs", {
  s <- rep(c(1, 0, 1, 0), c(3, 2, 4, 1))
  seg <- switch_segments(s)
  expect_identical(seg$state, c(1L, 0L, 1L, 0L))
  expect_identical(seg$start, c(1L, 4L, 6L, 10L))
  expect_identical(seg$end, c(3L, 5L, 9L, 10L))
  expect_identical(seg$n_frames, c(3L, 2L, 4L, 1L))
  expect_identical(nrow(switch_segments(c(TRUE, TRUE))), 1L)
  expect_error(switch_segments(c(1, 2)), class = "handmotion_error_bad_input")
  expect_error(switch_segments(c(1, NA)), class = "handmotion_error_bad_input")
})

planted_switch_grasps <- function() {
  runs <- c(5, 3, 6, 2, 4)
  sw <- rep(c(1L, 0L, 1L, 0L, 1L), runs)
  m <- matrix(seq_along(sw), length(sw), 2, dimnames = list(NULL, c("a", "b")))
  attr(m, "switch") <- sw
  attr(m, "time") <- (seq_along(sw) - 1) / 10
  grasps(list(m), meta = data.frame(id = "rec", subject = "7"), rate = 10, unit = "raw")
}

test_that("segment_by_switch cuts at every change and keeps the parent's metadata", {
  g <- planted_switch_grasps()
  s <- segment_by_switch(g)
  expect_length(s, 5)
  expect_identical(s$meta$n_frames, c(5L, 3L, 6L, 2L, 4L))
  expect_identical(s$meta$switch, c(1L, 0L, 1L, 0L, 1L))
  expect_identical(s$meta$parent, rep("rec", 5))
  expect_identical(s$meta$subject, rep("7", 5))
  expect_identical(s$meta$id[3], "rec_seg03")
  expect_identical(s$meta$start_frame, c(1L, 6L, 9L, 15L, 17L))
  expect_equal(s$meta$start_time_s, c(0, 0.5, 0.8, 1.4, 1.6))
  # frames land in the right segment, with their attributes sliced
  expect_equal(unname(s$recordings[[3]][, "a"]), 9:14)
  expect_identical(attr(s$recordings[[3]], "switch"), rep(1L, 6))
  expect_equal(attr(s$recordings[[3]], "time"), (0:5) / 10)
  expect_identical(s$rate, 10)
  expect_identical(s$unit, "raw")
})

test_that("keep and min_frames select runs, and what is left out is recorded", {
  g <- planted_switch_grasps()
  on <- segment_by_switch(g, keep = "on")
  expect_identical(on$meta$segment, c(1L, 3L, 5L))
  off <- segment_by_switch(g, keep = "off")
  expect_identical(off$meta$n_frames, c(3L, 2L))
  long <- segment_by_switch(g, keep = "on", min_frames = 5)
  expect_identical(long$meta$segment, c(1L, 3L))
  expect_identical(attr(long, "dropped")$segment, 5L)
  expect_error(segment_by_switch(g, keep = "off", min_frames = 10), class = "handmotion_error_no_segments")
})

test_that("switch states can be supplied, and are required", {
  g <- grasps(list(matrix(1:10, 10, 1)), rate = 50)
  expect_error(segment_by_switch(g), class = "handmotion_error_no_switch")
  s <- segment_by_switch(g, switch = rep(c(0, 1), each = 5))
  expect_length(s, 2)
  expect_error(segment_by_switch(g, switch = c(0, 1)), class = "handmotion_error_bad_input")
  expect_error(segment_by_switch(list()), class = "handmotion_error_bad_input")
})

test_that("a switch that never changes cuts nothing, with a classed warning naming the recording", {
  g <- grasps(list(matrix(1:10, 10, 1), matrix(1:8, 8, 1)), rate = 50)
  w <- expect_warning(s <- segment_by_switch(g, switch = list(rep(1, 10), rep(c(0, 1), 4))),
                      "never changes in 1 recording", class = "handmotion_warning_switch_unchanged")
  expect_identical(w$recording, g$meta$id[1])
  expect_length(s, 1L + 8L)   # the first whole, the second cut at each change
  expect_equal(s$recordings[[1]][, 1], 1:10)
  # a switch that changes: no warning
  expect_no_warning(segment_by_switch(g[2], switch = rep(c(0, 1), 4)))
})

test_that("the real calibration stream has 20 or 21 ON/OFF segments", {
  g <- read_graspdb14(shared_file("data", "graspdb14", "00_calib-rad-su01.txt"))
  s <- segment_by_switch(g)
  expect_true(length(s) %in% 20:21)
  expect_identical(s$meta$switch[1], 1L)
  expect_equal(sum(s$meta$n_frames), 6674L)
  expect_equal(sum(s$meta$n_frames[s$meta$switch == 0L]), 1909L)
  expect_identical(length(segment_by_switch(g, keep = "on")), sum(s$meta$switch == 1L))
})
