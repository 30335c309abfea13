test_that("PCA of last frames recovers a planted low-dimensional type", {
  # 20 last frames lying exactly in a 2-D affine subspace: 2 PCs explain all
  # variance, the mean is recovered, and a frame in the subspace has distance 0.
  withr::local_seed(3)
  p <- 16
  mu <- seq(10, 85, length.out = p)
  basis <- qr.Q(qr(matrix(rnorm(p * 2), p, 2)))
  scores <- scale(cbind(rnorm(20, 0, 10), rnorm(20, 0, 3)), scale = FALSE)
  last <- sweep(scores %*% t(basis), 2, mu, `+`)
  recs <- lapply(seq_len(20), function(i) rbind(rep(0, p), last[i, ]))
  g <- grasps(recs, meta = data.frame(grasp = rep("Tripod", 20)))
  # (two-frame recordings: only their last frames matter here)
  fit <- suppressWarnings(fit_grasp_classifier(g, method = "last_frame", ncomp = 2), classes = "handmotion_warning_short_recordings")
  expect_s3_class(fit, "last_frame_pca")
  expect_equal(unname(fit$models$Tripod$mean), mu, tolerance = 1e-8)
  cv <- cumulative_variance(fit)
  expect_named(cv, c("grasp_id", "grasp", paste0("pc", 1:16)))
  expect_equal(cv$grasp_id, 14L)
  expect_equal(cv$pc2, 1, tolerance = 1e-10)
  expect_true(cv$pc1 > 0.8 && cv$pc1 < 1)   # planted variance ratio 100:9
  expect_true(all(diff(unlist(cv[paste0("pc", 1:16)])) >= -1e-12))
  # PC1 spans the planted first direction (up to sign)
  expect_equal(abs(sum(fit$models$Tripod$rotation[, 1] * basis[, 1])), 1, tolerance = 1e-3)
  # distance: in-subspace frame 0, an orthogonal offset of 7 gives 7
  off <- qr.Q(qr(cbind(basis, rnorm(p))))[, 3]
  probe <- grasps(list(rbind(0, mu + 5 * basis[, 1]), rbind(0, mu + 7 * off)))
  d <- suppressWarnings(predict(fit, probe, type = "distance"), classes = "handmotion_warning_short_recordings")
  expect_equal(d$.dist_Tripod, c(0, 7), tolerance = 1e-8)
})

test_that("last-frame classification is near perfect on well-separated planted types", {
  g <- planted_types(types = c(1, 9, 17, 22, 31), subjects = 4, trials = 3, seed = 11)
  fit <- fit_grasp_classifier(g, method = "last_frame", ncomp = 5)
  pred <- predict(fit, g)$.pred_class
  expect_s3_class(pred, "factor")
  expect_equal(levels(pred), levels(g$meta$grasp))   # the training labels' levels
  expect_gte(mean(as.character(pred) == as.character(g$meta$grasp)), 0.98)
  # fresh recordings of the same planted types (new trials, same postures)
  fresh <- planted_types(types = c(1, 9, 17, 22, 31), subjects = 4, trials = 3, seed = 11)
  expect_gte(mean(as.character(predict(fit, fresh)$.pred_class) == as.character(fresh$meta$grasp)), 0.98)
})

test_that("types with too few recordings fall back to n - 1 PCs, with a warning", {
  g <- planted_types(types = c(1, 2), subjects = 1, trials = 3)
  expect_warning(fit <- fit_grasp_classifier(g, method = "last_frame", ncomp = 5), class = "handmotion_warning_few_recordings")
  expect_equal(unname(fit$ncomp_used), c(2L, 2L))
  expect_output(print(fit), "fewer than 5 PCs")
  one <- g[c(1, 4)]
  # one recording per type: said by the fit of any classifier, and by the
  # last-frame PCA's fallback to n - 1 = 0 PCs
  expect_warning(expect_warning(
    fit1 <- suppressWarnings(fit_grasp_classifier(one, method = "last_frame", ncomp = 1),
                             classes = "handmotion_warning_short_recordings"),
    "fewer than 3 recordings", class = "handmotion_warning_few_recordings"),
    "too few recordings for 1 PC", class = "handmotion_warning_few_recordings")
  expect_equal(unname(fit1$ncomp_used), c(0L, 0L))
  expect_true(all(is.na(cumulative_variance(fit1)$pc1)))
  expect_equal(as.character(predict(fit1, one)$.pred_class), as.character(one$meta$grasp))
})

test_that("bad input gives classed errors", {
  g <- planted_types(types = 1, subjects = 2, trials = 3)
  expect_error(fit_grasp_classifier(g, method = "last_frame", ncomp = 0), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, method = "last_frame", ncomp = 17), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, method = "last_frame", grasps = "Tripod"), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(list(), method = "last_frame"), class = "handmotion_error_bad_input")
  unl <- g
  unl$meta$grasp[] <- NA
  expect_error(fit_grasp_classifier(unl, method = "last_frame"), class = "handmotion_error_no_labels")
  fit <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
  other <- grasps(list(matrix(0, 3, 4)))
  expect_error(predict(fit, other), class = "handmotion_error_dof_mismatch")
})

test_that("unlabelled recordings are ignored in fitting and counted", {
  g <- planted_types(types = c(1, 2), subjects = 2, trials = 3)
  g$meta$grasp[1] <- NA
  fit <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
  expect_equal(fit$n_unlabelled, 1L)
  expect_equal(fit$models[[1]]$n, 5L)
})
