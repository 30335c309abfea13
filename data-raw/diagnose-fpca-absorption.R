# How much of the distance between a recording and a model's mean function
# the model's FPCs absorb, for its own type and for the others (issue 14,
# Table 5.3's counts G1 and G2 in thesis-tables/claims.md). A maintainer's
# diagnosis, not part of the calibration; it complements
# data-raw/diagnose-table-5-3-effects.R, which splits log Table 5.3 into a
# model effect A_i and a type effect B_j.
#
# The FPCs of every DoF are orthonormal under the model's quadrature weights,
# so a recording's squared distance to the model's mean is its squared
# residual (what eq. 4.4 ranks) plus its squared scores: the share of the
# scores is what the FPCs absorb. A model whose FPCs absorb much of the
# OTHER types' distance is a generalist (low A_i); the thesis' model 9,
# the minimum of nine types' columns, must be one.
#
# Findings (2026-11-26, the shipped calibration of main f1c71ab; seeds 1-3,
# `Rscript data-raw/diagnose-fpca-absorption.R 1:3`, about 40 s):
# * The FPCs absorb almost as much of the other types' distance as of their
#   own type's (0.76 against 0.78 on average over the models, every seed):
#   the models' bases are much alike, and a model's advantage on its own
#   type (the own cell's residual of -0.58 in the effects script) comes from
#   its mean function, not from its basis.
# * Per model, the share absorbed of the other types ranges 0.65-0.86, and
#   follows grasp_variability (cor 0.74-0.77). The poorest absorbers are the
#   types the calibration quieted to its floor 0.2 (seed 1: Distal Type,
#   Writing Tripod, Tripod Variation, Stick, Extension Type, Tip Pinch,
#   Lateral, Palmar; on seeds 2-3 Sphere 3 Finger, 0.47, replaces Palmar
#   among the eight): with little variation of their final posture, their
#   FPCs do not span the other types' posture differences.
# * The share absorbed alone does not predict the model effect A (cor -0.06
#   to -0.07), because it rises with the model's distance from the other
#   types (cor 0.79-0.82): a larger, mostly posture-shaped difference leaves
#   a larger share to the first FPC. Together with the target length they
#   explain 69-73% of A's variance:
#     A ~ 0.65 log(1 - share absorbed) + 0.73 log(distance of the other
#         types to the model's mean) - 0.44 log T_i
#   (standard errors about 0.09, 0.09 and 0.12). The length term is close
#   to the -0.5 of Table 5.3's division of a frame-grid norm (which grows as
#   sqrt(T_i)) by T_i. A model that would absorb more of the others' motion
#   without its mean moving away from theirs would be a generalist; no
#   per-type knob of the simulator gives one (see the effects script).
#
# Probes on seed 1 (not shipped; changes of Palmar Pinch's A and B, whose
# sd over the models are 0.11 and 0.19):
# * per-finger timing jitter of sd 0.24 of the motion (jitter_scale 6, a
#   parameter) made its model more of a generalist (A -0.09) but its type
#   much harder for every model (B +0.26); its model took one column (none
#   before);
# * with a throw-away patch of the simulator: independent final postures of
#   the fingers it does not use (3-5, sd 25 degrees) moved A and B up
#   together (+0.04, +0.17); doubling the still phases before and after its
#   motion moved both up (+0.23, +0.30); moving the final posture of its
#   fingers 3-5 to the mean posture of all types, with or without that
#   free variation (sd 0-20 degrees), moved A by -0.03 to +0.04 and B up by
#   0.02-0.13;
# * (2026-11-26, shipped calibration of main 0fc93b8; A 0.10 and B 0.02 as
#   shipped) more variation of its opening, aperture_variability times 2, 4
#   or 8 (0.2 as shipped), moved A by -0.02 to -0.04 and B up by 0.01-0.13;
#   more variation of its final posture, grasp_variability times 2 or 3,
#   moved A by +0.05 and -0.06 and B up by 0.19 and 0.39. Its model took no
#   column in any of the five, and G1 and G2 stayed at 18 and 19: a type
#   that varies more, in its opening or in its final posture, becomes harder
#   for every model before its own model becomes a generalist;
# * raising every quieted type's grasp_variability to 0.7 (posture_spread in
#   proportion) gave G1 22 but G2 22 and an FPCA accuracy of 42.6%
#   (tolerance 35.1 +/- 4).
#
# Run from the package root:
#   Rscript data-raw/diagnose-fpca-absorption.R [seeds]
# seeds: e.g. 1:3 (default 1).

pkgload::load_all(".", quiet = TRUE)
args <- commandArgs(trailingOnly = TRUE)
seeds <- if (length(args) >= 1L) eval(parse(text = args[1])) else 1L
p0 <- simulator_params()

# mean over the other types: a types x models table without its own cells
others_mean <- function(M) (colSums(M) - diag(M)) / (ncol(M) - 1L)

for (s in seeds) {
  g <- simulate_grasps(seed = s)
  models <- fit_grasp_models(g, seed = s)
  pr <- project(models, g)
  truth <- as.character(g$meta$grasp)
  types <- names(pr)
  resid2 <- vapply(pr, function(p) rowSums(p$residual^2), numeric(length(truth)))
  total2 <- resid2 + vapply(pr, function(p) apply(p$scores^2, 1L, sum), numeric(length(truth)))
  # types x models: mean squared residual and mean squared distance to the mean
  by_type <- function(M) t(vapply(types, function(ty) colMeans(M[truth == ty, , drop = FALSE]),
                                  numeric(ncol(M))))
  tot <- by_type(total2)
  absorbed <- 1 - by_type(resid2) / tot
  own <- diag(absorbed)
  others <- others_mean(absorbed)
  # Table 5.3 as the package builds it (classify() projects again, keeping
  # only the distances: the scores above are not part of its result)
  A <- distance_effects(distance_table(classify(models, g, method = "fpca"))[types, types])$model
  gv <- p0$grasp_variability[types]
  # the model's centrality: log mean squared distance of the other types'
  # recordings to its mean function (on project()'s [0, 1] time axis)
  centre <- log(others_mean(tot))
  T_i <- vapply(pr, function(p) p$target_length, numeric(1))
  fit <- stats::lm(A ~ log(1 - others) + centre + log(T_i))
  cat(sprintf("seed %d: absorbed, own type %.3f, other types %.3f (per model %.2f-%.2f); cor(absorbed of others, grasp_variability) %.2f\n",
              s, mean(own), mean(others), min(others), max(others), stats::cor(others, gv)))
  cat(sprintf("  model effect A: cor with absorbed of others %.2f, with log distance of others to the mean %.2f, with log T %.2f; R^2 of all three %.2f\n",
              stats::cor(A, others), stats::cor(A, centre), stats::cor(A, log(T_i)), summary(fit)$r.squared))
  cat(sprintf("  cor(absorbed of others, log distance of others to the mean) %.2f\n", stats::cor(others, centre)))
  print(round(stats::coef(summary(fit))[, 1:2], 3))
  o <- order(others)
  cat("  poorest absorbers: ", paste(sprintf("%s %.2f (gv %.2f)", types[o[1:8]], others[o[1:8]], gv[o[1:8]]),
                                     collapse = ", "), "\n", sep = "")
}
