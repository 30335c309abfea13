planted_model <- function(n = 80, p = 3, seed = 31, ...) {
  fit_grasp_model(planted_grasps(n = n, p = p, seed = seed, ...), warping = "linear", seed = 1)
}

# Scores that rebuild curves exactly: least squares on the model's components
# (independent of fpca_project's quadrature).
recover_alpha <- function(model, rec, j) {
  P <- matrix(model_basis(model)$components[, j, ], model$target_length)
  drop(qr.solve(P, rec[, j] - model_basis(model)$mean[, j]))
}

# CDF of the marginal of a Gaussian mixture along direction `a`.
mixture_cdf <- function(gm, a) {
  mu <- drop(gm$means %*% a)
  sdv <- vapply(seq_along(gm$weights), function(c) sqrt(drop(t(a) %*% gm$covs[, , c] %*% a)), 1)
  function(q) vapply(q, function(v) sum(gm$weights * stats::pnorm(v, mu, sdv)), 1)
}

gaussian_draws <- function(n, mu, S, seed) {
  with_seed(seed, matrix(stats::rnorm(n * length(mu)), n) %*% chol(S) + rep(mu, each = n))
}

test_that("generate returns a grasps set of the model's type, seeded and RNG-neutral", {
  m <- planted_model()
  set.seed(7)
  before <- .Random.seed
  new <- generate(m, n = 6, seed = 3)
  expect_identical(.Random.seed, before)
  expect_s3_class(new, "grasps")
  expect_length(new, 6)
  expect_identical(new$meta$id, paste0("gen", 1:6))
  expect_true(all(new$meta$grasp == "Tripod"))
  expect_true(all(is.na(new$meta$subject)))
  expect_true(all(new$meta$source == "generated"))
  expect_identical(new$dofs, m$dofs)
  expect_identical(new$rate, m$rate)
  expect_identical(generate(m, n = 6, seed = 3), new)
  expect_false(identical(generate(m, n = 6, seed = 4)$recordings, new$recordings))
  expect_identical(simulate(m, nsim = 6, seed = 3), new)
  expect_error(generate(m, n = 0), class = "handmotion_error_bad_input")
})

test_that("without the warp, curves are mean + FPCs times the attached scores", {
  m <- planted_model()
  new <- generate(m, n = 20, seed = 5, warp = FALSE)
  expect_true(all(new$meta$n_frames == m$target_length))
  sc <- attr(new, "scores")
  for (i in c(1, 7, 20)) for (j in 1:3) {
    expect_equal(recover_alpha(m, new$recordings[[i]], j), unname(sc[i, j, ]), tolerance = 1e-8)
  }
})

test_that("the warp is eq. 2.5's: length round(w(L)) and values at the inverted time", {
  m <- planted_model(len_sd = 6)
  flat <- generate(m, n = 30, seed = 9, warp = FALSE)
  warped <- generate(m, n = 30, seed = 9, warp = TRUE)
  L <- m$target_length
  for (i in 1:30) {
    beta <- warped$meta$warp_score[i]
    w <- warp_basis(m)$mean + beta * warp_basis(m)$components[, 1]
    w <- cummax(pmax(w, 1))
    w[1] <- 1
    n_new <- max(2L, as.integer(round(w[L])))
    expect_equal(warped$meta$n_frames[i], n_new)
    # the template time of each original frame, by approx() on the inverse
    s_of_t <- stats::approx(w, seq_len(L), xout = seq_len(n_new), rule = 2, ties = max)$y
    for (j in 1:3) {
      expect_equal(unname(warped$recordings[[i]][, j]),
                   stats::approx(seq_len(L), flat$recordings[[i]][, j], xout = s_of_t)$y,
                   tolerance = 1e-8)
    }
  }
  # lengths follow the training lengths (mean and spread within 15 %)
  big <- generate(m, n = 2000, seed = 1)
  expect_equal(mean(big$meta$n_frames), mean(m$alignment$n_frames), tolerance = 0.05)
  expect_equal(stats::sd(big$meta$n_frames), stats::sd(m$alignment$n_frames), tolerance = 0.15)
})

test_that("generated scores follow the fitted mixture (and a wrong sampler fails the test)", {
  m <- planted_model(n = 150, p = 2, sep = 10)
  new <- generate(m, n = 3000, seed = 11, warp = FALSE)
  dirs <- list(c(1, 0), c(0, 1), c(1, 1) / sqrt(2))
  for (j in 1:2) {
    alpha <- t(vapply(new$recordings, recover_alpha, numeric(2), model = m, j = j))
    gm <- m$gmm[[j]]
    expect_false(isTRUE(gm$fallback))
    for (a in dirs) {
      p <- suppressWarnings(stats::ks.test(drop(alpha %*% a), mixture_cdf(gm, a))$p.value)
      expect_gt(p, 1e-3)
    }
    # power check: a moment-matched single Gaussian is rejected by the same test
    wrong <- gaussian_draws(3000, colMeans(alpha), stats::cov(alpha), seed = 2)
    p_wrong <- suppressWarnings(stats::ks.test(wrong[, 1], mixture_cdf(gm, c(1, 0)))$p.value)
    expect_lt(p_wrong, 1e-3)
  }
})

test_that("a model set generates each requested type with n grasps", {
  a <- planted_grasps(n = 20, p = 2, grasp = "Ring", seed = 1)
  b <- planted_grasps(n = 20, p = 2, grasp = "Tripod", len = 60, seed = 2)
  g <- grasps(c(a$recordings, b$recordings),
              meta = data.frame(id = paste0("x", 1:40), grasp = c(a$meta$grasp, b$meta$grasp)),
              dofs = a$dofs)
  ms <- fit_grasp_models(g, warping = "linear", seed = 1)
  new <- generate(ms, n = 4, seed = 1)
  expect_length(new, 8)
  expect_identical(new$meta$id, paste0("gen", 1:8))
  expect_identical(as.character(new$meta$grasp), rep(c("Tripod", "Ring"), each = 4))
  expect_equal(dim(attr(new, "scores")), c(8L, 2L, 2L))
  one <- generate(ms, grasps = 31, n = 3, seed = 1)
  expect_true(all(one$meta$grasp == "Ring"))
  expect_identical(simulate(ms, nsim = 3, grasps = "Ring", seed = 1), one)
  expect_error(generate(ms, grasps = "Lateral"), class = "handmotion_error_bad_input")
  # a type without a model: the answer lists the types there are
  cnd <- expect_error(generate(ms, grasps = 17), class = "handmotion_error_unknown_grasp")
  expect_match(conditionMessage(cnd), "Index Finger Extension", fixed = TRUE)
  expect_match(conditionMessage(cnd), 'models for 2 types: "Tripod" and "Ring"', fixed = TRUE)
  expect_identical(cnd$argument, "grasps")
  expect_error(ms["Lateral"], '2 types: "Tripod" and "Ring"', class = "handmotion_error_unknown_grasp")
  # the Tripod type was planted about 60 frames long, the Ring type about 40
  expect_gt(mean(new$meta$n_frames[1:4]), mean(new$meta$n_frames[5:8]))
})

test_that("generated grasps from simulated data have the type's length and plausible angles", {
  g <- simulate_grasps(subjects = 5, grasps = 17, seed = 2)
  m <- fit_grasp_model(g, seed = 1)
  new <- generate(m, n = 200, seed = 1)
  expect_equal(mean(new$meta$n_frames), m$target_length, tolerance = 0.15)
  train <- do.call(rbind, g$recordings)
  gen <- do.call(rbind, new$recordings)
  span <- apply(train, 2, function(v) diff(range(v)))
  for (j in seq_along(g$dofs)) {
    expect_gte(min(gen[, j]), min(train[, j]) - 0.5 * span[j])
    expect_lte(max(gen[, j]), max(train[, j]) + 0.5 * span[j])
  }
  # the mean generated curve is close to the mean training curve (warped time)
  expect_lt(max(abs(colMeans(gen) - colMeans(train)) / span), 0.2)
})

# R's reference BLAS sums matrix products in the kernel's order, so there the
# two paths agree bit for bit; an optimised BLAS may reorder the sums.

expect_same_generation <- function(fast, ref) {
  expect_identical(fast$meta, ref$meta)
  expect_identical(attr(fast, "scores"), attr(ref, "scores"))
  expect_identical(names(fast$recordings), names(ref$recordings))
  expect_identical(lapply(fast$recordings, dimnames), lapply(ref$recordings, dimnames))
  # the same arithmetic in the same order; a compiler that fuses
  # multiply-adds may differ in the last bits, hence the tolerance
  expect_equal(fast$recordings, ref$recordings, tolerance = 1e-12)
}

test_that("the native kernel gives the R reference's grasps for the same seed", {
  m <- planted_model(len_sd = 6)
  for (warp in c(TRUE, FALSE)) {
    fast <- generate(m, n = 50, seed = 4, warp = warp)
    ref <- generate_reference(m, 50, 4, warp)
    expect_same_generation(fast, ref)
  }
  # three-component mixtures, three FPCs and two warp FPCs: every index of the
  # stacked sampler and of the warp basis is exercised
  # (linear warps vary by their duration only: two warp FPCs are one more than
  # their rank, and the warp mixture is one Gaussian -- said by a warning)
  m3 <- suppressWarnings(
    fit_grasp_model(planted_grasps(n = 60, p = 3, len_sd = 6, seed = 8), ncomp = 3, warp_ncomp = 2,
                    mixture_components = 3, warping = "linear", seed = 1),
    classes = "handmotion_warning_small_mixture")
  expect_equal(dim(m3$sampler$dofs$root), c(3L, 3L, 3L, 3L))
  fast <- generate(m3, n = 40, seed = 2)
  ref <- generate_reference(m3, 40, 2)
  expect_same_generation(fast, ref)
  # a single draw (R's matrix products take their vector branch there)
  expect_same_generation(generate(m3, n = 1, seed = 3),
                         generate_reference(m3, 1, 3))
  # the test can fail: another seed gives other grasps
  expect_false(identical(generate(m3, n = 40, seed = 5)$recordings, fast$recordings))
})

test_that("a model set's batch is the models' batches in turn, from one RNG stream", {
  a <- planted_grasps(n = 20, p = 2, grasp = "Ring", seed = 1)
  b <- planted_grasps(n = 20, p = 2, grasp = "Tripod", len = 60, seed = 2)
  g <- grasps(c(a$recordings, b$recordings),
              meta = data.frame(id = paste0("x", 1:40), grasp = c(a$meta$grasp, b$meta$grasp)),
              dofs = a$dofs)
  ms <- fit_grasp_models(g, warping = "linear", seed = 1)
  new <- generate(ms, n = 7, seed = 6)
  expect_same_generation(new, generate_reference(ms, 7, 6))
  # the same numbers as drawing model by model from the same stream
  parts <- with_seed(6, lapply(ms, draw_batch, n = 7L))
  expect_identical(unname(new$recordings), c(parts[[1]]$recordings, parts[[2]]$recordings))
  expect_identical(new$meta$n_frames, c(parts[[1]]$n_frames, parts[[2]]$n_frames))
  expect_identical(new$meta$n_frames, vapply(new$recordings, nrow, integer(1), USE.NAMES = FALSE))
  expect_identical(dimnames(attr(new, "scores"))[[1]], new$meta$id)
})

test_that("a model whose sampler was altered gets a classed error, not a crash", {
  m <- planted_model()
  bad <- m
  bad$sampler$dofs$k <- bad$sampler$dofs$k + 1L      # component count not matching its arrays
  expect_error(generate(bad, n = 3, seed = 1), class = "handmotion_error_bad_model")
  bad <- m
  bad$sampler$dofs$root <- bad$sampler$dofs$root[-1]
  expect_error(generate(bad, n = 3, seed = 1), class = "handmotion_error_bad_model")
  bad <- m
  bad$sampler$warp$mu <- "a"
  expect_error(generate(bad, n = 3, seed = 1), class = "handmotion_error_bad_model")
  bad <- m
  bad$fpca[[1]]$components <- bad$fpca[[1]]$components[, 1]
  expect_error(generate(bad, n = 3, seed = 1), class = "handmotion_error_bad_model")
  # the kernel checks on its own too (a sampler that bypasses the R check)
  smp <- m$sampler
  smp$dofs$k <- smp$dofs$k + 1L
  expect_error(.Call(hm_generate_batch, 3L, smp$dofs, smp$warp, model_basis(m)$mean, model_basis(m)$components,
                     as.numeric(warp_basis(m)$mean), matrix(as.numeric(warp_basis(m)$components), m$target_length),
                     TRUE, m$dofs, NULL, NULL, rep(NA_real_, length(m$dofs)), rep(NA_real_, length(m$dofs)), 0.05),
               "sampler cumw")
  # drawn scores and limits of the wrong size, or empty limits, are refused
  p <- length(m$dofs)
  nolim <- rep(NA_real_, p)
  expect_error(.Call(hm_generate_batch, 3L, m$sampler$dofs, m$sampler$warp, model_basis(m)$mean,
                     model_basis(m)$components, as.numeric(warp_basis(m)$mean),
                     matrix(as.numeric(warp_basis(m)$components), m$target_length), TRUE, m$dofs,
                     array(0, c(2, p, 2)), matrix(0, 3, 1), nolim, nolim, 0.05), "drawn FPC scores")
  expect_error(.Call(hm_generate_batch, 3L, m$sampler$dofs, m$sampler$warp, model_basis(m)$mean,
                     model_basis(m)$components, as.numeric(warp_basis(m)$mean),
                     matrix(as.numeric(warp_basis(m)$components), m$target_length), TRUE, m$dofs,
                     NULL, NULL, rep(1, p), rep(1, p), 0.05), "limits of DoF 1 are empty")
  expect_error(.Call(hm_generate_batch, 3L, m$sampler$dofs, m$sampler$warp, model_basis(m)$mean,
                     model_basis(m)$components, as.numeric(warp_basis(m)$mean),
                     matrix(as.numeric(warp_basis(m)$components), m$target_length), TRUE, m$dofs,
                     NULL, NULL, seq_len(p + 1), nolim, 0.05), "lower limits")
  # a warp far outside the data asks for more frames than one draw may have
  huge <- m
  huge$warp$fpca$mean <- huge$warp$fpca$mean * 1e6
  expect_error(generate(huge, n = 1, seed = 1), "at most 100000")
})

test_that("generate() refuses a model whose mixtures or FPC count were edited after fitting, as predict() does", {
  m <- planted_model()
  # a mixture edited after fitting: the stored sampler would draw the old one
  moved <- m
  moved$gmm[[1]]$means[1, 1] <- moved$gmm[[1]]$means[1, 1] + 5
  expect_error(generate(moved, n = 2, seed = 1), "gmm.*no longer match", class = "handmotion_error_bad_model")
  wide <- m
  wide$gmm[[2]]$covs[, , 1] <- 4 * wide$gmm[[2]]$covs[, , 1]
  expect_error(generate(wide, n = 2, seed = 1), "gmm", class = "handmotion_error_bad_model")
  warp <- m
  warp$warp$gmm$means[1, 1] <- warp$warp$gmm$means[1, 1] + 5
  expect_error(generate(warp, n = 2, seed = 1), "warp mixture", class = "handmotion_error_bad_model")
  # the FPC count its settings state, which project() and predict() check
  fewer <- m
  fewer$settings$ncomp <- 1L
  expect_error(generate(fewer, n = 2, seed = 1), "settings", class = "handmotion_error_bad_model")
  expect_error(project(fewer, planted_grasps(n = 3, p = 3, seed = 2)), class = "handmotion_error_bad_model")
  # the fitted model itself, and its sampler rebuilt from the same parts, generate
  expect_length(generate(m, n = 2, seed = 1), 2L)
  rebuilt <- m
  rebuilt$sampler <- build_sampler(m)
  expect_identical(generate(rebuilt, n = 2, seed = 1), generate(m, n = 2, seed = 1))
})

test_that("generate() refuses bad counts, flags and seeds with classed errors", {
  m <- planted_model()
  expect_error(generate(m, n = 1e10), class = "handmotion_error_bad_input")
  expect_error(generate(m, n = 2.5), class = "handmotion_error_bad_input")
  expect_error(generate(m, n = 2, seed = c(1, 2)), class = "handmotion_error_bad_input")
  expect_error(generate(m, n = 2, seed = "a"), class = "handmotion_error_bad_input")
  expect_error(generate(m, n = 2, warp = NA), class = "handmotion_error_bad_input")
})

test_that("generation streams in chunks through a callback, holding one chunk at a time", {
  m <- planted_model()
  seen <- list()
  res <- generate(m, n = 25, seed = 3, chunk = 10, callback = function(chunk, i) {
    seen[[i]] <<- list(n = length(chunk), ids = chunk$meta$id, class = class(chunk))
    "ignored"
  })
  expect_equal(res$n, 25)
  expect_identical(res$chunks, 3L)
  expect_identical(vapply(seen, `[[`, integer(1), "n"), c(10L, 10L, 5L))
  expect_identical(unlist(lapply(seen, `[[`, "ids")), paste0("gen", 1:25))   # ids run on
  expect_identical(seen[[1]]$class, "grasps")
  # the same seed gives the same chunks; the chunks are drawn one after another
  again <- list()
  generate(m, n = 25, seed = 3, chunk = 10, callback = function(chunk, i) again[[i]] <<- chunk)
  first <- generate(m, n = 10, seed = 3)
  expect_equal(again[[1]]$recordings, first$recordings)
  # a model set: chunk grasps per type
  ms <- fit_grasp_models(grasps(unname(c(planted_grasps(n = 20, p = 2, grasp = "Ring", seed = 1)$recordings,
                                         planted_grasps(n = 20, p = 2, grasp = "Tripod", seed = 2)$recordings)),
                                meta = data.frame(grasp = rep(c("Ring", "Tripod"), each = 20)),
                                dofs = c("d1", "d2")), warping = "linear", seed = 1)
  sizes <- integer()
  generate(ms, n = 7, chunk = 3, seed = 1, callback = function(chunk, i) sizes[i] <<- length(chunk))
  expect_identical(sizes, c(6L, 6L, 2L))
  expect_error(generate(m, n = 5, callback = "f"), class = "handmotion_error_bad_input")
  expect_error(generate(m, n = 5, chunk = 0, callback = identity), class = "handmotion_error_bad_input")
})
