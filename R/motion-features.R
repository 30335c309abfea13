# Fixed-length features of recordings of any length: the posture at given
# fractions of each recording's own duration (linear interpolation between
# frames) and the log duration. The generation yardstick and the
# discriminant classifier both describe a recording this way.

motion_features <- function(x, at, duration = TRUE) {
  p <- length(x$dofs)
  F <- t(vapply(x$recordings, function(r) posture_at(r, at), numeric(length(at) * p)))
  if (length(x$recordings) == 0L) F <- matrix(0, 0L, length(at) * p)
  colnames(F) <- paste0(rep(x$dofs, length(at)), "@", rep(signif(at, 3), each = p))
  if (duration) {
    F <- cbind(F, log_duration = log(x$meta$n_frames / x$rate))
  }
  F
}

# Postures of one recording (frames x DoFs) at fractions `at` of its length,
# as one vector (all DoFs at at[1], then at at[2], ...).
posture_at <- function(r, at) {
  ix <- fraction_index(nrow(r), at)
  as.vector(t(r[ix$lo, , drop = FALSE] * (1 - ix$w) + r[ix$hi, , drop = FALSE] * ix$w))
}

# Frames either side of fractions `at` of m frames (linear interpolation
# between frames), and the weight of the later one. The motion features, the
# recogniser's prefixes and a live stream all read postures this way.
fraction_index <- function(m, at) {
  pos <- 1 + at * (m - 1)
  lo <- floor(pos)
  hi <- lo + 1L
  hi[hi > m] <- m
  list(lo = lo, hi = hi, w = pos - lo)
}

# How far each DoF travels in a recording: log(1 + the sum of its absolute
# frame-to-frame changes, in the data's units). Two recordings can end in the
# same posture after very different amounts of motion (a finger that opens
# before it closes); no linear function of a few postures sees that, and on
# the default data it lifts the discriminant from 89% to 92% held out.
travel_features <- function(x) {
  p <- length(x$dofs)
  T <- t(vapply(x$recordings, function(r) log1p(colSums(abs(diff(r)))), numeric(p)))
  if (length(x$recordings) == 0L) T <- matrix(0, 0L, p)
  colnames(T) <- paste0(x$dofs, ".travel")
  T
}
