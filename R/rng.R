# The package never leaves a trace on the caller's random number generator:
# seeded code runs inside with_seed(), and code that goes through future's
# seeding (which switches the session to L'Ecuyer-CMRG) saves and restores the
# RNG around it.

# Snapshot and restore of the global RNG: the kind (kept internally by R, not
# only in `.Random.seed`, which may not exist yet) and the stream.
save_rng <- function() {
  list(kind = RNGkind(), seed = get0(".Random.seed", envir = globalenv(), inherits = FALSE))
}

restore_rng <- function(old) {
  # restoring the caller's own kinds; R warns about the old "Rounding" sampler on every set
  suppressWarnings(RNGkind(old$kind[1], old$kind[2], old$kind[3]))
  if (is.null(old$seed)) {
    if (exists(".Random.seed", envir = globalenv(), inherits = FALSE)) rm(".Random.seed", envir = globalenv())
  } else {
    assign(".Random.seed", old$seed, envir = globalenv())
  }
}

# Evaluate `expr` with the RNG seeded (in the caller's RNG kind), restoring the
# global RNG state and kind afterwards. A NULL seed evaluates `expr` as is.
# The RNG stream of each of `n` elements for a seed: the L'Ecuyer-CMRG
# sub-streams future_lapply(future.seed = seed) derives, computed here so a
# resumed fit (fit_grasp_models(cache = )) gives every remaining type the
# stream it has in a full run. The caller's RNG is left as it was.
element_streams <- function(seed, n) {
  old <- save_rng()
  on.exit(restore_rng(old))
  RNGkind("L'Ecuyer-CMRG")
  set.seed(seed)
  s <- get(".Random.seed", envir = globalenv())
  out <- vector("list", n)
  for (i in seq_len(n)) {
    out[[i]] <- parallel::nextRNGSubStream(s)
    s <- parallel::nextRNGStream(s)
  }
  out
}

# A seed that is not NULL or one whole number is a classed error naming the
# caller (the user-facing function).
with_seed <- function(seed, expr) {
  seed <- check_seed(seed, call = rlang::caller_env())
  if (is.null(seed)) return(expr)
  old <- save_rng()
  on.exit(restore_rng(old))
  set.seed(seed)
  expr
}

# An n x p matrix of standard normal draws, taken from the RNG in one call of
# n * p (filled by column, or by row with `byrow = TRUE`): the simulator's
# fixed draw order and the generators' noise depend on exactly these draws.
rnorm_matrix <- function(n, p, byrow = FALSE) {
  matrix(stats::rnorm(n * p), n, p, byrow = byrow)
}

# Consecutive draws of one kind for `n` rows, taken in one call of
# n * sum(widths) and cut into named blocks of columns, in order (a block of
# width 1 is a vector). runif() and rnorm() (inversion) take each value from
# the stream in turn, so these are the numbers, in the order, that one call
# per block would give: the simulator's fixed draw order is written as a few
# such calls instead of one line per block.
draw_blocks <- function(draw, n, widths) {
  x <- matrix(draw(n * sum(widths)), n, sum(widths))
  first <- cumsum(widths) - widths
  out <- lapply(seq_along(widths), function(b) x[, first[b] + seq_len(widths[b]), drop = widths[b] == 1L])
  names(out) <- names(widths)
  out
}
