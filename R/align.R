# Time alignment of the recordings of one grasp type (Jeppsson 2017, 3.1-3.2,
# 4.1.2, 5.1.1). The thesis aligned with a MATLAB multi-sequence DTW and fell
# back to linear warping when it failed. We align every recording to a common
# template with pairwise multivariate DTW and refine the template by DTW
# barycenter averaging (DBA: Petitjean, Ketterlin & Gancarski 2011), so no
# single recording is the arbitrary reference. Two engines do the pairwise
# step: "reference" is the dtw package, "fast" is src/dtw.c, which reproduces
# dtw's symmetric2 recursion and tie-breaking exactly (tests compare them).
# By default DTW compares shape features (per recording and DoF: centred on
# the start/end postures, scaled by the sd), because on raw angles it explains
# posture differences between subjects by holding recordings still; on the
# simulated data that dropped 7-23% of each type as degenerate, against 0-3%
# with shape features (features = "raw" keeps the plain comparison).

# One pairwise DTW by the dtw package (the "reference" engine, symmetric2 steps,
# Euclidean distance between frames, optionally a slanted band `window`): the
# warping path `index1`/`index2` and the accumulated `distance`.
dtw_pair_reference <- function(x, template, window) {
  args <- list(x, template, step.pattern = dtw::symmetric2, keep.internals = FALSE)
  # dtw warns when dist.method is given for one-column series; Euclidean is
  # its default anyway.
  if (ncol(x) > 1L) args$dist.method <- "Euclidean"
  if (!is.null(window)) {
    args$window.type <- "slantedband"
    args$window.size <- window
  }
  r <- do.call(dtw::dtw, args)
  list(index1 = as.integer(r$index1), index2 = as.integer(r$index2),
       distance = r$distance)
}

#' Align the recordings of one grasp type
#'
#' Warps every recording to a common length `L` with multivariate dynamic time
#' warping against a template refined by DTW barycenter averaging (DBA):
#' the initial template is the mean of all recordings linearly resampled to
#' `L`; each iteration aligns every recording to the template
#' (pairwise DTW) and replaces template frame `j` by the mean of all
#' recording frames matched to it, until the relative change of the template
#' (Frobenius norm) is below `tol` or after `max_iter` iterations.
#'
#' Warped recording `k` has as frame `j` the mean of its frames matched to
#' template frame `j`; its warping function gives, for each template frame,
#' the (mean) original frame matched to it, 1-based, non-decreasing, with its
#' ends pinned to 1 and `n_k` (DTW's boundary condition), so it also carries
#' the recording's length.
#'
#' **Degenerate warps** (Jeppsson 2017, Figure 5.1): a recording whose warping
#' function stays on one original frame for more than `max_stall * L`
#' consecutive template frames (at least two) is held still over a long
#' stretch of the warped time. Such recordings are dropped (listed in
#' `$degenerate`), and the template is refined again without them (at most
#' two more iterations; at most five rounds of dropping). If more than half of
#' the recordings are flagged at once, the template itself is suspect, so only
#' the worst is dropped and DBA restarts from the linear mean of the rest.
#' With `degenerate_warps = "constrain"` (default) the flagged recordings
#' are then aligned again, one by one, to that final template by DTW under a
#' slope constraint (local slopes between 1/3 and 3, the dtw package's
#' `symmetricP05`: a frame is held over at most three template frames, while
#' the recording may shift by any amount), or linearly if no such path exists,
#' and kept; `"drop"` (the thesis) leaves them out. When more than half of
#' the recordings stall at once (long rests and holds: the template itself
#' holds still), `"constrain"` aligns the whole type by slope-constrained DBA
#' from the linear mean instead of the rounds of restarts (without `window`).
#'
#' **Fallback**: if DTW fails (an error, e.g. non-finite values or no path
#' within `window`, a non-finite template, or fewer than two recordings
#' left), the whole type is warped linearly (`method = "linear"`, with the
#' reason in `fallback_reason`): each recording is resampled to `L` frames and
#' its warping function runs linearly from 1 to `n_k`.
#'
#' **Degenerate data** is aligned as well as it can be, and said: recordings
#' of a single frame or holding non-finite values, `window = 0` (only the
#' diagonal path) and the linear fallback raise one warning of class
#' `handmotion_warning_degenerate` (see [handmotion_errors]), listed in
#' `$degenerate_data` and by `print()`.
#'
#' Over-long recordings should be removed first (`find_overlong()`). Users
#' meet the result as a fitted model's `alignment` ([fit_grasp_model()]).
#'
#' @param recordings A list of numeric matrices (frames x DoFs, same DoFs),
#'   one grasp type; names are used as ids. A [grasps()] object is accepted.
#' @param target_length Length `L` of the warped recordings; default
#'   `round(mean(n_frames))`; at most 1,000,000 frames (the warped array
#'   holds `n x L x p` numbers).
#' @param engine `"fast"` (src/dtw.c) or `"reference"` (the dtw package)
#'   pairwise DTW; both give the same paths.
#' @param max_iter Maximum number of DBA iterations (0 = align to the linear
#'   mean only).
#' @param tol Convergence tolerance on the relative template change.
#' @param max_stall Longest allowed stall, as a fraction of `L`.
#' @param window Optional DTW window half-width: a band of that many template
#'   frames around the diagonal slanted from (1, 1) to (n, L).
#' @param features What DTW compares. `"shape"` (default): each recording's
#'   DoFs centred on the midpoint of its start and end postures and scaled by
#'   their standard deviation, so that differences in posture and excursion
#'   between subjects and objects are not mistaken for timing (DTW on raw
#'   angles then holds recordings still, a singular warp). `"raw"`: the
#'   angles as recorded. Either way the warped recordings are in data units.
#' @param degenerate_warps `"constrain"` keeps degenerate recordings with a
#'   slope-constrained or linear warp, `"drop"` drops them (the thesis; see Degenerate
#'   warps).
#' @return An object of class `grasp_alignment`, a list with `warped` (array
#'   `[n, L, p]`, dimnames ids, NULL, DoFs), `warps` (`n x L` matrix, original
#'   frame per template frame), `template` (`L x p`), `target_length`, `ids`,
#'   `n_frames` (original lengths, named), `method` (`"dtw"` or `"linear"`),
#'   `fallback_reason` (`NA` unless linear), `degenerate` (data frame `id`,
#'   `stall`, `n_frames`, `fallback` of the recordings with a degenerate DTW
#'   warp: `"dropped"` ones are not in `warped`, `"slope"` and `"linear"`
#'   ones are, with that warp), `dropped_warps` (their degenerate DTW
#'   warping functions), `iterations`, `converged`,
#'   `changes` (relative template change at each iteration), `engine`,
#'   `degenerate_warps`, `step_pattern` (`"symmetric2"`, or `"symmetricP05"`
#'   when most warps stalled at once and the whole type was aligned by
#'   slope-constrained DBA),
#'   `distance` (DTW cost per kept recording), `max_stall`, `features`,
#'   `feature_template` (the DBA template in the space DTW compared; with
#'   `features = "raw"` it equals `template`, otherwise `template` is the mean
#'   warped recording in data units), `degenerate_data` (data frame `class`,
#'   `message`: what of the input was degenerate, see above).
#' @seealso [autoplot.grasp_alignment()]
#' @examples
#' set.seed(1)
#' curve <- function(u) cbind(a = 50 * plogis((u - 0.5) / 0.08), b = 30 * sin(pi * u))
#' recs <- lapply(1:8, function(k) {
#'   n <- sample(35:45, 1); u <- seq(0, 1, length.out = n)
#'   curve(u + (k - 4.5) / 20 * u * (1 - u))
#' })
#' al <- align_recordings(recs)
#' al
#' dim(al$warped)
#' @noRd
align_recordings <- function(recordings, target_length = NULL, engine = c("fast", "reference"),
                             max_iter = 10, tol = 1e-3, max_stall = 0.25, window = NULL,
                             features = c("shape", "raw"), degenerate_warps = c("constrain", "drop")) {
  call <- rlang::caller_env()
  engine <- check_choice(engine, arg = "engine", call = call)
  features <- check_choice(features, arg = "features", call = call)
  degenerate_warps <- check_choice(degenerate_warps, arg = "degenerate_warps", call = call)
  if (inherits(recordings, "grasps")) recordings <- recordings$recordings
  recs <- align_check_recordings(recordings, call)
  n_frames <- vapply(recs, nrow, integer(1))
  L <- check_whole(target_length, "target_length", max = 1e6, allow_null = TRUE, call = call) %||%
    max(1L, as.integer(round(mean(n_frames))))
  check_whole(max_iter, "max_iter", min = 0, call = call)
  check_number(tol, "tol", min = 0, min_open = TRUE, call = call)
  check_number(max_stall, "max_stall", min = 0, min_open = TRUE, call = call)
  window <- check_number(window, "window", min = 0, allow_null = TRUE, call = call)

  al <- align_checked(recs, L, engine, max_iter, tol, max_stall, window, features, degenerate_warps)
  # degenerate data (one-frame or non-finite recordings, a zero window, the
  # linear fallback) is said at the top level, not only deep in the object
  al$degenerate_data <- alignment_degeneracies(al, recs, window)
  warn_degenerate(al$degenerate_data, "The alignment rests on degenerate data:")
  al
}

# The alignment of checked recordings (align_recordings() without its checks
# and warnings).
align_checked <- function(recs, L, engine, max_iter, tol, max_stall, window, features,
                          degenerate_warps = "constrain") {
  ids <- names(recs)
  n_frames <- vapply(recs, nrow, integer(1))
  if (length(recs) < 2L) {
    return(align_linear_fallback(recs, L, engine,
                            reason = "fewer than 2 recordings to align"))
  }
  norm <- if (features == "shape") shape_features(recs) else NULL
  feats <- if (is.null(norm)) recs else norm$features
  constrain <- degenerate_warps == "constrain"
  fit <- tryCatch(dba_with_drops(feats, L, engine, max_iter, tol, max_stall, window,
                                 stop_if_suspect = constrain && is.null(window)),
                  error = function(e) e)
  if (!inherits(fit, "error") && !is.null(fit$suspect)) {
    fit <- tryCatch(slope_dba_fit(fit, feats, L, engine, max_iter, tol), error = function(e) e)
  }
  if (inherits(fit, "error")) {
    return(align_linear_fallback(recs, L, engine, reason = conditionMessage(fit)))
  }
  if (length(fit$kept) < 2L) {
    return(align_linear_fallback(
      recs, L, engine,
      reason = as.character(cli::pluralize(
        "fewer than 2 recordings left after dropping {nrow(fit$degenerate)} degenerate warp{?s}"))))
  }
  if (constrain && is.null(fit$step_pattern) && nrow(fit$degenerate) > 0L) {
    fit <- constrain_degenerate(fit, feats, L, engine, max_stall)
  }
  kept <- fit$kept
  dofs <- colnames(recs[[1]])
  warped <- fit$run$warped
  feature_template <- fit$run$template
  if (!is.null(norm)) {
    # back to data units: the normalisation is affine per recording and DoF,
    # so the mean of the normalised matched frames maps to the raw mean
    # (x * scale + centre for all recordings at once: element [i, l, c]
    # of the array is scaled by scale[kept[i], c]; in C, src/dba-prep.c)
    warped <- .Call(hm_unshape_warped, warped, norm$scale, norm$centre, as.integer(kept))
    template <- matrix(colMeans(warped, dims = 1L), L)
  } else {
    template <- feature_template
  }
  dimnames(warped) <- list(ids[kept], NULL, dofs)
  warps <- fit$run$warps
  dimnames(warps) <- list(ids[kept], NULL)
  dimnames(template) <- list(NULL, dofs)
  dimnames(feature_template) <- list(NULL, dofs)
  new_grasp_alignment(
    warped = warped, warps = warps, template = template, target_length = L,
    ids = ids[kept], n_frames = n_frames[kept], method = "dtw",
    fallback_reason = NA_character_, degenerate = fit$degenerate,
    dropped_warps = fit$dropped_warps, iterations = fit$iterations,
    converged = fit$converged, changes = fit$changes, engine = engine,
    distance = stats::setNames(fit$run$distance, ids[kept]), max_stall = max_stall,
    features = features, feature_template = feature_template,
    degenerate_warps = degenerate_warps, step_pattern = fit$step_pattern %||% "symmetric2")
}

# Per recording and DoF: centre on the midpoint of the start and end postures
# (mean of the first and of the last few frames) and scale by the DoF's sd.
# Recordings of one type differ in posture offsets (subject, object size) and
# excursion; DTW on the raw angles "explains" such differences by holding a
# recording still (singular warps). The endpoints are the rest and the final
# posture whatever the timing, so unlike the mean over time this centre does
# not depend on the warp. The scale has a floor of 10% of the recording's
# largest DoF sd, so a DoF that barely moves is not blown up to noise.
# The shape features of every recording in one compiled call
# (src/dba-prep.c; shape_normaliser() and normalise_recording() in
# tests/testthat/helper-align-reference.R are the R reference): `features` (named like
# `recs`), and `centre` and `scale` (recordings x DoFs).
shape_features <- function(recs, k = 3L) {
  out <- .Call(hm_shape_features, unname(recs), as.integer(k))
  names(out$features) <- names(recs)
  out
}

new_grasp_alignment <- function(...) {
  structure(list(...), class = "grasp_alignment")
}

# DBA, then drop degenerate recordings and align again without them. After a
# few drops the template is refined from where it was (at most
# `refine_iter` iterations: the few dropped recordings barely moved it). When
# most recordings stall at once, the template itself is the problem (a
# compromise between good and broken recordings): only the worst is dropped
# and DBA restarts from the linear mean of the rest, since DBA is local and a
# template shaped by the broken ones can hold the others in a poor alignment.
# Recordings still flagged after the last round are dropped without a further
# refinement.
dba_with_drops <- function(recs, L, engine, max_iter, tol, max_stall, window,
                           max_rounds = 5L, refine_iter = 2L, stop_if_suspect = FALSE) {
  kept <- seq_along(recs)
  suspect <- NULL
  degenerate <- empty_degenerate()
  dropped_warps <- matrix(numeric(0), 0L, L)
  iterations <- 0L
  changes <- numeric(0)
  template <- mean_linear_template(recs, L)
  budget <- max_iter
  for (round in seq_len(max_rounds)) {
    run <- dba_run(recs[kept], template, engine, budget, tol, window)
    iterations <- iterations + run$iterations
    changes <- c(changes, run$changes)
    stall <- stall_lengths(run$warps)
    bad <- stall >= 2L & stall > max_stall * L
    if (!any(bad)) break
    restart <- sum(bad) > length(kept) / 2
    if (restart && stop_if_suspect) {
      # (degenerate_warps = "constrain": the caller aligns the whole type
      # by slope-constrained DBA instead of restarting, see slope_dba_fit())
      suspect <- data.frame(id = names(recs)[kept[bad]], stall = stall[bad],
                            n_frames = vapply(recs[kept[bad]], nrow, integer(1)), fallback = "slope",
                            stringsAsFactors = FALSE)
      bw <- run$warps[bad, , drop = FALSE]
      rownames(bw) <- names(recs)[kept[bad]]
      dropped_warps <- rbind(dropped_warps, bw)
      break
    }
    if (restart) bad <- stall == max(stall)
    degenerate <- rbind(degenerate, data.frame(
      id = names(recs)[kept[bad]], stall = stall[bad],
      n_frames = vapply(recs[kept[bad]], nrow, integer(1)), fallback = "dropped",
      stringsAsFactors = FALSE))
    bw <- run$warps[bad, , drop = FALSE]
    rownames(bw) <- names(recs)[kept[bad]]
    dropped_warps <- rbind(dropped_warps, bw)
    kept <- kept[!bad]
    # (the next round aligns the kept recordings again and replaces the run:
    # only the last round's run is cut to them, not a type's whole warped
    # curves copied every round)
    if (length(kept) < 2L || round == max_rounds) {
      run <- subset_run(run, !bad)
      break
    }
    if (restart) {
      template <- mean_linear_template(recs[kept], L)
      budget <- max_iter
    } else {
      template <- run$template
      budget <- min(max_iter, refine_iter)
    }
  }
  rownames(degenerate) <- NULL
  list(run = run, kept = kept, degenerate = degenerate, dropped_warps = dropped_warps,
       iterations = iterations, converged = run$converged, changes = changes, suspect = suspect)
}

empty_degenerate <- function() {
  data.frame(id = character(0), stall = integer(0), n_frames = integer(0),
             fallback = character(0), stringsAsFactors = FALSE)
}

# Keep the recordings dba_with_drops() flagged as degenerate: each is
# aligned again, alone, to the final template (estimated without them) by
# slope-constrained DTW (dtw_slope_pair(), R/align-slope.R, which cannot
# hold a frame still), or linearly if no such path exists (a recording less
# than a third or more than three times the template's length) or it still
# stalls. Returns `fit` with the recordings merged back in input order and
# `degenerate$fallback` saying which warp each got ("slope" or "linear").
constrain_degenerate <- function(fit, recs, L, engine, max_stall) {
  template <- fit$run$template
  flagged <- match(fit$degenerate$id, names(recs))
  p <- ncol(template)
  extra <- list(warped = array(0, c(length(flagged), L, p)), warps = matrix(0, length(flagged), L),
                distance = rep(NA_real_, length(flagged)))
  how <- character(length(flagged))
  for (a in seq_along(flagged)) {
    x <- recs[[flagged[a]]]
    path <- tryCatch(dtw_slope_pair(x, template, engine), error = function(e) NULL)
    r <- if (!is.null(path)) path_alignment(x, path, L)
    if (!is.null(r)) {
      st <- stall_lengths(r$warps)
      if (st >= 2L && st > max_stall * L) r <- NULL
    }
    if (is.null(r)) {
      wl <- linear_warp_function(nrow(x), L)
      r <- list(warped = array(apply_warp(x, wl), c(1L, L, p)), warps = matrix(wl, 1L),
                distance = NA_real_)
      how[a] <- "linear"
    } else {
      how[a] <- "slope"
    }
    extra$warped[a, , ] <- r$warped[1L, , ]
    extra$warps[a, ] <- r$warps[1L, ]
    extra$distance[a] <- r$distance
  }
  all <- c(fit$kept, flagged)
  ord <- order(all)
  run <- fit$run
  # (stacked and ordered in one compiled pass, src/array-rows.c: the type's
  # whole warped curves were copied twice for its few recordings aligned alone)
  run$warped <- .Call(hm_rows_of_two, run$warped, extra$warped, ord)
  run$warps <- rbind(run$warps, extra$warps)[ord, , drop = FALSE]
  run$distance <- c(run$distance, extra$distance)[ord]
  fit$run <- run
  fit$kept <- all[ord]
  fit$degenerate$fallback <- how
  fit
}

subset_run <- function(run, keep) {
  run$warped <- run$warped[keep, , , drop = FALSE]
  run$warps <- run$warps[keep, , drop = FALSE]
  run$distance <- run$distance[keep]
  run
}

# One DBA run from a given template. Returns the final template and the
# alignment of every recording to exactly that template.
dba_run <- function(recs, template, engine, max_iter, tol, window) {
  batch <- if (engine == "fast") dtw_batch_fast else dtw_batch_reference
  # Only the last alignment's warped recordings, warps and distances are
  # kept; the steps before it need the matched-frame sums alone (`full`).
  res <- batch(recs, template, window, full = max_iter == 0)
  iterations <- 0L
  converged <- FALSE
  changes <- numeric(0)
  while (iterations < max_iter) {
    updated <- res$sum / res$count
    if (!all(is.finite(updated))) stop("the DBA template became non-finite")
    change <- sqrt(sum((updated - template)^2)) /
      max(sqrt(sum(template^2)), .Machine$double.eps)
    template <- updated
    changes <- c(changes, change)
    iterations <- iterations + 1L
    converged <- change < tol
    res <- batch(recs, template, window, full = converged || iterations == max_iter)
    if (converged) break
  }
  res$warps <- pin_warp_ends(res$warps, vapply(recs, nrow, integer(1)))
  res$template <- template
  res$iterations <- iterations
  res$converged <- converged
  res$changes <- changes
  res
}

dtw_batch_fast <- function(recs, template, window, full = TRUE) {
  .Call(hm_dtw_batch, unname(recs), template, window, full)
}

# Same result as dtw_batch_fast, one dtw::dtw() call per recording (always
# the full result).
dtw_batch_reference <- function(recs, template, window, full = TRUE) {
  L <- nrow(template)
  p <- ncol(template)
  N <- length(recs)
  sum <- matrix(0, L, p)
  count <- integer(L)
  warped <- array(0, c(N, L, p))
  warps <- matrix(0, N, L)
  distance <- numeric(N)
  for (k in seq_len(N)) {
    x <- recs[[k]]
    if (!all(is.finite(x))) stop(sprintf("recording %d contains non-finite values", k))
    r <- dtw_pair_reference(x, template, window)
    cnt <- tabulate(r$index2, L)
    s <- rowsum(x[r$index1, , drop = FALSE], r$index2, reorder = TRUE)
    sum <- sum + s
    count <- count + cnt
    warped[k, , ] <- s / cnt
    warps[k, ] <- rowsum(r$index1, r$index2, reorder = TRUE)[, 1] / cnt
    distance[k] <- r$distance
  }
  dimnames(sum) <- NULL
  list(sum = sum, count = count, warped = warped, warps = warps, distance = distance)
}

# DTW's boundary condition matches original frame 1 to template frame 1 and
# n_k to L, but the mean of the frames matched there can differ (e.g. 1.5 when
# frames 1 and 2 both match template frame 1). Pinning the ends keeps every
# warping function running from 1 to n_k (so it carries the recording's
# length); monotonicity is preserved since all other matches lie inside.
pin_warp_ends <- function(warps, n) {
  warps[, 1L] <- 1
  if (ncol(warps) > 1L) warps[, ncol(warps)] <- n
  warps
}

# Longest run of template frames held on one original frame, per recording
# (compiled, src/dba-prep.c; stall_lengths_r() in the tests' helper-align-reference.R
# is the reference).
stall_lengths <- function(warps) {
  .Call(hm_stall_lengths, warps)
}

# The mean of the recordings linearly resampled to L frames. Compiled
# (src/dba-prep.c) with the warping functions from linear_warp_function(),
# one per distinct length; mean_linear_template_r() (tests' helper-align-reference.R)
# is the reference.
mean_linear_template <- function(recs, L) {
  n <- vapply(recs, nrow, integer(1))
  lengths <- sort(unique(n))
  warps <- lapply(lengths, linear_warp_function, L = L)
  acc <- .Call(hm_linear_mean, unname(recs), warps, match(n, lengths))
  cn <- colnames(recs[[1]])
  if (!is.null(cn)) dimnames(acc) <- list(NULL, cn) # as the R version's sum keeps them
  acc / length(recs)
}

# The thesis' fallback (5.1.1, Figure 5.2): linear warping paths.
align_linear_fallback <- function(recs, L, engine, reason) {
  ids <- names(recs)
  dofs <- colnames(recs[[1]])
  N <- length(recs)
  p <- ncol(recs[[1]])
  n_frames <- vapply(recs, nrow, integer(1))
  warps <- matrix(0, N, L, dimnames = list(ids, NULL))
  warped <- array(0, c(N, L, p), dimnames = list(ids, NULL, dofs))
  for (k in seq_len(N)) {
    w <- linear_warp_function(n_frames[k], L)
    warps[k, ] <- w
    warped[k, , ] <- apply_warp(recs[[k]], w)
  }
  template <- matrix(colMeans(warped, dims = 1L), L, p, dimnames = list(NULL, dofs))
  new_grasp_alignment(
    warped = warped, warps = warps, template = template, target_length = L,
    ids = ids, n_frames = n_frames, method = "linear", fallback_reason = reason,
    degenerate = empty_degenerate(), dropped_warps = matrix(numeric(0), 0L, L),
    iterations = 0L, converged = FALSE, changes = numeric(0), engine = engine,
    distance = stats::setNames(rep(NA_real_, N), ids), max_stall = NA_real_,
    features = NA_character_, feature_template = template)
}

linear_warp_function <- function(n, L) {
  if (L == 1L) return(1)
  seq(1, n, length.out = L)
}

# Evaluate recording x (n x p) at fractional original frames `warp` (1-based)
# by linear interpolation between neighbouring frames; times outside [1, n]
# are clamped. Vectorised over frames: two row gathers and a blend.
apply_warp <- function(x, warp) {
  if (!is.matrix(x)) x <- as.matrix(x)
  n <- nrow(x)
  if (n == 1L) return(x[rep.int(1L, length(warp)), , drop = FALSE])
  w <- pmin(pmax(warp, 1), n)
  i0 <- pmin(floor(w), n - 1)
  f <- w - i0
  out <- x[i0, , drop = FALSE] * (1 - f) + x[i0 + 1, , drop = FALSE] * f
  rownames(out) <- NULL
  out
}

#' @export
print.grasp_alignment <- function(x, ...) {
  n <- length(x$ids)
  p <- dim(x$warped)[3]
  L <- as.integer(x$target_length)
  cli::cat_line(cli::pluralize("<grasp_alignment> {n} recording{?s} x {p} DoF{?s} warped to L = {L} frames"))
  if (n > 0) {
    cli::cat_line(sprintf("  original frames: %d-%d (mean %.1f)", min(x$n_frames), max(x$n_frames),
                          mean(x$n_frames)))
  }
  if (x$method == "dtw") {
    it <- as.integer(x$iterations)
    state <- if (x$converged) "converged" else "not converged"
    cli::cat_line(cli::pluralize(
      "  method: DTW barycenter averaging ({x$engine} engine, {x$features} features), {it} iteration{?s}, {state}"))
    if (identical(x$step_pattern, "symmetricP05")) {
      cli::cat_line("  most warps stalled at once: the whole type aligned by slope-constrained DTW")
    }
  } else {
    cli::cat_line("  method: LINEAR warping (fallback: ", x$fallback_reason, ")")
  }
  # (the linear fallback has its own line above)
  notes <- x$degenerate_data
  if (!is.null(notes)) notes <- notes[notes$class != "linear_fallback", , drop = FALSE]
  dg <- format_degenerate(notes)
  if (length(dg)) cli::cat_line(dg)
  deg <- x$degenerate
  # (alignments made before the fallback existed dropped them all)
  how <- deg$fallback %||% rep("dropped", nrow(deg))
  show_ids <- function(ids) {
    paste0(paste(utils::head(ids, 5), collapse = ", "), if (length(ids) > 5) ", ..." else "")
  }
  stall <- sprintf("%g", x$max_stall)
  nd <- sum(how == "dropped")
  if (nd > 0) {
    ids <- show_ids(deg$id[how == "dropped"])
    cli::cat_line(cli::pluralize("  dropped {nd} degenerate warp{?s} (held still > {stall} L): {ids}"))
  }
  nc <- sum(how != "dropped")
  if (nc > 0) {
    nl <- sum(how == "linear")
    linear <- if (nl > 0) sprintf(" (%d linear: no such path)", nl) else ""
    ids <- show_ids(deg$id[how != "dropped"])
    cli::cat_line(cli::pluralize(
      "  kept {nc} degenerate warp{?s} (held still > {stall} L) by a fallback: slope-constrained DTW{linear}: {ids}"))
  }
  invisible(x)
}

# ---- input checks -----------------------------------------------------------

align_check_recordings <- function(recordings, call) {
  if (!is.list(recordings) || length(recordings) == 0L) {
    hm_abort("{.arg recordings} must be a non-empty list of numeric matrices.",
             "bad_input", argument = "recordings", call = call)
  }
  ids <- names(recordings)
  if (is.null(ids) || anyNA(ids) || any(!nzchar(ids)) || anyDuplicated(ids)) {
    ids <- as.character(seq_along(recordings))
  }
  recs <- recordings
  # (double matrices, the usual case, need no conversion: only the others go
  # through as_numeric_matrix(), which names the offending recording)
  ready <- vapply(recordings, function(x) is.double(x) && is.matrix(x) && length(x) > 0L,
                  logical(1))
  for (k in which(!ready)) {
    recs[[k]] <- as_numeric_matrix(recordings[[k]], sprintf("recordings[[\"%s\"]]", ids[k]),
                                  " (frames x DoFs)", finite = FALSE, call = call)
  }
  p <- vapply(recs, ncol, integer(1))
  if (any(p != p[1])) {
    bad <- ids[p != p[1]]
    hm_abort(c("All recordings must have the same number of DoFs ({p[1]}).",
               x = "Different: {.val {bad}}."),
             "bad_input", argument = "recordings", call = call)
  }
  names(recs) <- ids
  recs
}

