# Glove profiles: one description of a glove's channels that drawing,
# limits and calibration all read.

test_that("every shipped profile validates and says which channels are drawn", {
  for (nm in c("hust", "graspdb14", "cyberglove18", "cyberglove22", "resistive", "flexglove")) {
    p <- glove_profile(nm)
    expect_s3_class(p, "glove_profile")
    expect_false(anyDuplicated(p$channels$channel) > 0)
  }
  expect_equal(nrow(glove_profile("cyberglove18")$channels), 18)
  expect_equal(nrow(glove_profile("cyberglove22")$channels), 22)
  expect_equal(nrow(glove_profile("hust")$channels), 16)
  r <- glove_profile("resistive")
  expect_true(all(r$channels$unit == "raw"))
  expect_equal(sum(grepl("abd", r$channels$channel)), 4)
  expect_output(print(glove_profile("cyberglove18")), "not drawn: P-Arch")
})

test_that("a user's profile comes from a few columns or a CSV file, defaults filled in", {
  p <- glove_profile(data.frame(channel = c("a", "b", "pad"), joint = c("if-mcp", "if-pip", NA),
                                axis = c("x", "x", NA)), unit = "deg")
  expect_equal(p$channels$sign, c(1, 1, 1))
  expect_true(is.na(p$channels$axis[3]))
  f <- withr::local_tempfile(fileext = ".csv")
  utils::write.csv(p$channels, f, row.names = FALSE)
  q <- glove_profile(f)
  expect_equal(q$channels$channel, p$channels$channel)
  expect_equal(q$name, tools::file_path_sans_ext(basename(f)))
})

test_that("bad profiles are classed errors naming the channel", {
  expect_error(glove_profile(data.frame(joint = "if-mcp")), class = "handmotion_error_bad_glove")
  expect_error(glove_profile(data.frame(channel = c("a", "a"))), class = "handmotion_error_bad_glove")
  err <- expect_error(glove_profile(data.frame(channel = "a", joint = "if-mcp", axis = "x", unit = "raw")),
                      class = "handmotion_error_bad_glove")
  expect_match(conditionMessage(err), "a")
  expect_error(glove_profile("no such glove"), class = "handmotion_error_bad_glove")
  expect_error(glove_profile(data.frame(channel = "a", unit = "volts")), class = "handmotion_error_bad_glove")
})

test_that("a set without a profile gets one from its channel names; grasps(glove =) must match the DoFs", {
  g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 1, seed = 1)
  expect_equal(g$glove$name, "hust")
  m <- matrix(0, 5, 3, dimnames = list(NULL, c("x1", "x2", "x3")))
  expect_equal(grasps(list(m))$glove$name, "unknown")
  expect_error(grasps(list(m), glove = "resistive"), class = "handmotion_error_bad_glove")
})

test_that("stuck channels are flagged once, with a classed warning, and shown by print and summary", {
  set.seed(1)
  recs <- lapply(1:6, function(i) cbind(a = rnorm(20), b = 7, c = rnorm(20)))
  expect_warning(g <- grasps(recs, meta = data.frame(grasp = rep(c("x", "y"), 3))),
                 class = "handmotion_warning_stuck_channels")
  # a few poses, or data in which nothing moves, are not evidence of a stuck sensor
  expect_no_warning(few <- grasps(recs[1:3]))
  expect_equal(stuck_channels(few), character())
  expect_no_warning(grasps(lapply(1:6, function(i) cbind(a = 1, b = 2))))
  expect_equal(stuck_channels(g), "b")
  expect_output(print(g), "stuck channels.*b")
  expect_output(print(summary(g)), "Stuck channels.*b")
  expect_equal(stuck_channels(g[1:2]), "b")   # a subset keeps the glove's flags
})

test_that("raw counts are drawn through the profile: the same hand as its degrees", {
  raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 3), objects = 1, trials = 1, rate = 50,
                         glove = "resistive", rest = 0.2, hold = 0.2, session_sd = 0, seed = 4)
  pos <- forward_kinematics(raw)[[1]]
  expect_equal(dim(pos)[1], raw$meta$n_frames)
  deg <- calibrate(raw)
  pos2 <- forward_kinematics(deg)[[1]]
  expect_equal(pos, pos2, tolerance = 1e-8)
  # a closed grasp bends the index finger: its tip comes closer to the wrist than at rest
  tip <- grep("if-", dimnames(pos)[[2]], value = TRUE)
  tip <- tip[length(tip)]
  d <- sqrt(rowSums(pos[, tip, ]^2))
  expect_lt(d[length(d)], d[1])
  expect_s3_class(ggplot2::autoplot(raw, type = "hand"), "ggplot")
  w <- hand_3d(raw)
  expect_s3_class(w, "htmlwidget")
  f <- withr::local_tempfile(fileext = ".bvh")
  write_bvh(raw, f)
  expect_true(file.exists(f))
})

test_that("a glove with no drawn channel cannot be drawn, and says so", {
  m <- matrix(rnorm(30), 10, 3, dimnames = list(NULL, c("x1", "x2", "x3")))
  g <- grasps(list(m))
  expect_error(forward_kinematics(g), class = "handmotion_error_bad_mapping")
})

test_that("raw counts with CyberGlove sensor names and no profile are drawn through a guessed map, said once", {
  deg <- simulate_grasps(subjects = 1, grasps = c(a = 17), objects = 1, trials = 2, seed = 2)
  # counts rising with each HUST angle, named as the HUST DoFs
  recs <- lapply(deg$recordings, function(r) round(200 + 4 * r))
  expect_warning(g <- grasps(recs, rate = 50, unit = "raw"), class = "handmotion_warning_guessed_glove")
  expect_match(g$glove$name, "guessed")
  pos <- forward_kinematics(g)[[1]]
  expect_true(all(is.finite(pos)))
  # the guessed map is increasing: a more bent index MCP gives a larger angle
  d <- glove_degrees(list(matrix(c(rep(300, 16), rep(500, 16)), 2, byrow = TRUE)), g$glove)[[1]]
  expect_true(all(d[2, !is.na(g$glove$channels$axis)] > d[1, !is.na(g$glove$channels$axis)]))
})

test_that("raw counts given an angle profile (a CyberGlove's) keep its joints and get a guessed map", {
  set.seed(4)
  ch <- glove_profile("cyberglove22")$channels$channel
  recs <- lapply(1:6, function(i) matrix(round(500 + 100 * sin(outer(1:30 / 10, seq_along(ch)))), 30,
                                         length(ch), dimnames = list(NULL, ch)))
  expect_warning(g <- grasps(recs, rate = 100, unit = "raw", glove = "cyberglove22"),
                 class = "handmotion_warning_guessed_glove")
  expect_match(g$glove$name, "cyberglove22")
  expect_true(all(g$glove$channels$unit == "raw"))
  drawn <- !is.na(glove_profile("cyberglove22")$channels$axis)
  expect_identical(g$glove$channels$joint[drawn], glove_profile("cyberglove22")$channels$joint[drawn])
  expect_true(all(is.finite(forward_kinematics(g[1])[[1]])))
})

test_that("channel ranges are the ranges over every frame of every recording", {
  set.seed(8)
  recs <- lapply(c(4, 1, 6, 4, 9, 2, 4), function(n) matrix(stats::rnorm(n * 3, mean = n), n, 3,
                                                         dimnames = list(NULL, c("x", "y", "z"))))
  recs[[5]][2, 2] <- 100   # the largest value of y, inside a recording
  recs[[1]][1, 3] <- -50   # the smallest of z, the first value of the first
  recs[[7]][4, 1] <- 1e6   # the largest of x, the last value of the last
  all <- do.call(rbind, recs)
  r <- channel_ranges(recs)
  expect_identical(r$lo, apply(all, 2, min))
  expect_identical(r$hi, apply(all, 2, max))
  expect_identical(r$hi[["x"]], 1e6)
  # integer recordings are read as numbers
  expect_identical(channel_ranges(list(matrix(1:6, 3)))$hi, c(3, 6))
  recs <- lapply(recs, function(m) { m[, "y"] <- 2; m })
  expect_identical(find_stuck(recs), c(x = FALSE, y = TRUE, z = FALSE))
})
