# Planted grasp data for the classifier tests: each type has its own final
# posture (16 angles drawn far apart), reached by a smooth ramp from a common
# open hand, plus per-subject offsets and frame noise. `subject_sd` adds a
# subject x type interaction (a subject's personal version of each posture),
# which in-sample models absorb but held-out subjects do not.
planted_types <- function(types = c(1, 17, 22), subjects = 4, trials = 3, frames = 20,
                           spread = 60, noise = 1, subject_sd = 2, seed = 1) {
  withr::with_seed(seed, .rng_kind = "default", .rng_sample_kind = "default", {
    p <- 16
    postures <- lapply(types, function(t) stats::runif(p, 0, spread))
    recs <- list()
    meta <- list()
    for (s in seq_len(subjects)) {
      for (ti in seq_along(types)) {
        personal <- postures[[ti]] + stats::rnorm(p, 0, subject_sd)
        for (r in seq_len(trials)) {
          n <- frames + sample(-2:2, 1)
          ramp <- (1 - cos(pi * seq(0, 1, length.out = n))) / 2
          m <- outer(ramp, personal) + matrix(stats::rnorm(n * p, 0, noise), n, p)
          recs[[length(recs) + 1]] <- m
          meta[[length(meta) + 1]] <- data.frame(grasp = types[ti], subject = paste0("s", s),
                                                 object = "o1", trial = r)
        }
      }
    }
    grasps(recs, meta = do.call(rbind, meta))
  })
}

# The skeleton of the recognition tests' planted sets: `n_per` recordings of
# each type, made by `recording(type, i)` (a frames x 16 matrix) from the
# RNG stream of `seed`, recording i of a type belonging to subject
# (i - 1) %% subjects + 1. Each test file plants its own truth in `recording`.
planted_set <- function(types, n_per, subjects, seed, recording) {
  set.seed(seed)
  recs <- list()
  meta <- list()
  for (ty in types) {
    for (i in seq_len(n_per)) {
      recs[[length(recs) + 1L]] <- recording(ty, i)
      meta[[length(meta) + 1L]] <- data.frame(grasp = ty, subject = sprintf("S%02d", (i - 1) %% subjects + 1))
    }
  }
  grasps(recs, meta = do.call(rbind, meta), rate = 50)
}
