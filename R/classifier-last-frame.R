# Last-frame PCA (thesis section 4.2, second scheme; Tables 5.7 and 5.8).
# A grasp type is identified by its final hand posture, so each type is
# summarised by an ordinary PCA of the last frames of its recordings. A new
# recording is scored against each type by the Euclidean distance between its
# last frame and that frame's projection on the type's first ncomp PCs (centred on
# the type's mean last frame): the reconstruction error of the type's ncomp-PC
# subspace. The type with the smallest error wins.

# fit_grasp_classifier(method = "last_frame"): one PCA of the last frames per
# grasp type (documented there).
fit_last_frame_pca <- function(x, ncomp = 5, grasps = NULL, call = rlang::caller_env()) {
  check_grasps(x, call = call)
  ncomp <- check_whole(ncomp, "ncomp", max = length(x$dofs), call = call)
  types <- labelled_types(x, grasps, call = call)
  last <- last_frame_matrix(x)
  models <- lapply(types, function(type) {
    rows <- which(as.character(x$meta$grasp) == type)
    pca_of_frames(last[rows, , drop = FALSE])
  })
  names(models) <- types
  n_per <- vapply(models, function(m) m$n, integer(1))
  ncomp_used <- stats::setNames(pmin(ncomp, n_per - 1L), names(models))
  short <- names(ncomp_used)[ncomp_used < ncomp]
  if (length(short) > 0L) {
    hm_warn(c("{length(short)} grasp type{?s} ha{?s/ve} too few recordings for {ncomp} PCs: {.val {short}}.",
              i = "Using n - 1 components instead (see {.field ncomp_used})."),
            "few_recordings")
  }
  # the temperature of its probabilities, on held-out distances
  temperature <- fit_temperature(last_frame_heldout_distances(list(models = models, ncomp_used = ncomp_used), x, last),
                                 x$meta$grasp)
  new_grasp_classifier(models = models, ncomp = ncomp, ncomp_used = ncomp_used, dofs = x$dofs,
                       n_unlabelled = sum(is.na(x$meta$grasp)), classes = types, levels = grasp_levels(x),
                       n = n_per, temperature = temperature, class = "last_frame_pca")
}

# The last-frame PCA in the classifier family (R/classifier.R).
#' @export
classifier_distances.last_frame_pca <- function(object, new_data, ..., call = rlang::caller_env()) {
  last_frame_distances(object, new_data, call = call)
}

#' @export
classifier_method.last_frame_pca <- function(object) "last_frame"

#' @export
classifier_parts.last_frame_pca <- function(object) c(NextMethod(), "models", "dofs")

# The training recordings' distances to every type from PCAs fitted without
# them: held out by subject when the recordings name two or more subjects
# (as a new user's recordings would be), else one recording at a time. A
# type left with no recordings gives NA.
last_frame_heldout_distances <- function(fit, x, last) {
  subj <- x$meta$subject
  group <- if (!is.null(subj) && !anyNA(subj) && length(unique(subj)) > 1L) as.character(subj) else seq_along(x$recordings)
  lab <- as.character(x$meta$grasp)
  types <- names(fit$models)
  d <- matrix(NA_real_, nrow(last), length(types), dimnames = list(rownames(last), types))
  for (g in unique(group)) {
    out <- group == g
    for (type in types) {
      rows <- which(!out & lab %in% type)
      if (!length(rows)) next
      m <- pca_of_frames(last[rows, , drop = FALSE])
      centred <- sweep(last[out, , drop = FALSE], 2L, m$mean)
      v <- m$rotation[, seq_len(min(fit$ncomp_used[[type]], ncol(m$rotation))), drop = FALSE]
      d[out, type] <- sqrt(rowSums((centred - (centred %*% v) %*% t(v))^2))
    }
  }
  d
}

# Grasp types to model: the requested ones (validated) or all labelled types
# present, in Feix order.
labelled_types <- function(x, grasps = NULL, call = rlang::caller_env()) {
  have <- check_some_types(label_order(unique(as.character(stats::na.omit(x$meta$grasp)))), x, call = call)
  want <- check_grasp_selection(grasps, "grasps", levels = levels(x$meta$grasp), call = call)
  if (is.null(want)) return(have)
  absent <- setdiff(want, have)
  if (length(absent) > 0L) {
    hm_abort("No recordings of grasp type{?s} {.val {absent}} in {.arg x}.", "bad_input",
             argument = "grasps", call = call)
  }
  want
}

# n x DoF matrix of the last frame of every recording.
last_frame_matrix <- function(x) {
  out <- do.call(rbind, lapply(x$recordings, function(r) r[nrow(r), ]))
  dimnames(out) <- list(x$meta$id, x$dofs)
  out
}

pca_of_frames <- function(frames) {
  n <- nrow(frames)
  p <- ncol(frames)
  mu <- colMeans(frames)
  centred <- sweep(frames, 2L, mu)
  if (n > 1L) {
    s <- svd(centred, nu = 0L)
    r <- min(n - 1L, p)
    rotation <- s$v[, seq_len(r), drop = FALSE]
    vars <- s$d[seq_len(r)]^2 / (n - 1)
  } else {
    rotation <- matrix(0, p, 0L)
    vars <- numeric(0)
  }
  dimnames(rotation) <- list(colnames(frames), sprintf("PC%d", seq_len(ncol(rotation))))
  total <- sum(vars)
  # All p PCs (Table 5.7): components beyond the rank explain nothing more.
  cumvar <- rep(NA_real_, p)
  if (total > 0) cumvar <- c(cumsum(vars), rep(total, p - length(vars)))[seq_len(p)] / total
  list(mean = mu, rotation = rotation, sdev = sqrt(vars), cumvar = cumvar, n = n)
}

#' Cumulative variance explained by last-frame PCs (Table 5.7)
#'
#' @param fit A `fit_grasp_classifier(method = "last_frame")` result.
#' @return A data frame with one row per grasp type: `grasp_id`, `grasp` and
#'   `pc1` ... `pc<p>`, the cumulative fraction of variance explained by the
#'   first 1 ... p principal components of the type's last frames (`NA` for a
#'   type with one recording or no variance).
#' @noRd
#' @examples
#' set.seed(2)
#' recs <- lapply(1:8, function(i) matrix(rnorm(5 * 16), 5, 16))
#' g <- grasps(recs, meta = data.frame(grasp = rep(c(1, 2), 4)))
#' cumulative_variance(fit_grasp_classifier(g, method = "last_frame", ncomp = 2))
cumulative_variance <- function(fit) {
  if (!inherits(fit, "last_frame_pca")) {
    hm_abort("{.arg fit} must be a {.cls last_frame_pca} object, not {.obj_type_friendly {fit}}.",
             "bad_input", argument = "fit", call = rlang::caller_env())
  }
  types <- names(fit$models)
  cv <- do.call(rbind, lapply(fit$models, function(m) m$cumvar))
  colnames(cv) <- paste0("pc", seq_len(ncol(cv)))
  out <- data.frame(grasp_id = match(types, feix_levels()), grasp = types, cv,
                    stringsAsFactors = FALSE, check.names = FALSE)
  rownames(out) <- NULL
  out
}

last_frame_distances <- function(fit, x, call = rlang::caller_env()) {
  check_grasps(x, arg = "new_data", call = call, finite = FALSE)
  if (!identical(x$dofs, fit$dofs)) {
    hm_abort(c("{.arg new_data} has DoFs {.val {x$dofs}}, the model was fitted on {.val {fit$dofs}}.",
               i = "Both must have the same DoFs in the same order."),
             "dof_mismatch", argument = "new_data", call = call)
  }
  last <- last_frame_matrix(x)
  d <- vapply(names(fit$models), function(type) {
    m <- fit$models[[type]]
    centred <- sweep(last, 2L, m$mean)
    v <- m$rotation[, seq_len(fit$ncomp_used[[type]]), drop = FALSE]
    resid <- centred - (centred %*% v) %*% t(v)
    sqrt(rowSums(resid^2))
  }, numeric(nrow(last)))
  matrix(d, nrow(last), length(fit$models), dimnames = list(x$meta$id, names(fit$models)))
}

#' @export
print.last_frame_pca <- function(x, ...) {
  n <- vapply(x$models, function(m) m$n, integer(1))
  cv <- vapply(x$models, function(m) m$cumvar[x$ncomp], numeric(1))
  k <- as.integer(x$ncomp)
  cli::cat_line(cli::pluralize("<last_frame_pca> {length(x$models)} grasp type{?s}, {length(x$dofs)} DoF{?s}, {k} PC{?s}"))
  cli::cat_line(cli::pluralize("  recordings per type: {min(n)} to {max(n)}; variance explained by {k} PC{?s}: "),
                fmt_pct(min(cv, na.rm = TRUE)), " to ", fmt_pct(max(cv, na.rm = TRUE)))
  short <- names(x$ncomp_used)[x$ncomp_used < x$ncomp]
  if (length(short) > 0) {
    cli::cat_line(cli::pluralize("  fewer than {k} PC{?s} (too few recordings): "), paste(short, collapse = ", "))
  }
  n_unlab <- as.integer(x$n_unlabelled)
  if (n_unlab > 0) cli::cat_line(cli::pluralize("  ignored {n_unlab} unlabelled recording{?s}"))
  invisible(x)
}

#' @rdname summary.grasp_classifier
#' @export
summary.last_frame_pca <- function(object, ...) {
  classifier_summary_frame(object, ncomp_used = unname(object$ncomp_used[object$classes]),
                           var_explained = unname(vapply(object$classes, function(ty) {
                             object$models[[ty]]$cumvar[max(object$ncomp_used[[ty]], 1L)]
                           }, numeric(1))))
}
