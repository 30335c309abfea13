# The simulator's calibration (data-raw/calibrate-simulator.R) against the
# thesis' chapter-5 figures. The full check runs the whole default pipeline
# and takes minutes, so it runs only with HANDMOTION_SLOW_TESTS=true; the
# always-on checks use types whose figures do not depend on the other types
# (per-type fits and last-frame PCAs on the full 30-subject design).

quiet_knob_params <- function(...) {
  simulator_params(subject_dof_sd = 0, subject_type_sd = 0, trial_posture_sd = 0, rest_sd = 0,
                   noise_sd = 0, drift_sd = 0, dip_sd = 0, aperture_sd = 0,
                   object_response = simulator_params()$object_response * 0, ...)
}
per_type <- function(value) stats::setNames(rep(value, 33), feix_taxonomy$name)
last_frames_of <- function(g) t(vapply(recordings(g), function(r) r[nrow(r), ], numeric(16)))

test_that("posture_spread pulls the final postures towards their mean", {
  p1 <- quiet_knob_params(loadings = simulator_params()$loadings * 0, posture_spread = per_type(1))
  p0 <- p1
  p0$posture_spread[] <- 0
  ph <- p1
  ph$posture_spread[] <- 0.5
  sim <- function(p) last_frames_of(simulate_grasps(subjects = 1, grasps = c(3, 14, 22), objects = 1,
                                                    trials = 1, plant_overlong = FALSE, params = p))
  lf1 <- sim(p1); lf0 <- sim(p0); lfh <- sim(ph)
  # spread 0: every type ends in the same posture (the mean of all 33)
  expect_lt(max(abs(sweep(lf0, 2, lf0[1, ]))), 1e-9)
  centre <- colMeans(p1$postures)
  expect_equal(unname(lf0[1, names(centre)]), unname(centre))
  # spread 1/2: half-way between the mean and the taxonomy posture
  expect_equal(lfh[, names(centre)], (lf1[, names(centre)] + lf0[, names(centre)]) / 2)
})

test_that("factor_scale multiplies the subject factors of one type only", {
  L <- simulator_params()$loadings
  p <- quiet_knob_params(loadings = L, factor_scale = per_type(1), posture_spread = per_type(1),
                         grasp_variability = 1)
  p$factor_scale[3] <- 2
  g <- simulate_grasps(subjects = 20, grasps = c(3, 14), objects = 1, trials = 1, plant_overlong = FALSE,
                       params = p, seed = 3)
  lf <- last_frames_of(g)[, rownames(L)]
  is3 <- g$meta$grasp == "Medium Wrap"
  dev3 <- sweep(lf[is3, ], 2, p$postures[3, ])
  dev14 <- sweep(lf[!is3, ], 2, p$postures[14, ])
  # the same subjects' factors, twice as large in type 3
  expect_equal(unname(dev3), unname(2 * dev14), tolerance = 1e-8)
})

test_that("grasp_variability scales one type's variation of the final posture, not of the rest", {
  L <- simulator_params()$loadings
  sim <- function(v3, glove_sd, grasp_sd) {
    p <- quiet_knob_params(loadings = L * (grasp_sd > 0), factor_scale = per_type(1),
                           posture_spread = per_type(1), grasp_variability = 1,
                           subject_dof_sd = glove_sd, subject_type_sd = grasp_sd)
    p$grasp_variability[3] <- v3
    simulate_grasps(subjects = 20, grasps = c(3, 14), objects = 1, trials = 1, plant_overlong = FALSE,
                    params = p, seed = 3)
  }
  postures <- simulator_params()$postures
  dev <- function(g, type, id) {
    lf <- last_frames_of(g)[g$meta$grasp == type, rownames(L)]
    sweep(lf, 2, postures[id, ])
  }
  # the subjects' hands and styles: the same draws, half the deviation from
  # the type's posture in type 3 only
  half <- sim(0.5, 0, 3.5)
  full <- sim(1, 0, 3.5)
  expect_gt(stats::sd(dev(full, "Medium Wrap", 3)), 2)
  expect_equal(unname(dev(half, "Medium Wrap", 3)), unname(0.5 * dev(full, "Medium Wrap", 3)), tolerance = 1e-8)
  expect_equal(dev(half, "Tripod", 14), dev(full, "Tripod", 14))
  # the subject's own per-DoF offsets are scaled in the grasp too, not at rest
  own_half <- sim(0.5, 2.5, 0)
  own_full <- sim(1, 2.5, 0)
  expect_equal(unname(dev(own_half, "Medium Wrap", 3)), unname(0.5 * dev(own_full, "Medium Wrap", 3)),
               tolerance = 1e-8)
  first <- function(g) t(vapply(recordings(g), function(r) r[1, ], numeric(16)))
  expect_equal(first(own_half), first(own_full))
  expect_error(simulator_params(grasp_variability = c(1, 2)), class = "handmotion_error_bad_params")
})

test_that("aperture_variability scales how much the opening varies, not how wide it is on average", {
  open_depth <- function(v) {
    p <- quiet_knob_params(loadings = simulator_params()$loadings * 0, subject_dof_sd = 0,
                           posture_spread = per_type(1), preshape = per_type(0), aperture_sd = 0.3,
                           onset_jitter = 0, stall_per_object = c(0, 0), peak_time_sd = 0,
                           aperture_variability = v)
    g <- simulate_grasps(subjects = 10, grasps = 3, objects = 3, trials = 2, plant_overlong = FALSE,
                         params = p, seed = 2)
    # how far the index MCP opens below its rest angle
    vapply(recordings(g), function(r) r[1, "MCP2"] - min(r[, "MCP2"]), numeric(1))
  }
  d1 <- open_depth(1)
  dh <- open_depth(0.5)
  # the same draws: log depth varies half as much, around the same typical opening
  expect_equal(stats::sd(log(dh)) / stats::sd(log(d1)), 0.5, tolerance = 0.1)
  expect_equal(stats::median(dh), stats::median(d1), tolerance = 0.1)
})

test_that("preshape moves the peak aperture towards the type's final posture, not the end", {
  sim <- function(share) {
    p <- quiet_knob_params(loadings = simulator_params()$loadings * 0, posture_spread = per_type(1),
                           preshape = share, onset_jitter = 0, stall_per_object = c(0, 0),
                           peak_time_sd = 0)
    recordings(simulate_grasps(subjects = 1, grasps = 24, objects = 1, trials = 1, plant_overlong = FALSE,
                               params = p))[[1]]
  }
  r0 <- sim(0); r1 <- sim(0.5)
  p <- simulator_params()
  lean <- 0.5 * (p$postures[24, ] - colMeans(p$postures))
  n <- nrow(r0)
  expect_equal(r1[n, ], r0[n, ])                      # same final posture
  expect_equal(r1[1, ], r0[1, ])                      # same rest
  # in mid-motion the difference points along the type's lean
  mid <- r1[, names(lean)] - r0[, names(lean)]
  k <- which.max(rowSums(mid^2))
  expect_gt(stats::cor(mid[k, ], lean), 0.99)
  expect_error(simulator_params(preshape = 2), class = "handmotion_error_bad_params")
})

test_that("the hand is widest at the type's peak_time: earlier in precision grasps than in power grasps", {
  p <- quiet_knob_params(loadings = simulator_params()$loadings * 0, posture_spread = per_type(1),
                         preshape = per_type(0), onset_jitter = 0, stall_per_object = c(0, 0),
                         peak_time_sd = 0, lead_frames = c(2, 2), hold_frames = c(4, 4))
  expect_equal(unname(p$peak_time[c("Large Diameter", "Lateral", "Tip Pinch")]), c(0.55, 0.45, 0.35))
  g <- simulate_grasps(subjects = 1, grasps = c(1, 16, 24), objects = 1, trials = 1, plant_overlong = FALSE,
                       params = p)
  widest <- vapply(recordings(g), function(r) {
    motion <- nrow(r) - 4 - 3                     # frames 3 .. n - 4 move
    (which.min(r[, "MCP2"]) - 3) / motion          # the index finger opens widest
  }, numeric(1))
  # to within one frame of the motion (about 1/35)
  expect_lt(max(abs(widest - c(0.55, 0.45, 0.35))), 1 / 30)
  expect_error(simulator_params(peak_time_sd = -1), class = "handmotion_error_bad_params")
})

test_that("preshape acts on its own type only; one number applies to every type", {
  base <- quiet_knob_params(posture_spread = per_type(1), preshape = per_type(0), onset_jitter = 0,
                            stall_per_object = c(0, 0), peak_time_sd = 0)
  sim <- function(p) simulate_grasps(subjects = 8, grasps = c(3, 24), objects = 1, trials = 1,
                                     plant_overlong = FALSE, params = p, seed = 4)
  g0 <- sim(base)
  p <- base
  p$preshape[24] <- 0.5
  g1 <- sim(p)
  is24 <- g0$meta$grasp == "Tip Pinch"
  # type 3 is untouched, recording for recording; type 24's reach changes
  # but not its final posture
  expect_equal(recordings(g1)[!is24], recordings(g0)[!is24])
  expect_false(isTRUE(all.equal(recordings(g1)[is24], recordings(g0)[is24])))
  expect_equal(last_frames_of(g1[is24]), last_frames_of(g0[is24]))
  expect_equal(unname(simulator_params(preshape = 0.2)$preshape), rep(0.2, 33))
})

test_that("jitter_scale sets the unexplained timing variation of a type", {
  fit_var <- function(scale) {
    p <- simulator_params(jitter_scale = per_type(scale))
    g <- simulate_grasps(subjects = 6, grasps = 3, objects = 2, trials = 2, params = p, seed = 2)
    mean(summary(fit_grasp_models(g, seed = 1))$mean_var)
  }
  # no jitter: the FPCs explain more; much jitter: less
  expect_gt(fit_var(0), fit_var(3) + 1)
})

test_that("calibration_report() recomputes every target and lays the thesis beside", {
  skip_without_calibration_report()
  g <- simulate_grasps(subjects = 3, grasps = c(9, 22), objects = 2, trials = 2, seed = 1)
  rep <- calibration_report(g)
  expect_s3_class(rep, "calibration_report")
  expect_equal(rep$types$grasp_id, c(9L, 22L))
  expect_equal(nrow(rep$targets), 6L)
  expect_type(rep$targets$ok, "logical")
  th <- thesis_results
  expect_equal(rep$types$thesis_pc5, th$table_5_7$pc5[c(9, 22)])
  expect_equal(rep$types$thesis_mean_var, th$table_5_2$mean[c(9, 22)])
  # ours are computed from the fits, not copied
  expect_equal(rep$types$target_frames, as.integer(simulator_params()$target_frames$frames[c(9, 22)]))
  expect_true(all(rep$types$recall_last_frame >= 0 & rep$types$recall_last_frame <= 1))
  expect_equal(rep$targets$ours[5], mean(c(rep$types$recall_last_frame)), tolerance = 0.2)
  expect_output(print(rep), "targets within tolerance")
  # the structure figures sit beside the thesis' Table 5.3 claims
  st <- rep$structure
  expect_equal(nrow(st), 7L)
  expect_equal(st$thesis[4:7], th$table_5_3_claims$thesis[1:4])
  expect_type(st$ok, "logical")
  expect_output(print(rep), "Structure")
  expect_error(calibration_report(g, seeds = 1:2), class = "handmotion_error_bad_input")
  expect_error(calibration_report(seeds = c(1, 1)), class = "handmotion_error_bad_input")
  expect_error(calibration_report(g, models = "no"), class = "handmotion_error_bad_input")
  expect_error(calibration_report(g, last_frame = 1), class = "handmotion_error_bad_input")
})

test_that("confusion groups are found among the largest off-diagonal cells", {
  skip_without_calibration_report()
  types <- feix_levels()
  conf <- matrix(0L, 33, 33, dimnames = list(types, types))
  diag(conf) <- 100L
  # plant: adducted thumb -> fixed hook (group 1) is the largest confusion,
  # tripod -> precision sphere (group 3) the 11th largest
  big <- cbind(c(4, 1, 2, 3, 9, 10, 11, 16, 17, 18, 14), c(15, 2, 3, 1, 10, 11, 9, 17, 18, 16, 13))
  conf[big] <- c(50L, 40:32, 20L)
  expect_equal(confusion_groups_found(conf), 1L)
  conf[14, 13] <- 45L
  expect_equal(confusion_groups_found(conf), 2L)
  expect_equal(confusion_groups_found(conf, top = 1L), 1L)
  expect_equal(unname(confusion_groups_hit(conf)), c(TRUE, FALSE, TRUE))
})

test_that("the thesis' own Table 5.6 is laid out as ours and measured by the same rule", {
  skip_without_calibration_report()
  th <- thesis_confusion_fpca()
  d <- thesis_results$table_5_6_diagonal
  # rows are true types: the diagonal and the lower-bound column totals of
  # the recovered table come back
  expect_equal(unname(diag(th)), d$correct)
  expect_equal(unname(rowSums(th)), d$total)
  # its largest confusion is tip pinch classified as palmar pinch (113)
  off <- th
  diag(off) <- 0
  k <- which(off == max(off), arr.ind = TRUE)
  expect_equal(unname(c(k[1, ], max(off))), c(24, 9, 113))
  # of the three hard-to-discern groups only the first (adducted thumb ->
  # fixed hook, 82) is among its ten largest off-diagonal cells
  expect_equal(unname(confusion_groups_hit(th)), c(TRUE, FALSE, FALSE))
  rep <- calibration_report(simulate_grasps(subjects = 3, grasps = c(9, 22), objects = 2, trials = 2))
  expect_equal(rep$structure$thesis[3], 1)
})

test_that("reports over seeds give the mean, the spread and the worst seed", {
  skip_without_calibration_report()
  mk <- function(acc, worst_pc5) {
    targets <- data.frame(target = c("a", "b"), ours = c(acc, 0.8), thesis = c(0.64, 0.8),
                          tolerance = c(0.05, 0.05), worst = c(abs(acc - 0.64), worst_pc5))
    targets$ok <- targets$worst <= targets$tolerance
    st <- data.frame(figure = "r", ours = acc, thesis = 1, aim = "at least 0.7", ok = acc >= 0.7)
    structure(list(types = data.frame(grasp_id = 1L, grasp = "Tripod", recall_fpca = acc),
                   targets = targets, structure = st), class = "calibration_report")
  }
  rep <- calibration_combine(list(mk(0.62, 0.01), mk(0.70, 0.06)), c(3, 7))
  expect_equal(rep$targets$ours[1], 0.66)
  expect_equal(rep$targets$min[1], 0.62)
  expect_equal(rep$targets$max[1], 0.70)
  expect_equal(rep$targets$worst, c(0.06, 0.06))
  expect_equal(rep$targets$ok, c(FALSE, FALSE))       # each fails on one seed
  expect_equal(rep$types$recall_fpca, 0.66)
  expect_equal(rep$structure$ok, FALSE)
  expect_equal(unique(rep$by_seed$seed), c(3, 7))
  expect_output(print(rep), "2 seeds")
})

test_that("the default data meet the per-type targets (subset of types, full design)", {
  skip_without_calibration_report()
  # Per-type figures need only that type's recordings: simulate_grasps(grasps =)
  # is exactly that part of the default data, each model and each last-frame
  # PCA is fitted on its own type.
  types <- c(9, 22, 24)
  g <- simulate_grasps(grasps = types)
  ms <- fit_grasp_models(g, seed = 1)
  s <- summary(ms)
  cv <- cumulative_variance(fit_grasp_classifier(g, method = "last_frame", ncomp = 5))
  th <- thesis_results
  tol <- calibration_tolerances()
  expect_equal(s$target_length, th$table_5_1$target_frames[types])
  expect_true(all(abs(s$mean_var - th$table_5_2$mean[types]) <= tol[["mean_var"]]),
              info = paste(round(s$mean_var, 2), collapse = " "))
  expect_true(all(abs(cv$pc5 - th$table_5_7$pc5[types]) <= tol[["pc5"]]),
              info = paste(round(cv$pc5, 3), collapse = " "))
})

test_that("the stored calibration is what data-raw/simulator-calibration.csv says", {
  f <- test_path("..", "..", "data-raw", "simulator-calibration.csv")
  skip_if_not(file.exists(f), "data-raw/ not available (installed package)")
  cal <- utils::read.csv(f, stringsAsFactors = FALSE)
  p <- simulator_params()
  for (i in seq_len(nrow(cal))) {
    v <- if (is.na(cal$grasp_id[i])) p[[cal$parameter[i]]] else p[[cal$parameter[i]]][[cal$grasp_id[i]]]
    expect_equal(unname(v), cal$value[i], info = paste(cal$parameter[i], cal$grasp_id[i]))
  }
})

test_that("the whole default pipeline is the thesis' twin (slow)", {
  skip_without_calibration_report()
  skip_if_not(identical(Sys.getenv("HANDMOTION_SLOW_TESTS"), "true"),
              "set HANDMOTION_SLOW_TESTS=true to run the full calibration check")
  rep <- calibration_report(held_out = TRUE, folds = 5)
  expect_true(all(rep$targets$ok), info = paste(utils::capture.output(print(rep)), collapse = "\n"))
  expect_equal(rep$types$target_frames, rep$types$thesis_target_frames)
  h <- rep$held_out
  expect_false(anyNA(h$held_out))
  expect_true(all(h$held_out < h$in_sample))
})

test_that("the default reaches tell the grasp early (slow)", {
  # Any recalibration must keep this (issue 13 asks 75% at 300 ms on held-out
  # subjects; the shipped parameters give 77.7% on the default data).
  skip_if_not(identical(Sys.getenv("HANDMOTION_SLOW_TESTS"), "true"),
              "set HANDMOTION_SLOW_TESTS=true to run the early-recognition check")
  er <- evaluate_early_recognition(simulate_grasps(), ms = 300, fractions = NULL)
  expect_gte(er$accuracy, 0.75)
})

test_that("the shipped calibration's tolerances over seeds 1-5 (slow)", {
  skip_without_calibration_report()
  # five full pipelines (about a minute on 2 cores): every `make test` and
  # `make test-calibration`, never on CRAN. What holds on every one of seeds
  # 1-10 of the shipped parameters (measured 2026-11-25, see ?simulate_grasps):
  # frames, Table 5.2 per type (worst gap 1.50) and overall (95.71-95.80),
  # pc5 per type (worst gap 0.034), both accuracies (62.3-64.7%, 35.7-37.9%),
  # both recall correlations (Table 5.8 0.89-0.95, Table 5.6 0.74-0.85) and
  # Table 5.3's third and fourth counts (8-14 against 12, 4-6 against 9).
  # Not on every seed: the confusion groups (0-1 of 3; the thesis' own
  # table holds 1) and Table 5.3's first two counts (14-19 and 18-22
  # against 28 and 14).
  skip_if_not("true" %in% Sys.getenv(c("HANDMOTION_SLOW_TESTS", "HANDMOTION_CALIBRATION_SEEDS")),
              "set HANDMOTION_SLOW_TESTS=true to check seeds 1-5")
  rep <- calibration_report(seeds = 1:5)
  info <- paste(utils::capture.output(print(rep)), collapse = "\n")
  # every tolerance on every seed
  expect_true(all(rep$targets$ok), info = info)
  by <- rep$by_seed
  r58 <- by$ours[by$figure == "Table 5.8 per-type recall, correlation with the thesis"]
  r56 <- by$ours[by$figure == "Table 5.6 per-type recall, correlation with the thesis"]
  expect_length(r58, 5)
  expect_true(all(r58 >= 0.7), info = info)
  expect_true(all(r56 >= 0.7), info = info)
  # the report's own verdict: within 5 of the count the thesis states
  both_ok <- by$ok[by$figure == "Table 5.3: both at once"]
  drawn_ok <- by$ok[by$figure == "Table 5.3: types closest to the most attracting model"]
  expect_length(both_ok, 5)
  expect_true(all(both_ok), info = info)
  expect_true(all(drawn_ok), info = info)
  expect_equal(sort(unique(by$seed)), 1:5)
})
