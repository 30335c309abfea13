# Files as labs keep them: a folder per label, the same file name in several
# folders, time stamps in a column with unevenly spaced frames; and the
# shipped real flexglove recordings read in one line.

test_that("a folder per label: labels from folders, repeated file names give unique ids", {
  dir <- withr::local_tempdir()
  m <- matrix(1:12, 4, 3)
  for (rel in c("pen/P1_a_1.csv", "cup/P1_a_1.csv", "cup/P2_b_2.csv")) {
    write_fixture(file.path(dir, dirname(rel)), basename(rel),
                  c("a,b,c", apply(m, 1, paste, collapse = ",")))
  }
  g <- read_glove(dir, glove = tiny_glove(), pattern = "^(?<grasp>[^/]+)/(?<subject>P\\d)_")
  expect_length(g, 3)
  expect_identical(nrow(read_failures(g)), 0L)
  expect_identical(g$meta$id, c("cup/P1_a_1", "cup/P2_b_2", "pen/P1_a_1"))
  expect_identical(as.character(g$meta$grasp), c("cup", "cup", "pen"))
  expect_identical(g$meta$subject, c("P1", "P2", "P1"))
  expect_identical(g$rate, 50)
  # without a pattern (sub-folders asked for): still no error, ids unique
  h <- read_glove(dir, glove = tiny_glove(), recursive = TRUE)
  expect_identical(h$meta$id, g$meta$id)
  # files named one by one from two folders: the full paths
  two <- file.path(dir, c("pen/P1_a_1.csv", "cup/P1_a_1.csv"))
  k <- read_glove(two, glove = tiny_glove())
  expect_identical(k$meta$id, sub("\\.csv$", "", normalizePath(two, winslash = "/")))
})

test_that("bad time columns and unmatched folder patterns are classed errors naming the file", {
  dir <- withr::local_tempdir()
  m <- matrix(1:9, 3, 3)
  good <- write_timed(dir, "pen/ok.csv", c(0, 30, 60), m)
  no_time <- write_fixture(file.path(dir, "pen"), "no_time.csv",
                           c("a,b,c", apply(m, 1, paste, collapse = ",")))
  back <- write_timed(dir, "cup/back.csv", c(0, 30, 30), m)
  odd <- write_timed(dir, "loose.csv", c(0, 30, 60), m)
  g <- suppressWarnings(read_glove(dir, glove = tiny_glove(), time = "time_ms",
                                   pattern = "^(?<grasp>[^/]+)/"))
  # (the only file read; names that do not repeat stay plain ids)
  expect_identical(g$meta$id, "ok")
  f <- read_failures(g)
  expect_setequal(basename(f$file), c("no_time.csv", "back.csv", "loose.csv"))
  row <- function(name) f[basename(f$file) == name, ]
  expect_identical(row("no_time.csv")$class, "handmotion_error_missing_column")
  expect_identical(row("no_time.csv")$line, 1L)
  expect_identical(row("back.csv")$class, "handmotion_error_bad_time")
  expect_identical(row("back.csv")$line, 4L)
  expect_identical(row("loose.csv")$class, "handmotion_error_unknown_file_name")
  expect_match(row("loose.csv")$message, "loose")
  expect_warning(read_glove(dir, glove = tiny_glove(), time = "time_ms", pattern = "^(?<grasp>[^/]+)/"),
                 class = "handmotion_warning_read_failures")
  # one file: the error itself, naming the file
  err <- expect_error(read_glove(back, glove = tiny_glove(), time = "time_ms"),
                      class = "handmotion_error_bad_time")
  expect_identical(err$file, back)
  expect_identical(err$line, 4L)
  err <- expect_error(read_glove(no_time, glove = tiny_glove(), time = "time_ms"),
                      class = "handmotion_error_missing_column")
  expect_match(conditionMessage(err), "no_time.csv")
  expect_error(read_glove(dir, glove = tiny_glove(), time = NA), class = "handmotion_error_bad_input")
  expect_error(read_glove(dir, glove = tiny_glove(), recursive = "yes"), class = "handmotion_error_bad_input")
})

test_that("the shipped flexglove recordings read in one line, no manifest", {
  dir <- system.file("extdata", "flexglove", package = "handmotion")
  skip_if(!nzchar(dir), "flexglove extdata not installed")
  expect_false(file.exists(file.path(dir, "manifest.csv")))
  # the one-liner of ?read_glove
  g <- read_glove(system.file("extdata", "flexglove", package = "handmotion"), glove = "flexglove", time = "time_ms", pattern = "^(?<grasp>[^/]+)/(?<subject>P\\d)_(?<object>[a-z]+)_(?<trial>\\d+)$")
  expect_length(g, 626)
  expect_identical(nrow(read_failures(g)), 0L)
  expect_false(anyDuplicated(g$meta$id) > 0)
  folders <- setdiff(list.dirs(dir, full.names = FALSE, recursive = FALSE), "")
  expect_length(folders, 8)
  # folder names are Feix types: the labels are those types (grasps() labels)
  labels <- unique(as.character(g$meta$grasp))
  expect_setequal(tolower(labels), tolower(gsub("_", " ", folders)))
  expect_identical(sort(unique(g$meta$subject)), c("P1", "P2"))
  expect_identical(as.vector(table(g$meta$subject)), c(362L, 264L))
  # counts unchanged at the first frame (the grid starts at the first time)
  raw <- utils::read.csv(file.path(dir, "Ventral", "P1_pen_1.csv"))
  expect_equal(unname(g$recordings[["Ventral/P1_pen_1"]][1, ]), unname(unlist(raw[1, -1])))
  expect_equal(g$rate, 1000 / 30)
  expect_identical(g$glove$name, "flexglove")
  # the project's copy of the source (times in files of their own) reads to
  # the same set: the shipped files hold its values unchanged
  shared <- file.path(Sys.getenv("HANDMOTION_SHARED", "/work/shared"), "data", "flexglove")
  skip_if_not(dir.exists(shared), "the shared flexglove copy is not on this machine")
  expect_warning(
    s <- read_glove(shared, glove = "flexglove", time = "time_ms", timestamps = "timestamps",
                    pattern = "^(?<grasp>[^/]+)/(?<subject>P\\d)_(?<object>[a-z]+)_(?<trial>\\d+)$"),
    "excluded_synthetic", class = "handmotion_warning_read_failures")
  # (its list of left-out files sits beside the folders: reported, not read)
  expect_identical(basename(read_failures(s)$file), "excluded_synthetic.csv")
  expect_identical(s$meta$id, g$meta$id)
  expect_identical(s$rate, g$rate)
  expect_identical(unname(s$recordings), unname(g$recordings))
})

test_that("the flexglove profile: 6 raw channels 0-1023, flexion lowers the count", {
  p <- glove_profile("flexglove")
  ch <- p$channels
  expect_identical(ch$channel, paste0("flex", 1:6))
  expect_true(all(ch$unit == "raw" & ch$min == 0 & ch$max == 1023 & ch$sign == -1))
  # through the nominal map and the sign: a lower count is more flexion
  map <- nominal_map(ch)
  flexion <- function(count) ch$sign * (map$gain * count + map$offset)
  expect_true(all(flexion(80) > flexion(230)))
  expect_equal(flexion(230)[1:5], rep(0, 5))
  expect_equal(flexion(80)[1:5], rep(90, 5))
})
