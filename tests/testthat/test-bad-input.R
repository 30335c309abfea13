# Bad input that used to give a silent wrong answer or a file the readers
# reject: each is now a classed error naming the offending argument,
# recording or line. (issue "Robust at scale": fix the class, not the example)

test_that("forward kinematics refuses duplicated DoF names", {
  x <- matrix(10, 2, 16, dimnames = list(NULL, hust_dofs$name))
  colnames(x)[6] <- colnames(x)[5]
  expect_error(forward_kinematics(x, hand_skeleton()), class = "handmotion_error_bad_input")
  expect_error(forward_kinematics(x, hand_skeleton()), "Repeated")
  expect_error(forward_kinematics(x[, 1:16], hand_skeleton(), unit = c("deg", "rad")),
               class = "handmotion_error_bad_input")
})

test_that("grasps() refuses missing ids instead of renaming every recording", {
  r <- list(matrix(1, 3, 2), matrix(2, 3, 2))
  expect_error(grasps(r, meta = data.frame(id = c("a", NA)), dofs = c("u", "v")),
               class = "handmotion_error_bad_input")
  expect_error(grasps(stats::setNames(r, c("a", "")), dofs = c("u", "v")),
               class = "handmotion_error_bad_input")
  # no ids at all still get r1, r2, ...
  expect_identical(grasps(r, dofs = c("u", "v"))$meta$id, c("r1", "r2"))
})

test_that("a model is not fitted to unlabelled recordings", {
  g <- simulate_grasps(subjects = 2, grasps = 9, objects = 2, trials = 2, seed = 1)
  g$meta$grasp[] <- NA
  expect_error(fit_grasp_model(g), class = "handmotion_error_no_labels")
  g2 <- simulate_grasps(subjects = 2, grasps = 9, objects = 2, trials = 2, seed = 1)
  g2$meta$grasp[1] <- NA
  expect_error(fit_grasp_model(g2), class = "handmotion_error_bad_input")
})

test_that("writers refuse what their readers would refuse", {
  g <- simulate_grasps(subjects = 1, grasps = 9, objects = 1, trials = 1, seed = 1)
  dir <- withr::local_tempdir()
  for (d in c(-1, 0, 2.5, 5, 18)) {
    expect_error(write_hust(g, dir, digits = d, overwrite = TRUE), class = "handmotion_error_bad_input")
  }
  expect_error(write_hust(g, dir, sep = c(",", ";")), class = "handmotion_error_bad_input")
  gd <- graspdb14_fixture_grasps()
  for (d in c(-1, 0, 2, 11)) {
    expect_error(write_graspdb14(gd, dir, digits = d, overwrite = TRUE), class = "handmotion_error_bad_input")
  }
  bad <- gd
  attr(bad$recordings[[1]], "switch") <- rep(2L, nrow(bad$recordings[[1]]))
  expect_error(write_graspdb14(bad, dir, overwrite = TRUE), class = "handmotion_error_bad_recording")
  bad <- gd
  tm <- (seq_len(nrow(bad$recordings[[1]])) - 1) / 60
  tm[3] <- NA
  attr(bad$recordings[[1]], "time") <- tm
  expect_error(write_graspdb14(bad, dir, overwrite = TRUE), class = "handmotion_error_bad_recording")
  attr(bad$recordings[[1]], "time") <- rev(sort(stats::na.omit(c(tm, 1))))
  expect_error(write_graspdb14(bad, dir, overwrite = TRUE), class = "handmotion_error_bad_recording")
  f <- withr::local_tempfile(fileext = ".bvh")
  for (s in list(NaN, 0, -1, Inf, "a")) {
    expect_error(write_bvh(g, f, scale = s), class = "handmotion_error_bad_input")
  }
})

test_that("GraspDB14 files whose time stamps do not move forward are refused, naming the line", {
  dir <- withr::local_tempdir()
  gd <- graspdb14_fixture_grasps()
  path <- write_graspdb14(gd[1], dir)
  lines <- readLines(path)
  swap <- lines
  swap[c(4, 5)] <- lines[c(5, 4)]          # backwards
  writeLines(swap, path)
  cnd <- tryCatch(read_graspdb14(path), handmotion_error = function(e) e)
  expect_s3_class(cnd, "handmotion_error_bad_file")
  expect_identical(cnd$line, 5L)
  same <- lines
  same[5] <- sub("^(\\S+ \\S+ \\S+ \\S+ \\S+ \\S+)", sub("^((\\S+ ){5}\\S+).*", "\\1", lines[4]), lines[5])
  writeLines(same, path)                    # repeated
  expect_error(read_graspdb14(path), class = "handmotion_error_bad_value")
  # in a directory read the bad file is reported and the good ones are read
  writeLines(lines, file.path(dir, sub("su", "su9", basename(path))))   # (a copy beside it, named apart)
  out <- suppressWarnings(read_graspdb14(dir))
  expect_length(out, 1L)
  expect_identical(nrow(read_failures(out)), 1L)
})

test_that("a file named raw that holds radians is refused", {
  dir <- withr::local_tempdir()
  gd <- graspdb14_fixture_grasps()
  path <- write_graspdb14(gd[1], dir)
  raw_name <- file.path(dir, sub("-rad-", "-raw-", basename(path)))
  file.rename(path, raw_name)
  expect_error(read_graspdb14(raw_name), class = "handmotion_error_bad_value")
  expect_error(read_graspdb14(raw_name), "fractional")
})

test_that("hand-over refuses a non-positive ridge or eps", {
  g <- simulate_grasps(subjects = 2, grasps = 1:2, objects = 1, trials = 1, seed = 1, plant_overlong = FALSE)
  for (r in list(0, -1, NA, "a")) {
    expect_error(fit_handover(g, n_markers = 3, ridge = r), class = "handmotion_error_bad_input")
    expect_error(fit_handover(g, n_markers = 3, eps = r), class = "handmotion_error_bad_input")
  }
})

test_that("pictures, pages and videos refuse NaN frames, a skeleton without a DoF's joint and empty sets before writing", {
  g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
  id <- g$meta$id
  nan <- g
  nan$recordings[[1]][5:7, "PIP2"] <- NaN
  # a skeleton whose index finger ends at the PIP joint: DIP2 has no joint to turn
  short <- hand_skeleton()
  short$joints <- short$joints[!short$joints$name %in% c("if-dip", "if-tip"), ]
  # an edited skeleton whose joint lost its parent
  torn <- hand_skeleton()
  torn$joints <- torn$joints[torn$joints$name != "if-dip", ]
  empty <- g[integer(0)]
  dir <- withr::local_tempdir()
  page <- file.path(dir, "hand.html")
  expect_error(hand_3d(nan), "frame 5", class = "handmotion_error_bad_recording")
  expect_error(hand_3d(nan), id, fixed = TRUE)
  expect_error(hand_3d(g, skeleton = short), "DIP2", class = "handmotion_error_bad_skeleton")
  expect_error(hand_3d(g, skeleton = torn), "if-tip", class = "handmotion_error_bad_skeleton")
  expect_error(hand_3d(empty), "no recordings", class = "handmotion_error_bad_recording")
  expect_error(hand_3d(list(a = g, b = empty)), "x$b", fixed = TRUE)
  expect_error(write_hand_animation(nan, page), id, class = "handmotion_error_bad_recording")
  expect_error(write_hand_animation(g, page, skeleton = short), "if-dip", class = "handmotion_error_bad_skeleton")
  expect_error(write_hand_animation(empty, page), class = "handmotion_error_bad_recording")
  pos <- forward_kinematics(g$recordings[[1]], hand_skeleton(), unit = g$unit)
  pos[3, 2, 1] <- NA
  expect_error(write_hand_animation(pos, page), "first frame 3", class = "handmotion_error_bad_recording")
  expect_false(file.exists(page))
  expect_error(autoplot(nan, type = "hand", frame = 6), id, class = "handmotion_error_bad_recording")
  expect_error(autoplot(g, type = "hand", skeleton = short), class = "handmotion_error_bad_skeleton")
  expect_error(autoplot(empty, type = "hand"), class = "handmotion_error_bad_recording")
  expect_error(autoplot(g, type = "poses", compare = list(generated = empty)), "x[[2]]", fixed = TRUE)
  expect_error(autoplot(nan, type = "poses"), class = "handmotion_error_bad_recording")
  skip_if_not_installed("gganimate")
  skip_if_not_installed("magick")
  gif <- file.path(dir, "hand.gif")
  expect_error(write_hand_animation(nan, gif), id, class = "handmotion_error_bad_recording")
  expect_error(write_hand_animation(g, gif, skeleton = short), class = "handmotion_error_bad_skeleton")
  expect_error(write_hand_animation(empty, gif), class = "handmotion_error_bad_recording")
  expect_false(file.exists(gif))
})

test_that("a directory read reads every good file and reports every bad one", {
  dir <- withr::local_tempdir()
  gd <- graspdb14_fixture_grasps()
  good <- write_graspdb14(gd, dir)
  lines <- readLines(good[1])
  name <- function(su) file.path(dir, sprintf("01_ex01-rad-002-grasp-su%02d.txt", su))
  writeLines(c("an unknown header", lines[-1]), name(71))                          # bad header
  writeLines(c(lines, substr(lines[length(lines)], 1, 12)), name(72))              # truncated last line
  writeBin(as.raw(0:255), name(73))                                                # binary
  dir.create(name(74))                                                             # a folder, not a file
  file.symlink(file.path(dir, "nowhere.txt"), name(75))                            # a broken link
  # truncated = "drop": the cut-off file is read (with its own warning), the rest reported
  out <- withCallingHandlers(read_graspdb14(dir, truncated = "drop"),
                             handmotion_warning = function(w) invokeRestart("muffleWarning"))
  expect_length(out, length(good) + 1L)
  f <- read_failures(out)
  expect_identical(basename(f$file), basename(name(c(71, 73, 74, 75))))
  expect_identical(f$class, c("handmotion_error_bad_field_count", "handmotion_error_not_text",
                              "handmotion_error_unreadable_file", "handmotion_error_unreadable_file"))
  expect_identical(f$line, c(1L, NA, NA, NA))
  expect_match(f$message[3], "folder")
  expect_match(f$message[4], "broken symbolic link")
  # the summary warning is classed and names them
  expect_warning(suppressWarnings(read_graspdb14(dir), classes = "handmotion_warning_truncated_line"),
                 "5 of 7 files", class = "handmotion_warning_read_failures")
  # when every file fails, the error is classed and carries the report
  bad <- withr::local_tempdir()
  writeBin(as.raw(0:255), file.path(bad, basename(good[1])))
  writeLines("x", file.path(bad, "b.txt"))
  cnd <- tryCatch(suppressWarnings(read_graspdb14(bad)), handmotion_error_bad_file = function(e) e)
  expect_s3_class(cnd, "handmotion_error_no_files")
  expect_identical(nrow(cnd$failures), 2L)
})

test_that("HUST directories: unreadable files, binary files and a binary manifest are classed", {
  g <- simulate_grasps(subjects = 1, grasps = 1:4, objects = 1, trials = 1, seed = 1)
  dir <- withr::local_tempdir()
  write_hust(g, dir)
  man <- utils::read.csv(file.path(dir, "manifest.csv"))
  writeBin(as.raw(0:255), file.path(dir, man$file[1]))
  unlink(file.path(dir, man$file[2]))
  dir.create(file.path(dir, man$file[2]))
  hl <- readLines(file.path(dir, man$file[3]))
  writeLines(c(hl, "1.5 2"), file.path(dir, man$file[3]))
  expect_warning(suppressWarnings(read_hust(dir, truncated = "drop"), classes = "handmotion_warning_truncated_line"),
                 "2 of 4 files", class = "handmotion_warning_read_failures")
  out <- suppressWarnings(read_hust(dir, truncated = "drop"))
  expect_identical(out$meta$id, man$id[3:4])
  expect_identical(read_failures(out)$class,
                   c("handmotion_error_not_text", "handmotion_error_unreadable_file"))
  # a binary manifest: a classed file error, not "invalid multibyte string"
  writeBin(as.raw(c(0x80, 0xff, 0xfe, 0x41, 0xc3, 0x28, 0x0a, 0x66)), file.path(dir, "manifest.csv"))
  expect_error(read_hust(dir), class = "handmotion_error_bad_manifest")
  writeBin(as.raw(c(0x80, 0xff, 0x00, 0x41)), file.path(dir, "manifest.csv"))
  expect_error(read_hust(dir), class = "handmotion_error_not_text")
  # all files bad: one classed error
  unlink(file.path(dir, man$file[2]), recursive = TRUE)
  for (f in man$file) writeBin(as.raw(0:255), file.path(dir, f))
  write.csv(man, file.path(dir, "manifest.csv"), row.names = FALSE)
  expect_error(suppressWarnings(read_hust(dir)), class = "handmotion_error_no_files")
})

test_that("an empty selection is said as such, not as unlabelled recordings", {
  g <- simulate_grasps(subjects = 2, grasps = 1, objects = 1, trials = 2, seed = 1)
  empty <- g[g$meta$subject == "nobody"]
  expect_error(fit_grasp_models(empty), "no recordings", class = "handmotion_error_no_labels")
  expect_error(fit_grasp_models(g, grasps = integer(0)), "at least one", class = "handmotion_error_bad_input")
})
