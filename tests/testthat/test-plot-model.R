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
  # the mean is red; each FPC's band has its own colour
  expect_equal(sum(model$colour == "red"), L * 2L)              # one mean curve per panel
  expect_equal(length(unique(model$colour)), 1L + m$settings$ncomp)
  expect_equal(length(unique(b$data[[1]]$PANEL)), 2L)
  # the mean line of d1 is the model's mean curve
  on_mean <- vapply(seq_len(L), function(t) {
    any(abs(model$y[model$PANEL == 1 & model$x == t] - model_basis(m)$mean[t, "d1"]) < 1e-10)
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
  expect_equal(grey_d1, unname(m$alignment$warped["r3", , "d1"]))
  red_d1 <- d$y[d$PANEL == 1 & d$colour == "red"]
  expect_lt(max(abs(red_d1 - grey_d1)), 1)          # 2 FPCs explain the planted curves
  # a new recording through project()
  nd <- planted_grasps(n = 1, p = 3, seed = 62)
  b2 <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "projection", new_data = nd, dof = "d2"))
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
  expect_equal(points$x[points$PANEL == 2], unname(model_scores(m)[, "d2", 1]))
})

test_that("warps plot: one grey line per recording and the red mean", {
  m <- plot_model_fixture()
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "warps"))
  expect_equal(length(unique(b$data[[1]]$group)), 12L)
  expect_equal(b$data[[2]]$y, warp_basis(m)$mean)
})

test_that("without kept data the model layers still draw; bad DoFs are clear errors", {
  m <- plot_model_fixture(keep_data = FALSE)
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, dof = 1))
  expect_equal(nrow(b$data[[1]]), 0L)
  expect_gt(nrow(b$data[[2]]), 0L)
  expect_error(ggplot2::autoplot(m, type = "projection"), class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(m, dof = "PIP9"), class = "handmotion_error_bad_input")
})

test_that("a 33-class confusion heatmap labels its axes with ids and keys them in the caption", {
  lv <- feix_levels()
  cm <- grasp_confusion(lv, c(lv[-1], lv[1]))
  p <- ggplot2::autoplot(cm)
  b <- ggplot2::ggplot_build(p)
  expect_setequal(as.character(unique(p$data$truth)), as.character(1:33))
  cap <- b$plot$labels$caption
  expect_true(all(vapply(seq_along(lv), function(i) grepl(paste(i, lv[i]), cap, fixed = TRUE), logical(1))))
  # whole entries per line: no type name is split over two lines
  lines <- strsplit(cap, "\n", fixed = TRUE)[[1]]
  expect_gt(length(lines), 1L)
  expect_true(all(nchar(lines) <= 160))
  # classes with short names keep them and need no key
  small <- ggplot2::autoplot(grasp_confusion(c("a", "b"), c("a", "a")))
  expect_null(ggplot2::ggplot_build(small)$plot$labels$caption)
  two <- ggplot2::autoplot(grasp_confusion(c("Tripod", "Ring"), c("Tripod", "Tripod")))
  expect_equal(ggplot2::ggplot_build(two)$plot$labels$caption, "14 Tripod \u00b7 31 Ring")
})

test_that("the FPCA plot tells the mean and each FPC's band apart by colour and line type", {
  g <- simulate_grasps(subjects = 4, grasps = 3, objects = 1, trials = 2, seed = 1)
  m <- fit_grasp_model(g, seed = 1)
  p <- ggplot2::autoplot(m, dof = c("MCP2", "PIP2"))
  b <- ggplot2::ggplot_build(p)
  model <- b$data[[2]]
  kinds <- m$settings$ncomp + 1L
  expect_equal(length(unique(model$colour)), kinds)
  expect_equal(length(unique(model$linetype)), kinds)
  expect_equal(b$plot$labels$y, "angle (degrees)")
})

test_that("the alignment figure names each panel's axes in its strip", {
  curve <- function(u) cbind(a = 50 * plogis((u - 0.5) / 0.08), b = 30 * sin(pi * u))
  recs <- lapply(30:36, function(n) curve(seq(0, 1, length.out = n)^(n / 33)))
  p <- ggplot2::autoplot(align_recordings(recs))
  b <- ggplot2::ggplot_build(p)
  strips <- ggplot2::ggplot_gtable(b)
  expect_null(b$plot$labels$x)
  lab <- p$facet$params$labeller(data.frame(panel = levels(b$layout$layout$panel)))
  expect_match(lab[[1]][1], "recordings \\(y\\) by frames before warping \\(x\\)")
  expect_match(lab[[1]][2], "original frame \\(y\\) by warped frame \\(x\\)")
})

test_that("a model keeps its alignment once and draws it", {
  g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
  m <- fit_grasp_model(g, seed = 1)
  expect_s3_class(m$alignment, "grasp_alignment")
  expect_null(m$data)
  expect_identical(m$alignment$ids, m$ids)
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "alignment"))
  expect_equal(b$data, ggplot2::ggplot_build(ggplot2::autoplot(m$alignment))$data)
  small <- fit_grasp_model(g, seed = 1, keep_data = FALSE)
  expect_null(small$alignment)
  expect_error(ggplot2::autoplot(small, type = "alignment"), class = "handmotion_error_bad_input")
})
