test_that("BVH output re-parses with the right joints, frames and motion", {
  w <- written_bvh(6, 30, 60)
  rec <- w$rec
  f <- w$file
  x <- read_bvh(f)
  expect_s3_class(x, "grasps")
  b <- attr(x, "bvh")
  expect_equal(nrow(b$joints), 25L)             # 20 joints + 5 end sites (the fingertips)
  expect_equal(sum(b$joints$end_site), 5L)
  expect_equal(x$meta$n_frames, 30L)
  expect_equal(b$frame_time, 1 / 60, tolerance = 1e-8)
  expect_equal(x$rate, 60, tolerance = 1e-6)
  expect_equal(length(x$dofs), 3L * 20L)        # every joint's three rotations, the root's too
  expect_equal(dim(b$position), c(30L, 3L))
  expect_equal(b$channels$root[1:3], c("Xposition", "Yposition", "Zposition"))
  # the animation in the file poses the hand exactly as forward_kinematics() does
  pb <- bvh_positions(x)
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
  x <- read_bvh(f)
  expect_equal(x$meta$n_frames, 60L)
  pf <- forward_kinematics(a, s, unit = "rad", mode = "full")
  pb <- bvh_positions(x)
  expect_equal(unname(pb[, attr(x, "bvh")$joints$end_site, ]), unname(pf[, grep("tip", dimnames(pf)[[2]]), ]),
               tolerance = 1e-4)
})

test_that("grasps export, scaling and bad files", {
  g <- grasps(list(matrix(10, 5, 16), matrix(20, 7, 16)), rate = 25)
  f <- withr::local_tempfile(fileext = ".bvh")
  write_bvh(g, f, recording = 2, scale = 0.001)
  b <- read_bvh(f)
  expect_equal(b$meta$n_frames, 7L)
  expect_equal(attr(b, "bvh")$frame_time, 0.04)
  expect_equal(unname(attr(b, "bvh")$offsets["th-tmc", ]), c(20, -8, 0) / 1000)
  expect_error(write_bvh(g, f, recording = "nope", overwrite = TRUE), class = "handmotion_error_bad_input")
  writeLines(c("HIERARCHY", "ROOT r", "{", "OFFSET 0 0", "}", "MOTION", "Frames: 1", "Frame Time: 0.1", "0"), f)
  err <- expect_error(read_bvh(f), class = "handmotion_error_bad_file")
  expect_equal(err$line, 4L)
  writeLines(c("HIERARCHY", "ROOT r", "{", "OFFSET 0 0 0", "CHANNELS 1 Zrotation", "}", "MOTION",
               "Frames: 2", "Frame Time: 0.1", "0"), f)
  expect_error(read_bvh(f), class = "handmotion_error_bad_file")
  expect_error(read_bvh(tempfile()), class = "handmotion_error_bad_file")
  # a frame time of 0 and a negative channel count are named, with their line
  good <- c("HIERARCHY", "ROOT r", "{", "OFFSET 0 0 0", "CHANNELS 1 Zrotation", "End Site", "{", "OFFSET 0 1 0",
            "}", "}", "MOTION", "Frames: 2", "Frame Time: 0.1", "0", "5")
  writeLines(good, f)
  expect_equal(unname(read_bvh(f)$recordings[[1]][, 1]), c(0, 5))
  writeLines(replace(good, 13, "Frame Time: 0"), f)
  err <- expect_error(read_bvh(f), "positive", class = "handmotion_error_bad_file")
  expect_equal(err$line, 13L)
  writeLines(replace(good, 5, "CHANNELS -2 Zrotation"), f)
  err <- expect_error(read_bvh(f), class = "handmotion_error_bad_file")
  expect_equal(err$line, 5L)
})
