test_that("a stream updated frame by frame gives the batch prediction of the frames seen", {
  g <- late_types(n_per = 20)
  rec <- fit_grasp_recognizer(g, horizon = 30)
  r <- g$recordings[[5]]
  st <- start_recognition(rec)
  expect_output(print(st), "0 frames seen")
  for (t in seq_len(nrow(r))) {
    p <- update(st, r[t, ])
    if (t %in% c(1, 7, 30, 40)) {
      pb <- first_probs(rec, g[5], t)
      expect_equal(p[names(pb)], pb, tolerance = 1e-10, ignore_attr = TRUE)
    }
  }
  expect_equal(attr(p, "frames"), 40L)
  expect_equal(attr(p, "ms"), 800)
  expect_equal(sum(p), 1, tolerance = 1e-12)
  expect_output(print(st), "40 frames seen \\(800 ms\\); most likely")
  # past the horizon (30 frames) the prediction is the first 30 frames'
  p30 <- first_probs(rec, g[5], 30)
  for (t in 1:100) p <- update(st, r[nrow(r), ] + 50)
  expect_equal(attr(p, "frames"), 140L)
  expect_equal(p[names(p30)], p30, tolerance = 1e-10, ignore_attr = TRUE)
})
