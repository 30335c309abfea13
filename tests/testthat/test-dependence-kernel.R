# Planted truth for the kernel model: scores from three well separated
# clusters (a grasp type recorded on three objects). The kernel density's
# draws must land near the centres in the clusters' shares; one Gaussian
# with the scores' mean and covariance (what a Gaussian copula with normal
# marginals draws) puts a large share between them.

planted_clusters <- function(n_each = c(30, 20, 10), d = 3, seed = 1) {
  set.seed(seed)
  centres <- rbind(c(0, 0, 0), c(6, 0, 3), c(0, 6, -3))[, seq_len(d), drop = FALSE]
  lab <- rep(1:3, n_each)
  S <- centres[lab, , drop = FALSE] + matrix(stats::rnorm(length(lab) * d), ncol = d)
  colnames(S) <- paste0("s", seq_len(d))
  list(S = S, centres = centres, share = n_each / sum(n_each))
}

# the share of draws within radius r of each centre
near_share <- function(V, centres, r) {
  vapply(seq_len(nrow(centres)), function(k) mean(sqrt(colSums((t(V) - centres[k, ])^2)) < r), numeric(1))
}

test_that("the kernel sampler keeps three planted clusters a single Gaussian blurs", {
  for (d in 2:3) {
    pc <- planted_clusters(d = d)
    kd <- kernel_density(pc$S)
    # cross-validation picks a kernel narrower than the normal reference rule
    # (which assumes one Gaussian: 0.51-0.54 here; cross-validated 0.22-0.37)
    silverman <- (4 / (d + 2))^(1 / (d + 4)) * nrow(pc$S)^(-1 / (d + 4))
    expect_lt(kd$bandwidth, 0.75 * silverman)
    set.seed(2)
    V <- draw_kernel_vectors(kd, 20000)
    r <- 3 # within-cluster sd 1: about 0.99 (d = 2) or 0.97 (d = 3) of a cluster
    got <- near_share(V, pc$centres, r)
    # each cluster's share of draws is its share of recordings; with the
    # kernel's added spread 0.84 (d = 3) to 0.98 (d = 2) of the draws are near
    # a centre
    expect_equal(got / sum(got), pc$share, tolerance = 0.08)
    expect_gt(sum(got), 0.8)
    # one Gaussian of the same mean and covariance
    G <- MASS::mvrnorm(20000, colMeans(pc$S), stats::cov(pc$S))
    gauss <- near_share(G, pc$centres, r)
    # (0.53 to 0.70 near a centre: the rest falls between the clusters)
    expect_lt(sum(gauss), 0.75)
    expect_gt(sum(got) - sum(gauss), 0.2)
  }
})

test_that("the kernel density reproduces the scores' mean and covariance", {
  pc <- planted_clusters(d = 2)
  kd <- kernel_density(pc$S)
  set.seed(3)
  V <- draw_kernel_vectors(kd, 40000)
  expect_equal(colMeans(V), colMeans(pc$S), tolerance = 0.05, ignore_attr = TRUE)
  # the draws' covariance is the sample's (divisor n) plus the kernel's,
  # shrunk by 1 + h^2: the sample's own, as the kernel's is the shrunk sample
  # covariance
  want <- (stats::cov(pc$S) * (nrow(pc$S) - 1) / nrow(pc$S) + crossprod(kd$root)) / (1 + kd$bandwidth^2)
  expect_equal(diag(stats::cov(V)), diag(stats::cov(pc$S)), tolerance = 0.06, ignore_attr = TRUE)
  expect_equal(stats::cov(V), want, tolerance = 0.05, ignore_attr = TRUE)
  # a score without spread stays put
  S <- cbind(pc$S, s3 = 2)
  kd <- kernel_density(S)
  expect_true(all(draw_kernel_vectors(kd, 100)[, 3] == 2))
})

test_that("a kernel model generates inside the sensor range and its joint limits", {
  g <- simulate_grasps(subjects = 4, grasps = 1, objects = 3, trials = 3, seed = 1)
  m <- fit_grasp_model(g, seed = 1, dependence = "kernel")
  expect_equal(m$dependence$type, "kernel")
  kern <- m$dependence$kernel
  expect_equal(nrow(kern$scores), m$n_used)
  expect_true(kern$bandwidth > 0 && kern$bandwidth < 1.5)
  expect_output(print(m), "kernel density over")
  x <- generate(m, n = 40, seed = 2)
  lim <- m$limits[m$limits$enforced, ]
  for (i in seq_len(nrow(lim))) {
    v <- unlist(lapply(x$recordings, function(r) r[, lim$dof[i]]))
    expect_true(all(v >= lim$lo[i] - 1e-8 & v <= lim$hi[i] + 1e-8), info = lim$dof[i])
  }
  # the same seed gives the same grasps
  expect_identical(generate(m, n = 5, seed = 4)$recordings, generate(m, n = 5, seed = 4)$recordings)
})

test_that("a kernel model without its kernel density is a classed error", {
  g <- simulate_grasps(subjects = 3, grasps = 1, objects = 2, trials = 2, seed = 1)
  m <- fit_grasp_model(g, seed = 1, dependence = "kernel")
  m$dependence$kernel$root <- m$dependence$kernel$root[-1, ]
  expect_error(generate(m, n = 2), class = "handmotion_error_bad_model")
})

test_that("the compiled leave-one-out sums equal the R expression they replaced", {
  # the definition: per row the log-sum-exp of -D2 / (2 h^2), the diagonal out
  ref <- function(D2, grid) sapply(grid, function(h) {
    A <- -D2 / (2 * h^2)
    m <- apply(A, 1, max)
    m + log(rowSums(exp(A - m)))
  })
  set.seed(8)
  for (n in c(3L, 40L, 250L)) {
    Y <- matrix(rnorm(n * 6), n)
    sq <- rowSums(Y^2)
    D2 <- pmax(outer(sq, sq, `+`) - 2 * tcrossprod(Y), 0)
    diag(D2) <- Inf
    expect_identical(.Call(hm_kernel_loo_lse, D2, kernel_bandwidth_grid), ref(D2, kernel_bandwidth_grid))
  }
  # clusters far apart in many dimensions (as a type's objects): most terms
  # of a row are far below its largest, the ones the compiled sums skip
  Y <- matrix(rnorm(300 * 30), 300) + 4 * rep(1:3, each = 100)
  sq <- rowSums(Y^2)
  D2 <- pmax(outer(sq, sq, `+`) - 2 * tcrossprod(Y), 0)
  diag(D2) <- Inf
  expect_identical(.Call(hm_kernel_loo_lse, D2, kernel_bandwidth_grid), ref(D2, kernel_bandwidth_grid))
})
