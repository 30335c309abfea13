# (tests only)
# World positions of every BVH joint over the frames (frames x joints x 3)
# of a read_bvh() result, for checking an export against forward_kinematics().
bvh_positions <- function(x) {
  bvh <- bvh_parts(x)
  j <- bvh$joints
  n <- bvh$frames
  pidx <- match(j$parent, j$name)
  M <- vector("list", nrow(j))
  out <- array(0, c(n, nrow(j), 3), dimnames = list(NULL, j$name, c("x", "y", "z")))
  for (i in seq_len(nrow(j))) {
    p <- pidx[i]
    pos <- if (is.na(p)) matrix(0, n, 3) else out[, p, ] + M[[p]] %*% kronecker(bvh$offsets[i, ], diag(3))
    ch <- bvh$channels[[i]]
    if (is.na(p)) {
      tr <- match(c("Xposition", "Yposition", "Zposition"), ch)
      if (!anyNA(tr)) pos <- pos + bvh$motion[, paste0(j$name[i], ":", ch[tr]), drop = FALSE]
    }
    out[, i, ] <- pos
    R <- if (is.na(p)) rot_batch("x", rep(0, n)) else M[[p]]
    for (a in ch[grepl("rotation$", ch)]) {
      ax <- tolower(substr(a, 1, 1))
      R <- bmul(R, rot_batch(ax, bvh$motion[, paste0(j$name[i], ":", a)] * pi / 180))
    }
    M[[i]] <- R
  }
  out
}

# Batch rotations as n x 9 matrices (column-major 3 x 3 in each row).
rot_batch <- function(axis, a) {
  c <- cos(a)
  s <- sin(a)
  o <- rep(0, length(a))
  l <- rep(1, length(a))
  switch(axis,
         x = cbind(l, o, o, o, c, s, o, -s, c, deparse.level = 0),
         y = cbind(c, o, -s, o, l, o, s, o, c, deparse.level = 0),
         z = cbind(c, s, o, -s, c, o, o, o, l, deparse.level = 0))
}

bmul <- function(A, B) {
  C <- matrix(0, nrow(A), 9)
  for (j in 0:2) {
    b1 <- B[, 1 + 3 * j]
    b2 <- B[, 2 + 3 * j]
    b3 <- B[, 3 + 3 * j]
    for (i in 1:3) C[, i + 3 * j] <- A[, i] * b1 + A[, i + 3] * b2 + A[, i + 6] * b3
  }
  C
}

# A random HUST-shaped recording of `frames` frames written as BVH at `rate`
# into a temporary file (removed when the calling test ends).
written_bvh <- function(seed, frames, rate, env = parent.frame()) {
  set.seed(seed)
  rec <- matrix(runif(frames * 16, -10, 80), frames, 16, dimnames = list(NULL, hust_dofs$name))
  f <- withr::local_tempfile(fileext = ".bvh", .local_envir = env)
  write_bvh(rec, f, rate = rate)
  list(rec = rec, file = f)
}
