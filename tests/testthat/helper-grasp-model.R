# Synthetic grasps with a planted truth, for the model tests (grasp-model,
# generate, project, frame-pca, plot-model). Each DoF j is
#   theta_j(s) = mean_j(s) + alpha_1 phi_1(s) + alpha_2 phi_2(s) + noise,
# s in [0, 1] the template time, with phi_1 = sqrt(2) sin(pi s) and
# phi_2 = sqrt(2) sin(2 pi s) orthonormal in L2[0, 1]. alpha_1 is bimodal
# (+-sep, sd 2), alpha_2 ~ N(0, sd2). A recording of n frames samples s at
# (t - 1) / (n - 1): a linear time warp of a planted length.
planted_phi <- function(s) cbind(sqrt(2) * sin(pi * s), sqrt(2) * sin(2 * pi * s))

planted_mean <- function(s, j) 20 * j * (1 - cos(pi * s)) / 2 + 5

planted_grasps <- function(n = 60, p = 4, len = 40, len_sd = 4, sep = 10, sd2 = 3,
                           noise = 0.05, grasp = "Tripod", seed = 1) {
  with_seed(seed, {
    lens <- pmax(10L, as.integer(round(len + stats::rnorm(n, 0, len_sd))))
    comp <- sample(c(-1, 1), n * p, replace = TRUE)
    a1 <- matrix(comp * sep + stats::rnorm(n * p, 0, 2), n, p)
    a2 <- matrix(stats::rnorm(n * p, 0, sd2), n, p)
    recs <- lapply(seq_len(n), function(i) {
      s <- (seq_len(lens[i]) - 1) / (lens[i] - 1)
      ph <- planted_phi(s)
      m <- vapply(seq_len(p), function(j) planted_mean(s, j) + ph %*% c(a1[i, j], a2[i, j]),
                  numeric(length(s)))
      m <- matrix(m, length(s), p)
      m + stats::rnorm(length(m), 0, noise)
    })
    g <- grasps(recs, meta = data.frame(grasp = rep(grasp, n), subject = paste0("s", seq_len(n))),
                dofs = paste0("d", seq_len(p)))
    attr(g, "truth") <- list(a1 = a1, a2 = a2, lens = lens, sep = sep, sd2 = sd2)
    g
  })
}
