# Every classifier on real recordings (issue 40): the flexglove set (626
# recordings of a 6-flex-sensor glove, 8 grasp types, participants P1 and
# P2; $HANDMOTION_SHARED/data/flexglove, see its README.md), held out by
# participant: each participant's recordings are classified by a classifier
# fitted on the other's (evaluate_loso(), which holds out subjects by
# default). Per classifier: pooled and per-participant accuracy, and the time
# of its evaluate_loso() (target 10 s or less on flexglove); early
# recognition's evaluation on two workers (target 15 s or less). Published on
# the same data (two-fold by participant, with 97 synthetic copies in, so
# optimistic): CNN-BiLSTM 69.5%, an SVM on end postures 80.0%.
#
# Also: the likelihood distance with a number of FPCs per DoF chosen by
# nested folds inside the training participant, beside every fixed number;
# how much a per-recording offset (a glove that slipped between
# sessions) changes the predictions, and the same evaluation on the
# simulator's raw-count glove (one person, six objects, 5 folds by recording).
#
#   Rscript bench/bench-real-classify.R      (BENCH_QUICK=1: a fifth of the recordings)

source("bench/_common.R")
cat(sprintf("%s; load average %s on %d cores\n\n", bench_build, load_avg(), parallel::detectCores()))

shared <- Sys.getenv("HANDMOTION_SHARED", "/work/shared")
dir <- file.path(shared, "data", "flexglove")
if (!dir.exists(dir)) stop("flexglove not found under ", shared, " (set HANDMOTION_SHARED)")

# the folder read as the README describes it (header flex1..flex6, one row per frame)
read_flexglove <- function(dir, every = 1L) {
  man <- utils::read.csv(file.path(dir, "manifest.csv"), stringsAsFactors = FALSE)
  man <- man[seq(1L, nrow(man), by = every), ]
  recs <- lapply(file.path(dir, man$file), function(f) as.matrix(utils::read.csv(f)))
  grasps(recs, meta = data.frame(grasp = man$label, subject = man$subject, object = man$object,
                                 trial = man$trial), rate = 33.3)
}
g <- read_flexglove(dir, every = bq(1L, 5L))
cat(sprintf("flexglove: %d recordings, %s\n\n", length(g),
            paste(sprintf("%s %d", names(table(g$meta$subject)), table(g$meta$subject)), collapse = ", ")))

timed <- function(expr) {
  t <- system.time(value <- force(expr))
  # CPU of this process and of the workers it forked (multicore folds)
  cpu <- sum(t[c("user.self", "sys.self", "user.child", "sys.child")], na.rm = TRUE)
  list(value = value, elapsed = t[["elapsed"]], cpu = cpu)
}
fmt <- function(v) sprintf("%5.1f%%", 100 * v)

methods <- c(fpca = "FPCA likelihood distance", fpca_residual = "FPCA residual distance (thesis)",
             last_frame = "last-frame PCA (thesis)",
             weighted_fpca = "weighted FPCA distance", discriminant = "discriminant (subclass LDA)")
rows <- list()
for (m in names(methods)) {
  # the thesis' eq. 4.4 is fit_grasp_models(distance = "residual")
  r <- if (m == "fpca_residual") timed(evaluate_loso(g, method = "fpca", in_sample = FALSE, fit_args = list(distance = "residual")))
       else timed(evaluate_loso(g, method = m, in_sample = FALSE))
  ps <- r$value$per_subject
  rows[[m]] <- data.frame(classifier = methods[[m]], pooled = r$value$accuracy[["held_out"]],
                          P1 = ps$accuracy[ps$subject == "P1"], P2 = ps$accuracy[ps$subject == "P2"],
                          elapsed = r$elapsed, cpu = r$cpu)
  bench_record(sprintf("flexglove %s pooled accuracy", m), r$value$accuracy[["held_out"]], "fraction")
  for (s in ps$subject) bench_record(sprintf("flexglove %s accuracy, test %s", m, s), ps$accuracy[ps$subject == s], "fraction")
  bench_record(sprintf("flexglove evaluate_loso(%s)", m), r$elapsed, "s")
}

# the recogniser: held out the same way, from the first 300 ms and whole
oplan <- future::plan(future::multicore, workers = 2)
r <- timed(evaluate_early_recognition(g, ms = c(100, 300, 1000), fractions = c(0.5, 1)))
future::plan(oplan)
e <- as.data.frame(unclass(r$value)[names(r$value)])
whole <- e$accuracy[e$scale == "fraction" & e$value == 1]
rows$recognizer <- data.frame(classifier = "recogniser (whole recording)", pooled = whole, P1 = NA, P2 = NA,
                              elapsed = r$elapsed, cpu = r$cpu)
bench_record("flexglove recogniser accuracy, whole", whole, "fraction")
bench_record("flexglove recogniser accuracy, 300 ms", e$accuracy[e$scale == "ms" & e$value == 300], "fraction")
bench_record("flexglove evaluate_early_recognition(), 2 workers", r$elapsed, "s")
# per participant for the recogniser: fit on one, predict the other whole
per <- vapply(c("P1", "P2"), function(s) {
  rec <- fit_grasp_recognizer(g[g$meta$subject != s])
  test <- g[g$meta$subject == s]
  mean(as.character(predict(rec, test)$.pred_class) == as.character(test$meta$grasp))
}, numeric(1))
rows$recognizer$P1 <- per[["P1"]]
rows$recognizer$P2 <- per[["P2"]]

tab <- do.call(rbind, rows)
cat("Held out by participant (fit on one, classify the other):\n")
print(data.frame(classifier = tab$classifier, pooled = fmt(tab$pooled), `test P1` = fmt(tab$P1),
                 `test P2` = fmt(tab$P2), `elapsed s` = round(tab$elapsed, 2), `CPU s` = round(tab$cpu, 2),
                 check.names = FALSE), row.names = FALSE)
cat(sprintf("  (targets: evaluate_loso 10 s or less each; early recognition %.1f s on 2 workers, %.1f s CPU, target 15 s;\n   on a shared machine the CPU time is the figure to compare)\n",
            r$elapsed, r$cpu))
cat("  published, two-fold by participant with synthetic copies in: CNN-BiLSTM 69.5%, SVM on end postures 80.0%\n")
cat(sprintf("  the recogniser after 300 ms: %s\n\n", fmt(e$accuracy[e$scale == "ms" & e$value == 300])))

# A set-wide number k of FPCs per DoF for the likelihood distance, chosen by
# nested folds (issue 40, deliverable 5: the likelihood distance at 75%).
# The thesis model reads two FPCs per DoF; three were right more often held
# out by participant once, but that was seen on the test folds. The honest
# form of the choice: inside the training participant (the only one a fold
# has, so inner folds of recordings, stratified by type), fit with K = 4
# FPCs, cut each model to its first k (a DoF's first k scores do not change
# when more are computed; the score density is refitted for each k) and
# take the k right most often on the inner folds; then fit on the whole
# training participant and classify the held-out one at that k. Beside it:
# every fixed k on the held-out participant (what the choice would have to
# find) and a combination that chooses nothing, the sum of the k = 1..K
# distances. Not run under BENCH_QUICK: a fifth of the recordings leaves
# types with fewer than K + 1 recordings in an inner fold.
nested_ncomp <- function(g, K = 4L) {
  cut_model <- function(m, k) {
    m$settings$ncomp <- k
    m$fpca <- lapply(m$fpca, function(f) {
      f$components <- f$components[, seq_len(k), drop = FALSE]
      f$scores <- f$scores[, seq_len(k), drop = FALSE]
      f$var_explained <- f$var_explained[seq_len(k)]
      f$ncomp <- k
      f
    })
    m$likelihood_kernel <- likelihood_score_kernel(m)
    m
  }
  # (as evaluate_loso() fits the FPCA classifier: one Gaussian per DoF, no temperature)
  fit_K <- function(train) suppressWarnings(fit_model_set(train, ncomp = K, mixture_components = 1L,
                                                         calibrate = FALSE, seed = 1))
  # recordings x (k = 1..K, then the sum over k): right or wrong
  correct <- function(ms, test) {
    d <- lapply(seq_len(K), function(k) {
      # (the residual scale pooled again over the cut models, as fit_model_set() pools it)
      set <- new_grasp_models(pool_likelihood_residuals(lapply(fitted_models(ms), cut_model, k)),
                              levels = ms$levels, distance = "likelihood")
      suppressWarnings(fpca_distances(set, test)$distances)
    })
    d[[K + 1L]] <- Reduce(`+`, d)
    truth <- as.character(test$meta$grasp)
    vapply(d, function(m) colnames(m)[max.col(-m, ties.method = "first")] == truth, logical(length(test)))
  }
  lapply(stats::setNames(nm = sort(unique(g$meta$subject))), function(s) {
    train <- g[g$meta$subject != s]
    test <- g[g$meta$subject == s]
    inner <- make_folds(train, "recording", 5L, seed = 1)
    inner_acc <- colMeans(do.call(rbind, lapply(inner, function(f) correct(fit_K(train[!f]), train[f]))))
    chosen <- which.max(inner_acc[seq_len(K)])
    outer <- correct(fit_K(train), test)
    list(inner = inner_acc[seq_len(K)], chosen = chosen, outer = colMeans(outer), right = outer[, chosen],
         n = length(test))
  })
}
if (bench_quick) {
  cat("The likelihood distance with k FPCs chosen by nested folds: not run under BENCH_QUICK\n\n")
} else {
  nt <- timed(nested_ncomp(g))
  nested <- nt$value
  K <- length(nested[[1]]$inner)
  n_test <- vapply(nested, `[[`, 0, "n")
  cat("The likelihood distance with a set-wide number k of FPCs per DoF, held out by participant:\n")
  print(data.frame(
    `test` = names(nested),
    `inner folds, k = 1..4` = vapply(nested, function(r) paste(fmt(r$inner), collapse = ""), ""),
    `k chosen` = vapply(nested, `[[`, 0, "chosen"),
    `held out, k = 1..4` = vapply(nested, function(r) paste(fmt(r$outer[seq_len(K)]), collapse = ""), ""),
    `sum over k` = vapply(nested, function(r) fmt(r$outer[K + 1L]), ""),
    `chosen k` = vapply(nested, function(r) fmt(mean(r$right)), ""),
    check.names = FALSE), row.names = FALSE)
  nested_acc <- sum(vapply(nested, function(r) sum(r$right), 0)) / sum(n_test)
  fixed_acc <- colSums(t(vapply(nested, `[[`, numeric(K + 1L), "outer")) * n_test) / sum(n_test)
  cat(sprintf("  pooled: k chosen by nested folds %s; fixed k = 1..4:%s; sum over k %s (%.1f s, %.1f s CPU)\n\n",
              fmt(nested_acc), paste(fmt(fixed_acc[seq_len(K)]), collapse = ","), fmt(fixed_acc[K + 1L]),
              nt$elapsed, nt$cpu))
  bench_record("flexglove fpca accuracy, k FPCs chosen by nested folds", nested_acc, "fraction")
  for (k in seq_len(K)) bench_record(sprintf("flexglove fpca accuracy, k = %d FPCs", k), fixed_acc[k], "fraction")
  bench_record("flexglove fpca accuracy, sum of the distances over k = 1..4", fixed_acc[K + 1L], "fraction")
}

# How much the discriminant depends on the k-means seed of its subclasses:
# held out by participant as above, with seeds 1-10 (the package fits with
# seed 1). subclasses = "auto" averages the fits with 1, 2, 4 and 6
# subclasses per type, so no seed decides how many.
seed_acc <- local({
  F <- classifier_features(g, seq(0, 1, by = 0.125))
  y <- droplevels(as.factor(g$meta$grasp))
  t(vapply(1:10, function(seed) {
    ok <- logical(length(y))
    for (s in unique(g$meta$subject)) {
      tr <- g$meta$subject != s
      fit <- fit_subclass_lda(F[tr, , drop = FALSE], droplevels(y[tr]), "equal", "auto", seed = seed)
      ok[!tr] <- top_class(fit$types, subclass_lda_scores(fit, F[!tr, , drop = FALSE])) == as.character(y[!tr])
    }
    c(pooled = mean(ok), vapply(c("P1", "P2"), function(s) mean(ok[g$meta$subject == s]), numeric(1)))
  }, numeric(3)))
})
cat(sprintf("The discriminant over k-means seeds 1-10: pooled %s on average (%s to %s); test P1 %s, test P2 %s on average\n\n",
            fmt(mean(seed_acc[, "pooled"])), fmt(min(seed_acc[, "pooled"])), fmt(max(seed_acc[, "pooled"])),
            fmt(mean(seed_acc[, "P1"])), fmt(mean(seed_acc[, "P2"]))))
bench_record("flexglove discriminant accuracy, mean over k-means seeds 1-10", mean(seed_acc[, "pooled"]), "fraction")
bench_record("flexglove discriminant accuracy, lowest over k-means seeds 1-10", min(seed_acc[, "pooled"]), "fraction")

# Why the FPCA distance is low: how many training recordings its models keep
# (alignment and the over-long rule drop some), and whether they are trimmed
ms <- fit_grasp_models(g[g$meta$subject == "P1"], seed = 1, mixture_components = 1L)
sm <- summary(ms)
cat(sprintf("FPCA models on P1: %d of %d recordings kept; motion %s\n\n", sum(sm$n_used), sum(sm$n_input),
            fitted_models(ms)[[1]]$settings$motion))
bench_record("flexglove FPCA models: share of recordings kept", sum(sm$n_used) / sum(sm$n_input), "fraction")

# A per-recording offset (the glove slid between sessions): each recording
# of the test participant gets its own constant per channel, N(0, sd) with sd
# the observed sd of the rest level between recordings of one type. How many
# predictions of the discriminant change?
slipped <- function(x, sd, seed) {
  set.seed(seed)
  x$recordings <- lapply(x$recordings, function(r) sweep(r, 2, stats::rnorm(ncol(r), 0, sd), "+"))
  x
}
rest_sd <- stats::median(na.rm = TRUE, unlist(lapply(split(seq_along(g), g$meta$grasp), function(i) {
  if (length(i) > 1L) apply(t(vapply(g$recordings[i], function(r) r[1, ], numeric(length(g$dofs)))), 2, stats::sd)
})))
changed <- vapply(c("P1", "P2"), function(s) {
  cl <- fit_grasp_classifier(g[g$meta$subject != s])
  test <- g[g$meta$subject == s]
  mean(predict(cl, test)$.pred_class != predict(cl, slipped(test, rest_sd, 1))$.pred_class)
}, numeric(1))
cat(sprintf("A per-recording offset of sd %.1f counts (the rest level's spread within a type) changes %s of the discriminant's predictions\n\n",
            rest_sd, fmt(mean(changed))))
bench_record("flexglove discriminant predictions changed by a per-recording offset", mean(changed), "fraction")

# What the discriminant should be invariant to (issue 40): its features
# referred to each recording's own rest level (the median of its frames
# before the detected onset), to each participant's median rest level, and
# also divided by each participant's median range per channel (rest minus
# the smallest value). The per-participant forms use the held-out
# participant's unlabelled recordings together. Held out by participant as
# above, with the package's subclass ensemble.
rest <- t(mapply(function(r, s) apply(r[seq_len(max(3L, s - 1L)), , drop = FALSE], 2, stats::median),
                 g$recordings, find_motion(g)$start))
invariance <- local({
  p <- length(g$dofs)
  at <- seq(0, 1, by = 0.125)
  by_subject <- function(M) {
    for (s in unique(g$meta$subject)) {
      i <- g$meta$subject == s
      M[i, ] <- matrix(apply(M[i, , drop = FALSE], 2, stats::median), sum(i), ncol(M), byrow = TRUE)
    }
    M
  }
  range_ <- rest - t(vapply(g$recordings, function(r) apply(r, 2, min), numeric(p)))
  F <- classifier_features(g, at)
  level_cols <- c(seq_len(length(at) * p), ncol(F) - 2L * p + seq_len(2L * p))   # postures and extremes
  chan <- c(rep(seq_len(p), length(at)), rep(seq_len(p), 2L))
  refer <- function(level, scale = NULL) {
    G <- F
    G[, level_cols] <- F[, level_cols] - level[, chan]
    if (!is.null(scale)) G[, level_cols] <- G[, level_cols] / scale[, chan]
    G
  }
  y <- droplevels(as.factor(g$meta$grasp))
  acc <- function(G) {
    ok <- logical(length(y))
    for (s in unique(g$meta$subject)) {
      tr <- g$meta$subject != s
      fit <- fit_subclass_lda(G[tr, , drop = FALSE], y[tr], "equal", "auto")
      ok[!tr] <- top_class(fit$types, subclass_lda_scores(fit, G[!tr, , drop = FALSE])) == as.character(y[!tr])
    }
    c(pooled = mean(ok), vapply(c("P1", "P2"), function(s) mean(ok[g$meta$subject == s]), numeric(1)))
  }
  rbind(`as recorded` = acc(F), `each recording's rest level removed` = acc(refer(rest)),
        `each participant's rest level removed` = acc(refer(by_subject(rest))),
        `... and divided by the participant's range` = acc(refer(by_subject(rest), by_subject(range_))))
})
cat("The discriminant held out by participant, with its features referred to a rest level:\n")
print(data.frame(features = rownames(invariance), pooled = fmt(invariance[, "pooled"]), `test P1` = fmt(invariance[, "P1"]),
                 `test P2` = fmt(invariance[, "P2"]), check.names = FALSE), row.names = FALSE)
subject_rest <- apply(rest, 2, function(v) tapply(v, g$meta$subject, stats::median))
cat(sprintf("  the participants' median rest levels differ by %s counts on channels %s\n\n",
            paste(round(apply(subject_rest, 2, function(v) diff(range(v))), 1), collapse = ", "),
            paste(g$dofs, collapse = ", ")))
for (k in seq_len(nrow(invariance))) {
  bench_record(sprintf("flexglove discriminant, %s", rownames(invariance)[k]), invariance[k, "pooled"], "fraction")
}

# The same invariances for the FPCA likelihood distance (issue 40: "decide
# what the models should be invariant to"): every recording referred to a
# rest level before fitting and classifying (its own, or its participant's
# median), and also divided by the participant's median range per channel.
# The per-participant forms use the held-out participant's unlabelled
# recordings together; evaluate_loso() as in the table above.
fpca_invariance <- local({
  by_subject <- function(M) {
    for (s in unique(g$meta$subject)) {
      i <- g$meta$subject == s
      M[i, ] <- matrix(apply(M[i, , drop = FALSE], 2, stats::median), sum(i), ncol(M), byrow = TRUE)
    }
    M
  }
  low <- t(vapply(g$recordings, function(r) apply(r, 2, min), numeric(length(g$dofs))))
  referred <- function(level, scale = NULL) {
    recs <- lapply(seq_along(g), function(i) {
      r <- sweep(g$recordings[[i]], 2, level[i, ])
      if (is.null(scale)) r else sweep(r, 2, scale[i, ], "/")
    })
    grasps(recs, meta = g$meta[c("id", "grasp", "subject", "object", "trial")], rate = g$rate)
  }
  acc <- function(x) {
    ev <- evaluate_loso(x, method = "fpca", in_sample = FALSE)
    ps <- ev$per_subject
    c(pooled = ev$accuracy[["held_out"]], vapply(c("P1", "P2"), function(s) ps$accuracy[ps$subject == s], numeric(1)))
  }
  rbind(`as recorded` = acc(g), `each recording's rest level removed` = acc(referred(rest)),
        `each participant's rest level removed` = acc(referred(by_subject(rest))),
        `... and divided by the participant's range` = acc(referred(by_subject(rest), by_subject(rest - low))))
})
cat("The FPCA likelihood distance held out by participant, with the recordings referred to a rest level:\n")
print(data.frame(recordings = rownames(fpca_invariance), pooled = fmt(fpca_invariance[, "pooled"]),
                 `test P1` = fmt(fpca_invariance[, "P1"]), `test P2` = fmt(fpca_invariance[, "P2"]),
                 check.names = FALSE), row.names = FALSE)
cat("\n")
for (k in seq_len(nrow(fpca_invariance))) {
  bench_record(sprintf("flexglove fpca, %s", rownames(fpca_invariance)[k]), fpca_invariance[k, "pooled"], "fraction")
}

# The simulator's raw-count glove (bench/bench-glove.R's set): one person, 5 folds by recording
objects <- c(bottle = 1, mug = 9, ball = 17, pen = 22, card = 28, key = 31)
raw <- simulate_grasps(subjects = 1, grasps = objects[seq_len(bq(6, 3))], objects = 1, trials = bq(28, 8),
                       rate = 100, glove = "resistive", rest = 1, hold = 1, stuck = "thumb_cross",
                       plant_overlong = FALSE, seed = 3)
cat(sprintf("Simulated raw-count glove: %d recordings of %d channels, 5 folds by recording\n", length(raw), length(raw$dofs)))
for (m in setdiff(names(methods), "fpca_residual")) {
  r <- timed(evaluate_loso(raw, method = m, in_sample = FALSE))
  cat(sprintf("  %-30s %s  (%.1f s)\n", methods[[m]], fmt(r$value$accuracy[["held_out"]]), r$elapsed))
  bench_record(sprintf("simulated glove %s accuracy", m), r$value$accuracy[["held_out"]], "fraction")
}
