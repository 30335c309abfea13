split <- handover_split()

test_that("ranked 6 markers beat 3, the no-PCA regression and the hand-picked set on unseen data", {
  ref <- split$ref
  test <- split$test
  m6 <- select_markers(ref, 6)
  rk <- attr(m6, "ranking")
  m3 <- select_markers(rk, 3)
  e6 <- handover_error(test, predict(fit_handover(ref, m6), test))
  e3 <- handover_error(test, predict(fit_handover(ref, m3), test))
  e_direct <- handover_error(test, predict(fit_handover(ref, m6, method = "direct"), test))
  e_hand <- handover_error(test, predict(fit_handover(ref, select_markers(method = "handpicked")), test))
  # a useful reconstruction: well under the spread of the test angles themselves
  spread <- mean(abs(sweep(do.call(rbind, test$recordings), 2, colMeans(do.call(rbind, ref$recordings)))))
  expect_lt(e6, spread / 3)
  expect_lt(e6, e3)
  expect_lt(e6, e_direct)
  expect_lt(e6, e_hand)
})

test_that("LWR on all components equals LWR straight to the angles (why 'direct' is global)", {
  ref <- split$ref
  fit <- fit_handover(ref, n_markers = 3, smooth = FALSE)
  q <- forward_kinematics(split$test[1], markers = fit$markers)[[1]]
  y <- do.call(rbind, ref$recordings)
  direct_local <- lwr_predict(fit$ref_x, y, q, fit$neighbours_used, fit$ridge, fit$eps)
  via_pca <- predict(fit, split$test[1])$recordings[[1]]
  expect_equal(unname(via_pca), unname(direct_local), tolerance = 1e-8)
  # with fewer components the two differ
  few <- predict(fit_handover(ref, fit$markers, ncomp = 3, smooth = FALSE), split$test[1])
  expect_gt(max(abs(few$recordings[[1]] - via_pca)), 0.1)
})

test_that("a marker matrix query gives the same result as the grasps query; columns may be reordered", {
  fit <- fit_handover(split$ref, n_markers = 4)
  g1 <- split$test[1]
  mk <- forward_kinematics(g1, markers = fit$markers)[[1]]
  a <- predict(fit, g1)$recordings[[1]]
  b <- predict(fit, mk)
  expect_equal(unname(b$recordings[[1]]), unname(a))
  rev_cols <- mk[, rev(colnames(mk))]
  expect_equal(predict(fit, rev_cols)$recordings[[1]], b$recordings[[1]])
  expect_equal(predict(fit, mk)$recordings[[1]], b$recordings[[1]])
  # extra named markers (e.g. the full set) are ignored
  all13 <- forward_kinematics(g1, markers = TRUE)[[1]]
  expect_equal(predict(fit, all13)$recordings[[1]], b$recordings[[1]])
  # unnamed columns are refused: in another order they would give a wrong hand
  expect_error(predict(fit, unname(mk)), class = "handmotion_error_bad_markers")
  expect_error(predict(fit, unname(mk[, rev(seq_len(ncol(mk)))])), class = "handmotion_error_bad_markers")
})

test_that("wrong marker sets are refused with classed errors", {
  ref <- split$ref
  fit <- fit_handover(ref, markers = c("thumb_tip", "index_tip", "ring_tip"))
  mk <- forward_kinematics(split$test[1], markers = fit$markers)[[1]]
  expect_error(predict(fit, unname(mk[, 1:6])), class = "handmotion_error_bad_markers")
  expect_error(predict(fit, mk[, 1:6]), class = "handmotion_error_bad_markers")
  expect_error(predict(fit, mk[0, ]), class = "handmotion_error_bad_markers")
  inf <- mk
  inf[1, 1] <- Inf
  expect_error(predict(fit, inf), class = "handmotion_error_bad_markers")
  expect_error(fit_handover(ref, markers = c("thumb_tip", "wrist")), class = "handmotion_error_bad_markers")
  expect_error(fit_handover(ref, markers = c("thumb_tip", "thumb_tip")), class = "handmotion_error_bad_markers")
  expect_error(fit_handover(ref, markers = c("thumb_tip", "forearm_radial")),
               class = "handmotion_error_bad_markers")
  expect_error(fit_handover(ref, n_markers = 14), class = "handmotion_error_bad_markers")
  expect_error(fit_handover(ref, n_markers = 3, ncomp = 17), class = "handmotion_error_bad_input")
  expect_error(fit_handover(ref, n_markers = 3, neighbours = 2), class = "handmotion_error_bad_input")
  expect_error(fit_handover(ref, n_markers = 3, filter_size = 0), class = "handmotion_error_bad_input")
  expect_error(fit_handover("ref"), class = "handmotion_error_bad_input")
})

test_that("a reference too small for the regression is a classed error", {
  tiny <- split$ref[1]
  tiny$recordings[[1]] <- tiny$recordings[[1]][1:10, ]
  tiny$meta$n_frames <- 10L
  expect_error(fit_handover(tiny, markers = c("thumb_tip", "index_tip", "ring_tip")),
               class = "handmotion_error_reference_too_small")
  # with enough frames but fewer than k, every frame is a neighbour (recorded)
  fit <- fit_handover(split$ref[1], markers = c("thumb_tip", "index_tip"), neighbours = 1000)
  expect_equal(fit$neighbours_used, split$ref$meta$n_frames[1])
})

test_that("occluded (NaN) markers are dropped per frame, and fully occluded frames are an error", {
  fit <- fit_handover(split$ref, n_markers = 6)
  mk <- forward_kinematics(split$test[1], markers = fit$markers)[[1]]
  full <- predict(fit, mk)
  occ <- mk
  occ[5:9, 1:3] <- NaN           # first marker hidden for five frames
  occ[7, 4:6] <- NA              # and the second in one of them
  rec <- predict(fit, occ)
  used <- attr(rec, "handover")$markers_used[[1]]
  expect_equal(used[c(4, 5, 7, 10)], c(6, 5, 4, 6))
  expect_equal(rec$meta$occluded_frames, 5L)
  # a small degradation, not a collapse
  truth <- split$test[1]$recordings[[1]]
  e_full <- mean(abs(full$recordings[[1]][5:9, ] - truth[5:9, ]))
  e_occ <- mean(abs(rec$recordings[[1]][5:9, ] - truth[5:9, ]))
  expect_lt(e_occ, e_full + 5)
  blind <- mk
  blind[3, ] <- NaN
  expect_error(predict(fit, blind), class = "handmotion_error_occluded")
  direct <- fit_handover(split$ref, markers = fit$markers, method = "direct")
  expect_error(predict(direct, occ), class = "handmotion_error_occluded")
})

test_that("the cone filter scales with the rate and smooths without bias", {
  expect_equal(cone_size(120), 17L)
  expect_equal(cone_size(50), 7L)
  expect_equal(cone_size(60), 9L)
  expect_equal(cone_size(5), 1L)
  x <- cbind(rep(3, 50), seq_len(50))
  sm <- cone_filter(x, 7)
  expect_equal(sm[, 1], rep(3, 50))
  expect_equal(sm[4:47, 2], 4:47)        # linear trends pass through the interior
  noise <- with_seed(1, matrix(stats::rnorm(2000), 1000, 2))
  expect_lt(stats::sd(cone_filter(noise, 7)[, 1]), 0.6)
  expect_identical(cone_filter(x, 1), x)
})

test_that("neighbours = Inf is the paper's all-frame weighting and matches all frames", {
  small <- split$ref[1:6]
  a <- fit_handover(small, markers = c("thumb_tip", "middle_tip"), neighbours = Inf)
  b <- fit_handover(small, markers = c("thumb_tip", "middle_tip"), neighbours = sum(small$meta$n_frames))
  expect_equal(predict(a, split$test[1])$recordings, predict(b, split$test[1])$recordings)
})

test_that("search-based selection returns a logged greedy set", {
  s <- select_markers(split$ref, n = 2, method = "search", max_frames = 150, neighbours = 64)
  expect_length(s, 2)
  log <- attr(s, "search")
  expect_equal(nrow(log), 13 + 12)
  expect_equal(s[1], sub(",.*", "", log$set[log$step == 1][which.min(log$error[log$step == 1])]))
  expect_error(select_markers(split$ref, n = 2, method = "search", holdout = "nope"),
               class = "handmotion_error_bad_input")
  expect_error(select_markers(split$ref[split$ref$meta$grasp == split$ref$meta$grasp[1]], n = 2,
                              method = "search"),
               class = "handmotion_error_reference_too_small")
})

test_that("handover_error(by = \"markers\") tabulates and plots the comparison", {
  cmp <- handover_error(split$test[1:2], by = "markers", reference = split$ref,
                        sets = list(a = c("thumb_tip", "index_tip"),
                                    b = list(markers = c("thumb_tip", "index_tip"), method = "direct")),
                        neighbours = 64)
  expect_s3_class(cmp, "handover_comparison")
  expect_equal(as.character(cmp$set), c("a", "b"))
  expect_equal(cmp$method, c("pca", "direct"))
  expect_true(all(cmp$error > 0))
  expect_output(print(cmp), "handover_comparison")
  b <- ggplot2::ggplot_build(ggplot2::autoplot(cmp))
  expect_equal(b$data[[1]]$y, cmp$error)
  # each row is the plain error of that set's reconstruction
  fit_a <- fit_handover(split$ref, c("thumb_tip", "index_tip"), neighbours = 64)
  expect_equal(cmp$error[1], handover_error(split$test[1:2], predict(fit_a, split$test[1:2])))
  expect_error(handover_error(split$test, by = "markers", reference = split$ref, sets = list(1)),
               class = "handmotion_error_bad_input")
})

test_that("hand-over runs on the real GraspDB14 samples (radians, CyberGlove mapping)", {
  f1 <- shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt")
  f2 <- shared_file("data", "graspdb14", "04_ex01-rad-045-grasp-su03.txt")
  g <- read_graspdb14(c(f1, f2))
  # (a reader regression must fail here, not skip)
  expect_s3_class(g, "grasps")
  expect_length(g, 2L)
  fit <- fit_handover(g[2], n_markers = 6, neighbours = 64)
  rec <- predict(fit, g[1])
  expect_equal(rec$unit, "rad")
  e <- handover_error(g[1], rec)
  expect_true(is.finite(e))
  # reconstructing the reference's own frames is near exact; not exact, because
  # the sensors the CyberGlove mapping does not apply (I-AA, P-Arch) change
  # angles without moving any marker
  expect_lt(handover_error(g[2], predict(fit_handover(g[2], n_markers = 6, neighbours = 64, smooth = FALSE), g[2])), 0.2)
})

test_that("the C regression engine agrees with the R reference engine", {
  fit <- fit_handover(split$ref, n_markers = 4, smooth = FALSE)
  q <- forward_kinematics(split$test[1:2], markers = fit$markers)
  q <- do.call(rbind, q)
  for (k in c(20, 256, nrow(fit$ref_x))) {
    a <- lwr_predict(fit$ref_x, fit$ref_scores, q, k, fit$ridge, fit$eps)
    b <- lwr_predict_r(fit$ref_x, fit$ref_scores, q, k, fit$ridge, fit$eps)
    expect_equal(a, b, tolerance = 1e-8)
  }
  # a local model whose neighbours all coincide is rescued by the ridge
  flat <- matrix(1, 30, 3)
  y <- matrix(seq_len(30), 30, 1)
  expect_equal(drop(lwr_predict(flat, y, matrix(2, 1, 3), 30, 1e-3, 1e-6)), 15.5, tolerance = 1e-6)
})

test_that("the native local regression checks its arguments itself (no crash on bad input)", {
  x <- matrix(stats::rnorm(60), 20, 3)
  y <- matrix(stats::rnorm(40), 20, 2)
  q <- matrix(stats::rnorm(6), 2, 3)
  expect_equal(dim(lwr_predict(x, y, q, 5L, 1e-3, 1e-6)), c(2L, 2L))
  expect_error(.Call(hm_lwr_predict, x, y, matrix(1L, 2, 3), 5L, 1e-3, 1e-6), "double matrices")
  expect_error(.Call(hm_lwr_predict, x, y[1:5, ], q, 5L, 1e-3, 1e-6), "dimension mismatch")
  expect_error(.Call(hm_lwr_predict, x, y, q, 5L, 0, 1e-6), "positive")
  expect_error(.Call(hm_lwr_predict, x, y, q, 5L, 1e-3, NaN), "positive")
})

test_that("hand-over models are built by one constructor whose validator checks the shapes", {
  fit <- fit_handover(split$ref, n_markers = 3, neighbours = 64)
  expect_identical(validate_handover_model(fit), fit)
  broken <- unclass(fit)
  broken$rotation <- broken$rotation[-1, ]
  expect_error(validate_handover_model(structure(broken, class = "handover_model")))
  broken <- unclass(fit)
  broken$markers <- c(broken$markers, "ring_tip")
  expect_error(validate_handover_model(structure(broken, class = "handover_model")))
})
