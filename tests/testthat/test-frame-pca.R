test_that("the flip detector and the thesis' repair find and undo planted flips", {
  L <- 12
  v <- c(0.6, 0.8, 0)
  loadings <- array(rep(v, each = L), c(L, 3, 1))
  flipped <- c(5:8, 11)                       # sign changes entering 5, 9, 11, 12
  loadings[flipped, , 1] <- -loadings[flipped, , 1]
  weights <- array(rnorm(4 * L), c(4, L, 1))
  found <- sign_flip_frames(loadings)
  expect_identical(which(found[, 1]), c(5L, 9L, 11L, 12L))
  rep <- align_frame_signs(loadings, weights)
  expect_false(any(sign_flip_frames(rep$loadings)))
  expect_equal(rep$loadings[, , 1], matrix(v, L, 3, byrow = TRUE))
  # weights flip with their PC, so each frame's contribution is unchanged
  expect_equal(rep$weights[, flipped, 1], -weights[, flipped, 1])
  expect_equal(rep$weights[, -flipped, 1], weights[, -flipped, 1])
})

test_that("per-frame PCA recovers a planted rank-2 posture model", {
  # postures at frame t: mean_t + a_i(t) u_t + b_i(t) v_t with u_t, v_t
  # orthonormal directions that rotate slowly with t; small noise.
  set.seed(1)
  n <- 40; L <- 20; p <- 5
  W <- array(0, c(n, L, p), dimnames = list(paste0("r", 1:n), NULL, paste0("d", 1:p)))
  a <- rnorm(n, 0, 5); b <- rnorm(n, 0, 2)
  for (t in 1:L) {
    th <- t / L
    u <- c(cos(th), sin(th), 0, 0, 0)
    v <- c(0, 0, cos(th), sin(th), 0)
    W[, t, ] <- outer(rep(1, n), 1:p * t) + outer(a * (1 + th), u) + outer(b, v) +
      rnorm(n * p, 0, 0.01)
  }
  aln <- structure(list(warped = W), class = "grasp_alignment")
  m <- fit_frame_pca_model(aln, frame_ncomp = 2, ncomp = 2, nbasis = NULL, align_signs = TRUE)
  expect_s3_class(m, "frame_pca_model")
  expect_true(all(m$frame_var_explained[, 1] > 0.8))
  expect_gt(min(rowSums(m$frame_var_explained)), 0.999)
  # the two PCs of each frame span the planted plane of u_t and v_t
  for (t in c(1, 10, 20)) {
    th <- t / L
    V <- m$loadings[t, , ]
    for (w in list(c(cos(th), sin(th), 0, 0, 0), c(0, 0, cos(th), sin(th), 0))) {
      expect_gt(sqrt(sum(crossprod(V, w)^2)), 0.999)
    }
  }
  expect_lt(max(m$reconstruction$frame_pca_rmse), 0.05)
  expect_identical(m$sign_flips$aligned, c(0L, 0L))
})

test_that("without smoothing flips change nothing; with it the repair helps (thesis 5.1.2)", {
  g <- simulate_grasps(subjects = 6, grasps = 3, seed = 1)
  raw0 <- fit_frame_pca_model(g, nbasis = NULL, warping = "linear")
  fix0 <- fit_frame_pca_model(g, nbasis = NULL, warping = "linear", align_signs = TRUE)
  expect_equal(raw0$reconstruction, fix0$reconstruction, tolerance = 1e-8)
  raw <- fit_frame_pca_model(g, warping = "linear")
  fix <- fit_frame_pca_model(g, warping = "linear", align_signs = TRUE)
  # these recordings' per-frame PCs do flip sign (11 frames), so the repair has work to do
  expect_gt(sum(raw$sign_flips$raw), 0)
  expect_lt(mean(fix$reconstruction$frame_pca_rmse), mean(raw$reconstruction$frame_pca_rmse))
  # and the kept model (per-DoF FPCA) reconstructs better than either
  expect_lt(mean(fix$reconstruction$fpca_rmse), mean(fix$reconstruction$frame_pca_rmse))
  expect_identical(fix$sign_flips$aligned, rep(0L, 3))
  expect_identical(fix$sign_flips$raw, raw$sign_flips$raw)
})

test_that("autoplot shows the weight curves with the flip frames marked (Figure 5.3)", {
  set.seed(2)
  recs <- replicate(15, matrix(rnorm(30 * 4), 30, 4), simplify = FALSE)
  g <- grasps(recs, meta = data.frame(grasp = rep("Ring", 15)), dofs = paste0("d", 1:4))
  m <- fit_frame_pca_model(g, frame_ncomp = 2, warping = "linear", align_signs = TRUE)
  b <- ggplot2::ggplot_build(ggplot2::autoplot(m))
  lines <- b$data[[1]]
  expect_equal(length(unique(lines$PANEL)), 2L)            # raw and aligned
  expect_equal(nrow(lines), 2L * 15L * 30L)
  nflip <- sum(m$flip_frames[, 1])
  expect_gt(nflip, 0)   # noise recordings: the first PC's sign flips between frames
  expect_equal(nrow(b$data[[2]]), 2L * nflip)
  bl <- ggplot2::ggplot_build(ggplot2::autoplot(m, type = "loadings", component = 2))
  expect_equal(nrow(bl$data[[1]]), 2L * 4L * 30L)
  expect_error(ggplot2::autoplot(m, component = 3), class = "handmotion_error_bad_input")
  expect_error(fit_frame_pca_model(g, frame_ncomp = 5, warping = "linear"), class = "handmotion_error_bad_input")
  expect_output(print(m), "sign flips between frames")
})
