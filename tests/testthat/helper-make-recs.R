make_recs <- function(n = 3, frames = 20, p = 16) {
  lapply(seq_len(n), function(i) matrix(sin(seq_len(frames * p) / (5 + i)), frames, p))
}
