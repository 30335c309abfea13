test_that("probabilities print with three decimals and bounded ends, the numbers kept", {
  expect_identical(format_probability(c(1, 1 - 1e-12, 1.715671e-21, 0, 0.5, 0.9994, 0.0006, NA)),
                   c(">0.999", ">0.999", "<0.001", "<0.001", "0.500", "0.999", "0.001", NA))
  g <- late_types(n_per = 8)
  rec <- fit_grasp_recognizer(g, horizon = 10)
  st <- start_recognition(rec)
  r <- g$recordings[[1]]
  for (t in 1:10) p <- update(st, r[t, ])
  expect_s3_class(p, "grasp_probabilities")
  out <- capture.output(print(p))
  expect_false(any(grepl("e-|e\\+", out)))
  expect_match(out, "after 10 frames (200 ms)", fixed = TRUE, all = FALSE)
  # the stored values are the model's own, not the printed ones
  expect_identical(as.vector(unclass(p)), as.vector(st$state$probs))
  # the README's most likely types print the same way (a subset keeps the class)
  top <- head(sort(p, decreasing = TRUE), 3)
  expect_s3_class(top, "grasp_probabilities")
  expect_identical(as.vector(unclass(top)), utils::head(sort(as.vector(unclass(p)), decreasing = TRUE), 3))
  expect_false(any(grepl("e-|e\\+", capture.output(print(top)))))
  expect_equal(sum(p), 1, tolerance = 1e-12)
})
