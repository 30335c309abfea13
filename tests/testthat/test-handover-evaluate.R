split <- handover_split()

test_that("handover_error is the mean absolute angle error per frame in degrees", {
  g <- split$test[1:2]
  off <- g
  off$recordings <- lapply(g$recordings, function(r) r + rep(c(2, -2), length.out = length(r)))
  expect_equal(handover_error(g, off), 2)
  by_rec <- handover_error(g, off, by = "recording")
  expect_equal(by_rec$error, c(2, 2))
  expect_equal(nrow(handover_error(g, off, by = "frame")), sum(g$meta$n_frames))
  expect_equal(handover_error(g, off, by = "dof")$error, rep(2, 16))
  rad <- g
  rad$unit <- "rad"
  rad_off <- off
  rad_off$unit <- "rad"
  expect_equal(handover_error(rad, rad_off), 2 * 180 / pi)
  expect_error(handover_error(g, split$test[2:3]), class = "handmotion_error_bad_input")
  expect_error(handover_error(g, rad_off), class = "handmotion_error_bad_input")
})

test_that("PCA reconstruction error falls with the number of components (Figure 1)", {
  pe <- handover_error(split$ref, by = "ncomp")
  expect_s3_class(pe, "handover_pca_error")
  expect_equal(nrow(pe), 16)
  expect_true(all(diff(pe$error) <= 1e-9))
  expect_lt(pe$error[16], 1e-8)
  expect_equal(pe$variance[16], 1)
  held <- handover_error(split$test, by = "ncomp", reference = split$ref)
  expect_gt(held$error[2], pe$error[2] * 0.5)
  fit <- fit_handover(split$ref, n_markers = 3)
  expect_equal(handover_error(split$test, by = "ncomp", reference = fit)$error, held$error)
  expect_error(handover_error(split$test), class = "handmotion_error_bad_input")   # no recon
  b <- ggplot2::ggplot_build(ggplot2::autoplot(pe))
  expect_equal(nrow(b$data[[1]]), 16)
})
