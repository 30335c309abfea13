# Tests of the HUST-like simulator. Statistical tests plant a truth through
# the parameters (e.g. only subject factors, no noise) and check its recovery.

# Over-long fence used by the pipeline (also R/align-overlong.R); inline so this file
# does not depend on it.
fence <- function(n) max(stats::quantile(n, 0.75) + 3 * stats::IQR(n), 1.5 * stats::median(n))

# Parameters with every source of variation switched off except those given.
quiet_params <- function(...) {
  p <- simulator_params(subject_dof_sd = 0, subject_type_sd = 0, trial_posture_sd = 0, rest_sd = 0,
                        noise_sd = 0, drift_sd = 0, dip_sd = 0, aperture_sd = 0,
                        loadings = simulator_params()$loadings * 0,
                        object_response = simulator_params()$object_response * 0)
  # the calibration knobs back to 1: these tests are about the model as built
  # from the taxonomy (test-calibration.R covers the knobs)
  p$posture_spread[] <- 1
  p$factor_scale[] <- 1
  p$grasp_variability[] <- 1
  over <- list(...)
  p[names(over)] <- over
  p
}

last_frames <- function(g) t(vapply(recordings(g), function(r) r[nrow(r), ], numeric(16)))

test_that("the default design has the HUST shape and Table 5.1 frame counts", {
  g <- simulate_grasps()
  m <- g$meta
  expect_s3_class(g, "grasps")
  expect_equal(length(g), 8910L)
  expect_identical(g$dofs, hust_dofs$name)
  expect_equal(g$rate, 50)
  expect_equal(g$unit, "deg")
  expect_true(all(vapply(recordings(g), function(r) identical(colnames(r), hust_dofs$name), logical(1))))
  expect_equal(nlevels(droplevels(m$grasp)), 33L)
  expect_equal(sort(unique(m$subject)), sprintf("S%02d", 1:30))
  expect_equal(sort(unique(m$object)), c("large", "medium", "small"))
  expect_equal(sort(unique(m$trial)), 1:3)
  expect_true(all(table(m$grasp) == 270L))
  expect_false(anyDuplicated(m$id) > 0)
  expect_true(all(m$source == "simulated"))
  expect_true(all(c("overlong", "stalled", "object_size") %in% names(m)))

  # mean frame count of the ordinary recordings is exactly the stored target
  ord <- m[!m$overlong, ]
  means <- tapply(ord$n_frames, ord$grasp, mean)
  targets <- simulator_params()$target_frames
  expect_identical(unname(as.numeric(means)), as.numeric(targets$frames))

  # about 10 planted over-long recordings per type, all caught by the fence, nothing else caught
  expect_true(all(tapply(m$overlong, m$grasp, sum) == 10L))
  caught <- unsplit(lapply(split(m$n_frames, m$grasp), function(n) n > fence(n)), m$grasp)
  expect_identical(caught, m$overlong)
  ratio <- m$n_frames[m$overlong] / ave(m$n_frames, m$grasp, FUN = stats::median)[m$overlong]
  expect_true(all(ratio >= 1.9 & ratio <= 3.1))

  # ordinary durations vary (~10-15% CV) but stay ordinary
  cv <- tapply(ord$n_frames, ord$grasp, function(n) stats::sd(n) / mean(n))
  expect_true(all(cv > 0.08 & cv < 0.17))

  # stalled recordings: 1-2 per type and object, ordinary length
  st <- table(m$grasp[m$stalled], m$object[m$stalled])
  expect_true(all(st >= 1 & st <= 2))
})

test_that("the targets match the thesis' Table 5.1 when the shared tables are present", {
  tab <- utils::read.csv(shared_file("thesis-tables", "table_5_1.csv"))
  expect_identical(as.integer(simulator_params()$target_frames$frames), as.integer(tab$target_frames))
})

test_that("a seed gives identical results; another seed different ones", {
  a <- simulate_grasps(subjects = 2, grasps = 1:3, objects = 2, trials = 2, seed = 7)
  b <- simulate_grasps(subjects = 2, grasps = 1:3, objects = 2, trials = 2, seed = 7)
  c <- simulate_grasps(subjects = 2, grasps = 1:3, objects = 2, trials = 2, seed = 8)
  expect_identical(a, b)
  expect_false(identical(recordings(a), recordings(c)))
})

test_that("the global RNG is neither used nor changed", {
  withr::local_seed(42)
  before <- .Random.seed
  kind <- RNGkind()
  a <- simulate_grasps(subjects = 2, grasps = 1:2, objects = 1, trials = 1)
  expect_identical(.Random.seed, before)
  expect_identical(RNGkind(), kind)
  set.seed(99)
  b <- simulate_grasps(subjects = 2, grasps = 1:2, objects = 1, trials = 1)
  expect_identical(a, b)
  # nor do non-default RNG kinds change the result
  withr::local_rng_version("3.5.0")
  c <- simulate_grasps(subjects = 2, grasps = 1:2, objects = 1, trials = 1)
  expect_identical(recordings(a), recordings(c))
})

test_that("a subset of types equals that part of the full set", {
  full <- simulate_grasps(subjects = 3, objects = 2, trials = 2, seed = 3)
  part <- simulate_grasps(subjects = 3, grasps = c("Light Tool", "Index Finger Extension"),
                          objects = 2, trials = 2, seed = 3)
  expect_identical(as.character(unique(part$meta$grasp)), c("Light Tool", "Index Finger Extension"))
  expect_identical(recordings(part), recordings(full)[part$meta$id])
  keep <- full$meta$id %in% part$meta$id
  expect_identical(part$meta, `rownames<-`(full$meta[match(part$meta$id, full$meta$id), ], NULL))
  expect_equal(sum(keep), 24L)
})

test_that("bad arguments fail with classed errors naming the argument", {
  arg_of <- function(expr) rlang::catch_cnd(expr, classes = "handmotion_error")$argument
  expect_error(simulate_grasps(grasps = "Banana Grip"), class = "handmotion_error_unknown_grasp")
  expect_equal(arg_of(simulate_grasps(grasps = c(1, 34))), "grasps")
  expect_error(simulate_grasps(grasps = c("Tripod", "Banana")), "Banana")
  expect_error(simulate_grasps(grasps = c(1, 1)), class = "handmotion_error_bad_input")
  expect_error(simulate_grasps(grasps = integer(0)), class = "handmotion_error_bad_input")
  for (arg in c("subjects", "objects", "trials")) {
    for (bad in list(0, -2, 2.5, NA, "3", c(1, 2), Inf)) {
      args <- stats::setNames(list(bad), arg)
      expect_error(do.call(simulate_grasps, args), class = "handmotion_error_bad_input")
      expect_equal(arg_of(do.call(simulate_grasps, args)), arg)
    }
  }
  for (bad in list(0, -50, NA, "50", 5)) {
    expect_error(simulate_grasps(grasps = 1, rate = bad), class = "handmotion_error_bad_input")
    expect_equal(arg_of(simulate_grasps(grasps = 1, rate = bad)), "rate")
  }
  expect_equal(arg_of(simulate_grasps(seed = "a")), "seed")
  expect_equal(arg_of(simulate_grasps(seed = 1.5)), "seed")
  expect_equal(arg_of(simulate_grasps(overlong = NA)), "overlong")
  expect_error(simulate_grasps(params = 1), class = "handmotion_error_bad_params")
  expect_error(simulate_grasps(params = list(0)), class = "handmotion_error_bad_params")
  expect_error(simulate_grasps(grasps = 1, params = list(noise_sd = -1)), class = "handmotion_error_bad_params")
  expect_error(simulate_grasps(grasps = 1, params = list(no_such_thing = 1)), class = "handmotion_error_bad_input")
  p <- simulator_params()
  p$postures <- p$postures[1:3, ]
  expect_error(simulate_grasps(params = p), class = "handmotion_error_bad_params")
  expect_equal(rlang::catch_cnd(simulate_grasps(params = p))$parameter, "postures")
  expect_error(simulator_params(no_such_thing = 1), class = "handmotion_error_bad_input")
  expect_error(simulator_params(noise_sd = -1), class = "handmotion_error_bad_params")
  expect_error(simulator_params(overlong_multiplier = c(3, 2)), class = "handmotion_error_bad_params")
})

test_that("params replaces the named simulator parameters and keeps the rest", {
  quiet <- simulate_grasps(subjects = 2, grasps = 3, objects = 1, trials = 1, seed = 3,
                           params = list(noise_sd = 0, drift_sd = 0))
  full <- simulate_grasps(subjects = 2, grasps = 3, objects = 1, trials = 1, seed = 3,
                          params = simulator_params(noise_sd = 0, drift_sd = 0))
  expect_identical(quiet, full)
  expect_false(identical(quiet$recordings, simulate_grasps(subjects = 2, grasps = 3, objects = 1,
                                                           trials = 1, seed = 3)$recordings))
})

test_that("DIP follows 2/3 of PIP", {
  g <- simulate_grasps(subjects = 4, grasps = c(2, 13, 24), objects = 1, trials = 2, seed = 2)
  x <- do.call(rbind, recordings(g))
  for (f in 2:5) {
    fit <- stats::lm(x[, paste0("DIP", f)] ~ x[, paste0("PIP", f)])
    expect_equal(unname(stats::coef(fit)[2]), 2 / 3, tolerance = 0.03)
  }
  # exact without noise
  q <- simulate_grasps(subjects = 2, grasps = 1, objects = 1, trials = 1, params = quiet_params())
  r <- recordings(q)[[1]]
  expect_equal(r[, "DIP3"], r[, "PIP3"] * 2 / 3)
})

test_that("subject factors move several DoFs together as the loadings say", {
  L <- simulator_params()$loadings
  p <- quiet_params(loadings = L, stall_per_object = c(0, 0))
  g <- simulate_grasps(subjects = 400, grasps = 3, objects = 1, trials = 1, params = p, seed = 11)
  lf <- last_frames(g)[, rownames(L)]
  truth <- L %*% t(L)
  # sampling error of a covariance from 400 subjects is about 7% of its scale
  expect_lt(max(abs(stats::cov(lf) - truth)), 0.15 * max(diag(truth)))
  # planted truth for one factor: its joints correlate perfectly
  p1 <- quiet_params(loadings = L[, "spread", drop = FALSE])
  lf1 <- last_frames(simulate_grasps(subjects = 50, grasps = 3, objects = 1, trials = 1, params = p1))
  expect_equal(stats::cor(lf1[, "MCP2"], lf1[, "MCP5"]), -1, tolerance = 1e-8)
  expect_equal(stats::cor(lf1[, "MCP3"], lf1[, "PIP4"]), -1, tolerance = 1e-8)
  # with the default (noisy) parameters the factors still correlate finger flexions
  d <- last_frames(simulate_grasps(subjects = 30, grasps = 3, objects = 1, trials = 3, seed = 4))
  expect_gt(stats::cor(d[, "PIP3"], d[, "PIP4"]), 0.3)
})

test_that("final postures distinguish grasp types", {
  p <- quiet_params()
  g <- simulate_grasps(subjects = 1, objects = 1, trials = 1, plant_overlong = FALSE, params = p)
  lf <- last_frames(g)
  rownames(lf) <- as.character(g$meta$grasp)
  ife <- lf["Index Finger Extension", ]
  expect_true(all(ife[c("MCP2", "PIP2")] < 15))
  expect_true(all(ife[c("MCP3", "PIP3", "MCP4", "PIP4")] > 45))
  expect_true(all(lf["Small Diameter", c("MCP3", "PIP3")] > lf["Large Diameter", c("MCP3", "PIP3")] + 20))
  hook <- lf["Fixed Hook", ]
  expect_gt(hook[["PIP3"]] - hook[["MCP3"]], 30)
  expect_gt(lf["Tripod", "ABD1"], lf["Adducted Thumb", "ABD1"] + 20)
  # similar types are close, distinct ones far apart
  dist <- as.matrix(stats::dist(lf))
  expect_lt(dist["Prismatic 4 Finger", "Prismatic 3 Finger"], dist["Prismatic 4 Finger", "Medium Wrap"] / 2)
  expect_lt(dist["Adducted Thumb", "Light Tool"], dist["Adducted Thumb", "Tripod"] / 2)
  # every type has a posture of its own
  expect_gt(min(dist[upper.tri(dist)]), 3)
})

test_that("the hand opens to a peak aperture before closing, with smooth profiles", {
  p <- quiet_params(stall_per_object = c(0, 0))
  g <- simulate_grasps(subjects = 2, grasps = c(3, 14), objects = 1, trials = 1, plant_overlong = FALSE, params = p)
  for (r in recordings(g)) {
    n <- nrow(r)
    k <- which.min(r[, "MCP3"])
    expect_true(k > 1 && k < n)
    expect_lt(r[k, "MCP3"], r[1, "MCP3"] - 5)
    expect_lt(r[k, "MCP3"], r[n, "MCP3"] - 5)
    expect_gt(max(r[, "ABD1"]), r[1, "ABD1"] + 5)
    # rest at the start and a final hold: first two and last two frames equal
    expect_lt(max(abs(r[1, ] - r[2, ])), 0.5)
    expect_equal(r[n, ], r[n - 1, ])
    # minimum-jerk profiles: no jumps larger than a fraction of the range
    expect_lt(max(abs(diff(r[, "PIP3"]))), 0.25 * diff(range(r[, "PIP3"])))
  }
})

test_that("larger objects open the hand wider and flex the holding fingers less", {
  g <- simulate_grasps(subjects = 10, grasps = 3, objects = 3, trials = 2, plant_overlong = FALSE, seed = 5)
  lf <- last_frames(g)
  m <- g$meta
  flex <- rowMeans(lf[, c("MCP3", "PIP3", "MCP4", "PIP4")])
  expect_gt(mean(flex[m$object == "small"]) - mean(flex[m$object == "large"]), 8)
  open <- vapply(recordings(g), function(r) min(r[, "MCP3"]), numeric(1))
  expect_gt(mean(open[m$object == "small"]), mean(open[m$object == "large"]))
  expect_true(all(diff(unique(m$object_size)) > 0))
})

test_that("over-long recordings can be switched off; other rates scale the durations", {
  g <- simulate_grasps(subjects = 6, grasps = 1:2, objects = 3, trials = 3, plant_overlong = FALSE)
  expect_false(any(g$meta$overlong))
  expect_equal(as.numeric(tapply(g$meta$n_frames, g$meta$grasp, mean)[1:2]), c(43, 41))
  h <- simulate_grasps(subjects = 6, grasps = 1:2, objects = 3, trials = 3, rate = 100)
  ord <- h$meta[!h$meta$overlong, ]
  expect_equal(h$rate, 100)
  expect_equal(as.numeric(tapply(ord$n_frames, ord$grasp, mean)[1:2]), c(86, 82))
})

test_that("stalled recordings hold still mid-motion within ordinary length", {
  p <- quiet_params(stall_per_object = c(2, 2))
  g <- simulate_grasps(subjects = 12, grasps = 11, objects = 1, trials = 2, plant_overlong = FALSE, params = p)
  expect_equal(sum(g$meta$stalled), 2L)
  for (r in recordings(g)[g$meta$stalled]) {
    still <- rle(rowSums(abs(diff(r))) < 1e-9)
    # the longest still run (other than the final hold) covers >= 20% of the recording
    runs <- still$lengths[still$values]
    expect_gte(max(runs), 0.2 * nrow(r))
    expect_true(r[nrow(r), "MCP3"] != r[1, "MCP3"])
  }
  # small designs: at most a tenth of an object's recordings stall
  one <- simulate_grasps(subjects = 1, grasps = 1:3, objects = 1, trials = 1)
  expect_false(any(one$meta$stalled))
  expect_true(all(g$meta$n_frames[g$meta$stalled] < fence(g$meta$n_frames)))
})
