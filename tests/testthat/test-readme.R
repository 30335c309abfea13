# The README runs as written: every R block on its own, in a fresh R session
# (a callr subprocess each, as a reader who pastes one block into a new
# session), with the working directory a temporary directory so the files it
# writes (grasp.gif, grasp.bvh, output/) land there. The Python block is run by
# inst/python/tests/test_readme.py.
#
# The first two blocks work on the full default data (8910 recordings) and the
# first renders the whole thesis report: minutes, too slow for `make test`. The
# test runs them on a smaller design by these textual substitutions, and
# nothing else is changed. Each `from` must occur in its block exactly `times`
# times, so a README edit that drops or moves one fails here instead of
# silently running the full size.
readme_substitutions <- data.frame(
  block = c(1L, 1L, 2L, 2L),
  from = c("simulate_grasps(seed = 1)",
           'reproduce_thesis("output")',
           "simulate_grasps(seed = 1)",
           '"S20"'),
  to = c("simulate_grasps(subjects = 3, grasps = c(11, 14, 17, 25), seed = 1)",
         'reproduce_thesis("output", subjects = 2, grasps = c(17, 25), folds = 2)',
         "simulate_grasps(subjects = 3, grasps = c(11, 14, 17, 25), seed = 1)",
         '"S02"'),
  times = c(1L, 1L, 1L, 2L),
  why = c("3 subjects and 4 types (Power Sphere 11 and Tripod 14, which the block names) instead of 30 x 33",
          "the report's smallest design (as in test-report-reproduce-thesis.R)",
          "the same small design as the first block",
          "train on subjects 1-2 and hold out 3, as the README trains on 1-20 and holds out 21-30"),
  stringsAsFactors = FALSE
)

readme_path <- function() {
  path <- testthat::test_path("..", "..", "README.md")
  if (!file.exists(path)) testthat::skip("README.md is not beside the tests (installed package)")
  path
}

# The fenced blocks of one language, in order, as single strings.
readme_blocks <- function(path, lang) {
  lines <- readLines(path, warn = FALSE)
  opens <- which(lines == paste0("```", lang))
  closes <- which(lines == "```")
  vapply(opens, function(o) {
    end <- closes[closes > o][1]
    paste(lines[seq.int(o + 1L, end - 1L)], collapse = "\n")
  }, character(1))
}

substitute_readme <- function(blocks, subs) {
  for (i in seq_len(nrow(subs))) {
    b <- subs$block[i]
    hits <- lengths(regmatches(blocks[b], gregexpr(subs$from[i], blocks[b], fixed = TRUE)))
    if (hits != subs$times[i]) {
      stop(sprintf("README R block %d holds `%s` %d times, the test expects %d: update readme_substitutions",
                   b, subs$from[i], hits, subs$times[i]))
    }
    blocks[b] <- gsub(subs$from[i], subs$to[i], blocks[b], fixed = TRUE)
  }
  blocks
}

test_that("the substitution table is checked against the README", {
  blocks <- readme_blocks(readme_path(), "r")
  expect_error(substitute_readme(blocks, transform(readme_substitutions[1, ], times = 2L)),
               "expects 2")
  out <- substitute_readme(blocks, readme_substitutions)
  for (i in seq_len(nrow(readme_substitutions))) {
    expect_false(grepl(readme_substitutions$from[i], out[readme_substitutions$block[i]], fixed = TRUE))
  }
  # only the table's substitutions: the rest of every block is the README's text
  expect_identical(out[-unique(readme_substitutions$block)], blocks[-unique(readme_substitutions$block)])
})

# Run one block in a fresh R session whose working directory is `dir`: the
# files it wrote and the objects it left.
run_readme_block <- function(block, pkg, dir) {
  callr::r(function(block, pkg, dir) {
    # the package as the tests see it (its sources; the block's own
    # library() call, checked below, then finds it attached)
    suppressMessages(pkgload::load_all(pkg, quiet = TRUE, export_all = FALSE))
    setwd(dir)
    grDevices::pdf(NULL)
    exprs <- parse(text = block, keep.source = FALSE)
    for (e in exprs) withVisible(eval(e, globalenv()))
    list(files = sort(list.files(dir)), objects = ls(globalenv()),
         p = if (exists("p", globalenv())) unclass(get("p", globalenv())))
  }, args = list(block = block, pkg = pkg, dir = dir), show = FALSE)
}

test_that("every R block of the README runs on its own, in a fresh session", {
  skip_on_cran()
  skip_if_not_installed("callr")
  skip_if_not_installed("pkgload")
  skip_if_not(rmarkdown::pandoc_available("1.12.3"), "pandoc is not available (reproduce_thesis())")
  blocks <- substitute_readme(readme_blocks(readme_path(), "r"), readme_substitutions)
  expect_gte(length(blocks), 4L)
  pkg <- normalizePath(testthat::test_path("..", ".."))
  # every block starts by attaching the package: none leans on one before it
  for (b in blocks) expect_match(b, "^library\\(handmotion\\)")
  dirs <- character()
  for (i in seq_along(blocks)) dirs[i] <- withr::local_tempdir(sprintf("readme-%d-", i))
  ran <- Map(run_readme_block, blocks, pkg, dirs)
  first <- ran[[1]]
  expect_true(all(c("g", "ms", "new") %in% first$objects))
  # the files the first block writes went to its temporary working directory
  expect_true(all(c("grasp.bvh", "output") %in% first$files))
  expect_true(any(grepl("^grasp\\.(gif|mp4)$", first$files)))
  expect_true(file.exists(file.path(dirs[1], "output", "reproduce-thesis.html")))
  second <- ran[[2]]
  expect_true(all(c("g", "train", "held_out", "p") %in% second$objects))
  # the stream's probabilities after the last frame
  expect_equal(sum(second$p), 1, tolerance = 1e-8)
  # the real recordings: read, segmented, fitted and evaluated
  expect_true(all(c("g", "ms") %in% ran[[3]]$objects))
  expect_true(all(c("raw", "deg") %in% ran[[4]]$objects))
})

test_that("the README's API table lists every export, and its count is the number of exports", {
  path <- readme_path()
  ns_file <- testthat::test_path("..", "..", "NAMESPACE")
  skip_if_not(file.exists(ns_file), "NAMESPACE is not beside the tests")
  ns <- readLines(ns_file)
  exports <- sub("^export\\((.*)\\)$", "\\1", grep("^export\\(", ns, value = TRUE))
  lines <- readLines(path, warn = FALSE)
  api <- lines[seq(grep("^## The whole API", lines), grep("^## Data", lines) - 1L)]
  count <- as.integer(sub("^([0-9]+) functions.*", "\\1", grep("^[0-9]+ functions", api, value = TRUE)))
  expect_identical(count, length(exports))
  table <- paste(grep("^\\|", api, value = TRUE), collapse = " ")
  listed <- unique(sub("\\(\\)`$", "", sub("^`", "", regmatches(table, gregexpr("`[A-Za-z_.0-9]+\\(\\)`", table))[[1]])))
  expect_setequal(intersect(listed, exports), exports)
  # the table names nothing that is neither an export nor a generic the package has methods for
  generics <- c("summary", "predict", "print", "update")
  expect_identical(setdiff(listed, c(exports, generics)), character(0))
})
