# Subclasses of the discriminant (mixture discriminant analysis with a
# shared covariance). One Gaussian per grasp type assumes a type has one
# typical motion; real types are grasped round different objects (a coke can,
# a pineapple, a bottle are all Large Diameter), so a type's recordings form
# several clusters and its mean sits between them, near other types. On the
# real flexglove recordings (6 flex sensors, 8 types, 3 objects each), one
# Gaussian per type recognises 71.6% of the other participant's recordings,
# and 1-NN on the same features 82.6%: the classes are multimodal. Each type
# is therefore split into up to k subclasses by k-means on its standardised
# features; every subclass is a Gaussian sharing the one shrunk covariance,
# and a type's posterior is the sum of its subclasses' (their prior within
# the type is their share of its recordings). k = 1 is the one-Gaussian fit.
#
# k is a tuning parameter that real data did not pin down: chosen by an
# inner cross-validation (folds of training participants), held out by
# participant on flexglove, the choice swung with the k-means seed between
# one Gaussian per type and six subclasses, and the accuracy with it (82.4%
# to 85.8% over seeds 1-10). "auto" therefore chooses nothing: it fits every
# k of discriminant_subclass_choices and averages their class probabilities
# (an ensemble, as bagging averages; Hastie & Tibshirani's mixture
# discriminant analysis with several model sizes). A k that does not suit a
# set costs it little, since the others outvote it; where one Gaussian per
# type is right (types unimodal) the finer members agree with it. It is also
# cheaper than the inner choice, which fitted every k on every inner fold.

discriminant_subclass_choices <- c(1L, 2L, 4L, 6L)

# Smallest average subclass: a type is split into at most n / 5 subclasses,
# so every centre is the mean of about five recordings or more.
subclass_min_size <- 5L

# The discriminant of the subclasses: `subclasses` a whole number (that many
# clusters per type at most: one member) or "auto" (one member per k of
# discriminant_subclass_choices, probabilities averaged). A list with
# `members` (the fits of subclass_lda_member()), `types`, `type_prior`,
# `subclasses` (the number given, or "auto"), `subclasses_used` (per type:
# the clusters of the finest member), `shrinkage` (per member) and `n`
# (training recordings per type).
fit_subclass_lda <- function(F, y, prior, subclasses, seed = 1) {
  # The subclasses come from seeded k-means, so the same training recordings
  # must give the same classifier whatever RNG kind the caller runs:
  # evaluate_loso()'s folds run under future.seed, which switches to
  # L'Ecuyer-CMRG, and there set.seed(1) drew other k-means starts than a
  # plain fit_grasp_classifier() call. The caller's RNG is restored.
  old <- save_rng()
  on.exit(restore_rng(old))
  RNGkind("Mersenne-Twister", "Inversion", "Rejection")
  y <- droplevels(as.factor(y))
  ks <- if (identical(subclasses, "auto")) discriminant_subclass_choices else subclasses
  members <- lapply(ks, function(k) subclass_lda_member(F, y, prior, k, seed))
  finest <- members[[length(members)]]
  list(members = members, types = levels(y), type_prior = finest$type_prior, subclasses = subclasses,
       subclasses_used = finest$subclasses_used,
       shrinkage = vapply(members, function(m) m$shrinkage, numeric(1)),
       n = as.numeric(table(y)))
}

# One member: up to k subclasses per type, one shrunk covariance.
subclass_lda_member <- function(F, y, prior, k, seed) {
  sub <- subclass_labels(F, y, k, seed)
  fit <- fit_shrunk_lda(F, sub$label, prior = "equal")
  type_of <- sub$type[match(fit$classes, levels(sub$label))]
  counts <- table(y)
  type_prior <- if (prior == "equal") rep(-log(nlevels(y)), nlevels(y)) else log(as.numeric(counts) / sum(counts))
  names(type_prior) <- levels(y)
  # a subclass's prior: its type's times its share of the type's recordings
  fit$sub_log_prior <- type_prior[type_of] + log(fit$n / as.numeric(counts[type_of]))
  fit$type_of <- type_of
  fit$type_prior <- type_prior
  fit$types <- levels(y)
  fit$subclasses <- k
  fit$subclasses_used <- sub$used
  fit
}

# Log posterior of every type (rows normalised: their exponentials sum to
# one): the log of the members' posteriors averaged.
subclass_lda_scores <- function(fit, F) {
  P <- lapply(fit$members, function(m) {
    s <- member_log_posterior(m, F)
    exp(s - log_sum_exp_rows(s))
  })
  matrix(log(Reduce(`+`, P) / length(P)), nrow(F), length(fit$types), dimnames = list(rownames(F), fit$types))
}

# One member's log posterior (up to a constant per row) of every type: the
# log of the sum of its subclasses' posteriors.
member_log_posterior <- function(m, F) {
  s <- shrunk_lda_scores(m, F)
  s <- s + rep(m$sub_log_prior - m$log_prior, each = nrow(s))
  out <- vapply(m$types, function(t) log_sum_exp_rows(s[, m$type_of == t, drop = FALSE]), numeric(nrow(s)))
  matrix(out, nrow(s), length(m$types))
}

log_sum_exp_rows <- function(s) {
  if (ncol(s) == 1L) return(s[, 1])
  top <- s[cbind(seq_len(nrow(s)), max.col(s, ties.method = "first"))]
  top + log(rowSums(exp(s - top)))
}

# Subclass labels "type|j": k-means (seeded, 3 starts) on the features
# standardised over the whole set, within each type, with at most
# n_type / subclass_min_size clusters. A type whose recordings cannot be split
# (too few, or fewer distinct rows than clusters) stays one subclass;
# `used` records how many each type got.
subclass_labels <- function(F, y, k, seed) {
  Fc <- F - rep(colMeans(F), each = nrow(F))
  sd <- sqrt(colSums(Fc^2) / max(nrow(F) - 1L, 1L))
  sd[!is.finite(sd) | sd == 0] <- 1
  Z <- sweep(F, 2L, sd, "/")
  lab <- as.character(y)
  used <- stats::setNames(integer(nlevels(y)), levels(y))
  for (t in levels(y)) {
    i <- which(y == t)
    kt <- min(k, length(i) %/% subclass_min_size)
    cl <- if (kt >= 2L) {
      tryCatch(with_seed(seed, stats::kmeans(Z[i, , drop = FALSE], kt, nstart = 3L, iter.max = 30L)$cluster),
               error = function(e) NULL)
    }
    if (is.null(cl)) cl <- rep(1L, length(i))
    used[[t]] <- length(unique(cl))
    lab[i] <- paste(t, cl, sep = "|")
  }
  label <- factor(lab)
  list(label = label, type = sub("[|][^|]*$", "", levels(label)), used = used)
}
