# Generation of new grasps from fitted models (Jeppsson 2017, eq. 2.5):
# draw FPC scores alpha_i per DoF and a warp score beta from the mixtures,
# build each DoF's curve on the template grid, and map it back to original
# time through the sampled warping function. A batch is drawn by one native
# call per model (src/generate-kernel.c: scores, warps and the recording
# matrices themselves) and assembled with vectorised metadata columns, so
# there is no per-recording R work. The R reference of the same arithmetic
# (option handmotion.generate_kernel = "r") is kept to test the kernel.
#
# What a large batch costs (bench/bench-generate.R): beyond the arithmetic,
# R's garbage collector. Each recording is its own R vector; while a batch is
# being built every full collection re-marks and re-sweeps all recordings
# made so far (scattered over the batch's memory: a cache and TLB miss
# each), and a batch triggers a number of collections that grows with the
# logarithm of its size, as R's heap grows by about a fifth each time. So
# the cost per grasp rises slowly with batch size whatever the kernel does;
# the kernel keeps everything else small.

#' @importFrom generics generate
#' @export
generics::generate

#' Generate new grasps from a fitted model
#'
#' Samples FPC scores \eqn{\alpha_i} for every DoF and a warp score
#' \eqn{\beta} from the model's Gaussian mixtures and builds eq. 2.5 of
#' Jeppsson (2017): each DoF's curve on the template grid is
#' \eqn{p_{i,0} + P_i \alpha_i}; the warping function
#' \eqn{w(j) = q_0(j) + \beta q_1(j)} gives the original frame of template
#' frame `j` (made monotone and started at frame 1); the new recording has
#' `round(w(L))` frames and its value at original frame `t` is the curve at
#' the template time where `w` reaches `t`.
#'
#' A batch is drawn in one native pass per model (scores, warps and the
#' recording matrices), so large batches are cheap: on the 2-core reference
#' machine some 150,000-200,000 grasps a second for batches of 1,000 to
#' 100,000 (`bench/bench-generate.R`). For batches of several megabytes the
#' R heap is pre-sized once, which spares R's collector repeated full passes;
#' this changes no result. The random stream is used in a fixed order (all
#' FPC scores, then all warp scores, model by model), so a seed always gives
#' the same grasps.
#'
#' @param x A `grasp_model` ([fit_grasp_model()]) or `grasp_models`
#'   ([fit_grasp_models()]).
#' @param n Number of grasps to generate (per grasp type for a model set).
#' @param grasp For a model set: the grasp types to generate (names or ids
#'   1-33); all fitted types by default.
#' @param seed Optional seed; the global RNG is restored afterwards. With
#'   `NULL` the current RNG stream is used.
#' @param warp If `TRUE` (default) apply the sampled time warp; if `FALSE`
#'   return the curves on the model's template grid (`L` frames).
#' @param ... Unused.
#' @return A [grasps()] object with metadata `grasp` = the type, `subject` =
#'   `NA`, `source` = `"generated"`, ids `"gen1"`, `"gen2"`, ... and the warp
#'   score in column `warp_score`. The sampled FPC scores are attached as
#'   attribute `"scores"` (array grasps x DoF x FPC).
#' @seealso [simulate.grasp_model()] for the same through [stats::simulate()].
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' new <- generate(m, n = 5, seed = 2)
#' new
generate.grasp_model <- function(x, n = 1, seed = NULL, warp = TRUE, ...) {
  call <- rlang::caller_env()
  check_generate_n(n, call)
  generate_reserve(list(x), as.integer(n), isTRUE(warp))
  with_seed(seed, generate_batch(x, as.integer(n), warp = isTRUE(warp)))
}

#' @rdname generate.grasp_model
#' @export
generate.grasp_models <- function(x, n = 1, grasp = NULL, seed = NULL, warp = TRUE, ...) {
  call <- rlang::caller_env()
  check_generate_n(n, call)
  models <- select_models(x, grasp, call)
  generate_reserve(models, as.integer(n), isTRUE(warp))
  with_seed(seed, {
    # the models draw in turn from one RNG stream, then one assembly
    parts <- lapply(models, draw_batch, n = as.integer(n), warp = isTRUE(warp))
    assemble_generated(models, parts)
  })
}

#' Simulate grasps from a fitted model
#'
#' The [stats::simulate()] interface to [generate.grasp_model()].
#'
#' @param object A `grasp_model` or `grasp_models`.
#' @param nsim Number of grasps (per type for a model set).
#' @param seed Optional seed (the global RNG is restored afterwards).
#' @param ... Passed to [generate.grasp_model()] (e.g. `warp`, or `grasp` for
#'   a model set).
#' @return A [grasps()] object.
#' @importFrom stats simulate
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' simulate(m, nsim = 3, seed = 1)
simulate.grasp_model <- function(object, nsim = 1, seed = NULL, ...) {
  generate.grasp_model(object, n = nsim, seed = seed, ...)
}

#' @rdname simulate.grasp_model
#' @export
simulate.grasp_models <- function(object, nsim = 1, seed = NULL, ...) {
  generate.grasp_models(object, n = nsim, seed = seed, ...)
}

check_generate_n <- function(n, call) {
  if (!is.numeric(n) || length(n) != 1L || !is.finite(n) || n < 1 || n != round(n)) {
    hm_abort("{.arg n} must be one positive whole number of grasps, not {.val {format(n)}}.",
             "bad_input", argument = "n", call = call)
  }
}

# Draw the scores of a batch: alpha (n x p x ncomp) and beta (n x warp_ncomp),
# every DoF's mixture sampled at once from the model's precomputed sampler.
sample_scores <- function(model, n) {
  smp <- value_or(model$sampler, build_sampler(model))
  alpha <- sample_mixtures(smp$dofs, n)
  dimnames(alpha) <- list(NULL, model$dofs, paste0("FPC", seq_len(model$settings$ncomp)))
  beta <- matrix(sample_mixtures(smp$warp, n), n)
  list(alpha = alpha, beta = beta)
}

# Mixture parameters of every DoF stacked for vectorised sampling: cumulative
# weights (p x k), means (p x k x d) and symmetric square roots of the
# covariances (p x k x d x d). A point mass (constant DoF) has root 0.
# Computed once at fit time so a single draw costs no eigen-decompositions.
build_sampler <- function(model) {
  list(dofs = stack_mixtures(model$gmm, model$settings$ncomp),
       warp = stack_mixtures(list(model$warp$gmm), model$settings$warp_ncomp))
}

stack_mixtures <- function(gmms, d) {
  p <- length(gmms)
  k <- max(vapply(gmms, function(g) length(g$weights), integer(1)))
  cumw <- matrix(1, p, k)
  mu <- array(0, c(p, k, d))
  root <- array(0, c(p, k, d, d))
  for (j in seq_len(p)) {
    g <- gmms[[j]]
    kj <- length(g$weights)
    cumw[j, seq_len(kj)] <- cumsum(g$weights) / sum(g$weights)
    for (c in seq_len(kj)) {
      mu[j, c, ] <- g$means[c, ]
      e <- eigen(matrix(g$covs[, , c], d, d), symmetric = TRUE)
      root[j, c, , ] <- e$vectors %*% (sqrt(pmax(e$values, 0)) * t(e$vectors))
    }
  }
  list(cumw = cumw, mu = mu, root = root, p = p, k = k, d = d)
}

# n draws from each of the p stacked mixtures: an n x p x d array. The
# component of each draw is found from one uniform, the draw is
# mean + root %*% z with z standard normal.
sample_mixtures <- function(smp, n) {
  p <- smp$p
  k <- smp$k
  d <- smp$d
  np <- n * p
  j <- rep(seq_len(p), each = n)
  u <- stats::runif(np)
  z <- rep.int(1L, np)
  if (k > 1L) for (c in seq_len(k - 1L)) z <- z + (u > smp$cumw[j + p * (c - 1L)])
  Z <- matrix(stats::rnorm(np * d), np, d)
  base <- j + p * (z - 1L)                      # index of (dof, component)
  pk <- p * k
  out <- array(0, c(n, p, d))
  for (a in seq_len(d)) {
    v <- smp$mu[base + pk * (a - 1L)]
    for (b in seq_len(d)) v <- v + smp$root[base + pk * (a - 1L) + pk * d * (b - 1L)] * Z[, b]
    out[, , a] <- v
  }
  out
}

# Curves on the template grid for a batch: an (L * n) x p matrix, draw-major
# (rows (d - 1) * L + 1:L belong to draw d).
build_curves <- function(model, alpha) {
  n <- dim(alpha)[1]
  p <- dim(alpha)[2]
  L <- model$target_length
  B <- model$basis
  out <- matrix(0, L * n, p, dimnames = list(NULL, model$dofs))
  for (j in seq_len(p)) {
    P <- matrix(B$components[, j, ], L)              # L x k
    a <- matrix(alpha[, j, ], n)                       # n x k
    # L x n: each column one draw's curve; column-major order = draw-major rows.
    out[, j] <- as.vector(P %*% t(a) + B$mean[, j])
  }
  out
}

# Warping functions of a batch (n x L, original frame of each template
# frame): monotone, starting at frame 1.
build_warps <- function(model, beta) {
  n <- nrow(beta)
  W <- matrix(model$warp$mean, n, length(model$warp$mean), byrow = TRUE) +
    beta %*% t(model$warp$components)
  W[W < 1] <- 1
  W[, 1] <- 1
  # cummax along rows, vectorised over draws: running max column by column.
  if (ncol(W) > 1L) for (c in 2:ncol(W)) W[, c] <- pmax(W[, c], W[, c - 1L])
  W
}

# Map the curves of a batch back to original time (R reference of the
# kernel's step 3b). For draw d with warp w_d, original frame t takes the
# template time s where w_d(s) = t: the template interval is the last
# template frame j with w_d(j) <= t (warps are monotone, so a count),
# clamped to 1..L-1; past w_d(L) the last frame's value; a flat interval
# takes its left end.
unwarp_batch <- function(curves, W, n_new) {
  n <- nrow(W)
  L <- ncol(W)
  draw <- rep.int(seq_len(n), n_new)
  t_orig <- sequence(n_new)
  j <- rowSums(W[draw, , drop = FALSE] <= t_orig)
  at_end <- j >= L
  j <- pmin(pmax(j, 1L), L - 1L)
  lo <- W[cbind(draw, j)]
  span <- W[cbind(draw, j + 1L)] - lo
  f <- ifelse(span > 0, (t_orig - lo) / span, 0)
  f <- pmin(pmax(f, 0), 1)
  f[at_end] <- 1
  rows <- (draw - 1L) * L + j
  curves[rows, , drop = FALSE] * (1 - f) + curves[rows + 1L, , drop = FALSE] * f
}

# Split a stacked (sum n_new) x p matrix into one matrix per draw.
split_rows <- function(vals, n_new) {
  ends <- cumsum(n_new)
  starts <- ends - n_new + 1L
  lapply(seq_along(n_new), function(d) vals[starts[d]:ends[d], , drop = FALSE])
}

# Which implementation draws a batch: "c", the native kernel
# (src/generate-kernel.c: scores, warps and recordings in one pass), or "r",
# the vectorised R reference with the same arithmetic in the same order, kept
# to test the kernel against. Internal option `handmotion.generate_kernel`.
generate_kernel <- function() {
  k <- getOption("handmotion.generate_kernel", "c")
  if (!identical(k, "r")) "c" else "r"
}

# The raw draws of one batch from one model: list(recordings (unnamed
# n_new x p matrices with colnames = DoFs), n_frames, beta (n x warp_ncomp),
# alpha (n x p x ncomp)). Both kernels consume the RNG identically.
draw_batch <- function(model, n, warp = TRUE, kernel = generate_kernel()) {
  smp <- value_or(model$sampler, build_sampler(model))
  if (kernel == "c") {
    return(.Call(hm_generate_batch, as.integer(n), smp$dofs, smp$warp, model$basis$mean,
                 model$basis$components, as.numeric(model$warp$mean),
                 matrix(as.numeric(model$warp$components), model$target_length), isTRUE(warp),
                 model$dofs))
  }
  sc <- sample_scores(model, n)
  L <- model$target_length
  curves <- build_curves(model, sc$alpha)
  if (warp) {
    W <- build_warps(model, sc$beta)
    n_new <- pmax(2L, as.integer(round(W[, L])))
    recs <- split_rows(unwarp_batch(curves, W, n_new), n_new)
  } else {
    n_new <- rep.int(as.integer(L), n)
    recs <- split_rows(curves, n_new)
  }
  list(recordings = recs, n_frames = n_new, beta = sc$beta, alpha = unname(sc$alpha))
}

# Pre-size R's heap for a large batch (hm_reserve_heap() in
# src/generate-kernel.c): the batch's size in bytes is estimated from each
# model's mean warp (its end is the mean frame count). Only for batches of
# some megabytes (below that the heap's free room holds them), only without a
# vector-heap limit (the reservation briefly counts against it), and a failed
# reservation (address space refused) only forgoes the speed-up: the batch
# itself is unaffected. Option handmotion.generate_reserve = FALSE turns it
# off (bench/bench-generate.R measures both).
generate_reserve <- function(models, n, warp) {
  if (!isTRUE(getOption("handmotion.generate_reserve", TRUE))) return(invisible(FALSE))
  per_grasp <- vapply(models, function(m) {
    frames <- if (warp) max(2, m$warp$mean[m$target_length]) else m$target_length
    (frames * length(m$dofs) * 8 + 200) * 1.1
  }, numeric(1))
  bytes <- n * sum(per_grasp)
  if (!is.finite(bytes) || bytes < 4e6 || is.finite(mem.maxVSize())) return(invisible(FALSE))
  ok <- tryCatch({
    .Call(hm_reserve_heap, bytes)
    TRUE
  }, error = function(e) FALSE)
  invisible(ok)
}

# One grasps object from the draws of one or more models (in order): ids
# gen1..genN, the metadata built column by column (no per-recording R work,
# no data.frame() or rbind()), and the grasps object by new_grasps() without
# re-validating what the kernel guarantees.
assemble_generated <- function(models, parts) {
  first <- models[[1]]
  counts <- vapply(parts, function(pt) length(pt$n_frames), integer(1))
  N <- sum(counts)
  ids <- paste0("gen", seq_len(N))
  recs <- if (length(parts) == 1L) parts[[1]]$recordings else
    unlist(lapply(parts, `[[`, "recordings"), recursive = FALSE)
  names(recs) <- ids
  n_frames <- unlist(lapply(parts, `[[`, "n_frames"), use.names = FALSE)
  lev <- feix_levels()
  codes <- vapply(models, function(m) match(m$grasp, lev), integer(1))
  meta <- structure(list(id = ids,
                         grasp = structure(rep.int(codes, counts), levels = lev, class = "factor"),
                         subject = rep.int(NA_character_, N), object = rep.int(NA_character_, N),
                         trial = rep.int(NA_integer_, N), n_frames = n_frames,
                         source = rep.int("generated", N),
                         warp_score = unlist(lapply(parts, function(pt) pt$beta[, 1]), use.names = FALSE)),
                    class = "data.frame", row.names = c(NA_integer_, -N))
  out <- new_grasps(recs, meta, first$dofs, first$rate, first$unit, n_frames = n_frames)
  attr(out, "scores") <- stack_scores(parts, N, ids, first)
  out
}

# The FPC scores of all parts as one N x p x ncomp array named by id, DoF, FPC.
stack_scores <- function(parts, N, ids, model) {
  dn <- list(ids, model$dofs, paste0("FPC", seq_len(model$settings$ncomp)))
  if (length(parts) == 1L) {
    sc <- parts[[1]]$alpha
    dimnames(sc) <- dn
    return(sc)
  }
  sc <- array(0, c(N, length(dn[[2]]), length(dn[[3]])), dimnames = dn)
  at <- 0L
  for (pt in parts) {
    m <- dim(pt$alpha)[1]
    sc[at + seq_len(m), , ] <- pt$alpha
    at <- at + m
  }
  sc
}

# One batch from one model as a grasps object.
generate_batch <- function(model, n, warp = TRUE, kernel = generate_kernel()) {
  assemble_generated(list(model), list(draw_batch(model, n, warp, kernel)))
}
