test_that("a BVH read back is written back unchanged, and its angles are the recording's", {
  f <- written_bvh(7, 12, 30)$file
  x <- read_bvh(f)
  f2 <- withr::local_tempfile(fileext = ".bvh")
  write_bvh(x, f2)
  expect_identical(readLines(f2), readLines(f))
  expect_identical(x$meta$id, sub("\\.bvh$", "", basename(f)))
  # an edited recording is written with its new angles, the hierarchy kept
  y <- x
  y$recordings[[1]][, "if-pip:Xrotation"] <- 10
  write_bvh(y, f2, overwrite = TRUE)
  z <- read_bvh(f2)
  expect_equal(unname(z$recordings[[1]][, "if-pip:Xrotation"]), rep(10, 12))
  expect_identical(attr(z, "bvh")$joints, attr(x, "bvh")$joints)
})
