test_that("print and summary list what was removed and what fell back", {
  g <- planted_grasps(n = 20, p = 3, seed = 22)
  recs <- g$recordings
  recs[[2]] <- rbind(recs[[2]], recs[[2]], recs[[2]])
  recs <- lapply(recs, function(r) { r[, 3] <- 1; r })
  expect_warning(g3 <- grasps(recs, meta = g$meta, dofs = g$dofs), class = "handmotion_warning_stuck_channels")
  m <- fit_grasp_model(g3, warping = "linear", seed = 1)
  s <- summary(m)
  expect_s3_class(s, "summary_grasp_model")
  expect_identical(names(s), c("dof", "FPC1", "FPC2", "total", "mixture", "reason"))
  expect_equal(nrow(attr(s, "removed")), 1L)
  expect_snapshot(print(m))
  expect_snapshot(print(s))
})
