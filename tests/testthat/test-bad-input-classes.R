# Bad input by class (issue 34, item 8): objects edited after they were
# built, recordings too short and types too small to model, malformed
# files, fractional indices, invalid regular expressions and separators,
# and generics called on the wrong class. Each class gets a classed error
# naming the argument, recording, file or line, or a documented fallback
# with a classed warning naming them. tools/bad-input-corpus.R runs some 780
# such inputs; these are one or more per class.

test_that("a grasps set edited after construction is refused where it is used, naming the recording", {
  f <- bad_fixture()
  g <- f$g
  id <- g$meta$id[2]
  nan <- g
  nan$recordings[[2]][3, 4] <- NaN
  for (verb in list(function(x) fit_grasp_model(x, grasp = 1), function(x) fit_grasp_models(x),
                    function(x) fit_grasp_classifier(x), function(x) write_hust(x, withr::local_tempdir()),
                    function(x) forward_kinematics(x), function(x) summary(x), function(x) as.data.frame(x),
                    function(x) fit_handover(x, n_markers = 3), function(x) project(f$m, x))) {
    cnd <- expect_error(verb(nan), id, fixed = TRUE, class = "handmotion_error_bad_recording")
    expect_identical(cnd$recording, id)
  }
  expect_error(fit_grasp_model(nan, grasp = 1), "frame 3, DoF \"IP1\"")
  short_meta <- g
  short_meta$meta <- short_meta$meta[-1, ]
  expect_error(fit_grasp_models(short_meta), "meta has 17 rows for 18 recordings", class = "handmotion_error_bad_input")
  zero_rate <- g
  zero_rate$rate <- 0
  expect_error(write_bvh(zero_rate, withr::local_tempfile(fileext = ".bvh")), "rate", class = "handmotion_error_bad_input")
  renamed <- g
  renamed$dofs[1] <- "XX"
  expect_error(classify(f$ms, renamed), "columns other than dofs", class = "handmotion_error_bad_recording")
  frames <- g
  frames$meta$n_frames[2] <- 999L
  expect_error(autoplot(frames), id, fixed = TRUE, class = "handmotion_error_bad_recording")
  dup <- g
  dup$meta$id[2] <- dup$meta$id[1]
  cnd <- expect_error(evaluate_loso(dup), "unique", class = "handmotion_error_bad_input")
  expect_identical(cnd$argument, "x")
})

test_that("predict() and classify() leave a recording with NaN unclassified, with a classed warning naming it", {
  f <- bad_fixture()
  nan <- f$g
  nan$recordings[[2]][3, 4] <- NaN
  id <- nan$meta$id[2]
  w <- expect_warning(p <- predict(f$clf, nan), id, fixed = TRUE, class = "handmotion_warning_non_finite")
  expect_identical(w$recording, id)
  expect_true(is.na(p$.pred_class[2]))
  expect_false(anyNA(p$.pred_class[-2]))
  expect_warning(classify(f$ms, nan), id, fixed = TRUE, class = "handmotion_warning_non_finite")
})

test_that("empty selections are said to be empty", {
  f <- bad_fixture()
  empty <- f$g[integer(0)]
  expect_error(predict(f$clf, empty), "new_data.*no recordings", class = "handmotion_error_bad_input")
  expect_error(project(f$m, empty), "new_data.*no recordings", class = "handmotion_error_bad_input")
  expect_error(forward_kinematics(empty), "no recordings", class = "handmotion_error_bad_input")
  expect_error(autoplot(empty), "object.*no recordings", class = "handmotion_error_bad_input")
  expect_error(write_hust(empty, withr::local_tempdir()), "no recordings", class = "handmotion_error_bad_input")
  expect_error(generate(f$ms[integer(0)], n = 1), "no fitted models", class = "handmotion_error_bad_input")
  expect_error(grasp_confusion(character(0), character(0)), "empty", class = "handmotion_error_bad_input")
  expect_error(as_grasps(list()), "recordings", class = "handmotion_error_bad_input")
})

test_that("malformed BVH and skeleton files name the file and the line", {
  g <- bad_fixture()$g
  dir <- withr::local_tempdir()
  good <- readLines(write_bvh(g[1], file.path(dir, "good.bvh")))
  ch <- grep("CHANNELS 3", good)[1]
  ft <- grep("^Frame Time", good)
  off <- grep("OFFSET", good)[2]
  cases <- list(
    list(fn = "ft0.bvh", edit = function(x) replace(x, ft, "Frame Time: 0"), line = ft, re = "frame time"),
    list(fn = "neg.bvh", edit = function(x) replace(x, ch, sub("CHANNELS 3", "CHANNELS -3", x[ch])), line = ch, re = "CHANNELS"),
    list(fn = "frac.bvh", edit = function(x) replace(x, ch, sub("CHANNELS 3", "CHANNELS 2.5", x[ch])), line = ch, re = "2.5"),
    list(fn = "chan.bvh", edit = function(x) replace(x, ch, sub("Zrotation", "Wrotation", x[ch])), line = ch, re = "Wrotation"),
    list(fn = "inf.bvh", edit = function(x) replace(x, ft + 2L, sub("^\\S+", "Inf", x[ft + 2L])), line = ft + 2L, re = "infinite"),
    list(fn = "off.bvh", edit = function(x) replace(x, off, sub("OFFSET .*", "OFFSET NaN 0 0", x[off])), line = off, re = "OFFSET")
  )
  for (cs in cases) {
    path <- file.path(dir, cs$fn)
    writeLines(cs$edit(good), path)
    cnd <- expect_error(read_bvh(path), cs$re, class = "handmotion_error_bad_file")
    expect_identical(cnd$line, cs$line)
    expect_match(conditionMessage(cnd), cs$fn, fixed = TRUE)
  }
  j <- grep("^\\s*JOINT", good)[1:2]
  dup <- good
  dup[j[2]] <- sub("JOINT .*", sub("^\\s*JOINT ", "JOINT ", good[j[1]]), good[j[2]])
  writeLines(dup, file.path(dir, "dup.bvh"))
  expect_error(read_bvh(file.path(dir, "dup.bvh")), "used twice", class = "handmotion_error_bad_file")
  # skeletons: a non-finite position in a file or in an edited object
  sl <- readLines(write_skeleton(hand_skeleton(), file.path(dir, "good.xmlskel")))
  pos <- grep("<position>", sl)[2]
  sl[pos] <- sub(">.*<", ">Inf 0 0<", sl[pos])
  writeLines(sl, file.path(dir, "inf.xmlskel"))
  cnd <- expect_error(read_skeleton(file.path(dir, "inf.xmlskel")), "th-tmc", class = "handmotion_error_bad_skeleton")
  expect_s3_class(cnd, "handmotion_error_bad_file")
  sk <- hand_skeleton()
  sk$joints$x[3] <- NaN
  for (verb in list(function(s) forward_kinematics(g[1], skeleton = s), function(s) hand_3d(g[1], skeleton = s),
                    function(s) write_skeleton(s, file.path(dir, "nan.xmlskel")))) {
    expect_error(verb(sk), "th-mcp", class = "handmotion_error_bad_skeleton")
  }
  expect_false(file.exists(file.path(dir, "nan.xmlskel")))
  # a HUST file whose first line is text of another width: a classed warning, not a silent drop
  hust <- file.path(dir, "s09_g01_o1_t1.csv")
  write.csv(g$recordings[[1]], hust, row.names = FALSE)
  writeLines(c("a title line", readLines(hust)[-1]), hust)
  expect_warning(read_hust(hust), "s09_g01_o1_t1.csv", class = "handmotion_warning_unknown_header")
})

test_that("fractional, out-of-range and recycled indices are refused", {
  f <- bad_fixture()
  g <- f$g
  dir <- withr::local_tempdir()
  for (r in list(2.5, TRUE, 0, 99)) {
    expect_error(write_bvh(g, file.path(dir, "a.bvh"), recording = r), "recording", class = "handmotion_error_bad_input")
    expect_error(write_hand_animation(g, file.path(dir, "a.html"), recording = r), "recording", class = "handmotion_error_bad_input")
  }
  expect_error(forward_kinematics(g$recordings[[1]], frames = 2.5), "frames", class = "handmotion_error_bad_input")
  expect_error(autoplot(g, type = "hand", frame = 2.5), "`frame`", class = "handmotion_error_bad_input")
  expect_error(g[2.5], "whole", class = "handmotion_error_bad_input")
  expect_error(g[-99], "1..18", class = "handmotion_error_bad_input")
  expect_error(g[c(-1, 2)], "mix signs", class = "handmotion_error_bad_input")
  expect_identical(length(g[-1]), 17L)
  expect_error(f$ms[1.5], "whole", class = "handmotion_error_bad_input")
  expect_error(f$ms[c(TRUE, FALSE)], "length 3", class = "handmotion_error_bad_input")
  expect_identical(names(f$ms[c(TRUE, FALSE, TRUE)]), names(f$ms)[c(1, 3)])
  cnd <- expect_error(fit_grasp_models(g, grasps = -1), "grasps", class = "handmotion_error_unknown_grasp")
  expect_identical(cnd$argument, "grasps")
})

test_that("invalid regular expressions and separators name their argument", {
  g <- bad_fixture()$g
  dir <- withr::local_tempdir()
  write_hust(g[1:2], dir)
  gdb <- system.file("extdata", "graspdb14", package = "handmotion")
  for (p in c("(", "[", "(?<grasp>")) {
    expect_error(read_hust(dir, pattern = p), "pattern", class = "handmotion_error_bad_input")
    expect_error(read_hust(dir, file_pattern = p), "file_pattern", class = "handmotion_error_bad_input")
    expect_error(read_graspdb14(gdb, pattern = p), "pattern", class = "handmotion_error_bad_input")
    expect_error(read_glove(dir, glove = "hust", pattern = p), "pattern", class = "handmotion_error_bad_input")
  }
  expect_error(read_graspdb14(gdb, pattern = c("a", "b")), "pattern", class = "handmotion_error_bad_input")
  for (s in list(c(",", ";"), "", ",;", 1, TRUE)) {
    cnd <- expect_error(read_hust(dir, sep = s), "sep", class = "handmotion_error_bad_input")
    expect_identical(cnd$argument, "sep")
  }
  expect_length(read_hust(dir, sep = ","), 2L)
})

test_that("arguments that were checked only on some paths are checked on all", {
  g <- bad_fixture()$g
  # (a plain simulation returned before looking at rest, hold and session_sd)
  expect_error(simulate_grasps(subjects = 1, grasps = 1, rest = NaN), "rest", class = "handmotion_error_bad_input")
  expect_error(simulate_grasps(subjects = 1, grasps = 1, session_sd = -1), "session_sd", class = "handmotion_error_bad_input")
  for (w in list(-1, NaN, "a", c(1, 2))) {
    cnd <- expect_error(hand_3d(g[1], width = w), "width", class = "handmotion_error_bad_input")
    expect_identical(cnd$argument, "width")
  }
  expect_s3_class(hand_3d(g[1], width = "100%", height = 300), "htmlwidget")
})
