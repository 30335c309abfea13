# Generation of new grasps from fitted models (Jeppsson 2017, eq. 2.5):
# draw FPC scores alpha_i per DoF and a warp score beta from the mixtures,
# build each DoF's curve on the template grid, and map it back to original
# time through the sampled warping function. Everything is done for a whole
# batch at once (matrix algebra over draws and DoFs, one findInterval() for
# every warp inversion), so large batches are cheap.

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
  with_seed(seed, generate_batch(x, as.integer(n), warp = isTRUE(warp), id_offset = 0L))
}

#' @rdname generate.grasp_model
#' @export
generate.grasp_models <- function(x, n = 1, grasp = NULL, seed = NULL, warp = TRUE, ...) {
  call <- rlang::caller_env()
  check_generate_n(n, call)
  models <- select_models(x, grasp, call)
  with_seed(seed, {
    parts <- vector("list", length(models))
    offset <- 0L
    for (i in seq_along(models)) {
      parts[[i]] <- generate_batch(models[[i]], as.integer(n), warp = isTRUE(warp), id_offset = offset)
      offset <- offset + as.integer(n)
    }
    combine_generated(parts)
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

# Map the curves of a batch back to original time. For draw d with warp w_d,
# original frame t takes the template time s where w_d(s) = t. All draws are
# inverted by one findInterval() on the concatenated warps, each draw's warp
# shifted by an offset larger than any frame count so the whole vector stays
# sorted.
unwarp_batch <- function(curves, W) {
  n <- nrow(W)
  L <- ncol(W)
  n_new <- pmax(2L, as.integer(round(W[, L])))
  big <- max(n_new, W[, L]) + 2
  offs <- (seq_len(n) - 1) * big
  wvec <- as.vector(t(W + offs))                      # draw-major, sorted
  draw <- rep.int(seq_len(n), n_new)
  t_orig <- sequence(n_new)
  q <- t_orig + offs[draw]
  pos <- findInterval(q, wvec, rightmost.closed = FALSE)
  base <- (draw - 1L) * L
  j <- pos - base                                     # template interval, 0..L
  j[j < 1L] <- 1L
  at_end <- j >= L
  j[at_end] <- L - 1L
  lo <- wvec[base + j]
  hi <- wvec[base + j + 1L]
  span <- hi - lo
  f <- ifelse(span > 0, (q - lo) / span, 0)
  f[at_end] <- 1
  f <- pmin(pmax(f, 0), 1)
  rows <- base + j
  vals <- curves[rows, , drop = FALSE] * (1 - f) + curves[rows + 1L, , drop = FALSE] * f
  list(values = vals, n_new = n_new)
}

# Split a stacked (sum n_new) x p matrix into one matrix per draw.
split_rows <- function(vals, n_new) {
  ends <- cumsum(n_new)
  starts <- ends - n_new + 1L
  lapply(seq_along(n_new), function(d) vals[starts[d]:ends[d], , drop = FALSE])
}

# One batch from one model. `kernel = "c"` builds every recording in one
# native pass (src/generate-kernel.c); `kernel = "r"` is the vectorised R
# reference with the same arithmetic, kept to test the kernel against.
generate_batch <- function(model, n, warp = TRUE, id_offset = 0L, kernel = c("c", "r")) {
  kernel <- match.arg(kernel)
  sc <- sample_scores(model, n)
  L <- model$target_length
  if (warp) {
    W <- build_warps(model, sc$beta)
    n_new <- pmax(2L, as.integer(round(W[, L])))
  } else {
    W <- matrix(as.numeric(seq_len(L)), n, L, byrow = TRUE)
    n_new <- rep.int(as.integer(L), n)
  }
  if (kernel == "c") {
    recs <- .Call(hm_generate_batch, model$basis$mean, model$basis$components, sc$alpha, W,
                  n_new, model$dofs)
  } else {
    curves <- build_curves(model, sc$alpha)
    recs <- if (warp) {
      uw <- unwarp_batch(curves, W)
      split_rows(uw$values, uw$n_new)
    } else {
      split_rows(curves, n_new)
    }
  }
  ids <- paste0("gen", id_offset + seq_len(n))
  names(recs) <- ids
  # a plain list made a data frame directly: data.frame() costs more than a
  # whole single-grasp draw
  lev <- feix_levels()
  meta <- structure(list(id = ids, grasp = structure(rep.int(match(model$grasp, lev), n), levels = lev,
                                                     class = "factor"),
                         subject = rep.int(NA_character_, n), object = rep.int(NA_character_, n),
                         trial = rep.int(NA_integer_, n), n_frames = n_new,
                         source = rep.int("generated", n), warp_score = sc$beta[, 1]),
                    class = "data.frame", row.names = c(NA_integer_, -n))
  out <- new_grasps(recs, meta, model$dofs, model$rate, model$unit)
  dimnames(sc$alpha)[[1]] <- ids
  attr(out, "scores") <- sc$alpha
  out
}

combine_generated <- function(parts) {
  if (length(parts) == 1L) return(parts[[1]])
  recs <- unlist(lapply(parts, `[[`, "recordings"), recursive = FALSE)
  meta <- do.call(rbind, lapply(parts, `[[`, "meta"))
  first <- parts[[1]]
  out <- new_grasps(recs, meta, first$dofs, first$rate, first$unit)
  sc <- lapply(parts, attr, "scores")
  dims <- dim(sc[[1]])
  all_sc <- array(0, c(sum(vapply(sc, function(s) dim(s)[1], 1L)), dims[2], dims[3]),
                  dimnames = list(meta$id, dimnames(sc[[1]])[[2]], dimnames(sc[[1]])[[3]]))
  at <- 0L
  for (s in sc) {
    all_sc[at + seq_len(dim(s)[1]), , ] <- s
    at <- at + dim(s)[1]
  }
  attr(out, "scores") <- all_sc
  out
}
