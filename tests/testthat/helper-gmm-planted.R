# Planted two-component mixtures: n1 = round(n * w) points from N(0, S1),
# the rest from N(m2, S2).
planted_mixture <- function(seed, n, w, m2, S1 = diag(length(m2)), S2 = diag(length(m2))) {
  withr::with_seed(seed, {
    n1 <- round(n * w)
    draw <- function(m, S, k) {
      matrix(rnorm(k * length(m)), k) %*% chol(S) + rep(m, each = k)
    }
    rbind(draw(rep(0, length(m2)), S1, n1), draw(m2, S2, n - n1))
  })
}

# k planted Gaussian groups in d dimensions: group g > 1 shifted along
# coordinate (g - 2) %% d + 1, by 4 for the first d groups, 8 for the next
# d, ..., so that every group is apart from the others.
planted_groups <- function(seed, n, d, k) {
  withr::with_seed(seed, {
    grp <- rep(seq_len(k), length.out = n)
    shift <- matrix(0, k, d)
    for (g in seq_len(k)[-1]) shift[g, (g - 2L) %% d + 1L] <- 4 * (1 + (g - 2L) %/% d)
    matrix(rnorm(n * d), n) + shift[grp, , drop = FALSE]
  })
}
