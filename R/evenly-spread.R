# At most `k` of the indices 1..n, evenly spread from the first to the last
# (all n when k >= n). Deterministic, so a capped computation (a sample for a
# bandwidth, a start, a temperature, a drawn animation's frames) gives the
# same result every time and needs no seed.
evenly_spread <- function(n, k) unique(round(seq(1, n, length.out = min(n, k))))
