split <- handover_split()

test_that("a frame seen in the reference is reconstructed almost exactly", {
  fit <- fit_handover(split$ref, n_markers = 3, smooth = FALSE)
  rec <- predict(fit, split$ref[1:2])
  expect_s3_class(rec, "grasps")
  expect_identical(rec$meta$id, split$ref$meta$id[1:2])
  expect_lt(handover_error(split$ref[1:2], rec), 1e-3)
})
