test_that("autoplot draws one line per recording in one panel per DoF", {
  g <- grasps(make_recs(3, p = 2), meta = data.frame(grasp = c(1, 1, 2)), dofs = c("A", "B"))
  p <- ggplot2::autoplot(g)
  b <- ggplot2::ggplot_build(p)
  expect_identical(length(unique(b$data[[1]]$PANEL)), 2L)
  expect_identical(length(unique(b$data[[1]]$group)), 3L)
  expect_error(ggplot2::autoplot(g, colour = "nope"), class = "handmotion_error_bad_input")
})
