test_that("report tables right-align numbers, also when they carry marks", {
  d <- data.frame(type = c("Tripod", "Lateral"), n = c(270L, 268L), recall = c("31.9%", "-"),
                  thesis = c("\u2265245", "61?"), pcs = c("0.64 / 0.54", "0.70 / 0.61"))
  expect_equal(report_align(d), c("l", "r", "r", "r", "r"))
})

test_that("Appendix A's parts share one scale, so hands are drawn the same size in each", {
  small <- ggplot2::ggplot(data.frame(x = c(0, 1), y = c(0, 1)), ggplot2::aes(x, y)) +
    ggplot2::geom_point() + ggplot2::coord_equal()
  tall <- ggplot2::ggplot(data.frame(x = c(-1, 1), y = c(0, 3)), ggplot2::aes(x, y)) +
    ggplot2::geom_point() + ggplot2::coord_equal()
  parts <- report_same_scale(list(small, tall))
  ranges <- lapply(parts, function(p) ggplot2::ggplot_build(p)$layout$panel_params[[1]][c("x.range", "y.range")])
  expect_equal(ranges[[1]], ranges[[2]])
  # the union of what each part needs: nothing is cut off
  expect_true(ranges[[1]]$x.range[1] <= -1 && ranges[[1]]$x.range[2] >= 1)
  expect_true(ranges[[1]]$y.range[1] <= 0 && ranges[[1]]$y.range[2] >= 3)
})

test_that("the report's confusion matrices write counts and key at 9 points or more", {
  lv <- feix_taxonomy$name
  p <- report_confusion_plot(grasp_confusion(lv, rev(lv), levels = lv), "x")
  text_layer <- p$layers[[which(vapply(p$layers, function(l) inherits(l$geom, "GeomText"), logical(1)))]]
  expect_gte(text_layer$aes_params$size * ggplot2::.pt, 9 - 1e-9)
  expect_gte(p$theme$plot.caption$size, 9)
  expect_gte(p$theme$axis.text$size, 9)
})
