split <- handover_split()

test_that("the figures build: markers on the hand, component trajectories, ranking", {
  p <- ggplot2::autoplot(hand_skeleton(), markers = list(`hand-picked` = select_markers(method = "handpicked"),
                                                         tips = c("thumb_tip", "index_tip")))
  b <- ggplot2::ggplot_build(p)
  # the marker layer is the one whose data says which markers are recorded
  marks <- Filter(function(l) "selected" %in% names(l$data), b$plot$layers)[[1]]$data
  expect_equal(sum(marks$selected), 8)
  expect_equal(nrow(marks), 2 * 16)
  fit <- fit_handover(split$ref, n_markers = 3)
  rec <- predict(fit, split$test[1])
  p5 <- ggplot2::autoplot(fit, split$test[1], list(`3 markers` = rec), components = 1:2)
  d5 <- ggplot2::ggplot_build(p5)$plot$data
  expect_setequal(levels(d5$source), c("ground truth", "3 markers"))
  # with all components and smoothing the plotted scores are the model's smoothed scores
  s <- attr(rec, "handover")$scores[[1]]
  expect_equal(d5$score[d5$source == "3 markers" & d5$component == "PC1"], unname(s[, 1]))
  b_rank <- ggplot2::ggplot_build(ggplot2::autoplot(attr(select_markers(split$ref), "ranking")))
  expect_equal(nrow(b_rank$data[[1]]), 13)
  expect_output(print(fit), "handover_model")
})
