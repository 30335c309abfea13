# Known counts -> hand-computed metrics.
#   truth: A A A A B B C C C C
#   pred:  A A B B B B C C A C
# table (rows = predicted, cols = truth):
#        A B C
#   A    2 0 1
#   B    2 2 0
#   C    0 0 3
# accuracy 7/10; recall A 2/4, B 2/2, C 3/4 (balanced 0.75);
# precision A 2/3, B 2/4, C 3/3 (macro 13/18).
known_truth <- c("A", "A", "A", "A", "B", "B", "C", "C", "C", "C")
known_pred <- c("A", "A", "B", "B", "B", "B", "C", "C", "A", "C")

test_that("the table has rows = prediction and columns = truth", {
  cm <- grasp_confusion(known_truth, known_pred)
  expect_s3_class(cm, "grasp_confusion")
  expect_equal(names(dimnames(cm$table)), c("Prediction", "Truth"))
  expect_equal(cm$levels, c("A", "B", "C"))
  expect_equal(unname(unclass(cm$table)), matrix(c(2, 2, 0, 0, 2, 0, 1, 0, 3), 3))
  expect_equal(cm$n, 10L)
})

test_that("summary gives the hand-computed metrics", {
  s <- summary(grasp_confusion(known_truth, known_pred))
  expect_s3_class(s, "data.frame")
  # yardstick's names for the metric and its value
  expect_named(s, c(".metric", "class", ".estimate", "n"))
  est <- function(metric, class = NA) {
    s$.estimate[s$.metric == metric & (if (is.na(class)) is.na(s$class) else s$class %in% class)]
  }
  expect_equal(est("accuracy"), 0.7)
  expect_equal(est("balanced_accuracy"), 0.75)
  expect_equal(est("macro_precision"), 13 / 18)
  expect_equal(est("recall", "A"), 0.5)
  expect_equal(est("recall", "B"), 1)
  expect_equal(est("recall", "C"), 0.75)
  expect_equal(est("precision", "A"), 2 / 3)
  expect_equal(est("precision", "B"), 0.5)
  expect_equal(est("precision", "C"), 1)
  expect_equal(s$n[s$.metric == "recall"], c(4, 2, 4))
})

test_that("a class never predicted has NA precision, not a silent zero", {
  s <- summary(grasp_confusion(c("A", "B"), c("A", "A"), levels = c("A", "B")))
  expect_true(is.na(s$.estimate[s$.metric == "precision" & s$class %in% "B"]))
  expect_equal(s$.estimate[s$.metric == "recall" & s$class %in% "B"], 0)
})

test_that("missing truth or prediction is counted, not dropped silently", {
  cm <- grasp_confusion(c("A", NA, "B", "B"), c("A", "A", NA, "B"))
  expect_equal(cm$n, 2L)
  expect_equal(cm$n_missing_truth, 1L)
  expect_equal(cm$n_missing_predicted, 1L)
  expect_output(print(cm), "1 unlabelled")
  expect_output(print(cm), "1 recording without a prediction")
})

test_that("Feix names are put in Feix order and bad input gives classed errors", {
  cm <- grasp_confusion(c("Tripod", "Large Diameter"), c("Large Diameter", "Large Diameter"))
  expect_equal(cm$levels, c("Large Diameter", "Tripod"))
  expect_error(grasp_confusion("A", c("A", "B")), class = "handmotion_error_bad_input")
  expect_error(grasp_confusion("A", "Z", levels = "A"), class = "handmotion_error_bad_input")
})

test_that("as.data.frame gives the long form and round-trips through a table", {
  cm <- grasp_confusion(known_truth, known_pred)
  d <- as.data.frame(cm)
  expect_named(d, c("predicted", "truth", "n"))
  expect_equal(nrow(d), 9)
  expect_equal(d$n[d$predicted == "B" & d$truth == "A"], 2L)
  back <- grasp_confusion(cm$table)
  expect_equal(unclass(back$table), unclass(cm$table))
  expect_equal(summary(back)$.estimate, summary(cm)$.estimate)
  from_df <- grasp_confusion(data.frame(truth = known_truth, predicted = known_pred))
  expect_equal(unclass(from_df$table), unclass(cm$table))
  expect_error(grasp_confusion(matrix(1:6, 2)), class = "handmotion_error_bad_input")
  expect_error(grasp_confusion(list(1)), class = "handmotion_error_bad_input")
  expect_error(grasp_confusion(cm$table, levels = "A"), class = "handmotion_error_bad_input")
  expect_identical(grasp_confusion(cm), cm)
})

test_that("printed confusion and summary are stable", {
  cm <- grasp_confusion(known_truth, known_pred)
  expect_snapshot(print(cm))
  expect_snapshot(print(summary(cm)))
})

test_that("a 33-class matrix prints compactly with Feix ids", {
  lev <- feix_levels()
  truth <- factor(rep(lev, each = 3), levels = lev)
  pred <- truth
  pred[seq(1, 99, by = 9)] <- lev[9]
  cm <- grasp_confusion(truth, pred)
  expect_equal(length(cm$levels), 33)
  out <- capture.output(print(cm))
  expect_true(max(nchar(out)) <= 120)
  expect_snapshot(print(cm))
})

test_that("autoplot draws tiles and labels for every cell", {
  cm <- grasp_confusion(known_truth, known_pred)
  p <- ggplot2::autoplot(cm)
  expect_s3_class(p, "ggplot")
  b <- ggplot2::ggplot_build(p)
  tiles <- b$data[[1]]
  text <- b$data[[2]]
  expect_equal(nrow(tiles), 9)
  expect_setequal(text$label[text$label != ""], c("2", "2", "1", "2", "3"))
  # fill follows counts: the (C, C) cell with 3 is the darkest
  d <- p$data
  expect_equal(d$fill[d$predicted == "C" & d$truth == "C"], 3)
  pn <- ggplot2::autoplot(cm, normalise = TRUE)
  expect_equal(pn$data$fill[pn$data$predicted == "A" & pn$data$truth == "A"], 0.5)
  expect_error(ggplot2::autoplot(cm, type = "mosaic"))
})

test_that("autoplot's counts and key are large enough to read with 33 types", {
  lv <- feix_taxonomy$name
  cm <- grasp_confusion(lv, lv, levels = lv)
  p <- ggplot2::autoplot(cm)
  text_layer <- p$layers[[which(vapply(p$layers, function(l) inherits(l$geom, "GeomText"), logical(1)))]]
  # 8 points and more (the old 2 mm was under 6 points)
  expect_gte(text_layer$aes_params$size * ggplot2::.pt, 8 - 1e-9)
  expect_gte(p$theme$plot.caption$size, 9)
  # the colour bar below, leaving the matrix the figure's width
  expect_identical(p$theme$legend.position, "bottom")
  # the key names every type once, by its Feix id
  key <- strsplit(p$labels$caption, "\n| \u00b7 ")[[1]]
  expect_length(key, 33L)
  expect_true(all(nchar(strsplit(p$labels$caption, "\n")[[1]]) <= 90))
})

test_that("the key writes a label that is its own abbreviation once", {
  lv <- c("ball", "bottle", "card", "pen", "screwdriver")
  cm <- grasp_confusion(lv, lv, levels = lv)
  key <- strsplit(ggplot2::autoplot(cm)$labels$caption, "\n| \u00b7 ")[[1]]
  lab <- abbreviate(lv, minlength = 4)
  # "ball", not "ball ball"; "bttl bottle" as before
  expect_identical(key, unname(ifelse(lab == lv, lv, paste(lab, lv))))
  expect_true("ball" %in% key)
  expect_false(any(grepl("^(\\S+) \\1$", key)))
  expect_true(any(grepl("^bttl bottle$", key)))
})

test_that("print() says its counts in the singular or plural, on stdout", {
  # (cli::cat_line() writes to stdout: capture.output() and snapshots see it)
  one <- utils::capture.output(print(grasp_confusion("Ring", "Ring")))
  expect_identical(one[1], "<grasp_confusion> 1 class, 1 recording, accuracy 100.0%")
  two <- grasp_confusion(c("Ring", "Tripod", "Tripod", NA), c("Ring", "Ring", NA, "Ring"))
  out <- utils::capture.output(r <- print(two))
  expect_identical(r, two)
  expect_identical(out[1], "<grasp_confusion> 2 classes, 2 recordings, accuracy 50.0%")
  expect_true(all(c("  not tabulated: 1 unlabelled recording", "  not tabulated: 1 recording without a prediction")
                  %in% out))
  expect_silent(utils::capture.output(print(two)))
})
