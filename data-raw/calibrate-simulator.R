# Calibrates the HUST-like simulator so that the pipeline, run with all its
# defaults on the default data (simulate_grasps()), is a documented twin of
# the data of Jeppsson (2017), chapter 5, for any seed, type by type:
#   * Table 5.1  target frames per type       exact (already the simulator's
#                                              target_frames; only checked here)
#   * Table 5.2  mean variance explained by 2 FPCs per DoF, per type: +/- 2 points
#   * Table 5.7  cumulative variance of 5 last-frame PCs, per type:   +/- 0.05
#   * Table 5.8  per-type recall of the last-frame PCA classifier (its
#                diagonal over the column totals; the in-sample accuracy,
#                64%, follows from it)
#   * Table 5.6  per-type recall of the FPCA classifier (35% overall)
# Every figure is the MEAN OVER SEEDS of the default design (30 subjects x 33
# types x 3 objects x 3 trials), so the calibration fits the simulator, not
# one seed's sampling noise (issue 14).
#
# Only simulator parameters are tuned; the pipeline runs with its defaults
# and never sees a thesis number. The knobs (see ?simulator_params), all per
# type and updated for all 33 types at once in each round:
#   factor_scale[type]    subject factors in the final posture -> Table 5.7 pc5
#   posture_spread[type]  distinctness of the type's final posture from the
#                         mean posture of all types       -> Table 5.8 recall
#   jitter_scale[type]    finger-by-finger timing jitter   -> Table 5.2 mean
#   preshape_scale[type]  how early in the reach the hand takes the type's
#                         shape (mid-motion, not the end) -> Table 5.6 recall
#                         (goals: the thesis' recalls shifted on the logit
#                         scale so that their mean is the thesis' accuracy)
# Not targeted (measured by calibration_report()): the confusions between
# types and Table 5.3's counts; an attempt to lift the Table 5.2 floor of the
# pinch types by scaling their within-type variation made their models
# attract nearly every type and was dropped.
# Each knob moves its own figure monotonically; the updates are per-type
# secant steps on a transformed scale (log knob against logit recall, odds of
# pc5, jitter variance against the unexplained share), damped and bounded.
# The last frames do not depend on jitter or pre-shaping, so stage 1 (last
# frames only, cheap) settles factor_scale and posture_spread first; stage 2
# (the full pipeline) then tunes jitter_scale and preshape_scale.
#
# Cost control: stage 1 needs only simulate + last-frame PCA (seconds per
# seed); stage 2 fits one model per type per seed with a single Gaussian per
# score (the FPCA distance and the variance explained never read the score
# mixture, see fit_classifier()), with fewer seeds in the early rounds. Seeds
# run in parallel on CORES cores (forked).
#
# Output: data-raw/simulator-calibration.csv (parameter, grasp_id, value;
# grasp_id NA for a global parameter). data-raw/simulator-params.R applies it
# when it builds R/sysdata.rda, so simulator_params() defaults are the
# calibrated values. The last stage-2 round runs with exactly the written
# (rounded) values on all SEEDS, and its per-seed figures are the
# verification printed at the end (calibration_report(seeds = ) recomputes
# them independently).
#
# Run from the package root (7-14 minutes on 2 cores shared with other work,
# starting from the shipped values; less on a quiet machine):
#   Rscript data-raw/calibrate-simulator.R [path/to/thesis-tables]
# The thesis tables default to ../shared/thesis-tables (HANDMOTION_SHARED).

pkgload::load_all(".", quiet = TRUE)
t_start <- Sys.time()
args <- commandArgs(trailingOnly = TRUE)
tables <- if (length(args) >= 1L) args[1] else
  file.path(Sys.getenv("HANDMOTION_SHARED", file.path("..", "shared")), "thesis-tables")
if (!dir.exists(tables)) stop("thesis tables not found at ", tables, " (pass the path as the first argument)")
say <- function(...) cat(sprintf(...), "\n", sep = "")
elapsed <- function() as.numeric(difftime(Sys.time(), t_start, units = "mins"))

SEEDS <- 1:5          # every target is a mean over these seeds
CORES <- 2L
STAGE1_ROUNDS <- 10L
# posture_spread stays within these bounds: a type's final posture at most
# 2.5 times (at least 0.3 times) as far from the mean posture as the
# taxonomy's roles put it (an earlier run without bounds reached 5 for the
# pinch types, far beyond what the taxonomy supports; with these bounds the
# calibrated final postures lie within -2 to 76 degrees on every driven DoF)
SPREAD_RANGE <- c(0.3, 2.5)
STAGE2_SEEDS <- list(1:3, 1:3, 1:3, 1:5)  # seeds per stage-2 round; the last one verifies

# ---- targets (read here, used only to steer the simulator's knobs) ----------
read_tab <- function(f) utils::read.csv(file.path(tables, f), stringsAsFactors = FALSE)
t51 <- read_tab("table_5_1.csv")
t52 <- read_tab("table_5_2.csv")
t57 <- read_tab("table_5_7.csv")
dg <- read_tab("diagonals.csv")
stopifnot(identical(t52$grasp_id, 1:33), identical(t57$grasp_id, 1:33), identical(dg$grasp_id, 1:33))
# per-type recall = diagonal / column total (best guesses; totals are lower
# bounds, so recalls are upper bounds: see thesis-tables/README.md). A
# medium-confidence diagonal (FPCA types 2 and 3) counts half in the updates
# and in the weighted correlation.
conf_weight <- function(conf) c(high = 1, medium = 0.5, low = 0.25)[conf]
target <- list(
  frames = t51$target_frames,
  mean_var = t52$mean,
  pc5 = t57$pc5,
  recall_lf = dg$lastframe_pca_correct / dg$lastframe_pca_total,
  recall_fpca = dg$fpca_correct / dg$fpca_total,
  w_lf = unname(conf_weight(dg$lastframe_pca_correct_confidence)),
  w_fpca = unname(conf_weight(dg$fpca_correct_confidence))
)
stopifnot(identical(as.integer(simulator_params()$target_frames$frames), as.integer(target$frames)))

wcor <- function(x, y, w) {
  ok <- is.finite(x) & is.finite(y)
  stats::cov.wt(cbind(x[ok], y[ok]), wt = w[ok] / sum(w[ok]), cor = TRUE)$cor[1, 2]
}
logit <- function(q) { q <- pmin(pmax(q, 0.01), 0.99); log(q / (1 - q)) }
odds <- function(q) { q <- pmin(pmax(q, 1e-4), 1 - 1e-4); q / (1 - q) }
knob_round <- function(x) signif(x, 4)

# Vectorised secant step for 33 monotone relations y_k(log x_k): `hx`, `hy`
# are matrices (rounds x types) of past knob values and figures. The slope is
# estimated from the last two rounds where the knob moved, kept within
# [slope_min, slope_max] (noisy figures otherwise give wild steps), else the
# prior `slope0`; the step on log x is damped and capped at log(max_factor).
secant_log_vec <- function(hx, hy, goal, slope0, slope_min, slope_max, max_factor, damp = 0.8,
                           weight = 1) {
  n <- nrow(hx)
  x <- hx[n, ]
  y <- hy[n, ]
  slope <- rep(slope0, length(x))
  if (n >= 2L) {
    dx <- log(hx[n, ]) - log(hx[n - 1L, ])
    est <- (hy[n, ] - hy[n - 1L, ]) / dx
    use <- abs(dx) > 1e-3 & is.finite(est)
    slope[use] <- pmin(pmax(est[use], slope_min), slope_max)
  }
  step <- damp * weight * (goal - y) / slope
  x * exp(pmax(pmin(step, log(max_factor)), -log(max_factor)))
}

# Run f(seed) for each seed, in parallel (forked workers share the loaded
# package); any error stops the calibration.
over_seeds <- function(seeds, f) {
  res <- parallel::mclapply(seeds, f, mc.cores = min(CORES, length(seeds)), mc.preschedule = FALSE)
  bad <- vapply(res, inherits, logical(1), "try-error")
  if (any(bad)) stop("a seed failed: ", as.character(res[[which(bad)[1]]]))
  res
}
per_type_recall <- function(cl) {
  p <- cl$predictions
  ok <- !is.na(p$predicted) & as.character(p$truth) == as.character(p$predicted)
  as.numeric(tapply(ok, factor(as.character(p$truth), levels = feix_levels()), mean))
}

# ---- starting point ------------------------------------------------------------
# The taxonomy-built parameters, with the shipped calibration's per-type
# values as the start (a rerun after a small change converges in a round or
# two); a missing element starts at its built default.
p <- simulator_params()
say("start: preshape %.3f", p$preshape)

# ---- stage 1: last frames only (Table 5.7 pc5, Table 5.8 recalls) -------------
measure_last_frames <- function(p, seeds) {
  res <- over_seeds(seeds, function(s) {
    g <- simulate_grasps(seed = s, params = p)
    lf <- fit_last_frame_pca(g, k = 5)
    list(pc5 = cumulative_variance(lf)$pc5, recall = per_type_recall(classify(lf, g)))
  })
  list(pc5 = rowMeans(sapply(res, `[[`, "pc5")), recall = rowMeans(sapply(res, `[[`, "recall")),
       recall_by_seed = sapply(res, `[[`, "recall"))
}
stage1 <- function(p, rounds, label) {
  hx <- hy <- NULL
  for (it in seq_len(rounds)) {
    m <- measure_last_frames(p, SEEDS)
    acc <- mean(m$recall)   # equal-sized types: accuracy = mean recall
    r <- wcor(m$recall, target$recall_lf, target$w_lf)
    gap_pc5 <- max(abs(m$pc5 - target$pc5))
    rms <- sqrt(mean((m$recall - target$recall_lf)^2))
    say("  %s round %2d (%.1f min): pc5 worst |diff| %.3f; last-frame recall r %.3f, rms %.3f, accuracy %.3f",
        label, it, elapsed(), gap_pc5, r, rms, acc)
    # done when the recalls fit and pc5 fits or no longer moves (a type whose
    # factor_scale is at its bound)
    if ((rms < 0.01 && (gap_pc5 < 0.01 || (it > 1L && last_gap - gap_pc5 < 0.002))) || it == rounds) break
    last_gap <- gap_pc5
    # pc5: the odds of the first 5 PCs' share grow about with the square of
    # the factors' scale
    ratio <- (odds(target$pc5) / odds(m$pc5))^(0.5 * 0.8)
    p$factor_scale[] <- knob_round(pmin(pmax(p$factor_scale * ratio, 0.1), 6))
    # recall: logit(recall) rises with log(spread)
    hx <- rbind(hx, p$posture_spread)
    hy <- rbind(hy, logit(m$recall))
    p$posture_spread[] <- knob_round(pmin(pmax(
      secant_log_vec(hx, hy, logit(target$recall_lf), slope0 = 3, slope_min = 1, slope_max = 10,
                     max_factor = 1.5, weight = target$w_lf), SPREAD_RANGE[1]), SPREAD_RANGE[2]))
  }
  p
}
say("== stage 1: last frames, %d seeds per round", length(SEEDS))
p <- stage1(p, STAGE1_ROUNDS, "stage 1")

# ---- stage 2: the full pipeline (Table 5.2, Table 5.6 recalls) -----------------
measure_full <- function(p, seeds) {
  over_seeds(seeds, function(s) {
    g <- simulate_grasps(seed = s, params = p)
    ms <- fit_grasp_models(g, seed = 1, k = 1)
    cl <- classify(ms, g)
    sm <- summary(ms)
    lf <- fit_last_frame_pca(g, k = 5)
    conf <- table(factor(as.character(cl$predictions$truth), levels = feix_levels()),
                  factor(as.character(cl$predictions$predicted), levels = feix_levels()))
    list(mean_var = sm$mean_var[match(feix_levels(), sm$grasp)], recall = per_type_recall(cl),
         recall_lf = per_type_recall(classify(lf, g)), pc5 = cumulative_variance(lf)$pc5,
         conf = unclass(conf), minima = distance_minima(distance_table(cl)))
  })
}
say("== stage 2: full pipeline")
u_goal <- 100 - target$mean_var
hj <- hu <- hpx <- hpy <- NULL
pre_max <- 1 / p$preshape
# Some types keep a higher FPCA recall than the thesis' even with no
# pre-shaping at all (their final posture alone tells them apart), which
# would leave the accuracy too high. So the per-type goals are the thesis'
# recalls moved by one common shift on the logit scale, `shift`, updated
# each round until the mean recall (= the accuracy, equal-sized types) is
# the thesis' accuracy: the ranking and the shape of the thesis' recalls are
# kept, the level is the thesis' accuracy.
acc_fpca <- sum(dg$fpca_correct) / sum(dg$fpca_total)
shift <- 0
for (it in seq_along(STAGE2_SEEDS)) {
  seeds <- STAGE2_SEEDS[[it]]
  res <- measure_full(p, seeds)
  mv <- rowMeans(sapply(res, `[[`, "mean_var"))
  rec <- rowMeans(sapply(res, `[[`, "recall"))
  r <- wcor(rec, target$recall_fpca, target$w_fpca)
  worst <- which.max(abs(mv - target$mean_var))
  say("  round %d (%d seeds, %.1f min): mean_var worst |diff| %.2f (%s; mean %.2f); FPCA recall r %.3f, rms %.3f, accuracy %.3f",
      it, length(seeds), elapsed(), max(abs(mv - target$mean_var)), feix_levels()[worst], mean(mv), r,
      sqrt(mean((rec - target$recall_fpca)^2)), mean(rec))
  if (it == length(STAGE2_SEEDS)) break
  # a rerun starts from the shipped values: take the shift they were tuned
  # to (the median, since types at the floor are off their goals)
  if (it == 1L) shift <- stats::median(logit(target$recall_fpca) - logit(rec))
  shift <- shift + (logit(mean(rec)) - logit(acc_fpca))
  goal_fpca <- logit(target$recall_fpca) - shift
  say("    FPCA goal shift %.2f on the logit scale", shift)
  # Table 5.2: the unexplained share u = 100 - mean grows about linearly with
  # the jitter's variance, u = u0 + a j^2: a secant step on j^2 per type.
  # Types at the jitter floor that still explain too little (the pinches)
  # pull the overall mean (95.90) down; the types that can still move aim a
  # little higher instead (at most 0.6 points) to keep the overall mean.
  at_floor <- p$jitter_scale <= 0.021
  deficit <- sum(pmax(target$mean_var - mv, 0)[at_floor])
  lift <- min(0.6, deficit / max(1, sum(!at_floor)))
  u_goal <- 100 - target$mean_var - ifelse(at_floor, 0, lift)
  say("    Table 5.2 goals of the %d movable types raised by %.2f points", sum(!at_floor), lift)
  u <- 100 - mv
  j2 <- p$jitter_scale^2
  hj <- rbind(hj, j2)
  hu <- rbind(hu, u)
  n <- nrow(hj)
  slope <- rep(NA_real_, 33)
  if (n >= 2L) {
    dj <- hj[n, ] - hj[n - 1L, ]
    est <- (hu[n, ] - hu[n - 1L, ]) / dj
    use <- abs(dj) > 1e-6 & is.finite(est) & est > 0
    slope[use] <- est[use]
  }
  new <- ifelse(is.finite(slope), j2 + (u_goal - u) / slope, j2 * u_goal / u)
  # at most a factor 4 in variance per round; never quite zero jitter
  j2 <- pmin(pmax(new, j2 / 4, 0.02^2), j2 * 4, 4^2)
  p$jitter_scale[] <- knob_round(sqrt(j2))
  # Table 5.6: logit(recall) rises with log(preshape_scale)
  hpx <- rbind(hpx, p$preshape_scale)
  hpy <- rbind(hpy, logit(rec))
  p$preshape_scale[] <- knob_round(pmin(pmax(
    secant_log_vec(hpx, hpy, goal_fpca, slope0 = 1, slope_min = 0.3, slope_max = 6,
                   max_factor = 2, weight = target$w_fpca), 0.05), pre_max))
}

# ---- save, rebuild R/sysdata.rda ---------------------------------------------
per_type_rows <- function(el) data.frame(parameter = el, grasp_id = 1:33, value = unname(p[[el]]))
cal <- rbind(
  per_type_rows("posture_spread"), per_type_rows("factor_scale"), per_type_rows("jitter_scale"),
  per_type_rows("preshape_scale"),
  data.frame(parameter = "preshape", grasp_id = NA_integer_, value = p$preshape),
  data.frame(parameter = "final_variability", grasp_id = NA_integer_, value = p$final_variability)
)
utils::write.csv(cal, file.path("data-raw", "simulator-calibration.csv"), row.names = FALSE)
say("wrote data-raw/simulator-calibration.csv (%d values)", nrow(cal))
status <- system2(file.path(R.home("bin"), "Rscript"), file.path("data-raw", "simulator-params.R"))
if (!identical(status, 0L)) stop("data-raw/simulator-params.R failed")

# ---- verification: the last round ran with exactly these values ------------
by_seed <- do.call(rbind, lapply(seq_along(res), function(i) {
  x <- res[[i]]
  data.frame(seed = STAGE2_SEEDS[[length(STAGE2_SEEDS)]][i],
             mean_var_worst = max(abs(x$mean_var - target$mean_var)),
             overall_mean_var = mean(x$mean_var),
             pc5_worst = max(abs(x$pc5 - target$pc5)),
             acc_last_frame = mean(x$recall_lf), acc_fpca = mean(x$recall),
             r_last_frame = wcor(x$recall_lf, target$recall_lf, target$w_lf),
             r_fpca = wcor(x$recall, target$recall_fpca, target$w_fpca),
             x$minima[c("model_min_own_type", "type_min_own_model", "both", "n_attracted")])
}))
say("== verification (the written values, seeds %s)", paste(range(by_seed$seed), collapse = "-"))
print(by_seed, row.names = FALSE, digits = 3)
say("run time %.1f minutes", elapsed())
