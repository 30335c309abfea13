hust_csv_lines <- function(m, sep = ",", header = FALSE, dec = ".") {
  vals <- format(m, trim = TRUE, digits = 15)
  if (dec == ",") vals <- sub(".", ",", vals, fixed = TRUE)
  rows <- apply(vals, 1, paste, collapse = sep)
  if (header) c(paste(hust_dofs$name, collapse = sep), rows) else rows
}

test_that("a directory with a manifest data frame reads metadata and values", {
  h <- hust_fixture(3)
  dir <- withr::local_tempdir()
  for (i in 1:3) write_fixture(dir, sprintf("f%d.csv", i), hust_csv_lines(h$recordings[[i]]))
  man <- data.frame(file = sprintf("f%d.csv", 1:3), grasp = c("Power Sphere", "2", "inferior pincer"),
                    subject = c("S01", "S02", "S03"), object = c("ball", "pen", "cup"), trial = 1:3,
                    hand = "right")
  g <- read_hust(dir, manifest = man)
  expect_length(g, 3)
  expect_identical(g$dofs, hust_dofs$name)
  expect_identical(g$rate, 50)
  expect_identical(g$unit, "deg")
  expect_identical(as.integer(g$meta$grasp), c(11L, 2L, 33L))
  expect_identical(g$meta$subject, c("S01", "S02", "S03"))
  expect_identical(g$meta$trial, 1:3)
  expect_identical(g$meta$hand, rep("right", 3))
  expect_identical(g$meta$id, c("f1", "f2", "f3"))
  for (i in 1:3) expect_equal(unname(g$recordings[[i]]), unname(h$recordings[[i]]))
})

test_that("metadata can come from a regular expression with named groups", {
  h <- hust_fixture(2)
  dir <- withr::local_tempdir()
  write_fixture(dir, "s03_g11_o2_t1.csv", hust_csv_lines(h$recordings[[1]]))
  write_fixture(dir, "s04_g33_o1_t3.csv", hust_csv_lines(h$recordings[[2]]))
  g <- read_hust(dir, pattern = "^s(?<subject>\\d+)_g(?<grasp>\\d+)_o(?<object>\\d+)_t(?<trial>\\d+)$")
  expect_identical(as.integer(g$meta$grasp), c(11L, 33L))
  expect_identical(g$meta$subject, c("03", "04"))
  expect_identical(g$meta$object, c("2", "1"))
  expect_identical(g$meta$trial, c(1L, 3L))
  expect_error(read_hust(dir, pattern = "^(.*)$"), class = "handmotion_error_bad_input")
})

test_that("header or none, comma, semicolon with decimal comma, tabs, CRLF, quotes all read", {
  h <- hust_fixture(1)
  m <- h$recordings[[1]]
  dir <- withr::local_tempdir()
  variants <- list(
    plain = hust_csv_lines(m),
    header = hust_csv_lines(m, header = TRUE),
    semicolon = hust_csv_lines(m, sep = ";", dec = ","),
    semihead = hust_csv_lines(m, sep = ";", header = TRUE),
    tabs = hust_csv_lines(m, sep = "\t"),
    spaced = gsub(",", " , ", paste0(hust_csv_lines(m), ",  ")),
    quoted = c(paste0('"', hust_dofs$name, '"', collapse = ","), hust_csv_lines(m)),
    lower = c(tolower(paste(hust_dofs$name, collapse = ",")), "", hust_csv_lines(m))
  )
  for (v in names(variants)) {
    p <- write_fixture(dir, paste0(v, ".csv"), variants[[v]], eol = if (v == "header") "\r\n" else "\n")
    g <- read_hust(p)
    expect_equal(unname(g$recordings[[1]]), unname(m), label = v)
  }
})

test_that("a header naming the DoFs in another order puts columns back in order", {
  m <- hust_fixture(1)$recordings[[1]]
  perm <- c(16:1)
  lines <- c(paste(hust_dofs$name[perm], collapse = ","),
             apply(format(m[, perm], digits = 15, trim = TRUE), 1, paste, collapse = ","))
  dir <- withr::local_tempdir()
  g <- read_hust(write_fixture(dir, "rev.csv", lines))
  expect_equal(unname(g$recordings[[1]]), unname(m))
  expect_identical(colnames(g$recordings[[1]]), hust_dofs$name)
})

test_that("bad content gives classed errors naming file and line", {
  m <- hust_fixture(1)$recordings[[1]]
  good <- hust_csv_lines(m)
  dir <- withr::local_tempdir()
  check <- function(lines, class, line, ...) {
    p <- write_fixture(file.path(dir, class), "x.csv", lines, ...)
    err <- expect_error(read_hust(p), class = paste0("handmotion_error_", class))
    expect_s3_class(err, "handmotion_error_bad_file")
    expect_identical(err$file, p)
    expect_identical(err$line, as.integer(line))
    expect_match(conditionMessage(err), "x.csv", fixed = TRUE)
  }
  wrong <- good
  wrong[4] <- sub(",[^,]+$", "", wrong[4])
  check(wrong, "bad_field_count", 4)
  nonnum <- good
  nonnum[5] <- sub("^[^,]+", "n/a", nonnum[5])
  check(nonnum, "non_numeric", 5)
  trunc <- good
  trunc[length(trunc)] <- substr(trunc[length(trunc)], 1, 10)
  check(trunc, "truncated_line", length(good), final_eol = FALSE)
  check(character(), "empty_file", NA)
  check(paste(hust_dofs$name, collapse = ","), "empty_file", 1)
  p <- write_fixture(file.path(dir, "drop"), "x.csv", trunc, final_eol = FALSE)
  expect_warning(g <- read_hust(p, truncated = "drop"), class = "handmotion_warning_truncated_line")
  expect_equal(g$meta$n_frames, length(good) - 1L)
  expect_true(g$meta$dropped_last_line)
})

test_that("a directory with broken files and bad manifest rows reads the rest and reports each", {
  h <- hust_fixture(3)
  dir <- withr::local_tempdir()
  for (i in 1:3) write_fixture(dir, sprintf("f%d.csv", i), hust_csv_lines(h$recordings[[i]]))
  bad <- hust_csv_lines(h$recordings[[1]])
  bad[2] <- paste0(bad[2], ",99")
  write_fixture(dir, "broken.csv", bad)
  write_fixture(dir, "stray.csv", hust_csv_lines(h$recordings[[1]]))
  man <- data.frame(file = c("f1.csv", "f2.csv", "f3.csv", "broken.csv", "gone.csv"),
                    grasp = c("11", "Tripod", "Not A Grasp", "1", "2"), subject = "S1")
  # labels are the user's: "Not A Grasp" is a label like any other (the mix is said)
  expect_warning(expect_warning(g <- read_hust(dir, manifest = man), class = "handmotion_warning_read_failures"),
                 class = "handmotion_warning_mixed_labels")
  expect_identical(g$meta$id, c("f1", "f2", "f3"))
  expect_identical(as.character(g$meta$grasp), c("11", "Tripod", "Not A Grasp"))
  f <- read_failures(g)
  f <- f[order(basename(f$file)), ]
  expect_identical(basename(f$file), c("broken.csv", "gone.csv", "stray.csv"))
  expect_identical(f$class, paste0("handmotion_error_", c("bad_field_count", "file_not_found", "not_in_manifest")))
  expect_identical(f$line, c(2L, NA, NA))
})

test_that("pattern mismatches are reported per file; a single mismatching file is an error", {
  h <- hust_fixture(2)
  dir <- withr::local_tempdir()
  write_fixture(dir, "s1_g11.csv", hust_csv_lines(h$recordings[[1]]))
  p <- write_fixture(dir, "other.csv", hust_csv_lines(h$recordings[[2]]))
  re <- "^s(?<subject>\\d+)_g(?<grasp>\\d+)$"
  expect_warning(g <- read_hust(dir, pattern = re), class = "handmotion_warning_read_failures")
  expect_identical(g$meta$id, "s1_g11")
  expect_identical(read_failures(g)$class, "handmotion_error_unknown_file_name")
  expect_error(read_hust(p, pattern = re), class = "handmotion_error_unknown_file_name")
})

test_that("a manifest CSV is found in the directory and its rate and unit are used", {
  h <- hust_fixture(2)
  dir <- withr::local_tempdir()
  for (i in 1:2) write_fixture(dir, sprintf("%03d.csv", i), hust_csv_lines(h$recordings[[i]]))
  write_fixture(dir, "manifest.csv", c("file,id,grasp,subject,rate,unit", "001.csv,007,3,S1,100,rad",
                                       "002.csv,008,4,S2,100,rad"))
  g <- read_hust(dir)
  expect_identical(g$meta$id, c("007", "008"))
  expect_identical(g$rate, 100)
  expect_identical(g$unit, "rad")
  expect_identical(read_hust(dir, rate = 50)$rate, 50)
  # one file of the directory, with the manifest: only its row
  one <- read_hust(file.path(dir, "002.csv"), manifest = file.path(dir, "manifest.csv"))
  expect_identical(one$meta$id, "008")
  expect_error(read_hust(dir, manifest = data.frame(name = "x")), class = "handmotion_error_bad_manifest")
  expect_error(read_hust(dir, manifest = data.frame(file = "001.csv"), pattern = "x"),
               class = "handmotion_error_bad_input")
})

test_that("the shipped example directory reads", {
  dir <- system.file("extdata", "hust", package = "handmotion")
  skip_if(dir == "")
  g <- read_hust(dir)
  expect_length(g, 4)
  expect_setequal(as.character(g$meta$grasp), c("Power Sphere", "Palmar Pinch"))
  expect_equal(nrow(read_failures(g)), 0)
})
