test_that("a video frame draws the hand of the still pictures", {
  skip_on_cran()
  skip_if_not_installed("magick")
  g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
  geo <- hand_geometry()
  pos <- forward_kinematics(g$recordings[[1]], frames = c(1, 20))[, geo$joints, ]
  sp <- solid_polygons(project_array(pos, "oblique"), geo)
  # the frames draw every drawn segment and the palm of each hand
  per_hand <- table(sp$poly$hand[sp$poly$kind == "bone"])
  expect_equal(as.vector(per_hand), rep(sum(geo$segments$draw), 2))
  expect_equal(sum(sp$poly$kind == "palm"), 2L)
  # and a frame is drawn: some of its pixels are skin, not white
  f <- file.path(withr::local_tempdir(), "hand.gif")
  write_hand_animation(g, f, max_frames = 4, width = 120, height = 120)
  px <- matrix(as.integer(magick::image_data(magick::image_read(f)[2], channels = "rgb")), ncol = 3)
  # skin, shaded: warm (red well above blue), neither white nor grey
  expect_gt(mean(px[, 1] - px[, 3] > 40), 0.05)
})
