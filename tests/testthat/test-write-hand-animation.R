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
  skip_if_not_installed("gganimate")
  skip_if_not_installed("magick")
  g <- simulate_grasps(subjects = 2, grasps = 17, objects = 1, trials = 2, seed = 1)
  # (4 recordings cannot carry two-component mixtures: said, and irrelevant here)
  ms <- suppressWarnings(fit_grasp_models(g, seed = 1), classes = "handmotion_warning_small_mixture")
  new <- generate(ms, n = 1, seed = 3)
  f <- file.path(withr::local_tempdir(), "pair.gif")
  out <- write_hand_animation(list(recorded = g[1], generated = new), f, max_frames = 12,
                              width = 320, height = 200)
  n_max <- max(g$meta$n_frames[1], new$meta$n_frames)
  expected <- video_timing(n_max, g$rate, 12, "gif")
  expect_equal(attr(out, "frames"), expected$frames)
  im <- magick::image_read(f)
  expect_length(im, expected$frames)
  expect_equal(magick::image_info(im)$width[1], 320)
  first <- as.integer(magick::image_data(im[1], channels = "rgb"))
  last <- as.integer(magick::image_data(im[length(im)], channels = "rgb"))
  expect_gt(mean(first != last), 0.005)
})

test_that("an MP4 is written where ffmpeg is installed", {
  skip_on_cran()
  skip_if_not_installed("gganimate")
  skip_if(!nzchar(Sys.which("ffmpeg")) || !nzchar(Sys.which("ffprobe")), "ffmpeg is not installed")
  g <- simulate_grasps(subjects = 1, grasps = 9, objects = 1, trials = 1, seed = 1)
  f <- file.path(withr::local_tempdir(), "grasp.mp4")
  out <- write_hand_animation(g, f, max_frames = 10, width = 160, height = 160)
  frames <- system2("ffprobe", c("-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                 "stream=nb_read_frames", "-of", "csv=p=0", shQuote(f)), stdout = TRUE)
  expect_equal(as.integer(frames), attr(out, "frames"))
  expect_equal(attr(out, "frames"), 10L)
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
