test_that("video timing follows the documented rule", {
  # MP4: every recorded frame up to max_frames, at the rate that keeps the duration
  expect_equal(video_timing(60, 50, 150, "mp4"), list(frames = 60L, fps = 50))
  expect_equal(video_timing(60, 50, 30, "mp4"), list(frames = 30L, fps = 25))
  # GIF: frame delays in hundredths of a second
  expect_equal(video_timing(60, 50, 150, "gif"), list(frames = 60L, fps = 50))
  expect_equal(video_timing(60, 50, 30, "gif"), list(frames = 30L, fps = 25))
  expect_equal(video_timing(44, 50, 20, "gif"), list(frames = 18L, fps = 20))
  expect_equal(video_timing(30, 120, 10, "gif"), list(frames = 6L, fps = 25))
})

test_that("a GIF of a recorded and a generated grasp has the documented frames, and the hands move", {
  skip_on_cran()
  skip_if_not_installed("magick")
  g <- simulate_grasps(subjects = 2, grasps = 17, objects = 1, trials = 2, seed = 1)
  # (4 recordings cannot carry two-component mixtures: said, and irrelevant here)
  ms <- suppressWarnings(fit_grasp_models(g, seed = 1), classes = "handmotion_warning_small_mixture")
  new <- generate(ms, n = 1, seed = 3)
  f <- file.path(withr::local_tempdir(), "pair.gif")
  expect_invisible(out <- write_hand_animation(list(recorded = g[1], generated = new), f, max_frames = 12,
                                                width = 320, height = 200))
  expect_identical(out, f)      # the path, nothing more
  n_max <- max(g$meta$n_frames[1], new$meta$n_frames)
  expected <- video_timing(n_max, g$rate, 12, "gif")
  im <- magick::image_read(f)
  expect_length(im, expected$frames)
  # each frame shows for 1/fps s: the delay (hundredths of a second) of every
  # graphic control extension block (21 F9 04, flags, delay as 16-bit little endian)
  b <- as.integer(readBin(f, "raw", file.size(f)))
  at <- which(b[-(length(b) - 0:1)] == 0x21 & b[-c(1, length(b))] == 0xF9 & b[-(1:2)] == 0x04)
  delays <- b[at + 4] + 256 * b[at + 5]
  expect_length(delays, expected$frames)
  expect_equal(unique(delays), 100 / expected$fps)
  expect_equal(magick::image_info(im)$width[1], 320)
  first <- as.integer(magick::image_data(im[1], channels = "rgb"))
  last <- as.integer(magick::image_data(im[length(im)], channels = "rgb"))
  expect_gt(mean(first != last), 0.005)
})

test_that("an MP4 is written where ffmpeg is installed", {
  skip_on_cran()
  skip_if(!nzchar(Sys.which("ffmpeg")) || !nzchar(Sys.which("ffprobe")), "ffmpeg is not installed")
  g <- simulate_grasps(subjects = 1, grasps = 9, objects = 1, trials = 1, seed = 1)
  f <- file.path(withr::local_tempdir(), "grasp.mp4")
  out <- write_hand_animation(g, f, max_frames = 10, width = 160, height = 160)
  frames <- system2("ffprobe", c("-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                 "stream=nb_read_frames", "-of", "csv=p=0", shQuote(f)), stdout = TRUE)
  expect_equal(as.integer(frames), video_timing(g$meta$n_frames, g$rate, 10, "mp4")$frames)
  expect_equal(as.integer(frames), 10L)
  expect_identical(out, f)
})

test_that("bad arguments give classed errors", {
  rec <- matrix(0, 5, 16, dimnames = list(NULL, hust_dofs$name))
  expect_error(write_hand_animation(rec, "hand.avi"), class = "handmotion_error_bad_input")
  expect_error(write_hand_animation(rec, "hand.gif", width = 0), class = "handmotion_error_bad_input")
  expect_error(write_hand_animation(rec, "hand.gif", max_frames = 1), class = "handmotion_error_bad_input")
  expect_error(write_hand_animation("x", "hand.gif"), class = "handmotion_error_bad_input")
  expect_error(write_hand_animation(rec[1, , drop = FALSE], "hand.gif"), "two or more frames",
               class = "handmotion_error_bad_recording")
})

test_that("an existing file is replaced only with overwrite = TRUE", {
  skip_on_cran()
  skip_if_not_installed("magick")
  rec <- matrix(0, 4, 16, dimnames = list(NULL, hust_dofs$name))
  rec[, "PIP2"] <- c(0, 20, 40, 60)
  dir <- withr::local_tempdir()
  for (f in file.path(dir, c("hand.gif", "hand.html"))) {
    writeLines("keep me", f)
    err <- expect_error(write_hand_animation(rec, f, width = 64, height = 64), class = "handmotion_error_file_exists")
    expect_match(conditionMessage(err), basename(f), fixed = TRUE)
    expect_identical(readLines(f), "keep me")
    expect_identical(write_hand_animation(rec, f, width = 64, height = 64, overwrite = TRUE), f)
    expect_false(identical(readLines(f, warn = FALSE)[1], "keep me"))
  }
})
