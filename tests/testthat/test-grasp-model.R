# Planted truth (helper-grasp-model.R): each DoF is mean + a1 phi1 + a2 phi2 on
# template time, a1 bimodal at +-sep, recordings linear time-scalings of
# planted lengths. Linear warping recovers the template curves exactly up to
# interpolation, so FPCA, scores, mixtures and warps can be checked against
# what was planted.

test_that("FPCs, mean, scores and variance explained recover the planted truth", {
  g <- planted_grasps(n = 80, p = 3, seed = 11)
  tr <- attr(g, "truth")
  m <- fit_grasp_model(g, warping = "linear", seed = 1)
  expect_s3_class(m, "grasp_model")
  expect_identical(m$grasp, "Tripod")
  expect_equal(m$n_used, 80L)
  expect_equal(m$target_length, as.integer(round(mean(tr$lens))))
  s <- m$argvals
  phi <- planted_phi(s)
  for (j in 1:3) {
    P <- model_basis(m)$components[, j, ]
    # phi1 has a positive integral: the sign convention keeps it positive
    expect_gt(cor(P[, 1], phi[, 1]), 0.99)
    expect_gt(abs(cor(P[, 2], phi[, 2])), 0.99)
    truth_mean <- planted_mean(s, j) + mean(tr$a1[, j]) * phi[, 1] + mean(tr$a2[, j]) * phi[, 2]
    expect_lt(max(abs(model_basis(m)$mean[, j] - truth_mean)), 0.3)
    expect_gt(sum(model_var_explained(m)[j, ]), 0.99)
    expect_gt(cor(model_scores(m)[, j, 1], tr$a1[, j]), 0.995)
    expect_gt(abs(cor(model_scores(m)[, j, 2], tr$a2[, j])), 0.95)
  }
})

test_that("the mixture on FPC1 finds the two planted modes", {
  g <- planted_grasps(n = 120, p = 2, sep = 10, seed = 12)
  m <- fit_grasp_model(g, warping = "linear", seed = 1)
  for (j in 1:2) {
    gm <- m$gmm[[j]]
    expect_false(isTRUE(gm$fallback))
    modes <- sort(gm$means[, 1])
    # scores are centred, so the modes sit at about -+sep (planted), within 2
    expect_equal(modes, c(-10, 10), tolerance = 0.2)
    expect_true(all(gm$weights > 0.3 & gm$weights < 0.7))
  }
})

test_that("warping functions are in original frames and one FPC carries the length", {
  g <- planted_grasps(n = 50, p = 2, len_sd = 5, seed = 13)
  m <- fit_grasp_model(g, warping = "linear", seed = 1)
  nk <- m$alignment$n_frames
  L <- m$target_length
  expect_equal(unname(m$alignment$warps[, L]), unname(as.numeric(nk)))
  expect_equal(unname(m$alignment$warps[, 1]), rep(1, 50))
  expect_gt(m$warp$fpca$var_explained[1], 0.999)
  # positive warp score = longer grasp
  expect_gt(cor(warp_basis(m)$scores[, 1], nk), 0.999)
  expect_gt(warp_basis(m)$components[L, 1], 0)
})

test_that("over-long recordings are removed by the documented rule and recorded", {
  g <- planted_grasps(n = 30, p = 2, seed = 14)
  recs <- g$recordings
  recs[[3]] <- rbind(recs[[3]], recs[[3]], recs[[3]])
  recs[[7]] <- rbind(recs[[7]], recs[[7]], recs[[7]])
  g2 <- grasps(recs, meta = g$meta, dofs = g$dofs)
  m <- fit_grasp_model(g2, warping = "linear", seed = 1)
  expect_setequal(m$removed$id[m$removed$reason == "overlong"], c("r3", "r7"))
  expect_equal(m$n_used, 28L)
  expect_false(any(c("r3", "r7") %in% m$ids))
  # the target length is the mean of what is kept
  expect_equal(m$target_length, as.integer(round(mean(g2$meta$n_frames[-c(3, 7)]))))
  # the rule is an argument: a fence far out keeps them, a bad one is refused
  loose <- fit_grasp_model(g2, warping = "linear", seed = 1, overlong = c(iqr_mult = 100, median_mult = 5))
  expect_equal(loose$n_used, 30L)
  expect_error(fit_grasp_model(g2, overlong = c(iqr = 1)), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_model(g2, overlong = c(iqr_mult = -1)), class = "handmotion_error_bad_input")
})

test_that("a constant DoF is a recorded fallback, not a crash", {
  g <- planted_grasps(n = 20, p = 3, seed = 16)
  recs <- lapply(g$recordings, function(r) { r[, 2] <- 10; r })
  # constant in every recording: a stuck channel, said once where the data are built
  expect_warning(g2 <- grasps(recs, meta = g$meta, dofs = g$dofs), "d2", class = "handmotion_warning_stuck_channels")
  expect_no_warning(m <- fit_grasp_model(g2, warping = "linear", seed = 1))
  expect_output(print(m), "stuck channels held constant: d2")
  # constant within the type only: the model says so itself
  other <- planted_grasps(n = 4, p = 3, seed = 17, grasp = "Ring")
  meta <- rbind(g$meta[c("id", "grasp")], data.frame(id = paste0("ring", 1:4), grasp = "Ring"))
  both <- grasps(c(recs, unname(other$recordings)), meta = meta, dofs = g$dofs)
  expect_warning(fit_grasp_model(both, grasp = "Tripod", warping = "linear", seed = 1), "d2",
                 class = "handmotion_warning_constant_dofs")
  expect_true(any(m$fallbacks$step == "fpca" & m$fallbacks$dof == "d2"))
  expect_true(all(is.na(model_var_explained(m)["d2", ])))
  expect_true(isTRUE(m$gmm$d2$point_mass))
  expect_equal(unname(model_basis(m)$mean[, "d2"]), rep(10, m$target_length))
  s <- summary(m)
  expect_identical(s$mixture[s$dof == "d2"], "point mass")
  new <- generate(m, n = 3, seed = 1)
  expect_true(all(vapply(new$recordings, function(r) all(abs(r[, "d2"] - 10) < 1e-9), logical(1))))
})

test_that("identical recordings give fallbacks for every DoF and the warp", {
  g <- planted_grasps(n = 1, p = 2, seed = 17)
  r <- g$recordings[[1]]
  g2 <- grasps(rep(list(r), 6), meta = data.frame(grasp = rep("Ring", 6)), dofs = g$dofs)
  expect_warning(m <- fit_grasp_model(g2, warping = "linear", seed = 1), class = "handmotion_warning_identical_recordings")
  expect_setequal(m$fallbacks$dof[m$fallbacks$step == "fpca"], c("d1", "d2"))
  expect_true("warp_fpca" %in% m$fallbacks$step)
  new <- generate(m, n = 2, seed = 1)
  expect_equal(unname(new$recordings[[1]]), unname(r), tolerance = 1e-8)
})

test_that("too few recordings, mixed types and bad arguments are clear errors", {
  g <- planted_grasps(n = 2, p = 2, seed = 18)
  expect_error(fit_grasp_model(g, warping = "linear"), class = "handmotion_error_too_few_recordings")
  a <- planted_grasps(n = 5, p = 2, grasp = "Ring", seed = 1)
  b <- planted_grasps(n = 5, p = 2, grasp = "Tripod", seed = 2)
  mixed <- grasps(c(a$recordings, b$recordings),
                  meta = data.frame(id = paste0("x", 1:10), grasp = c(a$meta$grasp, b$meta$grasp)),
                  dofs = a$dofs)
  expect_error(fit_grasp_model(mixed), class = "handmotion_error_multiple_grasps")
  expect_warning(m <- fit_grasp_model(mixed, grasp = "ring", warping = "linear", seed = 1),
                 class = "handmotion_warning_small_mixture")
  expect_identical(m$grasp, "Ring")
  expect_equal(m$grasp_id, 31L)
  expect_error(fit_grasp_model(mixed, grasp = "Tripod", engine = "quick"),
               class = "handmotion_error_bad_input")
  expect_error(fit_grasp_model(mixed, grasp = "Tripod", ncomp = 0), class = "handmotion_error_bad_input")
  expect_error(fit_grasp_model(list()), class = "handmotion_error_bad_input")
})

test_that("a fit is reproducible with its seed and leaves the global RNG alone", {
  g <- planted_grasps(n = 30, p = 2, seed = 21)
  set.seed(99)
  before <- .Random.seed
  m1 <- fit_grasp_model(g, warping = "linear", seed = 5)
  expect_identical(.Random.seed, before)
  m2 <- fit_grasp_model(g, warping = "linear", seed = 5)
  m1$timing <- m2$timing <- NULL
  expect_identical(m1, m2)
})

test_that("simulated grasps fit with DTW and explain most of the variance", {
  g <- simulate_grasps(subjects = 5, grasps = 3, seed = 1)
  m <- fit_grasp_model(g, seed = 1)
  expect_identical(m$grasp, "Medium Wrap")
  expect_equal(m$n_used + nrow(m$removed), length(g))
  expect_gt(stats::median(rowSums(model_var_explained(m))), 0.7)
})

test_that("a failed EM is replaced by a single Gaussian and recorded (Table 5.1)", {
  # 5 recordings cannot carry two full-covariance components in 2-D
  g <- planted_grasps(n = 5, p = 2, seed = 23)
  expect_warning(m <- fit_grasp_model(g, warping = "linear", seed = 1), class = "handmotion_warning_small_mixture")
  em <- m$fallbacks[m$fallbacks$step == "mixture", ]
  expect_setequal(em$dof, c("d1", "d2"))
  expect_true(all(grepl("single Gaussian", em$reason)))
  expect_true(all(vapply(m$gmm, function(x) isTRUE(x$fallback), logical(1))))
  # the single Gaussian has the sample mean of the scores
  expect_equal(unname(drop(m$gmm$d1$means)), unname(colMeans(model_scores(m)[, "d1", ])), tolerance = 1e-8)
  expect_identical(summary(m)$mixture, c("single Gaussian", "single Gaussian"))
})

test_that("a model on linear warps can be drawn, whether asked for or fallen back to", {
  # regression: model fitting built a second, thinner linear-alignment object
  # whose missing fields made autoplot() of it fail ("invalid 'times' argument")
  g <- planted_grasps(n = 30, p = 3, seed = 3)
  aln <- frame_pca_alignment(g, rlang::current_env(), warping = "linear")
  expect_s3_class(ggplot2::ggplot_build(autoplot(aln)), "ggplot_built")
  asked <- suppressWarnings(fit_grasp_model(g, warping = "linear", seed = 1), classes = "handmotion_warning_small_mixture")
  expect_identical(asked$warping$method, "linear")
  for (type in c("fpca", "mixture", "warps")) {
    expect_s3_class(ggplot2::ggplot_build(autoplot(asked, type = type)), "ggplot_built")
  }
  local_failing_alignment()
  expect_warning(fell <- fit_grasp_model(g, seed = 1), class = "handmotion_warning_linear_fallback")
  expect_identical(fell$warping$method, "linear")
  expect_match(fell$fallbacks$reason[fell$fallbacks$step == "warping"], "linear warping")
  expect_s3_class(ggplot2::ggplot_build(autoplot(fell, type = "warps")), "ggplot_built")
  expect_equal(fell$alignment$warps, asked$alignment$warps)
})

test_that("the FPCA of a constant DoF prints and has every field of an fpca_fit", {
  # regression: the constant stand-in was built by hand without n, ncomp and
  # delta, so printing it failed with "invalid format '%d'"
  g <- planted_grasps(n = 30, p = 3, seed = 4)
  g$recordings <- lapply(g$recordings, function(r) { r[, 2] <- 7; r })
  expect_warning(m <- fit_grasp_model(g, seed = 1), class = "handmotion_warning_constant_dofs")
  f <- m$fpca[[2]]
  expect_true(f$constant)
  expect_identical(f$n, m$n_used)
  expect_identical(f$ncomp, 2L)
  expect_output(print(f), "2 components")
  expect_output(print(m$fpca[[1]]), "variance explained")
  expect_setequal(names(f), names(m$fpca[[1]]))
})

test_that("recordings with a degenerate DTW warp stay in the model with a fallback warp; the thesis' rule drops them", {
  # (on this design DTW stalls on 3 of the 32 Light Tool recordings)
  g <- simulate_grasps(subjects = 8, grasps = "Light Tool", objects = 2, trials = 2, seed = 1)
  thesis <- suppressWarnings(fit_grasp_model(g, seed = 1, degenerate_warps = "drop"))
  gone <- thesis$removed$id[thesis$removed$reason == "degenerate warp"]
  expect_gte(length(gone), 1)
  expect_false(any(gone %in% thesis$ids))
  m <- suppressWarnings(fit_grasp_model(g, seed = 1))
  expect_identical(m$n_used, thesis$n_used + length(gone))
  expect_true(all(gone %in% m$ids))
  expect_false(any(m$removed$reason == "degenerate warp"))
  expect_setequal(m$warping$degenerate$id, gone)
  expect_true(all(m$warping$degenerate$fallback %in% c("slope", "linear")))
  expect_true(all(m$warping$degenerate$stall > 0.25 * m$target_length))
  # their warps no longer stall, are monotone and end-pinned
  w <- m$alignment$warps[gone, , drop = FALSE]
  expect_true(all(handmotion:::stall_lengths(w) <= 0.25 * m$target_length))
  expect_true(all(apply(w, 1, function(r) all(diff(r) >= 0))))
  expect_equal(unname(w[, m$target_length]), unname(m$alignment$n_frames[gone]))
  expect_true("degenerate_warp" %in% m$fallbacks$step)
  expect_output(print(m), sprintf("%d degenerate warps? kept by a fallback", length(gone)))
  # the others are aligned as under the thesis' rule
  expect_equal(m$alignment$warps[thesis$ids, ], thesis$alignment$warps)
  s <- summary(fit_grasp_models(g, seed = 1))
  expect_identical(s$n_warp_fallback, length(gone))
  expect_identical(s$n_degenerate, 0L)
  expect_error(fit_grasp_model(g, degenerate_warps = "keep"), class = "handmotion_error_bad_input")
})
