# Planted truth for the alignment tests: recordings are a known smooth grasp
# curve (3 DoFs) observed through known monotone time warps
#   g_a(u) = u + a u (1 - u),  |a| < 1,
# sampled at n_k equally spaced original frames, plus small noise. The warps'
# parameters are balanced around 0, so the DBA template's time axis is (up to
# noise) the curve's own, and recording k's true warping function is
# w_k(j) = 1 + (n_k - 1) g_a^{-1}((j - 1) / (L - 1)).
grasp_curve <- function(u) {
  cbind(a = 60 * stats::plogis((u - 0.45) / 0.07), b = 30 * sin(pi * u), c = 40 * u^2)
}

time_warp <- function(u, a) u + a * u * (1 - u)

inverse_time_warp <- function(s, a) {
  if (a == 0) return(s)
  # root in [0, 1] of a u^2 - (1 + a) u + s = 0
  ((1 + a) - sqrt((1 + a)^2 - 4 * a * s)) / (2 * a)
}

planted_alignment <- function(N = 20, centre = 40, noise = 0.3, seed = 2) {
  withr::with_seed(seed, {
    a <- seq(-0.6, 0.6, length.out = N)
    n <- round(centre * (1 + 0.12 * stats::rnorm(N)))
    recs <- lapply(seq_len(N), function(k) {
      u <- seq(0, 1, length.out = n[k])
      grasp_curve(time_warp(u, a[k])) + stats::rnorm(n[k] * 3, sd = noise)
    })
  })
  names(recs) <- sprintf("rec%02d", seq_len(N))
  list(recs = recs, a = a, n = n)
}

true_warps <- function(pl, L) {
  s <- seq(0, 1, length.out = L)
  t(vapply(seq_along(pl$n), function(k) 1 + (pl$n[k] - 1) * inverse_time_warp(s, pl$a[k]),
           numeric(L)))
}
