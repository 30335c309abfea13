# Evaluation splits for any study design. With recordings of two or more
# subjects a held-out fold holds out whole subjects (a classifier must work
# for a hand it never saw); with one subject, folds hold out recordings,
# stratified by label so every fold sees every class. One function makes the
# folds for every evaluation (evaluate_loso(), evaluate_early_recognition(),
# evaluate_generation()).
#
# Stratified k-fold is written here rather than taken from rsample: its
# vfold_cv() pools classes under 10% of the data into one stratum by default
# (any study with more than ten labels), and the whole of it is the dozen
# lines below.

# Folds as a list of logical vectors over the recordings of `x` (TRUE = held
# out in that fold), with attribute `scheme` (a sentence for print()) and
# `split` ("subject" or "recording"). `split = "auto"` is by subject when at
# least two subjects are known, else by recording; `folds` is the number of
# folds (NULL: one per subject, or 5 by recording).
make_folds <- function(x, split = c("auto", "subject", "recording"), folds = NULL, seed = 1,
                       subjects = NULL, call = rlang::caller_env()) {
  split <- check_choice(split, c("auto", "subject", "recording"), arg = "split", call = call)
  subj <- x$meta$subject
  all_subjects <- unique(stats::na.omit(subj))
  if (split == "auto") split <- if (length(all_subjects) >= 2L) "subject" else "recording"
  if (split == "subject") {
    if (is.null(subjects)) subjects <- all_subjects
    subjects <- unique(as.character(subjects))
    unknown <- setdiff(subjects, all_subjects)
    if (length(unknown) > 0L) {
      hm_abort("Unknown subject{?s} {.val {unknown}}.", "bad_input", argument = "subjects", call = call)
    }
    if (length(all_subjects) < 2L || length(subjects) < 1L) {
      hm_abort(c("Folds by subject need at least two subjects; {.arg x} has {length(all_subjects)}.",
                 i = "Use {.code split = \"recording\"} (or the default {.code \"auto\"}) for stratified folds of recordings."),
               "too_few_subjects", argument = "x", call = call)
    }
    groups <- subject_folds(subjects, folds, seed, call = call)
    if (length(groups) == 1L && setequal(groups[[1]], all_subjects)) {
      hm_abort("With one fold holding every subject nothing is left for training; use more {.arg folds}.",
               "too_few_subjects", argument = "folds", call = call)
    }
    out <- lapply(groups, function(s) !is.na(subj) & subj %in% s)
    names(out) <- vapply(groups, paste, character(1), collapse = ",")
    scheme <- if (is.null(folds)) "leave-one-subject-out"
              else sprintf("leave-group-out (%d folds of subjects)", length(groups))
    return(structure(out, scheme = scheme, split = "subject"))
  }
  # (folds of recordings: at least two, at most one recording each)
  k <- check_whole(folds %||% 5L, "folds", min = 2, max = length(x), call = call)
  fold <- stratified_fold_ids(x$meta$grasp, k, seed)
  out <- lapply(seq_len(k), function(f) fold == f)
  names(out) <- paste("fold", seq_len(k))
  structure(out, scheme = sprintf("%d-fold by recording, stratified by label (seed %s)", k, format(seed)),
            split = "recording")
}

# Fold ids 1..k for labels: each label's recordings are shuffled (seeded) and
# dealt round the folds, continuing where the previous label stopped, so each
# fold gets floor or ceiling of its share of every label and the folds differ
# in size by at most one.
stratified_fold_ids <- function(labels, k, seed) {
  lab <- as.character(labels)
  lab[is.na(lab)] <- "\r(unlabelled)"
  fold <- integer(length(lab))
  start <- 0L
  with_seed(seed, {
    for (l in sort(unique(lab))) {
      idx <- which(lab == l)
      idx <- idx[sample.int(length(idx))]
      fold[idx] <- (start + seq_along(idx) - 1L) %% k + 1L
      start <- (start + length(idx)) %% k
    }
  })
  fold
}

# Subjects grouped into folds: one per subject, or `folds` seeded random
# groups of near-equal size.
subject_folds <- function(subjects, folds, seed, call = rlang::caller_env()) {
  if (is.null(folds)) return(as.list(subjects))
  # (groups of subjects: at most one subject each)
  folds <- check_whole(folds, "folds", max = length(subjects), call = call)
  shuffled <- with_seed(seed, sample(subjects))
  unname(split(shuffled, rep_len(seq_len(folds), length(shuffled))))
}

# A 95% Wilson score interval for a proportion of `correct` out of `n`: it
# stays inside [0, 1] and is sensible at 0 or n correct, where the normal
# interval is not.
accuracy_interval <- function(correct, n, level = 0.95) {
  if (is.na(n) || n == 0) return(c(lower = NA_real_, upper = NA_real_))
  z <- stats::qnorm(1 - (1 - level) / 2)
  p <- correct / n
  centre <- (p + z^2 / (2 * n)) / (1 + z^2 / n)
  half <- z * sqrt(p * (1 - p) / n + z^2 / (4 * n^2)) / (1 + z^2 / n)
  c(lower = max(0, centre - half), upper = min(1, centre + half))
}
