# The error-class hierarchy (?handmotion_errors) and the messages users read.

test_that("every specific class sits under one family and the root", {
  expect_identical(error_classes("truncated_line"),
                   c("handmotion_error_truncated_line", "handmotion_error_bad_file", "handmotion_error"))
  expect_identical(error_classes("unknown_grasp"),
                   c("handmotion_error_unknown_grasp", "handmotion_error_bad_input", "handmotion_error"))
  expect_identical(error_classes("too_few_recordings"),
                   c("handmotion_error_too_few_recordings", "handmotion_error_fit_failed", "handmotion_error"))
  expect_identical(error_classes("missing_dependency"),
                   c("handmotion_error_missing_dependency", "handmotion_error"))
  # a skeleton file's fault is both a skeleton and a file error, not a bad argument
  expect_identical(error_classes(c("bad_skeleton", "bad_file")),
                   c("handmotion_error_bad_skeleton", "handmotion_error_bad_file", "handmotion_error"))
  expect_false("bad_argument" %in% names(error_families))
})

test_that("errors from the public functions carry their family", {
  expect_error(find_overlong(c(40, NA, 42)), class = "handmotion_error_bad_input")
  expect_error(simulate_grasps(grasps = "No Such Grasp"), class = "handmotion_error_bad_input")
  bad <- withr::local_tempfile(fileext = ".xmlskel")
  writeLines("<skeleton><oops></skeleton>", bad)
  expect_error(read_skeleton(bad), class = "handmotion_error_bad_file")
  g <- simulate_grasps(subjects = 1, grasps = 1, objects = 1, trials = 2, seed = 1)
  expect_error(fit_grasp_model(g[1:2], ncomp = 2, warping = "linear"), class = "handmotion_error_fit_failed")
})

test_that("user-facing errors read well", {
  m <- fit_grasp_model(planted_grasps(n = 20, p = 2, seed = 2), warping = "linear", seed = 1)
  expect_snapshot(error = TRUE, {
    generate(m, n = -1)
    generate(m, n = 2, seed = "x")
    fit_grasp_model(planted_grasps(n = 20, p = 2), engine = "fastest")
    fit_grasp_models(planted_grasps(n = 20, p = 2), ncmop = 3)
    align_recordings(list(a = matrix(1:6, 3), b = "x"))
    simulate_grasps(subjects = 0)
  })
})

# Every class given literally to a raiser in R/: the error raisers
# (hm_abort(), hm_condition(), abort_bad_file() and the checkers' `class =`)
# and hm_warn(), with the class as the second argument or named `class`.
raised_classes <- function(dir) {
  errors <- c("hm_abort", "hm_condition", "abort_bad_file")
  found <- list()
  walk <- function(e, file) {
    if (!is.call(e)) return(invisible())
    fn <- if (is.name(e[[1]])) as.character(e[[1]]) else ""
    args <- as.list(e)[-1]
    nm <- rlang::names2(args)
    cls <- NULL
    if (fn %in% c(errors, "hm_warn")) {
      cls <- if ("class" %in% nm) args[[which(nm == "class")]] else if (sum(nm == "") >= 2L) args[nm == ""][[2]]
      if (is.null(cls)) cls <- if (fn == "hm_warn") "note" else "bad_input"
    } else if (startsWith(fn, "check_") && "class" %in% nm) {
      cls <- args[[which(nm == "class")]]
    }
    if (is.call(cls) && identical(cls[[1]], as.name("c"))) cls <- Filter(is.character, as.list(cls)[-1])
    if (length(cls) && all(vapply(as.list(cls), is.character, logical(1)))) {
      found[[length(found) + 1L]] <<- data.frame(file = file, kind = if (fn == "hm_warn") "warning" else "error",
                                                 class = unlist(cls), stringsAsFactors = FALSE)
    }
    for (a in args) if (!missing(a)) walk(a, file)
  }
  for (f in list.files(dir, "\\.R$", full.names = TRUE)) {
    for (e in parse(f, keep.source = FALSE)) walk(e, basename(f))
  }
  unique(do.call(rbind, found))
}

# The text of one bullet of ?handmotion_errors (from its roxygen source),
# from its start to the next bullet or paragraph.
errors_doc_section <- function(doc, start) {
  at <- regexpr(start, doc, fixed = TRUE)
  rest <- substring(doc, at)
  end <- regexpr("\n\\* |\n\n", substring(rest, 2L))
  substring(rest, 1L, if (end > 0) end else nchar(rest))
}

test_that("every class raised in R/ is in the table, in its documented family", {
  r_dir <- test_path("..", "..", "R")
  skip_if_not(file.exists(file.path(r_dir, "errors.R")), "needs the source tree")
  raised <- raised_classes(r_dir)
  # the scan sees the raisers (a scan that found nothing could not fail)
  expect_gt(nrow(raised), 100L)
  expect_true(all(c("bad_model", "too_few_recordings", "truncated_line", "projection_failed") %in% raised$class))
  err <- unique(raised$class[raised$kind == "error"])
  warn <- unique(raised$class[raised$kind == "warning"])
  expect_equal(setdiff(err, names(error_families)), character(0))
  expect_equal(setdiff(warn, names(warning_families)), character(0))
  src <- readLines(file.path(r_dir, "errors.R"))
  doc <- paste(sub("^#' ?", "", grep("^#'", src, value = TRUE)), collapse = "\n")
  sections <- list(bad_input = "* `handmotion_error_bad_input`", bad_file = "* `handmotion_error_bad_file`",
                   fit_failed = "* `handmotion_error_fit_failed`")
  for (cl in setdiff(names(error_families), names(sections))) {
    fam <- error_families[[cl]]
    text <- if (is.na(fam)) doc else errors_doc_section(doc, sections[[fam]])
    expect_true(grepl(paste0("`", cl, "`|`handmotion_error_", cl, "`"), text),
                label = sprintf("class %s documented under its family %s", cl, fam))
  }
  degenerate <- errors_doc_section(doc, "**Warnings**")
  others <- errors_doc_section(doc, "Other warnings:")
  for (cl in names(warning_families)) {
    text <- if (is.na(warning_families[[cl]])) others else degenerate
    expect_true(grepl(paste0("`", cl, "`"), text), label = sprintf("warning %s documented", cl))
  }
  # fit failures are not bad arguments: a model set records them as failed types
  for (cl in c("bad_model", "engine_failed", "alignment_failed")) {
    expect_identical(error_classes(cl), c(paste0("handmotion_error_", cl), "handmotion_error_fit_failed",
                                          "handmotion_error"))
  }
  # the one class for a missing suggested package
  expect_false("missing_package" %in% raised$class)
})

test_that("each generic method is defined once in R/", {
  r_dir <- test_path("..", "..", "R")
  skip_if_not(file.exists(file.path(r_dir, "errors.R")), "needs the source tree")
  defs <- unlist(lapply(list.files(r_dir, "\\.R$", full.names = TRUE), function(f) {
    e <- parse(f, keep.source = FALSE)
    unlist(lapply(e, function(x) if (is.call(x) && identical(x[[1]], as.name("<-")) && is.name(x[[2]])) as.character(x[[2]])))
  }))
  expect_equal(defs[duplicated(defs)], character(0))
})
