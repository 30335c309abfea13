test_that("re-writing the real samples reproduces them line for line", {
  dir <- dirname(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  g <- read_graspdb14(dir)
  out <- withr::local_tempdir()
  paths <- write_graspdb14(g, out)
  expect_setequal(basename(paths), basename(g$meta$source))
  for (p in paths) {
    expect_identical(readLines(p), readLines(file.path(dir, basename(p))), label = basename(p))
  }
})

test_that("write then read is lossless to the written precision", {
  set.seed(3)
  n <- c(40, 25)
  recs <- lapply(n, function(k) matrix(stats::runif(k * 23, -1.6, 1.6), k, 23))
  attr(recs[[2]], "switch") <- rep(c(1L, 0L, 1L), c(10, 5, 10))
  g <- grasps(recs, meta = data.frame(id = c("a", "b"), grasp = c(11, NA), subject = c("su03", "12"),
                                      object = c("Tennis ball (64 mm diameter)", "Mug"), trial = c(4, 7)),
              dofs = cyberglove_sensors$name, rate = 60, unit = "rad")
  out <- withr::local_tempdir()
  paths <- write_graspdb14(g, out)
  expect_identical(basename(paths), c("01_11_ex03-rad-004-grasp-su03.txt", "04_ex01-rad-007-grasp-su12.txt"))
  h <- read_graspdb14(out)
  h <- h[match(basename(paths), basename(h$meta$source))]
  for (i in 1:2) {
    expect_equal(unname(h$recordings[[i]]), unname(g$recordings[[i]]), tolerance = 5e-6,
                 ignore_attr = TRUE)
    expect_true(max(abs(h$recordings[[i]] - g$recordings[[i]])) <= 0.5e-5 + 1e-12)
  }
  expect_identical(attr(h$recordings[[2]], "switch"), attr(recs[[2]], "switch"))
  expect_identical(attr(h$recordings[[1]], "switch"), rep(1L, 40))
  # frames spaced 1 / rate apart, written to 5 decimals
  expect_equal(attr(h$recordings[[1]], "time"), (0:39) / 60, tolerance = 1e-5)
  expect_equal(h$rate, 60, tolerance = 1e-3)
  expect_identical(as.character(h$meta$grasp), c("Power Sphere", NA))
  expect_identical(h$meta$subject, c("3", "12"))
  expect_identical(h$meta$trial, c(4L, 7L))
  expect_identical(h$meta$object, c("Tennis ball (64 mm diameter)", "Mug"))
})

test_that("read, write, read keeps metadata, time stamps and switch states", {
  dir <- system.file("extdata", "graspdb14", package = "handmotion")
  skip_if(dir == "")
  g <- suppressWarnings(read_graspdb14(dir), classes = "handmotion_warning_stuck_channels")
  out <- withr::local_tempdir()
  write_graspdb14(g, out)
  h <- suppressWarnings(read_graspdb14(out), classes = "handmotion_warning_stuck_channels")
  expect_identical(h$meta$id, g$meta$id)
  keep <- setdiff(names(g$meta), "source")
  expect_equal(h$meta[keep], g$meta[keep])
  expect_equal(h$recordings, g$recordings)
  expect_identical(h$rate, g$rate)
})

test_that("raw counts are written as integers", {
  g <- suppressWarnings(grasps(list(matrix(rep(c(0, 255, 17, 100), length.out = 46), 2, 23)),
                               meta = data.frame(id = "r", object = "Bowl", subject = "2"),
                               dofs = cyberglove_sensors$name, unit = "raw", rate = 60),
                        classes = "handmotion_warning_guessed_glove")
  out <- withr::local_tempdir()
  p <- write_graspdb14(g, out)
  expect_identical(basename(p), "06_ex01-raw-001-grasp-su02.txt")
  expect_match(readLines(p)[1], "^2014 01 01 00 00 00.00000 1 0 17 0 17 0 17 ")
  back <- suppressWarnings(read_graspdb14(p), classes = "handmotion_warning_guessed_glove")
  expect_equal(unname(back$recordings[[1]]), unname(g$recordings[[1]]), ignore_attr = TRUE)
  g$recordings[[1]][1, 1] <- 0.5
  expect_error(write_graspdb14(g, out, overwrite = TRUE), class = "handmotion_error_bad_recording")
})

test_that("the writer refuses what the format cannot hold", {
  out <- withr::local_tempdir()
  h <- hust_fixture(1)
  expect_error(write_graspdb14(h, out), class = "handmotion_error_bad_input")
  g <- grasps(list(matrix(0, 3, 23)), dofs = cyberglove_sensors$name, unit = "deg")
  expect_error(write_graspdb14(g, out), class = "handmotion_error_bad_input")
  g$unit <- "rad"
  # no object and no subject: no file name can be built
  err <- expect_error(write_graspdb14(g, out), class = "handmotion_error_bad_input")
  expect_identical(err$recording, "r1")
  p <- write_graspdb14(g, out, file_names = "x.txt")
  expect_error(write_graspdb14(g, out, file_names = "x.txt"), class = "handmotion_error_file_exists")
  expect_silent(write_graspdb14(g, out, file_names = "x.txt", overwrite = TRUE))
  expect_error(write_graspdb14(g, out, file_names = "y.txt", start_time = "yesterday"),
               class = "handmotion_error_bad_input")
})

test_that("calibration and scenario 2 names are built from the metadata", {
  g <- grasps(list(matrix(0, 2, 23), matrix(0, 2, 23)),
              meta = data.frame(id = c("c", "u"), subject = c("1", "5"), scenario = c("calib", "2"),
                                object_id = c(NA, 9L), action_code = c(NA, "f_l"), trial = c(NA, 12L)),
              dofs = cyberglove_sensors$name, unit = "rad", rate = 60)
  out <- withr::local_tempdir()
  p <- write_graspdb14(g, out)
  expect_identical(basename(p), c("00_calib-rad-su01.txt", "09_f_l_ex02-rad-012-grasp-su05.txt"))
  h <- read_graspdb14(out)
  expect_identical(h$meta$action[h$meta$scenario == "2"], "close tightly")
})
