test_that("printed tables show shares as percentages, the data keep the fractions", {
  d <- small_design()
  t56 <- thesis_table("5.6", confusion = d$cl, held_out = d$ev$confusion)
  expect_s3_class(t56, "thesis_table")
  expect_true(all(t56$recall >= 0 & t56$recall <= 1))
  out <- capture.output(print(t56))
  # every recall, ours, held out and the thesis', as a percentage with one decimal
  for (v in c(t56$recall, t56$recall_held_out, t56$thesis_recall)) {
    expect_true(any(grepl(sprintf("%.1f%%", 100 * v), out, fixed = TRUE)), label = format(v))
  }
  # no raw fraction such as 0.64074074 anywhere
  expect_false(any(grepl("\\b0\\.[0-9]{4,}", out)))
  t57 <- thesis_table("5.7", fit = d$lf, pcs = 1:3)
  out57 <- capture.output(print(t57))
  expect_true(any(grepl(sprintf("%.1f%%", 100 * t57$pc1[1]), out57, fixed = TRUE)))
  expect_false(any(grepl("\\b0\\.[0-9]{4,}", out57)))
  # percentages of Table 5.2 (already in percent) and Table 5.3's distances: one decimal
  out52 <- capture.output(print(thesis_table("5.2", models = d$ms)))
  expect_false(any(grepl("[0-9]\\.[0-9]{2,}", out52)))
  out53 <- capture.output(print(thesis_table("5.3", classification = d$cl)))
  expect_false(any(grepl("[0-9]\\.[0-9]{2,}", out53)))
  # printing returns the table itself, unchanged
  shown <- NULL
  capture.output(shown <- print(t56))
  expect_identical(shown, t56)
})
