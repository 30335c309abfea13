# Generation of new grasps from fitted models (Jeppsson 2017, eq. 2.5):
# draw FPC scores alpha_i per DoF and a warp score beta from the mixtures,
# build each DoF's curve on the template grid, and map it back to original
# time through the sampled warping function. A batch is drawn by one native
# call per model (src/generate-kernel.c: scores, warps and the recording
# matrices themselves) and assembled with vectorised metadata columns, so
# there is no per-recording R work. An R transcription of the same arithmetic
# lives in the tests (helper-generate-reference.R) to check the kernel.
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
#' Samples FPC scores `alpha_i` for every DoF and a warp score
#' `beta` from the model's Gaussian mixtures and builds eq. 2.5 of
#' Jeppsson (2017): each DoF's curve on the template grid is
#' `p_i0 + P_i alpha_i`; the warping function
#' `w(j) = q_0(j) + beta q_1(j)` gives the original frame of template
#' frame `j` (made monotone and started at frame 1); the new recording has
#' `round(w(L))` frames and its value at original frame `t` is the curve at
#' the template time where `w` reaches `t`.
#'
#' A batch is drawn in one native pass per model (scores, warps and the
#' recording matrices), so large batches are cheap: on the 2-core reference
#' machine some 150,000-200,000 grasps a second for batches of 1,000 to
#' 100,000 (`bench/bench-generate.R`). The random stream is used in a fixed
#' order (all FPC scores, then all warp scores, model by model), so a seed
#' always gives the same grasps.
#'
#' **Streaming.** More grasps than memory holds are generated in chunks with
#' `callback`: each chunk of at most `chunk` grasps (per type for a model set)
#' is passed to `callback(chunk, i)` (the chunk a `grasps` object, `i` its
#' number) and dropped, so memory stays at one chunk; write each to files
#' with [write_hust()] or [write_bvh()], or keep a summary. Ids run on across
#' chunks (`gen1`, ... `genN`). The chunks are drawn one after another from
#' one random stream, so a seed gives the same chunks every time (not the
#' same grasps as one batch of `n`). At most 10 million grasps per call
#' without a callback.
#'
#' **Dependence.** A model fitted with `dependence = "copula"` draws all FPC
#' scores of all DoFs and the warp scores jointly from its Gaussian copula,
#' one fitted with `dependence = "kernel"` from a kernel density on the
#' training recordings' joint score vectors (see [fit_grasp_model()]), so the
#' fingers move together as in the recordings; the thesis' model draws each
#' DoF on its own.
#'
#' **Joint limits.** With `limits = TRUE` every DoF whose recordings respect
#' the default hand's joint limits ([hand_skeleton()], mapped by
#' [joint_map()]; the ranges of the model's `limits` table, where
#' `enforced` is `TRUE`: at most 10% of the training frames outside) is kept
#' inside its range by a smooth map on the template curve: the identity
#' inside the range less a margin of 5% of its width, and beyond that an
#' exponential approach to the limit whose slope is 1 where it starts. Unlike
#' a hard clip it leaves no kink in the motion, and values well inside the
#' range are unchanged. A DoF that the recordings themselves leave in more
#' than 10% of frames is measured differently from the skeleton's axis (on
#' HUST-like data, `ABD1`) and is left alone. [evaluate_generation()]
#' reports the share of frames outside the limits beside the recordings'.
#'
#' **Sensor ranges.** A channel that no skeleton joint limits (a raw-count
#' sensor, a pressure pad, a channel of your own glove) is kept inside its
#' sensor's range: the range of the glove profile ([glove_profile()]: `min`,
#' `max`) narrowed to the training recordings' range, or for a raw channel
#' without a declared range the training recordings' range.
#'
#' **Rest and hold.** A model fitted to recordings trimmed to their motion
#' (`fit_grasp_model(motion = )`) remembers how long the recordings rested
#' before and held after it, and how much the hand trembled meanwhile;
#' generated grasps get a rest and a hold drawn from those, so they look
#' like the recordings. The rest and the hold come together from one
#' training recording whose motion is among the five nearest to the
#' generated motion in length and in how far each channel moved, and follow
#' that recording's own path (its drift and tremor) about the generated
#' motion's first and last posture: a long reach comes with a short hold as
#' in the recordings, and a hold settles back after the reach (real fingers
#' relax a little once they grasp) by about as much as the recordings'
#' holds after a reach of that size.
#'
#' @param x A `grasp_model` ([fit_grasp_model()]) or `grasp_models`
#'   ([fit_grasp_models()]).
#' @param n Number of grasps to generate (per grasp type for a model set).
#' @param grasps For a model set: the grasp types to generate (names or ids
#'   1-33); all fitted types by default.
#' @param seed Seed of the draws (default 1: like every handmotion verb
#'   that draws random numbers, a call repeats itself); the global RNG is
#'   restored afterwards. `NULL` uses the current RNG stream (a new draw on
#'   every call).
#' @param warp If `TRUE` (default) apply the sampled time warp; if `FALSE`
#'   return the curves on the model's template grid (`L` frames).
#' @param limits Keep generated values inside their limits? `TRUE`: every
#'   enforced limit of the model (joint limits of the skeleton, sensor ranges
#'   of the glove, the training range of raw channels); a warning of class
#'   `handmotion_warning_no_limits` says when a model has none. `FALSE`:
#'   none. `NULL` (default): the sensor ranges always (a glove cannot read
#'   outside them), and the joint limits for a model fitted with
#'   `dependence = "copula"` or `"kernel"` (the thesis' independent model generates its
#'   angles exactly as the thesis did). See Joint limits.
#' @param phases For a model of recordings trimmed to their motion: add the
#'   rest before and the hold after each generated motion (`TRUE`, default;
#'   see Rest and hold), or return the motion alone (`FALSE`).
#' @param chunk With `callback`, the number of grasps per chunk (per type).
#' @param callback Optional function `(chunk, i)` called with each chunk (see
#'   Streaming); its return values are discarded.
#' @param ... Unused; any argument given here is an error (a misspelt name).
#' @return A [grasps()] object with metadata `grasp` = the type, `subject` =
#'   `NA`, `source` = `"generated"`, ids `"gen1"`, `"gen2"`, ... and the warp
#'   score in column `warp_score`. The sampled FPC scores are attached as
#'   attribute `"scores"` (array grasps x DoF x FPC). With `callback`,
#'   invisibly the number of grasps generated and chunks passed.
#' @seealso [simulate.grasp_model()] for the same through [stats::simulate()].
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' new <- generate(m, n = 5, seed = 2)
#' new
generate.grasp_model <- function(x, n = 1, seed = 1, warp = TRUE, limits = NULL, chunk = 10000,
                                 callback = NULL, phases = TRUE, ...) {
  # (a misspelt argument would vanish into `...` without a word)
  check_dots_for(list(...), generate.grasp_model, "generate", call = rlang::caller_env())
  phases <- check_flag(phases, "phases", call = rlang::caller_env())
  generate_models(list(x), n, seed, warp, limits, chunk, callback, call = rlang::caller_env(), phases = phases)
}

#' @rdname generate.grasp_model
#' @export
generate.grasp_models <- function(x, n = 1, grasps = NULL, seed = 1, warp = TRUE,
                                  limits = NULL, chunk = 10000, callback = NULL, phases = TRUE, ...) {
  call <- rlang::caller_env()
  # (the old `grasp = ` would otherwise reach `grasps` by partial matching)
  check_renamed_args(names(sys.call()), "generate", own = names(formals(generate.grasp_models)), call = call)
  check_dots_for(list(...), generate.grasp_models, "generate", call = call)
  phases <- check_flag(phases, "phases", call = call)
  check_grasp_models(x, "x", "generate", each = FALSE, call = call)  # (each model: validate_sampler())
  generate_models(select_models(x, grasps, call), n, seed, warp, limits, chunk, callback, call = call,
                  phases = phases)
}

# The one generation path of both methods: checks, then one batch (the
# models draw in turn from one RNG stream, then one assembly), or chunks
# handed to a callback.
generate_models <- function(models, n, seed, warp, limits, chunk, callback, call, phases = TRUE) {
  streaming <- !is.null(callback)
  n <- check_whole(n, "n", max = if (streaming) 1e12 else max_grasps_per_call, call = call)
  warp <- check_flag(warp, "warp", call = call)
  if (!is.null(limits)) limits <- check_flag(limits, "limits", call = call)
  seed <- check_seed(seed, call = call)
  chunk <- check_whole(chunk, "chunk", max = max_grasps_per_call, call = call)
  if (!length(models)) {
    hm_abort("{.arg x} holds no fitted models (an empty selection?): there is nothing to generate from.",
             "bad_input", argument = "x", call = call)
  }
  for (m in models) validate_sampler(m, call)
  if (isTRUE(limits)) {
    none <- vapply(models, function(m) !any(m$limits$enforced %||% FALSE), logical(1))
    if (any(none)) {
      hm_warn(c("No limits to keep for {.val {vapply(models[none], `[[`, '', 'grasp')}}: generated as drawn.",
                i = "Limits come from the skeleton's joints, the glove profile's sensor ranges or, for raw channels, the training data's range."),
              "no_limits")
    }
  }
  draw <- function(m, n) {
    got <- draw_batch(m, n, warp = warp, limits = limits, call = call)
    lim <- generation_limits(m, limits)
    # what the kernel draws stays inside the limits by its smooth map; what
    # is added here (residuals, rest and hold) is clipped to them, and a
    # zero-width range (a stuck channel) is held exactly
    if (!is.null(m$residuals)) got <- clip_draws(add_residuals(got, m), lim)
    # a model of trimmed recordings puts their rest and hold back around the
    # motion, so generated grasps look like the recordings (see phases)
    if (warp && isTRUE(phases) && !is.null(m$phases)) got <- clip_draws(add_still_phases(got, m), lim)
    hold_flat_limits(got, lim)
  }
  if (!streaming) {
    return(with_seed(seed, assemble_generated(models, lapply(models, draw, n = n))))
  }
  if (!is.function(callback)) {
    hm_abort("{.arg callback} must be a function of a chunk and its number.", "bad_input",
             argument = "callback", call = call)
  }
  sizes <- c(rep(chunk, n %/% chunk), if (n %% chunk) n %% chunk)
  with_seed(seed, {
    done <- 0
    for (i in seq_along(sizes)) {
      out <- assemble_generated(models, lapply(models, draw, n = sizes[i]), first_id = done + 1)
      done <- done + length(out)
      callback(out, i)
      out <- NULL
    }
  })
  invisible(list(n = n * length(models), chunks = length(sizes)))
}

#' Simulate grasps from a fitted model
#'
#' The [stats::simulate()] interface to [generate.grasp_model()].
#'
#' @param object A `grasp_model` or `grasp_models`.
#' @param nsim Number of grasps (per type for a model set).
#' @param seed Seed of the draws (default 1, as in [generate()]; `NULL`
#'   uses the current RNG stream); the global RNG is restored afterwards.
#' @param ... Passed to [generate.grasp_model()] (e.g. `warp`, or `grasps` for
#'   a model set).
#' @return A [grasps()] object.
#' @importFrom stats simulate
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' simulate(m, nsim = 3, seed = 1)
simulate.grasp_model <- function(object, nsim = 1, seed = 1, ...) {
  generate.grasp_model(object, n = nsim, seed = seed, ...)
}

#' @rdname simulate.grasp_model
#' @export
simulate.grasp_models <- function(object, nsim = 1, seed = 1, ...) {
  # (through `...` an old `grasp =` would reach `grasps` by partial matching)
  check_renamed_args(...names(), "simulate", own = names(formals(generate.grasp_models)))
  generate.grasp_models(object, n = nsim, seed = seed, ...)
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

# Whether a stacked sampler (stack_mixtures()) still holds the mixtures
# `gmms`: weights and means compared as stored, covariances through their
# symmetric roots (root %*% root), so no eigen decomposition is redone (a few
# microseconds per mixture, not the millisecond of a rebuild).
sampler_matches <- function(gmms, st, tol = 1e-6) {
  if (length(gmms) != st$p) return(FALSE)
  close <- function(a, b) length(a) == length(b) && all(abs(a - b) <= tol * (1 + abs(b)))
  cumw <- matrix(st$cumw, st$p, st$k)
  mu <- array(st$mu, c(st$p, st$k, st$d))
  root <- array(st$root, c(st$p, st$k, st$d, st$d))
  for (j in seq_along(gmms)) {
    g <- gmms[[j]]
    kj <- length(g$weights)
    if (!is.list(g) || kj > st$k || !close(cumw[j, seq_len(kj)], cumsum(g$weights) / sum(g$weights))) return(FALSE)
    for (c in seq_len(kj)) {
      r <- matrix(root[j, c, , ], st$d, st$d)
      if (!close(mu[j, c, ], as.numeric(g$means[c, ])) ||
          !close(as.numeric(r %*% r), as.numeric(g$covs[, , c]))) return(FALSE)
    }
  }
  TRUE
}

# The raw draws of one batch from one model, by the native kernel: list(
# recordings (unnamed n_new x p matrices with colnames = DoFs), n_frames,
# beta (n x warp_ncomp), alpha (n x p x ncomp)).
# The kernel's own checks (lengths, the frame bound) come back as classed
# errors naming the model.
draw_batch <- function(model, n, warp = TRUE, limits = NULL, call = rlang::caller_env()) {
  smp <- model$sampler %||% build_sampler(model)
  # the copula and kernel models draw their scores here, the independent one
  # in the native kernel
  scores <- if (joint_dependence(model)) draw_joint_scores(model, n)
  lim <- generation_limits(model, limits)
  # a zero-width range (a stuck channel) is held exactly afterwards, not mapped
  flat <- !is.na(lim$lo) & lim$hi <= lim$lo
  lim$lo[flat] <- NA_real_
  lim$hi[flat] <- NA_real_
  B <- model_basis(model)
  W <- warp_basis(model)
  tryCatch(
    .Call(hm_generate_batch, as.integer(n), smp$dofs, smp$warp, B$mean,
          B$components, W$mean, W$components, isTRUE(warp),
          model$dofs, scores$alpha, scores$beta, lim$lo, lim$hi, generation_limit_margin),
    error = function(e) {
      msg <- conditionMessage(e)
      hm_abort(c("The model of {.val {model$grasp}} cannot generate.", x = "{msg}"),
               "bad_model", argument = "x", grasp = model$grasp, call = call)
    })
}

# The per-DoF limits the kernel keeps a model's draws inside: the enforced
# rows of model$limits (recorded_limits()), NA elsewhere and when off. `on`
# NULL (the default) keeps the sensor ranges (a glove cannot read outside
# them) and, for the copula model, the joint limits too.
generation_limits <- function(model, on) {
  p <- length(model$dofs)
  lo <- hi <- rep(NA_real_, p)
  lim <- model$limits
  if (!isFALSE(on) && !is.null(lim) && nrow(lim)) {
    src <- lim$source %||% rep("skeleton", nrow(lim))
    keep <- lim$enforced & (isTRUE(on) | src != "skeleton" | joint_dependence(model))
    lim <- lim[keep, , drop = FALSE]
    j <- match(lim$dof, model$dofs)
    lo[j] <- lim$lo
    hi[j] <- lim$hi
  }
  list(lo = lo, hi = hi)
}

# The smooth limit map starts this share of a DoF's range inside each limit
# (src/generate-kernel.c, soft_limit()): 5 degrees of a 0-100 degree PIP.
generation_limit_margin <- 0.05

# Limits of one call: the number of grasps one generate() call returns (a
# larger set is drawn in several calls), and the frames of one draw (checked
# in the kernel too: src/generate-kernel.c, HM_MAX_GENERATED_FRAMES).
max_grasps_per_call <- 1e7

# The error raiser of a model validator: bad(what) says that `model` cannot
# `action` (generate, project) because of `what` (cli inline markup,
# interpolated in the caller), as a handmotion_error_bad_model.
model_fault <- function(model, action, arg, call) {
  function(what, .envir = parent.frame()) {
    what <- cli::format_inline(what, .envir = .envir)
    hm_abort(c("The model of {.val {model$grasp %||% \"?\"}} cannot {action}: {what}.",
               i = "Was it changed after fitting? Refit it with {.fn fit_grasp_model}."),
             "bad_model", argument = arg, grasp = model$grasp, call = call)
  }
}

# Check a model's stored sampler and basis against each other before they
# reach native code: a model altered by hand (a component count that does
# not match its arrays, a basis of another size) gets a classed error naming
# what does not fit, not a crash.
validate_sampler <- function(model, call = rlang::caller_env()) {
  bad <- model_fault(model, "generate", "x", call)
  if (!inherits(model, "grasp_model")) bad("it is not a {.cls grasp_model}")
  fault <- model_parts_fault(model)
  if (!is.null(fault)) bad(fault)
  smp <- model$sampler %||% build_sampler(model)
  L <- model$target_length
  p <- length(model$dofs)
  if (length(model$fpca) != p) bad("it does not hold one FPCA per DoF")
  check_stack <- function(st, p_want, what) {
    dims <- c(st$p, st$k, st$d)
    if (!is.numeric(dims) || length(dims) != 3L || anyNA(dims) || any(dims < 1)) {
      bad("its {what} sampler has no valid sizes")
    }
    if (st$p != p_want) bad("its {what} sampler holds {st$p} mixture{?s}, not {p_want}")
    want <- list(cumw = c(st$p, st$k), mu = c(st$p, st$k, st$d), root = c(st$p, st$k, st$d, st$d))
    for (el in names(want)) {
      if (!is.double(st[[el]]) || length(st[[el]]) != prod(want[[el]]) || anyNA(st[[el]])) {
        bad("its {what} sampler's {.field {el}} does not hold {prod(want[[el]])} numbers ({paste(want[[el]], collapse = ' x ')})")
      }
    }
  }
  check_stack(smp$dofs, p, "DoF")
  check_stack(smp$warp, 1L, "warp")
  fault <- fpca_shape_fault(model, smp$dofs$d)
  if (!is.null(fault)) bad(paste0(fault, ", as its sampler has"))
  # the number of FPCs its settings state, as project() (and so predict())
  # checks: an edited ncomp is refused here too, not drawn past
  fault <- fpca_shape_fault(model)
  if (!is.null(fault)) bad(paste0(fault, ", as its settings say"))
  # the stored sampler was built from the mixtures at fitting: a mixture
  # edited since would be ignored without a word, so it must still match
  if (!is.null(model$sampler)) {
    if (!sampler_matches(model$gmm, smp$dofs)) {
      bad("its {.field gmm} mixtures were changed after fitting and no longer match its sampler")
    }
    if (!sampler_matches(list(model$warp$gmm), smp$warp)) {
      bad("its {.field warp} mixture was changed after fitting and no longer matches its sampler")
    }
  }
  wf <- model$warp$fpca
  if (length(wf$mean) != L || length(wf$components) != L * smp$warp$d) {
    bad("its warp basis does not match its warp sampler")
  }
  if (identical(model$dependence$type, "copula")) {
    cop <- model$dependence$copula
    D <- NROW(cop$columns)
    if (!is.list(cop) || !is.data.frame(cop$columns) || !is.double(cop$root) ||
        !identical(dim(cop$root), c(D, D)) || !is.double(cop$quantiles) ||
        NCOL(cop$quantiles) != D || NROW(cop$quantiles) != length(cop$z)) {
      bad("its copula (columns, root, quantiles) is incomplete")
    }
  }
  if (identical(model$dependence$type, "kernel")) {
    kern <- model$dependence$kernel
    D <- NROW(kern$columns)
    if (!is.list(kern) || !is.data.frame(kern$columns) || !is.double(kern$root) ||
        !identical(dim(kern$root), c(D, D)) || !is.double(kern$scores) || NCOL(kern$scores) != D ||
        NROW(kern$scores) < 1L || anyNA(kern$scores) || anyNA(kern$root)) {
      bad("its kernel density (columns, scores, root) is incomplete")
    }
  }
  invisible(model)
}

# Split a stacked (sum n_new) x p matrix into one matrix per draw.
split_rows <- function(vals, n_new) {
  ends <- cumsum(n_new)
  starts <- ends - n_new + 1L
  lapply(seq_along(n_new), function(d) vals[starts[d]:ends[d], , drop = FALSE])
}

# One grasps object from the draws of one or more models (in order): ids
# gen1..genN, the metadata built column by column (no per-recording R work,
# no data.frame() or rbind()), and the grasps object by new_grasps() without
# re-validating what the kernel guarantees.
assemble_generated <- function(models, parts, first_id = 1) {
  first <- models[[1]]
  counts <- vapply(parts, function(pt) length(pt$n_frames), integer(1))
  N <- sum(counts)
  ids <- if (first_id - 1 + N < .Machine$integer.max) paste0("gen", as.integer(first_id - 1) + seq_len(N))
         else paste0("gen", format(first_id - 1 + seq_len(N), scientific = FALSE, trim = TRUE))
  recs <- if (length(parts) == 1L) parts[[1]]$recordings else
    unlist(lapply(parts, `[[`, "recordings"), recursive = FALSE)
  names(recs) <- ids
  n_frames <- unlist(lapply(parts, `[[`, "n_frames"), use.names = FALSE)
  lev <- model_levels(first)
  codes <- vapply(models, function(m) match(m$grasp, lev), integer(1))
  meta <- structure(list(id = ids,
                         grasp = structure(rep.int(codes, counts), levels = lev, class = "factor"),
                         subject = rep.int(NA_character_, N), object = rep.int(NA_character_, N),
                         trial = rep.int(NA_integer_, N), n_frames = n_frames,
                         source = rep.int("generated", N),
                         warp_score = unlist(lapply(parts, function(pt) pt$beta[, 1]), use.names = FALSE)),
                    class = "data.frame", row.names = c(NA_integer_, -N))
  out <- new_grasps(recs, meta, first$dofs, first$rate, first$unit, n_frames = n_frames, glove = first$glove)
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


# Rest before and hold after each generated motion: the rest and hold of
# one training recording whose motion is like the generated one (in length
# and in displacement, phase_donors()), each as that recording's own path
# (its drift and tremor) about the generated motion's first or last posture.
# A hold is not frozen: the fingers settle back after the reach, by more the
# further they reached (see still_phases()), so a donor that reached about
# as far carries a settling of about the right size.
add_still_phases <- function(got, model) {
  ph <- still_paths(model$phases, length(model$dofs))
  p <- length(model$dofs)
  len <- vapply(got$recordings, nrow, integer(1))
  disp <- matrix(vapply(got$recordings, function(r) r[nrow(r), ] - r[1, ], numeric(p)), ncol = p, byrow = TRUE)
  pick <- phase_donors(ph, len, disp)
  got$recordings <- lapply(seq_along(got$recordings), function(i) {
    r <- got$recordings[[i]]
    rest <- ph$rest_path[[pick[i]]]
    hold <- ph$hold_path[[pick[i]]]
    out <- rbind(rest + rep(r[1, ], each = nrow(rest)), r, hold + rep(r[nrow(r), ], each = nrow(hold)))
    colnames(out) <- colnames(r)
    out
  })
  got$n_frames <- got$n_frames + ph$rest[pick] + ph$hold[pick]
  got
}

# The still phases' paths of a model; a model fitted before they were kept
# (lengths and tremor only) gets paths of white tremor about the posture.
still_paths <- function(ph, p) {
  if (!is.null(ph$rest_path)) return(ph)
  noise <- function(m) rnorm_matrix(m, p) * rep(ph$tremor, each = m)
  ph$rest_path <- lapply(ph$rest, noise)
  ph$hold_path <- lapply(ph$hold, noise)
  ph
}

# For each generated motion (its length `len` and displacement `disp`, one
# row each) a training recording drawn at random from the
# `phase_neighbours` nearest: distance in the log motion length (weighted to
# count as much as all channels together, as the rest and hold lengths
# follow it: a long reach, a short hold) and in each channel's displacement,
# every coordinate in units of its spread over the training recordings. So
# the rest and hold follow the motion as in the recordings, resampled rather
# than copied. A model fitted before the displacements were kept matches on
# length alone; one fitted before the motion lengths were kept pairs at
# random.
phase_donors <- function(ph, len, disp) {
  N <- length(ph$rest)
  n <- length(len)
  if (is.null(ph$motion)) return(sample.int(N, n, replace = TRUE))
  k <- min(phase_neighbours, N)
  unit <- function(v) { s <- stats::sd(v); if (is.finite(s) && s > 0) s else 1 }
  lm <- log(ph$motion)
  train <- cbind(lm / unit(lm) * sqrt(NCOL(disp)))
  new <- cbind(log(len) / unit(lm) * sqrt(NCOL(disp)))
  if (!is.null(ph$displacement)) {
    s <- apply(ph$displacement, 2, unit)
    train <- cbind(train, sweep(ph$displacement, 2, s, "/"))
    new <- cbind(new, sweep(disp, 2, s, "/"))
  }
  rank <- sample.int(k, n, replace = TRUE)
  # in blocks of rows, so a batch of millions never holds all its distances;
  # the k nearest of every row by k passes of max.col(), not an order() a row
  out <- integer(n)
  for (first in seq(1L, n, by = phase_block)) {
    rows <- first:min(n, first + phase_block - 1L)
    D <- outer(rowSums(new[rows, , drop = FALSE]^2), rowSums(train^2), "+") -
      2 * tcrossprod(new[rows, , drop = FALSE], train)
    at <- cbind(seq_along(rows), 0L)
    for (r in seq_len(k)) {
      at[, 2] <- max.col(-D, ties.method = "first")
      hit <- rank[rows] == r
      out[rows[hit]] <- at[hit, 2]
      D[at] <- Inf
    }
  }
  out
}
phase_block <- 4096L
phase_neighbours <- 5L

# Residual resampling (fit_grasp_model(residuals = "resample")): each
# generated motion gets the residual curves of one training recording drawn
# at random, stretched to its length.
add_residuals <- function(got, model) {
  res <- model$residuals
  n <- length(got$recordings)
  pick <- sample.int(dim(res)[1], n, replace = TRUE)
  L <- dim(res)[2]
  got$recordings <- lapply(seq_len(n), function(i) {
    r <- got$recordings[[i]]
    ix <- fraction_index(L, seq(0, 1, length.out = nrow(r)))
    e <- res[pick[i], ix$lo, , drop = TRUE] * (1 - ix$w) + res[pick[i], ix$hi, , drop = TRUE] * ix$w
    r + matrix(e, nrow(r), ncol(r))
  })
  got
}

# Every generated value inside the limits `lim` (generation_limits()).
clip_draws <- function(got, lim) {
  lo <- ifelse(is.na(lim$lo), -Inf, lim$lo)
  hi <- ifelse(is.na(lim$hi), Inf, lim$hi)
  got$recordings <- lapply(got$recordings, function(r) {
    out <- sweep(sweep(r, 2, lo, pmax), 2, hi, pmin)
    dimnames(out) <- dimnames(r)
    out
  })
  got
}

# Channels whose range has no width (a stuck sensor: every training value the
# same) read exactly that value in every generated frame.
hold_flat_limits <- function(got, lim) {
  flat <- which(!is.na(lim$lo) & lim$hi <= lim$lo)
  if (!length(flat)) return(got)
  got$recordings <- lapply(got$recordings, function(r) {
    r[, flat] <- rep(lim$lo[flat], each = nrow(r))
    r
  })
  got
}
