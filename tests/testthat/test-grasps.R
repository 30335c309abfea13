make_recs <- function(n = 3, frames = 20, p = 16) {
  lapply(seq_len(n), function(i) matrix(sin(seq_len(frames * p) / (5 + i)), frames, p))
}

test_that("grasps() builds a validated set with metadata and set attributes", {
  g <- grasps(make_recs(), meta = data.frame(grasp = c("Tripod", "tripod", 31),
                                             subject = c("a", "b", "a"), trial = 1:3))
  expect_s3_class(g, "grasps")
  expect_length(g, 3)
  expect_identical(g$dofs, hust_dofs$name)
  expect_identical(g$rate, 50)
  expect_identical(g$unit, "deg")
  expect_identical(levels(g$meta$grasp), feix_taxonomy$name)
  expect_identical(as.character(g$meta$grasp), c("Tripod", "Tripod", "Ring"))
  expect_identical(g$meta$n_frames, rep(20L, 3))
  expect_identical(names(g$meta)[1:7],
                   c("id", "grasp", "subject", "object", "trial", "n_frames", "source"))
  expect_identical(colnames(recordings(g)[[1]]), hust_dofs$name)
})

test_that("grasp names are matched loosely and the thesis' spelling of type 33 is accepted", {
  g <- grasps(make_recs(3), meta = data.frame(grasp = c("power-sphere", "SPHERE_4_FINGER", "Inferrior Pincer")))
  expect_identical(as.integer(g$meta$grasp), c(11L, 26L, 33L))
})

test_that("bad inputs give classed errors that name the recording or argument", {
  recs <- make_recs(2)
  expect_error(grasps("a"), class = "handmotion_error_bad_input")
  expect_error(grasps(list()), class = "handmotion_error_bad_input")
  bad_na <- recs; bad_na[[2]][3, 4] <- NA
  expect_error(grasps(bad_na), "r2", class = "handmotion_error_bad_recording")
  bad_inf <- recs; bad_inf[[1]][1, 1] <- Inf
  expect_error(grasps(bad_inf), "frame 1", class = "handmotion_error_bad_recording")
  bad_chr <- recs; bad_chr[[1]] <- matrix("a", 20, 16)
  expect_error(grasps(bad_chr), "r1", class = "handmotion_error_bad_recording")
  ragged <- recs; ragged[[2]] <- ragged[[2]][, 1:15]
  expect_error(grasps(ragged), "15 DoF columns, expected 16", class = "handmotion_error_bad_recording")
  empty <- recs; empty[[1]] <- matrix(numeric(0), 0, 16)
  expect_error(grasps(empty), "zero length", class = "handmotion_error_bad_recording")
  expect_error(grasps(list(1:5)), "vector", class = "handmotion_error_bad_recording")
  # labels are the user's: a label that is no Feix type is kept, and a mix is said
  expect_warning(grasps(recs, meta = data.frame(grasp = c("Tripod", "Nonsense"))),
                 "Nonsense", class = "handmotion_warning_mixed_labels")
  expect_warning(grasps(recs, meta = data.frame(grasp = c(1, 34))), class = "handmotion_warning_mixed_labels")
  expect_error(grasps(recs, meta = data.frame(grasp = 1)), "1 row", class = "handmotion_error_bad_input")
  expect_error(grasps(recs, meta = data.frame(id = c("x", "x"))), "duplicated", class = "handmotion_error_bad_input")
  expect_error(grasps(recs, rate = -1), class = "handmotion_error_bad_input")
  expect_error(grasps(recs, unit = "furlong"), class = "handmotion_error_bad_input")
  expect_error(grasps(recs, dofs = c("a", "a")), class = "handmotion_error_bad_input")
  # all of them are handmotion errors
  expect_error(grasps(recs, rate = 0), class = "handmotion_error")
})

test_that("subsetting by index, logical and id keeps metadata aligned", {
  g <- grasps(make_recs(4), meta = data.frame(id = c("a", "b", "c", "d"), grasp = c(1, 2, 1, 2)))
  expect_identical(g[2:3]$meta$id, c("b", "c"))
  expect_identical(g[g$meta$grasp == "Large Diameter"]$meta$id, c("a", "c"))
  expect_identical(g[c("d", "a")]$meta$id, c("d", "a"))
  expect_identical(names(recordings(g[c("d", "a")])), c("d", "a"))
  expect_error(g["zz"], class = "handmotion_error_bad_input")
  expect_error(g[c(TRUE, FALSE)], class = "handmotion_error_bad_input")
  expect_error(g[7], class = "handmotion_error_bad_input")
})

test_that("as.data.frame gives the long form with times from the sampling rate", {
  recs <- list(matrix(1:6, 3, 2), matrix(7:10, 2, 2))
  g <- grasps(recs, meta = data.frame(grasp = c(1, 2), subject = "s", object = "o", trial = 1),
              dofs = c("A", "B"), rate = 10)
  df <- as.data.frame(g)
  expect_identical(nrow(df), 10L)
  expect_identical(names(df), c("id", "frame", "time", "dof", "angle", "grasp", "subject", "object", "trial"))
  expect_identical(df$angle, as.numeric(c(1:6, 7:10)))
  expect_identical(as.character(df$dof), c(rep(c("A", "B"), each = 3), rep(c("A", "B"), each = 2)))
  expect_equal(df$time[df$id == "r1" & df$dof == "A"], c(0, 0.1, 0.2))
})

test_that("print and summary describe the set", {
  g <- grasps(make_recs(3), meta = data.frame(grasp = c(1, 1, 2), subject = c("a", "b", "a")))
  expect_snapshot(print(g))
  s <- summary(g)
  expect_identical(s$recordings, c(2L, 1L))
  expect_snapshot(print(s))
})

test_that("a generated set prints where it comes from, not zero subjects and objects", {
  g <- grasps(make_recs(3), meta = data.frame(grasp = c(1, 1, 2), subject = c("a", "b", "a")))
  gen <- g
  gen$meta$subject <- NA_character_
  gen$meta$source <- "generated"
  out <- capture.output(print(gen))
  expect_match(out, "generated by fitted models: 1 to 2 per type", fixed = TRUE, all = FALSE)
  expect_false(any(grepl("subjects: 0", out, fixed = TRUE)))
  # generate() itself: n per type
  ms <- fit_grasp_models(planted_grasps(n = 20, p = 2, grasp = "Ring", seed = 1), warping = "linear", seed = 1)
  expect_output(print(generate(ms, n = 3, seed = 1)), "grasp types: 1; generated by fitted models: 3 per type",
                fixed = TRUE)
  # recorded and generated together: both said
  mixed <- grasps(unname(c(g$recordings, gen$recordings)), meta = rbind(
    transform(g$meta[c("grasp", "subject")], source = "recorded"),
    transform(gen$meta[c("grasp", "subject")], source = "generated")))
  expect_output(print(mixed), "subjects: 2; objects: 0 (recorded); 3 generated by fitted models", fixed = TRUE)
})

test_that("a list of matrices where a grasps set belongs points at as_grasps()", {
  g <- grasps(make_recs(3), meta = data.frame(grasp = c(1, 1, 2)))
  ms <- fit_grasp_models(planted_grasps(n = 20, p = 2, grasp = "Ring", seed = 1), warping = "linear", seed = 1)
  cnd <- expect_error(predict(ms, list(matrix(0, 10, 2))), "as_grasps(new_data)", fixed = TRUE,
                      class = "handmotion_error_bad_input")
  expect_identical(cnd$argument, "new_data")
  expect_error(predict(ms, 1), "grasps()", fixed = TRUE, class = "handmotion_error_bad_input")
})

test_that("autoplot draws one line per recording in one panel per DoF", {
  g <- grasps(make_recs(3, p = 2), meta = data.frame(grasp = c(1, 1, 2)), dofs = c("A", "B"))
  p <- ggplot2::autoplot(g)
  b <- ggplot2::ggplot_build(p)
  expect_identical(length(unique(b$data[[1]]$PANEL)), 2L)
  expect_identical(length(unique(b$data[[1]]$group)), 3L)
  expect_error(ggplot2::autoplot(g, colour = "nope"), class = "handmotion_error_bad_input")
})

test_that("with_seed leaves the global RNG untouched", {
  set.seed(42); before <- .Random.seed
  x <- with_seed(1, runif(3))
  expect_identical(.Random.seed, before)
  expect_identical(x, with_seed(1, runif(3)))
})

test_that("several unknown grasp types are all named in one error", {
  expect_error(as_feix_grasp(c("foo", "bar", "Tripod")), "foo", class = "handmotion_error_unknown_grasp")
  expect_error(as_feix_grasp(c(40, 50)), class = "handmotion_error_unknown_grasp")
})

test_that("finite values whose sum overflows are accepted, a non-finite one anywhere is not", {
  big <- matrix(1.5e308, 3, 2)
  expect_identical(unname(grasps(list(big))$recordings[[1]][3, 2]), 1.5e308)
  for (bad in c(NA, NaN, -Inf)) {
    m <- big
    m[2, 2] <- bad
    err <- expect_error(grasps(list(m)), class = "handmotion_error_bad_recording")
    expect_match(conditionMessage(err), "frame 2")
  }
  expect_error(grasps(list(matrix(c(1L, NA, 3L, 4L), 2))), class = "handmotion_error_bad_recording")
})
