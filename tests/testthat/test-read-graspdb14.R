# ---- the real GraspDB14 samples (read in place, skipped when absent) ----

test_that("the controlled-transport sample reads with its metadata and ~60 Hz", {
  f <- shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt")
  g <- read_graspdb14(f)
  expect_s3_class(g, "grasps")
  expect_length(g, 1)
  expect_equal(dim(g$recordings[[1]]), c(282L, 23L))
  expect_identical(g$dofs, cyberglove_sensors$name)
  m <- g$meta
  expect_identical(as.integer(m$grasp), 11L)
  expect_identical(as.character(m$grasp), "Power Sphere")
  expect_identical(m$object_id, 1L)
  expect_match(m$object, "Tennis ball")
  expect_identical(m$subject, "4")
  expect_identical(m$subject_id, 4L)
  expect_identical(m$trial, 4L)
  expect_identical(m$scenario, "3")
  expect_identical(g$unit, "rad")
  # 281 intervals over 4.68 s: 60.04 Hz (the MATLAB tool's n / elapsed would give 60.26)
  expect_equal(g$rate, 60.04, tolerance = 0.001)
  expect_equal(m$duration, 4.68, tolerance = 1e-6)
  expect_true(abs(g$rate - 60) < 1)
  expect_identical(attr(g$recordings[[1]], "switch"), rep(1L, 282))
  # first value of the file: T-TMJ at frame 1
  expect_equal(g$recordings[[1]][[1, "T-TMJ"]], -0.68112)
  expect_equal(g$recordings[[1]][[1, "W-AA"]], 0.11760)
  expect_equal(nrow(read_failures(g)), 0)
})

test_that("the calibration stream has 20 or 21 switch segments and parses fast", {
  f <- shared_file("data", "graspdb14", "00_calib-rad-su01.txt")
  g <- read_graspdb14(f)
  expect_identical(g$meta$scenario, "calib")
  expect_identical(g$meta$subject, "1")
  expect_true(is.na(g$meta$grasp))
  expect_equal(g$meta$n_frames, 6674L)
  expect_equal(sum(attr(g$recordings[[1]], "switch") == 0), 1909)
  expect_true(nrow(switch_segments(attr(g$recordings[[1]], "switch"))) %in% 20:21)
  expect_true(length(segment_by_switch(g)) %in% 20:21)
  expect_equal(g$rate, 60, tolerance = 0.01)
})

test_that("a directory of the real samples reads every motion file and the annotation", {
  dir <- dirname(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  g <- read_graspdb14(dir)
  expect_length(g, 6)
  expect_equal(nrow(read_failures(g)), 0)
  m <- g$meta
  ex02 <- m[m$scenario == "2", ]
  expect_identical(ex02$action, "interact")
  expect_identical(ex02$hand, "right")
  expect_identical(ex02$action_code, "i_r")
  expect_match(ex02$object, "Pen")
  expect_setequal(m$scenario, c("calib", "1", "2", "3"))
  # per-file rates are kept, the set's rate is their median
  expect_equal(g$rate, round(stats::median(m$file_rate), 2))
  expect_true(all(abs(m$file_rate - 60) < 1))
  expect_s3_class(m$start_time, "POSIXct")
  ann <- attr(g, "annotations")
  expect_equal(nrow(ann), 5)
  expect_identical(unique(ann$id), "01_11_ex03-rad-004-grasp-su04")
  expect_equal(max(ann$end), m$n_frames[m$id == "01_11_ex03-rad-004-grasp-su04"])
})

# ---- file names ----

test_that("all documented file-name patterns are decoded", {
  dir <- withr::local_tempdir()
  rows <- graspdb14_row_text(4)
  names <- c("01_ex01-rad-002-grasp-su01.txt", "01_i_r_ex02-raw-025-grasp-su01.txt",
             "01_11_ex03-1-rad-001-grasp-su04.txt", "00_calib-rad-su01.txt",
             "09_O_L_EX02-rad-003-GRASP-SU07.TXT", "12_06_ex03-rad-010-grasp-su10.txt ")
  for (n in names) write_fixture(dir, trimws(n), rows)
  info <- lapply(file.path(dir, trimws(names)), parse_graspdb14_name)
  expect_identical(vapply(info, `[[`, "", "scenario"), c("1", "2", "3", "calib", "2", "3"))
  expect_identical(vapply(info, `[[`, 1L, "grasp_id"), c(NA, NA, 11L, NA, NA, 6L))
  expect_identical(vapply(info, `[[`, 1L, "subject_id"), c(1L, 1L, 4L, 1L, 7L, 10L))
  expect_identical(vapply(info, `[[`, 1L, "trial"), c(2L, 25L, 1L, NA, 3L, 10L))
  expect_identical(vapply(info, `[[`, "", "datatype"), c("rad", "raw", "rad", "rad", "rad", "rad"))
  expect_identical(info[[3]]$variant, "1")
  expect_identical(info[[2]]$action, "interact")
  expect_identical(info[[5]]$action, "open")
  expect_identical(info[[5]]$hand, "left")
  expect_identical(info[[5]]$object, "Oval jar")
  expect_true(is.na(info[[4]]$object))
})

test_that("unknown file-name patterns are classed errors naming the file", {
  dir <- withr::local_tempdir()
  rows <- graspdb14_row_text(3)
  bad <- c("motion.txt", "01_ex04-rad-001-grasp-su01.txt", "01_ex03-rad-001-grasp-su01.txt",
           "01_11_ex01-rad-001-grasp-su01.txt", "01_99_ex03-rad-001-grasp-su01.txt",
           "01_ex01-deg-001-grasp-su01.txt")
  for (n in bad) {
    p <- write_fixture(dir, n, rows)
    err <- expect_error(read_graspdb14(p), class = "handmotion_error_unknown_file_name")
    expect_s3_class(err, "handmotion_error_bad_file")
    expect_identical(err$file, p)
    expect_true(is.na(err$line))
    expect_match(conditionMessage(err), n, fixed = TRUE)
  }
})

# ---- content: liberal where the format allows, strict where it does not ----

test_that("CRLF, tabs, trailing and leading blanks, blank lines and no final newline are fine", {
  dir <- withr::local_tempdir()
  rows <- graspdb14_row_text(6)
  ref <- read_graspdb14(write_fixture(dir, "01_ex01-rad-001-grasp-su01.txt", rows))
  messy <- paste0("  ", gsub(" 1 ", "\t1\t", rows), "   ")
  messy <- append(messy, "", after = 3)
  p <- write_fixture(file.path(dir, "m"), "01_ex01-rad-001-grasp-su01.txt", messy,
                     eol = "\r\n", final_eol = FALSE)
  g <- read_graspdb14(p)
  expect_equal(unname(g$recordings[[1]]), unname(ref$recordings[[1]]), ignore_attr = TRUE)
  expect_equal(g$meta$n_frames, 6L)
  p2 <- write_fixture(file.path(dir, "cr"), "01_ex01-rad-001-grasp-su01.txt", rows, eol = "\r")
  expect_equal(read_graspdb14(p2)$meta$n_frames, 6L)
})

test_that("raw files read with unit raw", {
  dir <- withr::local_tempdir()
  vals <- matrix(sample(0:255, 4 * 23, replace = TRUE), 4, 23)
  lines <- sprintf("2014 09 12 08 49 %08.5f 1 %s", 21.712 + 0:3 * 0.016,
                   apply(vals, 1, paste, collapse = " "))
  # raw counts of named CyberGlove sensors: drawn through a guessed map, said once
  expect_warning(g <- read_graspdb14(write_fixture(dir, "01_ex01-raw-002-grasp-su01.txt", lines)),
                 class = "handmotion_warning_guessed_glove")
  expect_identical(g$unit, "raw")
  expect_equal(unname(g$recordings[[1]]), vals, ignore_attr = TRUE)
})

test_that("bad content gives classed errors naming file and line", {
  dir <- withr::local_tempdir()
  name <- "01_ex01-rad-001-grasp-su01.txt"
  rows <- graspdb14_row_text(5)
  check <- function(lines, class, line, ...) {
    p <- write_fixture(file.path(dir, class), name, lines, ...)
    err <- expect_error(read_graspdb14(p), class = paste0("handmotion_error_", class))
    expect_s3_class(err, "handmotion_error_bad_file")
    expect_identical(err$file, p)
    expect_identical(err$line, as.integer(line))
    expect_match(conditionMessage(err), name, fixed = TRUE)
    err
  }
  wrong <- rows
  wrong[3] <- sub(" [^ ]+ $", " ", wrong[3])          # 29 fields in the middle
  e <- check(wrong, "bad_field_count", 3)
  expect_match(conditionMessage(e), "29 fields")
  nonnum <- rows
  nonnum[4] <- sub("1 ", "1 abc ", sub(" [^ ]+ $", " ", nonnum[4]))
  e <- check(nonnum, "non_numeric", 4)
  expect_identical(e$field, 8L)
  trunc <- rows
  trunc[5] <- substr(trunc[5], 1, 60)
  check(trunc, "truncated_line", 5, final_eol = FALSE)
  check(character(), "empty_file", NA)
  check(c("", "   ", ""), "empty_file", 3)
  sw <- rows
  sw[2] <- sub(" 1 ", " 2 ", sw[2])
  check(sw, "bad_value", 2)
  date <- rows
  date[1] <- sub("2014 09 15", "2014 13 15", date[1])
  check(date, "bad_value", 1)
  nan <- rows
  nan[2] <- sub(" [^ ]+ $", " NaN ", nan[2])
  check(nan, "non_numeric", 2)
})

test_that("a truncated last line can be dropped, and that is recorded", {
  dir <- withr::local_tempdir()
  rows <- graspdb14_row_text(5)
  rows[5] <- substr(rows[5], 1, 60)
  p <- write_fixture(dir, "01_ex01-rad-001-grasp-su01.txt", rows, final_eol = FALSE)
  expect_warning(g <- read_graspdb14(p, truncated = "drop"), class = "handmotion_warning_truncated_line")
  expect_equal(g$meta$n_frames, 4L)
  expect_true(g$meta$dropped_last_line)
})

test_that("a directory with broken files reads the good ones and names each broken one", {
  dir <- withr::local_tempdir()
  good <- graspdb14_row_text(8)
  write_fixture(dir, "01_ex01-rad-001-grasp-su01.txt", good)
  write_fixture(dir, "01_11_ex03-rad-002-grasp-su01.txt", good)
  short <- good
  short[6] <- "2014 09 15 08 02 09.1 1 0.1"
  write_fixture(dir, "02_ex01-rad-003-grasp-su01.txt", short)
  write_fixture(dir, "03_ex01-rad-004-grasp-su01.txt", character())
  write_fixture(dir, "readme.txt", "hello")
  text <- good
  text[2] <- sub(" 1 ", " x ", text[2])
  write_fixture(dir, "04_ex01-rad-005-grasp-su01.txt", text)
  write_fixture(dir, "notes.md", "not matched by the pattern")
  expect_warning(g <- read_graspdb14(dir), class = "handmotion_warning_read_failures")
  expect_length(g, 2)
  expect_setequal(g$meta$id, c("01_ex01-rad-001-grasp-su01", "01_11_ex03-rad-002-grasp-su01"))
  f <- read_failures(g)
  expect_identical(f, attr(g, "failures"))
  expect_equal(nrow(f), 4)
  f <- f[order(basename(f$file)), ]
  expect_identical(basename(f$file), c("02_ex01-rad-003-grasp-su01.txt", "03_ex01-rad-004-grasp-su01.txt",
                                       "04_ex01-rad-005-grasp-su01.txt", "readme.txt"))
  expect_identical(f$class, paste0("handmotion_error_",
                                   c("bad_field_count", "empty_file", "non_numeric", "unknown_file_name")))
  expect_identical(f$line, c(6L, NA, 2L, NA))
  expect_true(all(nzchar(f$message)))
  # the warning names the broken files
  w <- tryCatch(read_graspdb14(dir), warning = function(w) w)
  expect_match(conditionMessage(w), "4 of 6 files")
  expect_match(conditionMessage(w), "readme.txt", fixed = TRUE)
})

test_that("a directory whose files all fail is an error carrying the report", {
  dir <- withr::local_tempdir()
  write_fixture(dir, "junk.txt", "x")
  err <- expect_error(suppressWarnings(read_graspdb14(dir)), class = "handmotion_error_no_files")
  expect_equal(nrow(err$failures), 1)
  expect_error(read_graspdb14(file.path(dir, "nope.txt")), class = "handmotion_error_file_not_found")
})

test_that("mixed rad and raw files: the rad files are read, the raw ones reported", {
  dir <- withr::local_tempdir()
  write_fixture(dir, "01_ex01-rad-001-grasp-su01.txt", graspdb14_row_text(4))
  raw <- sprintf("2014 09 12 08 49 %08.5f 1 %s", 21.712 + 0:3 * 0.016, paste(rep(100, 23), collapse = " "))
  write_fixture(dir, "01_ex01-raw-001-grasp-su01.txt", raw)
  expect_warning(g <- read_graspdb14(dir), class = "handmotion_warning_read_failures")
  expect_identical(g$unit, "rad")
  expect_identical(read_failures(g)$class, "skipped_datatype")
  expect_no_warning(g2 <- read_graspdb14(dir, datatype = "raw"))
  expect_identical(g2$unit, "raw")
  expect_identical(read_failures(g2)$class, "skipped_datatype")
  expect_length(g2, 1)
})

test_that("a single-frame file falls back to the nominal rate and says so", {
  dir <- withr::local_tempdir()
  g <- read_graspdb14(write_fixture(dir, "01_ex01-rad-001-grasp-su01.txt", graspdb14_row_text(1)))
  expect_equal(g$rate, 60)
  expect_match(g$meta$rate_source, "nominal")
})

test_that("the shipped examples read", {
  dir <- system.file("extdata", "graspdb14", package = "handmotion")
  skip_if(dir == "")
  # the report discards the I-AA sensor: it never changes, and is flagged as stuck
  expect_warning(g <- read_graspdb14(dir), "I-AA", class = "handmotion_warning_stuck_channels")
  expect_equal(stuck_channels(g), "I-AA")
  expect_length(g, 5)
  expect_identical(sort(g$meta$scenario), c("1", "2", "3", "3", "calib"))
  expect_identical(g$meta$variant[g$meta$grasp_id %in% 2L], "1")
})
