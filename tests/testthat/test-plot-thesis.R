# Figure helpers of the thesis report, tested through ggplot_build().

strip_recording <- function(n = 21) {
  rec <- matrix(0, n, 16, dimnames = list(NULL, hust_dofs$name))
  rec[, c("MCP3", "PIP3", "MCP4", "PIP4", "MCP5", "PIP5")] <- seq(0, 80, length.out = n)
  rec
}

test_that("autoplot(type = \"frame_counts\") marks exactly the recordings the over-long rule removes", {
  lens <- c(40, 41, 42, 39, 40, 43, 38, 41, 40, 120)
  recs <- lapply(lens, function(n) matrix(0, n, 16))
  g <- grasps(recs, meta = data.frame(grasp = rep("Tripod", 10)))
  p <- ggplot2::autoplot(g, type = "frame_counts")
  b <- ggplot2::ggplot_build(p)
  expect_equal(as.character(p$data$status), ifelse(find_overlong(lens), "over-long", "kept"))
  expect_equal(sum(p$data$status == "over-long"), 1L)
  # the dashed fence is the rule's threshold
  expect_equal(unique(b$data[[2]]$xintercept), overlong_threshold(lens))
  # the rule is the model's `overlong` argument; a value left out keeps its default
  tight <- ggplot2::ggplot_build(ggplot2::autoplot(g, type = "frame_counts", overlong = c(median_mult = 1)))
  expect_equal(unique(tight$data[[2]]$xintercept),
               overlong_threshold(lens, overlong_rule(iqr_mult = 3, median_mult = 1)))
  # every recording is counted once in the histogram
  expect_equal(sum(b$data[[1]]$count), length(lens))
})

test_that("autoplot(type = \"frame_counts\") draws one panel per requested type and rejects absent ones", {
  g <- simulate_grasps(subjects = 3, grasps = c(3, 15), objects = 1, trials = 2, seed = 1)
  p <- ggplot2::autoplot(g, type = "frame_counts")
  expect_setequal(levels(p$data$grasp), c("Medium Wrap", "Fixed Hook"))
  expect_equal(levels(ggplot2::autoplot(g, type = "frame_counts", grasps = 15)$data$grasp), "Fixed Hook")
  expect_error(ggplot2::autoplot(g, type = "frame_counts", grasps = "Tripod"), class = "handmotion_error_too_few_recordings")
  expect_error(ggplot2::autoplot(g, type = "frame_counts", overlong = c(iqr = 1)), class = "handmotion_error_bad_input")
})

test_that("autoplot(type = \"strip\") draws each set at the same fractions of its own duration", {
  a <- grasps(list(strip_recording(21)), meta = data.frame(grasp = "Tripod"))
  b <- grasps(list(strip_recording(41)), meta = data.frame(grasp = "Tripod"))
  p <- ggplot2::autoplot(a, type = "strip", label = "recorded", compare = list(generated = b), n_frames = 5)
  built <- ggplot2::ggplot_build(p)
  pts <- p$layers[[2]]$data
  expect_equal(levels(pts$time), c("0%", "25%", "50%", "75%", "100%"))
  expect_setequal(unique(pts$frame[pts$set == "recorded"]), c(1, 6, 11, 16, 21))
  expect_setequal(unique(pts$frame[pts$set == "generated"]), c(1, 11, 21, 31, 41))
  # a grid of 2 sets x 5 times
  expect_equal(nrow(built$layout$layout), 10L)
  # the fingers close over time: the tip of the middle finger moves towards the palm
  tip <- pts[pts$set == "recorded" & pts$joint == "mf-tip", ]
  tip <- tip[order(tip$frame), ]
  root <- pts[pts$set == "recorded" & pts$joint == "root", ][1, ]
  reach <- sqrt((tip$x - root$x)^2 + (tip$y - root$y)^2 + (tip$z - root$z)^2)
  expect_true(reach[1] > reach[5])
})

test_that("autoplot(type = \"strip\") picks recordings by index or id and checks its arguments", {
  g <- grasps(list(strip_recording(11), strip_recording(21)),
              meta = data.frame(id = c("a", "b"), grasp = c("Tripod", "Tripod")))
  p <- ggplot2::autoplot(g, type = "strip", recording = "b", n_frames = 3)
  expect_equal(sort(unique(p$layers[[2]]$data$frame)), c(1, 11, 21))
  p2 <- ggplot2::autoplot(g, type = "strip", recording = 1, n_frames = 3)
  expect_equal(sort(unique(p2$layers[[2]]$data$frame)), c(1, 6, 11))
  # a recording shorter than n_frames keeps each frame once
  short <- grasps(list(strip_recording(3)), meta = data.frame(grasp = "Tripod"))
  expect_equal(sort(unique(ggplot2::autoplot(short, type = "strip", n_frames = 6)$layers[[2]]$data$frame)), 1:3)
  expect_error(ggplot2::autoplot(g, type = "strip", recording = "zz"), class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(g, type = "strip", recording = 3), class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(g, type = "strip", n_frames = 1), class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(g, type = "strip", compare = list(x = "x")), class = "handmotion_error_bad_input")
})
