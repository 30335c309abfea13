late_types <- function(n_per = 36, subjects = 6, seed = 1) {
  planted_set(c("Tripod", "Ring"), n_per, subjects, seed, function(ty, i) {
    m <- 40L
    s <- seq(0, 1, length.out = m)
    common <- outer(s, stats::rnorm(16, 30, 3))                   # both types close alike ...
    part <- outer(pmax(0, (s - 0.5) / 0.5), c(rep(0, 15), if (ty == "Tripod") 25 else -25)) # ... then DoF 16 parts
    common + part + matrix(stats::rnorm(m * 16, 0, 0.5), m)
  })
}

# The class probabilities of the first recording, named by class.
first_probs <- function(rec, x, frames) {
  p <- predict(rec, x, frames = frames, type = "prob")
  stats::setNames(unlist(p[1, ]), sub("^\\.pred_", "", names(p)))
}
