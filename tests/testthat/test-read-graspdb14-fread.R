# The numbers of well-formed GraspDB14 files come from data.table::fread(),
# several files per call (R/read-graspdb14-fread.R); every other file goes to
# the text parser. Planted truth: the text parser's reading of the same file.

test_that("fread and the text parser read the real samples to identical numbers", {
  dir <- dirname(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  files <- list.files(dir, pattern = "[0-9][.]txt$", full.names = TRUE)
  fast <- graspdb14_fread_many(files)
  for (i in seq_along(files)) {
    expect_false(is.null(fast[[i]]), label = basename(files[i]))
    text <- graspdb14_text_fields(files[i])
    expect_identical(fast[[i]]$values, text$values)
    expect_identical(fast[[i]]$line_no, text$line_no)
  }
})

test_that("files written by write_graspdb14() go through fread in one call, to the written values", {
  g <- simulate_grasps(subjects = 1, grasps = 1:4, objects = 1, trials = 2, rate = 60, seed = 2)
  recs <- lapply(g$recordings, function(m) (m[, c(1:16, 1:7)] * pi / 180))
  x <- grasps(recs, meta = data.frame(id = g$meta$id, grasp = as.integer(g$meta$grasp), subject = "su01",
                                      object = graspdb14_objects$name[1], trial = seq_along(recs)),
              dofs = cyberglove_sensors$name, rate = 60, unit = "rad")
  files <- write_graspdb14(x, withr::local_tempdir())
  fast <- graspdb14_fread_many(files)
  expect_false(any(vapply(fast, is.null, logical(1))))
  for (i in seq_along(files)) expect_identical(fast[[i]]$values, graspdb14_text_fields(files[i])$values)
  back <- read_graspdb14(dirname(files[1]))
  expect_equal(unname(back$recordings[[3]]), unname(round(recs[[3]], 5)), ignore_attr = TRUE, tolerance = 1e-12)
})

test_that("a bad file among good ones is found alone: the others are read, it is reported by line", {
  dir <- withr::local_tempdir()
  rows <- graspdb14_row_text(8)
  names <- sprintf("01_ex01-rad-%03d-grasp-su01.txt", 1:7)
  paths <- vapply(names, function(n) write_fixture(dir, n, rows), "")
  short <- rows
  short[5] <- sub(" [^ ]+ $", " ", short[5])   # 29 fields: plain characters, fread refuses the group
  write_fixture(dir, names[4], short)
  hidden <- rows
  hidden[2] <- sub(" 1 ", " 1 NaN ", sub(" [^ ]+ $", " ", hidden[2]))  # not plain: text parser
  write_fixture(dir, names[6], hidden)
  fast <- graspdb14_fread_many(unname(paths))
  expect_identical(vapply(fast, is.null, logical(1)), c(FALSE, FALSE, FALSE, TRUE, FALSE, TRUE, FALSE))
  # fread refusing a group leaves it able to read the next one
  expect_identical(graspdb14_fread_many(paths[[1]])[[1]]$values, fast[[1]]$values)
  expect_warning(g <- read_graspdb14(dir), class = "handmotion_warning_read_failures")
  expect_length(g, 5)
  f <- read_failures(g)
  expect_identical(basename(f$file), names[c(4, 6)])
  expect_identical(f$class, c("handmotion_error_bad_field_count", "handmotion_error_non_numeric"))
  expect_identical(f$line, c(5L, 2L))
})

test_that("a switch or time stamp fread reads as a number is still checked, by line", {
  dir <- withr::local_tempdir()
  rows <- graspdb14_row_text(6, switch = c(1, 1, 1, 2, 1, 1))
  p <- write_fixture(dir, "01_ex01-rad-001-grasp-su01.txt", rows)
  expect_false(is.null(graspdb14_fread_many(p)[[1]]))
  err <- expect_error(read_graspdb14(p), class = "handmotion_error_bad_value")
  expect_identical(err$line, 4L)
})

test_that("the plain files of a group are concatenated, each line ended, the others left out", {
  dir <- withr::local_tempdir()
  a <- write_fixture(dir, "a.txt", c("1 2", "3 4"))                      # 2 lines
  b <- write_fixture(dir, "b.txt", c("5 6e-1", "-7\t+8"), final_eol = FALSE)  # last line open
  c <- write_fixture(dir, "c.txt", c("# a comment", "1 2"))              # not plain
  d <- write_fixture(dir, "d.txt", c("9 10\r"))                           # CR: plain bytes
  e <- file.path(dir, "e.txt")
  file.create(e)                                                         # empty
  sub <- file.path(dir, "sub.txt")
  dir.create(sub)                                                        # a folder
  files <- c(a, b, c, d, e, sub, file.path(dir, "missing.txt"))
  size <- graspdb14_readable_size(files)
  expect_identical(size, c(8, 12, 16, 6, 0, 0, 0))
  got <- graspdb14_plain_text(files, size)
  expect_identical(got$n_lines, c(2, 2, NA, 1, NA, NA, NA))
  expect_identical(got$text, "1 2\n3 4\n5 6e-1\n-7\t+8\n9 10\r\n")
  expect_identical(graspdb14_plain_text(c, 16)$text, "")
})

test_that("a file whose rows sum past the largest double is still read, to the same numbers", {
  # fread's rows are checked for finite values through their sums: a row of
  # finite values whose sum overflows sends its file to the text parser
  dir <- withr::local_tempdir()
  v <- matrix(round(seq_len(4 * 23) / 1000, 5), 4, 23, byrow = TRUE)
  v[2, 1:2] <- 1.5e308
  p <- write_fixture(dir, "01_ex01-rad-001-grasp-su01.txt", graspdb14_row_text(4, values = v))
  q <- write_fixture(dir, "01_ex01-rad-002-grasp-su01.txt", graspdb14_row_text(4))
  fast <- graspdb14_fread_many(c(p, q))
  expect_null(fast[[1]])
  expect_false(is.null(fast[[2]]))
  g <- read_graspdb14(dir)
  expect_identical(read_failures(g)$file, character())
  expect_identical(unname(g$recordings[[1]][2, 1:2]), c(1.5e308, 1.5e308))
  expect_equal(unname(g$recordings[[1]][-2, ]), v[-2, ], tolerance = 1e-12)
})
