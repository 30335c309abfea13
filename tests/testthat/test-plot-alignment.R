test_that("autoplot draws the frame-count histogram and one path per recording", {
  pl <- planted_alignment(N = 6, seed = 14)
  recs <- pl$recs
  recs$stuck <- grasp_curve(seq(0, 0.45, length.out = 30))
  al <- align_recordings(recs, max_iter = 3, features = "raw", degenerate_warps = "drop")
  b <- ggplot2::ggplot_build(autoplot(al))
  expect_length(b$data, 2)
  expect_equal(sum(b$data[[1]]$count), 7)               # all original frame counts
  lines <- b$data[[2]]
  expect_equal(length(unique(lines$group)), 7)          # 6 kept + 1 dropped
  expect_equal(nrow(lines), 7 * al$target_length)
  expect_true("red" %in% lines$colour)                   # the dropped one highlighted
  expect_equal(sum(lines$colour == "red"), al$target_length)
  expect_identical(levels(b$layout$layout$panel), c("frame counts before warping", "warping paths"))
  p <- ggplot2::ggplot_build(autoplot(al, type = "paths"))
  expect_equal(range(p$data[[1]]$x), c(1, al$target_length))
  h <- ggplot2::ggplot_build(autoplot(al, type = "histogram"))
  expect_equal(sum(h$data[[1]]$count), 7)
  # kept by the fallback: its kept path in orange, its degenerate DTW path in red
  kept <- align_recordings(recs, max_iter = 3, features = "raw")
  kl <- ggplot2::ggplot_build(autoplot(kept, type = "paths"))$data[[1]]
  expect_equal(length(unique(kl$group)), 8)
  expect_equal(sum(kl$colour == "darkorange"), kept$target_length)
  expect_equal(sum(kl$colour == "red"), kept$target_length)
  local_failing_alignment()
  expect_warning(forced <- align_recordings(pl$recs), class = "handmotion_warning_linear_fallback")
  lin <- ggplot2::ggplot_build(autoplot(forced, type = "paths"))
  d <- lin$data[[1]]
  # linear fallback: straight paths
  expect_true(all(tapply(d$y, d$group, function(y) diff(range(diff(y)))) < 1e-8))
})
