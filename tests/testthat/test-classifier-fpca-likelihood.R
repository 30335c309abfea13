# The FPCA likelihood distance (fit_grasp_models(distance = "likelihood")).

# Two types with one shape (a ramp to one posture direction) that differ
# only in amplitude: type A reaches amplitude ~1, type B ~2, each recording
# its own amplitude (10% spread). A recording's projection on either type's
# first FPC (the ramp times the posture) absorbs its amplitude, so both
# types leave the same residual: only the scores tell them apart.
amplitude_types <- function(subjects = 4, trials = 8, seed = 1) {
  withr::with_seed(seed, {
    base <- stats::runif(16, 20, 60)
    recs <- list()
    meta <- list()
    for (s in seq_len(subjects)) for (ty in c("A", "B")) for (r in seq_len(trials)) {
      amp <- (if (ty == "A") 1 else 2) * (1 + stats::rnorm(1, 0, 0.1))
      n <- 20 + sample(-2:2, 1)
      ramp <- (1 - cos(pi * seq(0, 1, length.out = n))) / 2
      recs[[length(recs) + 1]] <- outer(ramp, amp * base) + matrix(stats::rnorm(n * 16, 0, 1), n, 16)
      meta[[length(meta) + 1]] <- data.frame(grasp = ty, subject = paste0("s", s), object = "o1", trial = r)
    }
    g <- grasps(recs, meta = do.call(rbind, meta))
    # labels A/B are not Feix names: keep them as given
    g
  })
}

test_that("the likelihood distance separates types of one shape and different amplitude; the residual cannot", {
  g <- amplitude_types()
  train <- g[g$meta$subject != "s4"]
  test <- g[g$meta$subject == "s4"]
  acc <- function(distance) {
    ms <- fit_grasp_models(train, seed = 1, ncomp = 1, mixture_components = 1, distance = distance)
    expect_identical(ms$distance, distance)
    cl <- classify(ms, test)
    mean(as.character(cl$predictions$predicted) == as.character(cl$predictions$truth))
  }
  # amplitudes 1 and 2 with a 10% spread are 5 sd apart: all 16 held-out
  # recordings right. (The residual is right here too: with 24 training
  # recordings a type's FPC is estimated with an error that the amplitude
  # gap turns into residual; see the next test for what the likelihood adds.)
  expect_gte(acc("likelihood"), 15 / 16)
})

test_that("the likelihood distance reads the scores: a recording in both types' span goes by its amplitude", {
  g <- amplitude_types()
  ms <- fit_grasp_models(g, seed = 1, ncomp = 1, mixture_components = 1, motion = "as_recorded")
  # a noiseless recording on the common shape at amplitude 2 (type B's) lies
  # in (nearly) both types' mean + FPC span: its residual is small under either
  # model, and its score is likely under B only
  a <- fitted_models(ms)[["A"]]
  shape <- vapply(a$fpca, function(f) f$mean, numeric(a$target_length))
  one <- grasps(list(2 * shape), meta = data.frame(grasp = "B", subject = "new"))
  d <- predict(ms, one, type = "distance")
  expect_lt(d$.dist_B, d$.dist_A)
  res <- predict(fit_grasp_models(g, seed = 1, ncomp = 1, mixture_components = 1, motion = "as_recorded",
                                  distance = "residual"), one, type = "distance")
  # the residual difference is small against the likelihood's
  expect_lt(abs(res$.dist_A - res$.dist_B), abs(d$.dist_A - d$.dist_B))
})

test_that("the likelihood distance is minus twice the log density of the residual by DoF and of the joint scores", {
  g <- amplitude_types(subjects = 2, trials = 6)
  ms <- fit_grasp_models(g, seed = 1, ncomp = 1, mixture_components = 1)
  d <- predict(ms, g, type = "distance")
  # by hand, for model A: project, then the scaled chi-square of each DoF's
  # residual (its moments pooled over A and B, weighted by their recordings
  # less one) and the Gaussian kernel density of the joint score vector
  m <- fitted_models(ms)[["A"]]
  pr <- project(m, g)
  ref <- numeric(length(g))
  for (j in seq_along(m$dofs)) {
    mom <- vapply(fitted_models(ms), function(mm) {
      ev <- mm$fpca[[j]]$eigenvalues[-1]
      ev <- ev[ev > 0]
      (mm$n_used - 1) * c(sum(ev), sum(ev^2), 1)
    }, numeric(3))
    s <- rowSums(mom)
    a <- s[2] / s[1]
    nu <- s[1]^2 / s[2] / s[3]
    ref <- ref + pr$residual[, j]^2 / a + nu * log(2 * pi * a)
  }
  X <- vapply(m$fpca, function(f) f$scores[, 1], numeric(m$n_used))   # training scores, n x 16
  S <- pr$scores[, , 1]
  kd <- kernel_density(X)
  K <- kd$bandwidth^2 * kd$cor * tcrossprod(apply(X, 2, stats::sd))
  Ki <- solve(K)
  logdet <- determinant(K)$modulus[[1]]
  dens <- apply(S, 1, function(s) {
    q <- apply(X, 1, function(xi) sum((s - xi) * (Ki %*% (s - xi))))
    mean(exp(-q / 2 - logdet / 2 - ncol(X) / 2 * log(2 * pi)))
  })
  ref <- ref - 2 * log(dens)
  expect_equal(unname(d$.dist_A), unname(ref), tolerance = 1e-8)
})

# Two types whose every DoF is alike, told apart only by how the DoFs go
# together: each recording ramps to amplitude u on DoFs 1-8 and v on 9-16,
# (u, v) one of (1, 1), (2, 2) for type A (two objects) and one of (1, 2),
# (2, 1) for type B. Each DoF's scores have the same two clusters in both
# types, so a density DoF by DoF cannot tell them apart; the joint one can.
coupled_types <- function(subjects = 4, trials = 8, seed = 1) {
  withr::with_seed(seed, {
    base <- stats::runif(16, 20, 60)
    recs <- list()
    meta <- list()
    for (s in seq_len(subjects)) for (ty in c("A", "B")) for (r in seq_len(trials)) {
      u <- 1 + r %% 2
      v <- if (ty == "A") u else 3 - u
      amp <- c(rep(u, 8), rep(v, 8)) * (1 + stats::rnorm(16, 0, 0.05))
      n <- 20 + sample(-2:2, 1)
      ramp <- (1 - cos(pi * seq(0, 1, length.out = n))) / 2
      recs[[length(recs) + 1]] <- outer(ramp, amp * base) + matrix(stats::rnorm(n * 16, 0, 1), n, 16)
      meta[[length(meta) + 1]] <- data.frame(grasp = ty, subject = paste0("s", s), object = "o1", trial = r)
    }
    grasps(recs, meta = do.call(rbind, meta))
  })
}

test_that("the joint score density tells apart types that differ only in how their DoFs go together", {
  g <- coupled_types()
  train <- g[g$meta$subject != "s4"]
  test <- g[g$meta$subject == "s4"]
  acc <- function(ms) {
    cl <- classify(ms, test)
    mean(as.character(cl$predictions$predicted) == as.character(cl$predictions$truth))
  }
  ms <- fit_grasp_models(train, seed = 1, ncomp = 1, mixture_components = 2)
  # 16 held-out recordings, 4 per (type, object): all right
  expect_gte(acc(ms), 15 / 16)
  # the same models scored DoF by DoF (each DoF's own two-cluster mixture,
  # the former score term) are near chance: the marginals are the same
  m <- fitted_models(ms)
  pr <- lapply(m, function(mm) project(mm, test))
  per_dof <- vapply(names(m), function(t) {
    -2 * rowSums(vapply(seq_along(m[[t]]$dofs), function(j) {
      mix <- m[[t]]$gmm[[j]]
      gmm_log_density(mix$weights, mix$means, mix$covs, matrix(pr[[t]]$scores[, j, ], ncol = 1))
    }, numeric(length(test))))
  }, numeric(length(test)))
  expect_lt(mean(colnames(per_dof)[max.col(-per_dof)] == test$meta$grasp), 0.8)
})

test_that("the likelihood distance ignores a gain and an offset of each channel common to all recordings", {
  g <- coupled_types(subjects = 3, trials = 6)
  set.seed(9)
  gain <- stats::runif(16, 0.3, 4) * sample(c(-1, 1), 16, TRUE)   # counts that fall as a finger bends, too
  offset <- stats::runif(16, -300, 300)
  moved <- g
  moved$recordings <- lapply(g$recordings, function(r) sweep(sweep(r, 2, gain, "*"), 2, offset, "+"))
  # linear warping, as for recordings trimmed to their motion (real gloves'):
  # the DTW's own choice of warps depends on the channels' units
  dist <- function(x) {
    ms <- fit_grasp_models(x, seed = 1, ncomp = 1, mixture_components = 1, warping = "linear")
    as.matrix(as.data.frame(predict(ms, x, type = "distance")))
  }
  d0 <- dist(g)
  d1 <- dist(moved)
  # every distance moves by the same constant (the log of the gains), so
  # the ranking is the same: differences between types are unchanged
  expect_equal(d1[, 1] - d1[, 2], d0[, 1] - d0[, 2], tolerance = 1e-6)
  expect_equal(max.col(-d1), max.col(-d0))
})

test_that("a type of fewer than three recordings keeps the DoF-by-DoF score mixtures", {
  g <- amplitude_types(subjects = 1, trials = 2)
  expect_warning(ms <- fit_grasp_models(g, seed = 1, ncomp = 1, mixture_components = 1),
                 class = "handmotion_warning_few_recordings")
  m <- fitted_models(ms)[["A"]]
  expect_null(likelihood_score_kernel(m))
  pr <- project(m, g)
  ref <- numeric(length(g))
  for (j in seq_along(m$dofs)) {
    f <- m$fpca[[j]]
    if (isTRUE(f$constant)) next
    ev <- f$eigenvalues[-1]
    ev <- ev[is.finite(ev) & ev > 0]
    a <- max(if (length(ev)) sum(ev^2) / sum(ev) else 0, 1e-8 * max(f$eigenvalues, 1))
    nu <- if (length(ev)) max(sum(ev)^2 / sum(ev^2), 1) else 1
    mix <- m$gmm[[j]]
    ref <- ref + pr$residual[, j]^2 / a + nu * log(2 * pi * a) -
      2 * gmm_log_density(mix$weights, mix$means, mix$covs, matrix(pr$scores[, j, ], ncol = 1))
  }
  expect_equal(unname(predict(ms, g, type = "distance")$.dist_A), unname(ref), tolerance = 1e-8)
})

test_that("distance is checked, kept by subsetting, and printed", {
  g <- amplitude_types(subjects = 2, trials = 4)
  expect_error(fit_grasp_models(g, seed = 1, ncomp = 1, distance = "residuals"), class = "handmotion_error_bad_input")
  ms <- fit_grasp_models(g, seed = 1, ncomp = 1, mixture_components = 1, distance = "residual")
  expect_identical(ms[c("A", "B")]$distance, "residual")
  expect_output(print(classify(ms, g)), "projection distance")
  ml <- fit_grasp_models(g, seed = 1, ncomp = 1, mixture_components = 1)
  expect_output(print(classify(ml, g)), "likelihood distance")
  # a set built without the choice is ranked by the residual
  bare <- new_grasp_models(ms$models)
  expect_equal(predict(bare, g, type = "distance"), predict(ms, g, type = "distance"))
  expect_error(new_grasp_models(ms$models, distance = "residuals"))
})

# Type A's recordings are tidy (one shape, small noise); type B's have
# another shape and loose, smooth detours of their own, so B's FPCs leave a
# large residual on its own recordings. A new participant's A recordings
# carry a small detour of their own that no FPC of A spans: under each
# type's own residual scale B's loose scale makes their residual cheap and
# B takes them; under the set's pooled scale they go to A, whose shape
# fits them.
loose_types <- function(n_a = 16, n_b = 16, n_new = 16, seed = 1) {
  withr::with_seed(seed, {
    p <- 4
    base <- stats::runif(p, 20, 60)
    curve <- function(ty, detour) {
      n <- 30
      s <- seq(0, 1, length.out = n)
      shape <- if (ty == "A") (1 - cos(pi * s)) / 2 else sqrt(s)
      bump <- vapply(seq_len(p), function(j) detour * stats::rnorm(1) * sin(pi * stats::runif(1, 1, 4) * s), numeric(n))
      outer(shape, base * (1 + stats::rnorm(p, 0, 0.05))) + bump * rep(base, each = n) +
        matrix(stats::rnorm(n * p, 0, 0.2), n, p)
    }
    recs <- c(lapply(seq_len(n_a), function(i) curve("A", 0.01)), lapply(seq_len(n_b), function(i) curve("B", 0.3)),
              lapply(seq_len(n_new), function(i) curve("A", 0.08)))
    grasps(recs, meta = data.frame(grasp = rep(c("A", "B", "A"), c(n_a, n_b, n_new)),
                                   subject = rep(c("s1", "s1", "new"), c(n_a, n_b, n_new))))
  })
}

test_that("the residual scale is pooled over types: a loose type does not take what another type's FPCs fit", {
  g <- loose_types()
  train <- g[g$meta$subject == "s1"]
  test <- g[g$meta$subject == "new"]
  ms <- fit_grasp_models(train, seed = 1, ncomp = 1, mixture_components = 1, motion = "as_recorded",
                         warping = "linear")
  m <- fitted_models(ms)
  # the pooled moments: each DoF's discarded eigenvalues' sum and sum of
  # squares, averaged over A and B weighted by their recordings less one
  own <- lapply(m, function(mm) vapply(mm$fpca, function(f) {
    ev <- f$eigenvalues[-1]
    ev <- ev[ev > 0]
    c(sum(ev), sum(ev^2))
  }, numeric(2)))
  w <- vapply(m, function(mm) mm$n_used - 1, numeric(1))
  pooled <- (own$A * w[["A"]] + own$B * w[["B"]]) / sum(w)
  for (mm in m) {
    expect_equal(mm$likelihood_residual$s1, unname(pooled[1, ]), tolerance = 1e-10)
    expect_equal(mm$likelihood_residual$s2, unname(pooled[2, ]), tolerance = 1e-10)
  }
  # B's own residual is far larger than A's (the plant)
  expect_gt(min(own$B[1, ] / own$A[1, ]), 10)
  right <- function(set) mean(as.character(predict(set, test)$.pred_class) == "A")
  # pooled: the 16 new recordings go to A (at most one lost)
  expect_gte(right(ms), 15 / 16)
  # each type's own scale (the models without the pooled moments): B takes most
  unpooled <- ms
  for (t in names(m)) unpooled[[t]]$likelihood_residual <- NULL
  expect_lte(right(unpooled), 0.5)
})

test_that("the compiled score kernel gives the R expression's log densities to the bit, NA for a row with NaN", {
  g <- simulate_grasps(subjects = 3, grasps = c(17, 25), objects = 2, trials = 2, seed = 3)
  ms <- fit_grasp_models(g, seed = 1)
  for (m in fitted_models(ms)) {
    kern <- likelihood_score_kernel(m)
    expect_false(is.null(kern))
    sc <- project(m, g)$scores
    expect_identical(score_kernel_log_density(kern, sc), score_kernel_log_density_reference(kern, sc))
    # a far-off recording (every term underflows but the nearest) and a NaN
    sc[1, , ] <- sc[1, , ] * 50
    sc[2, 1, 1] <- NaN
    got <- score_kernel_log_density(kern, sc)
    expect_identical(got[-2], score_kernel_log_density_reference(kern, sc)[-2])
    expect_true(is.finite(got[1]))
    expect_true(is.na(got[2]))
  }
})
