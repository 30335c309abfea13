# The report's settings, argument checks, and one render of the whole report
# on a tiny design (2 subjects, 2 grasp types), checking the HTML, the CSV
# tables and the PNG figures it writes.

test_that("report settings come from params, else environment variables, else the full design", {
  withr::local_envvar(HANDMOTION_REPORT_SUBJECTS = NA, HANDMOTION_REPORT_GRASPS = NA,
                      HANDMOTION_REPORT_FOLDS = NA, HANDMOTION_REPORT_SEED = NA)
  full <- report_settings(NULL)
  expect_equal(full$subjects, 30L)
  expect_equal(full$grasps, 1:33)
  expect_null(full$folds)
  expect_null(full$output_dir)

  withr::local_envvar(HANDMOTION_REPORT_SUBJECTS = "4", HANDMOTION_REPORT_GRASPS = "17, 25,9",
                      HANDMOTION_REPORT_FOLDS = "loso", HANDMOTION_REPORT_SEED = "7")
  small <- report_settings(NULL)
  expect_equal(small$subjects, 4L)
  expect_equal(small$grasps, c(9L, 17L, 25L))
  expect_null(small$folds)
  expect_equal(small$seed, 7L)

  # params win over the environment; 0 folds means leave-one-subject-out
  p <- report_settings(list(subjects = 6, seed = 2, folds = 3, grasps = c("Tripod", "Ring"),
                            output_dir = "out"))
  expect_equal(p[c("subjects", "seed", "folds", "grasps", "output_dir")],
               list(subjects = 6L, seed = 2L, folds = 3L, grasps = c(14L, 31L), output_dir = "out"))
  expect_null(report_settings(list(folds = 0L))$folds)
})

test_that("reproduce_thesis() rejects impossible designs before rendering anything", {
  out <- withr::local_tempdir()
  expect_error(reproduce_thesis(out, subjects = 1), class = "handmotion_error_bad_input")
  expect_error(reproduce_thesis(out, subjects = 4, folds = 5), class = "handmotion_error_bad_input")
  expect_error(reproduce_thesis(out, grasps = 17), class = "handmotion_error_bad_input")
  expect_error(reproduce_thesis(out, grasps = c(17, 99)), class = "handmotion_error")
  expect_error(reproduce_thesis(c("a", "b"), subjects = 3), class = "handmotion_error_bad_input")
  expect_length(list.files(out), 0L)
})

test_that("reproduce_thesis() replaces an earlier report only with overwrite = TRUE, as every writer", {
  out <- withr::local_tempdir()
  writeLines("an earlier report", file.path(out, "reproduce-thesis.html"))
  cnd <- expect_error(reproduce_thesis(out, subjects = 2, grasps = c(17, 25), folds = 2),
                      "overwrite = TRUE", class = "handmotion_error_file_exists")
  expect_identical(cnd$argument, "overwrite")
  expect_identical(readLines(file.path(out, "reproduce-thesis.html")), "an earlier report")
  # the tables of an earlier report count as well
  unlink(file.path(out, "reproduce-thesis.html"))
  dir.create(file.path(out, "tables"))
  writeLines("x", file.path(out, "tables", "timings.csv"))
  expect_error(reproduce_thesis(out, subjects = 2, grasps = c(17, 25), folds = 2),
               "timings.csv", class = "handmotion_error_file_exists")
  expect_error(reproduce_thesis(out, overwrite = NA), class = "handmotion_error_bad_input")
})

test_that("the report renders on a tiny design with its tables and figures", {
  skip_on_cran()
  skip_if_not(rmarkdown::pandoc_available("1.12.3"), "pandoc is not available")
  out <- withr::local_tempdir()
  withr::local_options(handmotion.progress = TRUE)  # (helper-progress.R turns it off for the tests)
  said <- capture.output(html <- reproduce_thesis(out, subjects = 2, grasps = c(17, 25), folds = 2, seed = 1),
                         type = "message")
  expect_equal(normalizePath(html), normalizePath(file.path(out, "reproduce-thesis.html")))
  # progress: a line per step, saying what it does and (after the first) the time left; then where the report is
  steps <- grep("^  \\[ *[0-9]+/[0-9]+\\] ", said, value = TRUE)
  expect_gte(length(steps), 10L)
  expect_match(steps[1], "simulate the data", fixed = TRUE)
  expect_match(steps[length(steps)], "left)", fixed = TRUE)
  expect_match(said[length(said) - 1L], html, fixed = TRUE)
  expect_match(said[1], "2 subjects x 2 grasp types", fixed = TRUE)
  expect_true(file.exists(html))
  page <- gsub("\\s+", " ", paste(readLines(html, warn = FALSE), collapse = "\n"))
  has <- function(text) grepl(text, page, fixed = TRUE)  # (expect_match would print the page)
  for (heading in c("Table 5.1", "Table 5.2", "Table 5.3", "Table 5.6", "Table 5.7", "Table 5.8",
                    "Figure 5.3", "Appendix A", "Timings")) {
    expect_true(has(heading), label = heading)
  }
  # self-contained: the figures are embedded, not linked
  expect_gt(lengths(regmatches(page, gregexpr("data:image/png;base64", page, fixed = TRUE))), 10)
  expect_false(has("Error in "))
  # the 3D viewer is in the page (recorded against generated)
  expect_true(has('class="hand3d html-widget'))
  # Figure 5.1's Medium Wrap is not in this design: the report says what it drew instead
  expect_true(has("the thesis used Medium Wrap, which is not in this design"))

  # a reader can trust the text: no maths from a CDN (the page works offline),
  # no "(s)" plurals, the lost Table 5.3 said plainly, a verdict under the tables
  expect_false(grepl("mathjax", page, ignore.case = TRUE))
  text <- gsub("<[^>]+>", " ", gsub("<(script|style)\\b.*?</\\1>", " ", page, perl = TRUE))
  expect_false(grepl("[a-z]\\(s\\)", text))
  expect_false(grepl("\\b1 (types|recordings|models|DoFs)\\b", text))
  expect_true(has("values were lost from the text extraction"))
  expect_true(has('class="verdict"'))
  expect_true(has("reproduced by construction"))
  expect_true(has("What the twin reproduces, and what it does not"))
  expect_false(has("main job"))
  # written for a reader of the report: no simulator setting by its code
  # name, no file of the source repository that an installed package lacks
  for (internal in c("data-raw", "grasp_variability", "aperture_variability", "calibrate-simulator", ":::")) {
    expect_false(grepl(internal, text, fixed = TRUE), label = internal)
  }
  # a number beside a percentage reads as two cells: every cell holding a
  # percentage or a count is right-aligned
  # (the tables of results: not the software versions at the end)
  results <- sub('id="software".*$', "", page)
  cells <- regmatches(results, gregexpr("<td[^>]*>\\s*[0-9][0-9,]*(\\.[0-9]+)?%?\\s*</td>", results))[[1]]
  expect_gt(length(cells), 20)
  expect_true(all(grepl('text-align: right|align="right"', cells)))

  tables <- c("table_5_1", "table_5_2", "table_5_3", "table_5_3_claims", "table_5_6", "table_5_7",
              "table_5_8", "accuracy", "timings", "figure_5_3_sign_flips", "classifiers_held_out",
              "recognition_recall", "table_5_6_confusion", "table_5_6_confusion_held_out",
              "table_5_8_confusion", "table_5_8_confusion_held_out", "verdicts", "software")
  expect_setequal(sub("\\.csv$", "", list.files(file.path(out, "tables"))), tables)
  figures <- c("figure_5_1", "figure_5_1_frame_counts", "figure_5_2", "figure_5_2_frame_counts", "figure_5_3",
               "figure_5_4", "figure_5_5", "figure_5_6", "table_5_3", "table_5_4", "table_5_5", "table_5_6",
               "table_5_8", "appendix_a_1", "classifiers_accuracy", "recognition_confusion",
               "table_5_6_beside_thesis", "table_5_8_beside_thesis", "recall_beside_thesis")
  expect_setequal(sub("\\.png$", "", list.files(file.path(out, "figures"))), figures)
  png_magic <- as.raw(c(0x89, 0x50, 0x4e, 0x47))
  for (f in list.files(file.path(out, "figures"), full.names = TRUE)) {
    expect_identical(readBin(f, "raw", 4L), png_magic)
  }

  t51 <- utils::read.csv(file.path(out, "tables", "table_5_1.csv"))
  expect_equal(t51$grasp_id, c(17L, 25L))
  expect_true(all(c("target_frames", "thesis_target_frames") %in% names(t51)))
  acc <- utils::read.csv(file.path(out, "tables", "accuracy.csv"))
  expect_equal(nrow(acc), 2L)
  expect_true(all(acc$in_sample >= 0 & acc$in_sample <= 1 & acc$held_out >= 0 & acc$held_out <= 1))
  expect_equal(unique(acc$scheme), "leave-one-subject-out")
  every <- utils::read.csv(file.path(out, "tables", "classifiers_held_out.csv"))
  expect_equal(nrow(every), 4L)
  expect_true(all(every$held_out >= 0 & every$held_out <= 1))
  expect_equal(every$held_out[1:2], acc$held_out)
  # the confusion matrices as CSV: model rows, one column per true type, every recording once
  cm <- utils::read.csv(file.path(out, "tables", "table_5_8_confusion.csv"), check.names = FALSE)
  expect_named(cm, c("model_id", "model", "true_17", "true_25"))
  expect_equal(sum(cm[c("true_17", "true_25")]), sum(t51$n_used + t51$n_overlong + t51$n_degenerate))
  sw <- utils::read.csv(file.path(out, "tables", "software.csv"))
  expect_equal(sw$version[sw$software == "handmotion"], as.character(utils::packageVersion("handmotion")))
  expect_true(any(grepl("^R version", sw$version)))
  verdicts <- utils::read.csv(file.path(out, "tables", "verdicts.csv"))
  expect_true(all(c("Table 5.1", "Table 5.2", "Table 5.3", "Table 5.7", "Tables 5.6, 5.8") %in% verdicts$table))
  expect_true(all(nzchar(verdicts$verdict) & nzchar(verdicts$why)))
  tim <- utils::read.csv(file.path(out, "tables", "timings.csv"))
  expect_true(all(c("fit the grasp models", "held-out evaluation, FPCA", "whole report") %in% tim$step))
  expect_true(all(tim$seconds >= 0))
})

test_that("the report template calls the package's functions by name, not through :::", {
  rmd <- system.file("report", "reproduce-thesis.Rmd", package = "handmotion")
  # (a line starting ":::" is a pandoc fenced div, not R)
  expect_false(any(grepl("[[:alnum:]_.]:::[[:alpha:]_.]", readLines(rmd))))
})

test_that("the vignette is a thin wrapper around the report template", {
  vig <- test_path("..", "..", "vignettes", "reproduce-thesis.Rmd")
  skip_if_not(file.exists(vig), "vignette sources are not available")
  text <- readLines(vig)
  expect_true(any(grepl('system.file("report", "reproduce-thesis.Rmd", package = "handmotion")', text,
                        fixed = TRUE)))
  expect_true(nzchar(system.file("report", "reproduce-thesis.Rmd", package = "handmotion")))
})

test_that("the cost model of the design grows with the design", {
  # (the estimate of the time left is tested in test-report-eta.R)
  settings <- list(subjects = 30, grasps = 1:33, folds = NULL)
  # ten times the subjects, about ten times the work
  big <- handmotion:::report_step_costs(list(subjects = 300, grasps = 1:33, folds = NULL), 1)
  expect_gt(sum(big) / sum(handmotion:::report_step_costs(settings, 1)), 8)
  # every step of the model has a kind
  kinds <- handmotion:::report_step_kinds(handmotion:::report_step_model$step)
  expect_false(anyNA(kinds))
})
