# R transcription of the compiled k-means (src/gmm-em.c: hm_gmm_kmeans), to test it.

# A few Lloyd iterations from given centres.
gmm_kmeans <- function(Y, centres, iters = 10L) {
  lab <- integer(nrow(Y))
  for (i in seq_len(iters)) {
    dist <- -2 * Y %*% t(centres) + rep(rowSums(centres^2), each = nrow(Y))
    new <- max.col(-dist, ties.method = "first")
    if (identical(new, lab)) break
    lab <- new
    for (g in unique(lab)) centres[g, ] <- colMeans(Y[lab == g, , drop = FALSE])
  }
  lab
}

