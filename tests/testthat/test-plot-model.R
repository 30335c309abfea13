plot_model_fixture <- function(keep_data = TRUE) {
  fit_grasp_model(planted_grasps(n = 12, p = 3, seed = 61), warping = "linear", seed = 1,
                  keep_data = keep_data)
}

test_that("fpca plot: grey samples, red mean and mean +- 2 sd x FPC (Figure 5.4)", {
  m <- plot_model_fixture()
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, dof = c("d1", "d3")))
  L <- m$target_length
  samples <- b$data[[1]]
  model <- b$data[[2]]
  expect_equal(nrow(samples), 12L * L * 2L)
  expect_true(all(samples$colour == "grey70"))
  expect_equal(nrow(model), (1L + 4L) * L * 2L)
  expect_true(all(model$colour == "red"))
  expect_equal(length(unique(b$data[[1]]$PANEL)), 2L)
  # the mean line of d1 is the model's mean curve
  on_mean <- vapply(seq_len(L), function(t) {
    any(abs(model$y[model$PANEL == 1 & model$x == t] - m$basis$mean[t, "d1"]) < 1e-10)
  }, logical(1))
  expect_true(all(on_mean))
  lay <- b$layout$layout
  expect_identical(as.character(lay$dof), c("d1", "d3"))
})

test_that("projection plot shows a recording and its FPC projection (Figure 5.5)", {
  m <- plot_model_fixture()
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "projection", recording = "r3"))
  d <- b$data[[1]]
  L <- m$target_length
  expect_equal(nrow(d), 2L * L * 3L)
  expect_setequal(unique(d$colour), c("grey50", "red"))
  grey_d1 <- d$y[d$PANEL == 1 & d$colour == "grey50"]
  expect_equal(grey_d1, unname(m$data$warped["r3", , "d1"]))
  red_d1 <- d$y[d$PANEL == 1 & d$colour == "red"]
  expect_lt(max(abs(red_d1 - grey_d1)), 1)          # 2 FPCs explain the planted curves
  # a new recording through project()
  nd <- planted_grasps(n = 1, p = 3, seed = 62)
  b2 <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "projection", newdata = nd, dof = "d2"))
  expect_equal(nrow(b2$data[[1]]), 2L * L)
  expect_error(ggplot2::autoplot(m, type = "projection", recording = 99), class = "handmotion_error_bad_input")
})

test_that("mixture plot draws contours for every DoF and the scores (Figure 5.6)", {
  m <- plot_model_fixture()
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "mixture"))
  contours <- b$data[[1]]
  points <- b$data[[2]]
  expect_setequal(unique(as.integer(contours$PANEL)), 1:3)
  expect_equal(nrow(points), 12L * 3L)
  expect_equal(points$x[points$PANEL == 2], unname(m$scores[, "d2", 1]))
})

test_that("warps plot: one grey line per recording and the red mean", {
  m <- plot_model_fixture()
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "warps"))
  expect_equal(length(unique(b$data[[1]]$group)), 12L)
  expect_equal(b$data[[2]]$y, m$warp$mean)
})

test_that("without kept data the model layers still draw; bad DoFs are clear errors", {
  m <- plot_model_fixture(keep_data = FALSE)
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, dof = 1))
  expect_equal(nrow(b$data[[1]]), 0L)
  expect_gt(nrow(b$data[[2]]), 0L)
  expect_error(ggplot2::autoplot(m, type = "projection"), class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(m, dof = "PIP9"), class = "handmotion_error_bad_input")
})
