# The R helpers the Python front end calls (R/python-bridge.R).

test_that("py_call() returns values, and errors and warnings as data with their classes", {
  ok <- py_call("simulate_grasps", list(subjects = 1, grasps = 17, objects = 1, trials = 2, seed = 1))
  expect_true(ok$ok)
  expect_s3_class(ok$value, "grasps")
  expect_length(ok$value, 2L)
  expect_length(ok$warnings, 0L)

  bad <- py_call("simulate_grasps", list(subjects = -1))
  expect_false(bad$ok)
  expect_true("handmotion_error_bad_input" %in% bad$class)
  expect_match(bad$message, "subjects")
  # no ANSI escapes reach Python
  expect_false(grepl("\033[", bad$message, fixed = TRUE))

  warned <- py_call(function(x) {
    hm_warn("a planted warning", "degenerate_data")
    warning("a base warning")
    x + 1
  }, list(x = 1))
  expect_true(warned$ok)
  expect_identical(warned$value, 2)
  expect_length(warned$warnings, 2L)
  expect_identical(warned$warnings[[1]]$message, "a planted warning")
  expect_true("handmotion_warning_degenerate_data" %in% warned$warnings[[1]]$class)
  expect_identical(warned$warnings[[2]]$message, "a base warning")

  # a warning before an error is kept with the error
  both <- py_call(function() {
    warning("first")
    stop("then")
  }, list())
  expect_false(both$ok)
  expect_identical(both$message, "then")
  expect_identical(both$warnings[[1]]$message, "first")
})

test_that("py_grasps_out() and py_grasps_in() are inverse, keeping label levels, meta and glove", {
  x <- simulate_grasps(subjects = 2, grasps = c(mug = 9, ball = 17), objects = 1, trials = 2, seed = 2,
                       glove = "resistive")
  # uneven lengths, so a wrong offset between recordings would show
  expect_gt(length(unique(x$meta$n_frames)), 1L)
  flat <- py_grasps_out(x)
  expect_identical(length(flat$values), sum(x$meta$n_frames) * length(x$dofs))
  expect_false(is.factor(flat$meta$grasp))
  back <- py_grasps_in(flat$values, flat$n_frames, flat$meta[setdiff(names(flat$meta), "n_frames")],
                       flat$dofs, flat$rate, flat$unit, levels = flat$levels, glove = flat$glove,
                       glove_name = flat$glove_name)
  expect_s3_class(back, "grasps")
  expect_identical(back$recordings, x$recordings)
  expect_identical(levels(back$meta$grasp), levels(x$meta$grasp))
  expect_identical(as.character(back$meta$grasp), as.character(x$meta$grasp))
  expect_identical(back$meta$id, x$meta$id)
  expect_identical(back$glove$channels, x$glove$channels)
  expect_identical(c(back$rate, back$unit), c(x$rate, x$unit))
})

test_that("the recordings' switch states cross the bridge both ways", {
  g <- read_graspdb14(system.file("extdata", "graspdb14", "00_calib-rad-su01.txt", package = "handmotion"))
  flat <- py_grasps_out(g)
  expect_identical(flat$switch[[1]], attr(g$recordings[[1]], "switch"))
  back <- py_grasps_in(flat$values, flat$n_frames, flat$meta[setdiff(names(flat$meta), "n_frames")],
                       flat$dofs, flat$rate, flat$unit, levels = flat$levels, switch = flat$switch)
  expect_identical(segment_by_switch(back)$meta$n_frames, segment_by_switch(g)$meta$n_frames)
  # one state per frame, or a classed error
  expect_error(py_grasps_in(flat$values, flat$n_frames, flat$meta[setdiff(names(flat$meta), "n_frames")],
                            flat$dofs, flat$rate, flat$unit, switch = list(flat$switch[[1]][-1])),
               class = "handmotion_error_bad_input")
  # recordings without a switch stay without one
  x <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
  expect_null(py_grasps_out(x)$switch[[1]])
})

test_that("py_grasps_in() validates through grasps()", {
  expect_error(py_grasps_in(c(1, NaN), 1L, data.frame(id = "a"), c("a", "b"), 50, "deg"),
               class = "handmotion_error_bad_input")
})

test_that("py_grasps_in() refuses counts that do not match the values, before cutting them apart", {
  meta <- data.frame(id = c("a", "b"))
  # one value short, one too many: both named, with the arithmetic
  expect_error(py_grasps_in(as.double(1:9), c(2L, 3L), meta, c("x", "y"), 50, "deg"),
               class = "handmotion_error_bad_input", regexp = "5 frames of 2 DoFs are 10 values, not 9")
  expect_error(py_grasps_in(as.double(1:11), c(2L, 3L), meta, c("x", "y"), 50, "deg"),
               class = "handmotion_error_bad_input", regexp = "not 11")
  # counts that are not counts (what the C routine must never see)
  for (bad in list(c(2L, NA), c(-1L, 6L), c(2.5, 2.5), "5")) {
    expect_error(py_grasps_in(as.double(1:10), bad, meta, c("x", "y"), 50, "deg"),
                 class = "handmotion_error_bad_input", regexp = "n_frames")
  }
  expect_error(py_grasps_in(as.double(1:10), c(2L, 3L), meta, character(), 50, "deg"),
               class = "handmotion_error_bad_input", regexp = "dofs")
  # counts Python sends as doubles, values as integers: the same recordings
  # (column-major, recording after recording)
  x <- py_grasps_in(1:10, c(2, 3), meta, c("x", "y"), 50, "deg")
  expect_identical(unname(x$recordings[[1]]), matrix(c(1, 2, 3, 4), 2))
  expect_identical(unname(x$recordings[[2]]), matrix(5:10 + 0, 3))
})

test_that("the small helpers answer what Python asks", {
  expect_identical(py_default_dofs(16L), hust_dofs$name)
  expect_identical(py_default_dofs(3L), paste0("dof", 1:3))
  x <- simulate_grasps(subjects = 2, grasps = c(11, 17), objects = 2, trials = 2, seed = 1)
  ms <- fit_grasp_models(x, seed = 1)
  expect_setequal(py_fitted_types(ms), c("Power Sphere", "Index Finger Extension"))
  dep <- py_dependence_matrix(ms[["Power Sphere"]])
  expect_identical(dim(dep), c(16L, 16L))
  expect_equal(unname(diag(dep)), rep(1, 16))
})

test_that("py_widget_html() gives the widget as one self-contained page", {
  skip_if_not(rmarkdown::pandoc_available("1.12.3"), "pandoc is not available")
  x <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
  page <- py_widget_html(hand_3d(x))
  expect_length(page, 1L)
  expect_match(page, "<html", fixed = TRUE)
  # self-contained: no script is loaded from a file beside the page
  expect_false(grepl("<script src=\"(?!data:)[^\"]*\\.js\"", page, perl = TRUE))
})

test_that("print_text is what print() writes, and writes nothing itself", {
  g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
  out <- capture.output(lines <- python_bridge("print_text", g))
  expect_identical(out, character(0))
  expect_identical(lines, capture.output(print(g)))
})
