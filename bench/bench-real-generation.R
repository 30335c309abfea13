# Natural generation on real data (issue 40): how far generated grasps are
# from held-out recordings of the other participant, as a multiple of how
# far the training participant's own recordings are (evaluate_generation(),
# kernel MMD on the postures at 25/50/75/100% of the recording and the log
# duration), for the thesis' model and the copula model, with the rest and
# the hold; the durations' KS distance; and whether any generated value
# leaves the recorded range of its sensor (or 0..1023). Target: MMD ratio
# 1.25 or less on flexglove by participant folds. Also the simulated
# raw-count glove of bench-glove.R (its 15 channels, one person, 5 folds by
# recording), the stand-in for a wide glove.
#
# The recordings are read with unit = "raw": raw channels keep inside their
# recorded range at generation (read in the default degrees, channels no
# skeleton map knows have no limits, and about 6% of generated frames left
# the recorded range). With 2 folds and 8-90 recordings a type the MMD
# ratios move by about 0.05-0.1 with the seed: compare runs of one seed.
# Figures (2026-11-27, 5 repetitions; MMD ratio / duration KS ratio):
#   seed 1: before (rest and hold drawn apart from the motion) thesis 1.45 /
#   1.44, copula 1.34 / 1.38; after (drawn with it) thesis 1.36 / 1.10,
#   copula 1.27 / 1.16. seed 2: before 1.44 / 1.51 and 1.40 / 1.41; after
#   1.47 / 1.15 and 1.42 / 1.24. So the durations are mended, the MMD is
#   not: its gap is in the postures (swapping generated postures for real
#   ones brings it to 1.02-1.04), for the thesis' model from drawing each
#   DoF apart (real scores shuffled per DoF: 1.56-1.58). Simulated glove
#   (seed 1): thesis 1.03 -> 1.09, copula 1.26 -> 1.26.
# The kernel model (dependence = "kernel": the joint score vector from a
# kernel density on the training recordings' vectors, which keeps a type's
# per-object clusters that the copula blurs), seed 1: flexglove MMD thesis
# 1.41, copula 1.40, kernel 1.24 (duration KS 1.15 / 1.10 / 1.27; final
# posture correlation gap 1.39 / 1.02 / 1.08); no generated frame outside
# the recorded range or 0..1023 for any model. Simulated glove: thesis
# 1.03, copula 1.26, kernel 1.26. Read by read_glove() from the shipped
# copy instead (issue 40's measure, seeds 1-5, 5 repetitions): kernel 1.21
# (1.18-1.24), copula 1.28 (1.23-1.34), thesis 1.23 (1.11-1.31).
# The still phases (2026-11-28, branch gen125): a hold is no frozen
# posture. The real recordings' own motions with their rest replaced by the
# onset posture plus tremor keep their MMD ratio (1.00 at every block); with
# their hold replaced by the end posture plus tremor they go to 1.19 / 1.28
# at the 75% / 100% postures (the fingers settle back by about a tenth of
# the reach), and with the rest and hold paths of another recording among
# the 5 nearest in motion length and displacement back to 0.99 / 1.04.
# Generation now does that. Read by read_glove() as bench-real-generation-
# blocks.R reads it, participant folds, seeds 1-5, 5 repetitions each,
# thesis and copula fitted together (about 10 s CPU a seed, load 5-20):
# thesis 1.28 (1.17-1.38) -> 1.21 (1.15-1.29), copula 1.30 (1.28-1.31) ->
# 1.20 (1.15-1.25); duration KS ratio 1.06 -> 1.06 and 1.03 -> 1.00; no
# generated frame outside the recorded range. Doubtful: the simulated wide
# glove (15 channels, 100 Hz, 1.4 s rest, 5 folds by recording, seeds 1-4,
# 3 repetitions) went thesis 1.44 / 1.47 / 0.94 / 1.22 -> 1.61 / 1.79 /
# 1.11 / 0.96 and copula 1.40 / 1.86 / 1.91 / 1.11 -> 1.47 / 2.38 / 1.92 /
# 1.20: its real-vs-real MMD is 0.02-0.05 (one person, folds by recording),
# so the ratios swing by 0.3 with the seed, and its still phases are flat by
# construction (its own recordings with flat or donor holds have the same
# MMD), but the means moved the wrong way by 0.1-0.17.
# The mixture guard on trimmed recordings (2026-11-29): the thesis' model's
# two-component mixtures fitted slivers to a few recordings; guarded by
# default on trimmed recordings, seeds 1-4 (3 repetitions, read_glove()):
# 1.28 / 1.22 / 1.29 / 1.33 -> 1.23 / 1.21 / 1.19 / 1.22; the simulated
# wide glove, seeds 1-3: 1.31 / 1.16 / 1.52 -> 1.16 / 1.17 / 1.32.
#
# Needs the flexglove data set (HANDMOTION_SHARED, default /work/shared):
#   Rscript bench/bench-real-generation.R     (BENCH_QUICK=1: 1 repetition, 3 types)

source("bench/_common.R")
shared <- Sys.getenv("HANDMOTION_SHARED", "/work/shared")
dir <- file.path(shared, "data", "flexglove")
if (!file.exists(file.path(dir, "manifest.csv"))) stop("flexglove not found under ", dir)

# the folder as recorded: one CSV per recording (flex1..flex6), labels and
# participants from the manifest, about 33 Hz
man <- utils::read.csv(file.path(dir, "manifest.csv"), stringsAsFactors = FALSE)
if (bench_quick) man <- man[man$label %in% c("Large_diameter", "Ventral", "Fixed_hook"), ]
recs <- lapply(man$file, function(f) as.matrix(utils::read.csv(file.path(dir, f))))
names(recs) <- sub("[.]csv$", "", gsub("/", "__", man$file))
flex <- grasps(recs, meta = data.frame(grasp = man$label, subject = man$subject, object = man$object,
                                       trial = man$trial, stringsAsFactors = FALSE),
               rate = 33.3, unit = "raw")
reps <- bq(5, 1)

# share of generated frames outside each channel's recorded range (the
# model's training range) and outside the 10-bit ADC's 0..1023
range_check <- function(x, fit) {
  lo <- apply(do.call(rbind, x$recordings), 2, min)
  hi <- apply(do.call(rbind, x$recordings), 2, max)
  vapply(names(fit), function(nm) {
    ms <- suppressWarnings(do.call(fit_grasp_models, c(list(x, seed = 1), fit[[nm]])))
    G <- do.call(rbind, generate(ms, n = 200, seed = 2)$recordings)
    c(recorded = mean(rowSums(sweep(G, 2, lo, `<`) | sweep(G, 2, hi, `>`)) > 0),
      adc = mean(G < 0 | G > 1023))
  }, numeric(2))
}

report <- function(label, ev) {
  d <- as.data.frame(unclass(ev)[names(ev)], stringsAsFactors = FALSE)
  d <- d[d$grasp == "overall" & d$metric %in% c("mmd", "duration_ks", "posture_cor_gap"), ]
  for (i in seq_len(nrow(d))) {
    cat(sprintf("  %-7s %-16s generated %.4f  real %.4f  ratio %.2f\n", d$model[i], d$metric[i],
                d$generated[i], d$baseline[i], d$ratio[i]))
    bench_record(sprintf("%s %s %s ratio", label, d$model[i], d$metric[i]), d$ratio[i], "x")
  }
}

fit <- list(thesis = list(), copula = list(dependence = "copula"), kernel = list(dependence = "kernel"))
cat(sprintf("flexglove: %d recordings, %d types, participants %s\n", length(flex),
            length(unique(flex$meta$grasp)), paste(unique(flex$meta$subject), collapse = ", ")))
t <- system.time(ev <- evaluate_generation(recordings = flex, split = "subject", folds = 2, reps = reps, fit = fit))
cat(sprintf("evaluate_generation(), participant folds, %d repetitions: %.1f s elapsed, %.1f s CPU\n",
            reps, t[["elapsed"]], cpu_of(t)))
report("flexglove", ev)
rc <- range_check(flex, fit)
for (nm in colnames(rc)) {
  cat(sprintf("  %-7s generated frames outside the recorded range %.4f, outside 0..1023 %.4f\n", nm,
              rc["recorded", nm], rc["adc", nm]))
  bench_record(sprintf("flexglove %s share outside recorded range", nm), rc["recorded", nm], "fraction")
}

# the wide-glove stand-in: bench-glove.R's simulated raw-count set
objects <- c(bottle = 1, mug = 9, ball = 17, pen = 22, card = 28, key = 31)
raw <- simulate_grasps(subjects = 1, grasps = objects[seq_len(bq(6, 2))], objects = 1, trials = bq(28, 8),
                       rate = 100, glove = "resistive", rest = 1, hold = 1, stuck = "thumb_cross",
                       plant_overlong = FALSE, seed = 3)
cat(sprintf("\nsimulated raw-count glove: %d recordings of %d channels, 5 folds by recording\n",
            length(raw), length(raw$dofs)))
t <- system.time(ev2 <- suppressWarnings(evaluate_generation(recordings = raw, folds = 5, reps = reps, fit = fit)))
cat(sprintf("evaluate_generation(): %.1f s elapsed\n", t[["elapsed"]]))
report("simulated glove", ev2)
