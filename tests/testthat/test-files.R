test_that("every writer refuses to replace a file without overwrite = TRUE, naming it", {
  rec <- matrix(0, 3, 16, dimnames = list(NULL, hust_dofs$name))
  g <- grasps(list(rec, rec + 1), meta = data.frame(grasp = c(1, 2), subject = "S01"))
  dir <- withr::local_tempdir()
  bvh <- file.path(dir, "a.bvh")
  skel <- file.path(dir, "a.xmlskel")
  write_bvh(rec, bvh)
  write_skeleton(hand_skeleton(), skel)
  write_hust(g, file.path(dir, "hust"))
  gdb <- graspdb14_fixture_grasps()
  write_graspdb14(gdb, file.path(dir, "gdb"))
  before <- tools::md5sum(c(bvh, skel))
  for (attempt in list(quote(write_bvh(rec + 5, bvh)), quote(write_skeleton(hand_skeleton(), skel)),
                       quote(write_hust(g, file.path(dir, "hust"))),
                       quote(write_graspdb14(gdb, file.path(dir, "gdb"))))) {
    err <- expect_error(eval(attempt), class = "handmotion_error_file_exists")
    expect_true(length(err$file) >= 1L && all(file.exists(err$file)))
    expect_match(cli::ansi_strip(conditionMessage(err)), basename(err$file[1]), fixed = TRUE)
  }
  expect_identical(tools::md5sum(c(bvh, skel)), before)   # nothing was written
  write_bvh(rec + 5, bvh, overwrite = TRUE)
  expect_false(identical(tools::md5sum(bvh), before[1]))
  expect_silent(write_skeleton(hand_skeleton(), skel, overwrite = TRUE))
})
