# Two types that differ only between fixed fractions of the motion: on the
# way to the same end posture, DoF 1 (which otherwise stays near rest)
# overshoots by 15 (type Tripod: the hand opens before it closes, a
# preshape) or undershoots by 15 (Ring) for three frames at a random moment.
# Their travel is the same, and postures at fractions 1/8 apart (8 frames)
# catch the moment in about three recordings of eight; the extremes of the
# motion see it in every one.
overshoot_types <- function(n_per = 30, subjects = 3, seed = 1) {
  planted_set(c("Tripod", "Ring"), n_per, subjects, seed, function(ty, i) {
    m <- sample(60:70, 1)
    s <- (1 - cos(pi * seq(0, 1, length.out = m))) / 2
    target <- c(0, stats::rnorm(15, 40, 3))
    r <- outer(s, target) + matrix(stats::rnorm(m * 16, 0, 1), m)
    at <- sample(10:(m - 10), 1) + -1:1
    r[at, 1] <- r[at, 1] + if (ty == "Tripod") 15 else -15
    r
  })
}
