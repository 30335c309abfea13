test_that("BVH output re-parses with the right joints, frames and motion", {
  set.seed(6)
  rec <- matrix(runif(30 * 16, -10, 80), 30, 16, dimnames = list(NULL, hust_dofs$name))
  f <- withr::local_tempfile(fileext = ".bvh")
  write_bvh(rec, f, rate = 60)
  b <- read_bvh(f)
  expect_equal(nrow(b$joints), 25L)             # 20 joints + 5 end sites (the fingertips)
  expect_equal(sum(b$joints$end_site), 5L)
  expect_equal(b$frames, 30L)
  expect_equal(b$frame_time, 1 / 60, tolerance = 1e-8)
  expect_equal(ncol(b$motion), 6L + 3L * 19L)
  expect_equal(b$channels$root[1:3], c("Xposition", "Yposition", "Zposition"))
  # the animation in the file poses the hand exactly as forward_kinematics() does
  pb <- bvh_positions(b)
  pf <- forward_kinematics(rec)
  inner <- b$joints$name[!b$joints$end_site]
  expect_equal(pb[, inner, ], pf[, inner, ], tolerance = 1e-4, ignore_attr = TRUE)
  tips <- c("th-tip", "if-tip", "mf-tip", "rf-tip", "lf-tip")
  expect_equal(unname(pb[, b$joints$end_site, ]), unname(pf[, tips, ]), tolerance = 1e-4)
})

test_that("a real GraspDB14 recording with wrist motion exports exactly", {
  s <- read_skeleton(shared_file("data", "graspdb14", "default.xmlskel"))
  raw <- utils::read.table(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  a <- as.matrix(raw[1:60, 8:30])
  colnames(a) <- joint_map("graspdb14")$dof
  f <- withr::local_tempfile(fileext = ".bvh")
  write_bvh(a, f, s, unit = "rad", mode = "full")
  b <- read_bvh(f)
  expect_equal(b$frames, 60L)
  pf <- forward_kinematics(a, s, unit = "rad", mode = "full")
  pb <- bvh_positions(b)
  expect_equal(unname(pb[, b$joints$end_site, ]), unname(pf[, grep("tip", dimnames(pf)[[2]]), ]),
               tolerance = 1e-4)
})

test_that("grasps export, scaling and bad files", {
  g <- grasps(list(matrix(10, 5, 16), matrix(20, 7, 16)), rate = 25)
  f <- withr::local_tempfile(fileext = ".bvh")
  write_bvh(g, f, recording = 2, scale = 0.001)
  b <- read_bvh(f)
  expect_equal(b$frames, 7L)
  expect_equal(b$frame_time, 0.04)
  expect_equal(unname(b$offsets["th-tmc", ]), c(20, -8, 0) / 1000)
  expect_error(write_bvh(g, f, recording = "nope"), class = "handmotion_error_bad_input")
  writeLines(c("HIERARCHY", "ROOT r", "{", "OFFSET 0 0", "}", "MOTION", "Frames: 1", "Frame Time: 0.1", "0"), f)
  err <- expect_error(read_bvh(f), class = "handmotion_error_bad_file")
  expect_equal(err$line, 4L)
  writeLines(c("HIERARCHY", "ROOT r", "{", "OFFSET 0 0 0", "CHANNELS 1 Zrotation", "}", "MOTION",
               "Frames: 2", "Frame Time: 0.1", "0"), f)
  expect_error(read_bvh(f), class = "handmotion_error_bad_file")
  expect_error(read_bvh(tempfile()), class = "handmotion_error_bad_file")
})
