test_that("as_grasps() round-trips the long form and takes matrices and lists", {
  g <- simulate_grasps(subjects = 2, grasps = c(1, 17), objects = 1, trials = 1, seed = 1)
  back <- as_grasps(as.data.frame(g), rate = g$rate)
  expect_identical(back$meta$id, g$meta$id)
  expect_equal(back$recordings, g$recordings, ignore_attr = TRUE)
  expect_identical(as.character(back$meta$grasp), as.character(g$meta$grasp))
  expect_identical(back$dofs, g$dofs)
  expect_identical(as_grasps(g), g)
  m <- g$recordings[[1]]
  one <- as_grasps(m)
  expect_s3_class(one, "grasps")
  expect_equal(one$recordings[[1]], m, ignore_attr = TRUE)
  expect_identical(as_grasps(unname(m))$dofs, hust_dofs$name)   # 16 unnamed: the HUST DoFs
  two <- as_grasps(list(a = m, b = m * 2), rate = 60)
  expect_identical(two$meta$id, c("a", "b"))
  expect_identical(two$rate, 60)
})

test_that("as_grasps() refuses what it cannot read, naming the problem", {
  g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 1, seed = 1)
  d <- as.data.frame(g)
  expect_error(as_grasps(d[setdiff(names(d), "angle")]), class = "handmotion_error_bad_input")
  expect_error(as_grasps(d[-5, ]), class = "handmotion_error_bad_recording")   # a missing cell
  expect_error(as_grasps("a"), class = "handmotion_error_bad_input")
})
