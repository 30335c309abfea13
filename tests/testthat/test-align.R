# ---- pairwise DTW: fast engine == dtw package ------------------------------

test_that("fast pairwise DTW equals dtw::dtw on random inputs", {
  withr::local_seed(1)
  for (rep in 1:40) {
    n <- sample(1:50, 1); m <- sample(1:50, 1); p <- sample(c(1, 2, 16), 1)
    x <- matrix(stats::rnorm(n * p), n, p)
    y <- matrix(stats::rnorm(m * p), m, p)
    fast <- dtw_align_pair(x, y)
    ref <- dtw_align_pair(x, y, engine = "reference")
    expect_identical(fast$index1, ref$index1)
    expect_identical(fast$index2, ref$index2)
    expect_equal(fast$distance, ref$distance, tolerance = 1e-10)
  }
})

test_that("fast pairwise DTW breaks ties exactly like dtw::dtw", {
  # small integer values: many exactly tied predecessor costs
  withr::local_seed(3)
  n_ties <- 0
  for (rep in 1:150) {
    n <- sample(1:10, 1); m <- sample(1:10, 1); p <- sample(1:2, 1)
    x <- matrix(sample(0:1, n * p, TRUE), n, p)
    y <- matrix(sample(0:1, m * p, TRUE), m, p)
    fast <- dtw_align_pair(x, y)
    ref <- dtw_align_pair(x, y, engine = "reference")
    expect_identical(fast[c("index1", "index2")], ref[c("index1", "index2")])
    expect_equal(fast$distance, ref$distance, tolerance = 1e-10)
  }
  # a fully tied case: constant sequences, every path costs the same
  x <- matrix(0, 5, 2); y <- matrix(0, 7, 2)
  expect_identical(dtw_align_pair(x, y)[1:2], dtw_align_pair(x, y, engine = "reference")[1:2])
})

test_that("the slanted-band window matches dtw's and fails cleanly when too narrow", {
  withr::local_seed(4)
  x <- matrix(stats::rnorm(45 * 4), 45); y <- matrix(stats::rnorm(40 * 4), 40)
  for (w in c(0.5, 2, 5, 12)) {
    fast <- dtw_align_pair(x, y, window = w)
    ref <- dtw_align_pair(x, y, engine = "reference", window = w)
    expect_identical(fast[1:2], ref[1:2])
    expect_equal(fast$distance, ref$distance, tolerance = 1e-10)
    expect_true(all(abs(fast$index2 - fast$index1 * 40 / 45) <= w | fast$index1 == 1 & fast$index2 == 1))
  }
  expect_error(dtw_align_pair(matrix(1:10 + 0, 10), matrix(1:3 + 0, 3), window = 0),
               class = "handmotion_error_alignment_failed")
})

test_that("pairwise DTW paths are valid and handle n = 1 and L = 1", {
  x <- matrix(1:6 + 0, 6, 1); y <- matrix(c(1, 3, 6), 3, 1)
  p <- dtw_align_pair(x, y)
  expect_identical(c(p$index1[1], p$index2[1]), c(1L, 1L))
  expect_identical(c(utils::tail(p$index1, 1), utils::tail(p$index2, 1)), c(6L, 3L))
  steps <- cbind(diff(p$index1), diff(p$index2))
  expect_true(all(steps %in% 0:1) && all(rowSums(steps) >= 1))
  one <- dtw_align_pair(matrix(2, 1, 2), matrix(c(1, 2, 3, 4), 2, 2))
  expect_identical(one$index1, c(1L, 1L)); expect_identical(one$index2, 1:2)
  expect_equal(one$distance, sqrt(2) + 2)   # d(1,1) + d(1,2), horizontal step weight 1
  single <- dtw_align_pair(matrix(c(0, 3), 1), matrix(c(4, 3), 1))
  expect_identical(single$index1, 1L); expect_equal(single$distance, 4)
})

test_that("pairwise DTW rejects bad input with classed errors", {
  expect_error(dtw_align_pair(matrix(1, 3, 2), matrix(1, 3, 3)), class = "handmotion_error_bad_input")
  expect_error(dtw_align_pair(matrix(c(1, NA), 2), matrix(1, 3)), class = "handmotion_error_bad_input")
  expect_error(dtw_align_pair("a", matrix(1, 3)), class = "handmotion_error_bad_input")
  expect_error(dtw_align_pair(matrix(1, 3), matrix(1, 3), window = -1), class = "handmotion_error_bad_input")
  expect_error(dtw_align_pair(matrix(1, 3), matrix(1, 3), engine = "slow"))
})

# ---- DBA alignment -----------------------------------------------------------

test_that("align_recordings recovers planted warping functions within one frame", {
  pl <- planted_alignment()
  al <- align_recordings(pl$recs)
  L <- round(mean(pl$n))
  expect_s3_class(al, "grasp_alignment")
  expect_identical(al$method, "dtw")
  expect_identical(al$target_length, as.integer(L))
  expect_identical(dim(al$warped), c(20L, as.integer(L), 3L))
  expect_identical(dimnames(al$warped), list(names(pl$recs), NULL, c("a", "b", "c")))
  expect_identical(dim(al$warps), c(20L, as.integer(L)))
  expect_equal(unname(al$n_frames), as.integer(pl$n))
  expect_equal(nrow(al$degenerate), 0)
  err <- abs(al$warps - true_warps(pl, L))
  expect_lt(mean(err), 1)                 # mean absolute error under one frame
  expect_true(all(rowMeans(err) < 1))     # and for every recording
  # warping functions: monotone from 1 to n_k
  expect_true(all(apply(al$warps, 1, function(w) all(diff(w) >= 0))))
  expect_equal(unname(al$warps[, 1]), rep(1, 20))
  expect_equal(unname(al$warps[, L]), pl$n)
  # warped recordings resemble the curve on the template grid
  truth <- grasp_curve(seq(0, 1, length.out = L))
  expect_lt(sqrt(mean((al$template - truth)^2)), 1.5)
})

test_that("linear warping does much worse than DTW on the planted warps", {
  # guards against a test that cannot fail: the planted warps are far from linear
  pl <- planted_alignment()
  L <- round(mean(pl$n))
  lin <- t(vapply(pl$n, function(n) seq(1, n, length.out = L), numeric(L)))
  expect_gt(mean(abs(lin - true_warps(pl, L))), 2)
})

test_that("shape features see timing through posture offsets and excursion", {
  # each recording gets its own posture offset and excursion scale per DoF
  # (like subjects and object sizes); the planted warps stay recoverable
  pl <- planted_alignment(seed = 21)
  L <- round(mean(pl$n))
  withr::with_seed(22, {
    off <- matrix(stats::rnorm(20 * 3, sd = 8), 20)
    sc <- matrix(stats::runif(20 * 3, 0.7, 1.3), 20)
  })
  recs <- Map(function(x, k) sweep(sweep(x, 2, sc[k, ], "*"), 2, off[k, ], "+"), pl$recs, 1:20)
  shape <- align_recordings(recs)
  raw <- align_recordings(recs, features = "raw")
  truth <- true_warps(pl, L)
  expect_identical(shape$features, "shape")
  expect_lt(mean(abs(shape$warps - truth)), 1)
  expect_gt(mean(abs(raw$warps[rownames(raw$warps), ] - truth[match(raw$ids, names(recs)), ])), 1.5)
  # warped recordings are in data units: offsets and scales are kept
  expect_equal(unname(shape$warped[, 1, 1]), unname(vapply(recs, function(x) x[1, 1], 1)), tolerance = 0.05 * 60)
  expect_equal(unname(colMeans(shape$warped[, , 2])), unname(shape$template[, 2]), tolerance = 1e-10)
  # identical shapes with different offsets: identity warps, data untouched
  x <- grasp_curve(seq(0, 1, length.out = 30))
  same <- align_recordings(list(x, x + 10, 2 * x - 5))
  expect_equal(unname(same$warps), matrix(rep(1:30, each = 3), 3, 30))
  expect_equal(unname(same$warped[3, , ]), unname(2 * x - 5))
})

test_that("fast and reference engines give the same alignment", {
  pl <- planted_alignment(N = 8, seed = 5)
  fast <- align_recordings(pl$recs, max_iter = 4)
  ref <- align_recordings(pl$recs, max_iter = 4, engine = "reference")
  expect_identical(ref$engine, "reference")
  expect_equal(fast$warps, ref$warps, tolerance = 1e-10)
  expect_equal(fast$warped, ref$warped, tolerance = 1e-10)
  expect_equal(fast$template, ref$template, tolerance = 1e-10)
  expect_equal(fast$distance, ref$distance, tolerance = 1e-10)
  expect_identical(fast$iterations, ref$iterations)
})

# Degenerate warps (Figure 5.1) arise when DTW compares raw angles: a recording
# missing part of the motion is held on one frame while the template moves on.
# (With the default shape features such a recording is stretched instead, so
# these tests use features = "raw".)
test_that("the thesis' rule drops a recording held still over a long stretch", {
  pl <- planted_alignment(N = 12, seed = 7)
  recs <- pl$recs
  # the glove stopped early: the last half of the motion is missing, so the
  # warped recording holds its last frame for about half of the template
  u <- seq(0, 0.5, length.out = 30)
  recs$stuck_end <- grasp_curve(u)
  # and one that started late: it holds its first frame
  recs$stuck_start <- grasp_curve(seq(0.55, 1, length.out = 30))
  al <- align_recordings(recs, features = "raw", degenerate_warps = "drop")
  L <- al$target_length
  expect_identical(al$method, "dtw")
  expect_setequal(al$degenerate$id, c("stuck_end", "stuck_start"))
  expect_true(all(al$degenerate$fallback == "dropped"))
  expect_true(all(al$degenerate$stall > 0.25 * L))
  expect_identical(al$degenerate$n_frames[match("stuck_end", al$degenerate$id)], 30L)
  expect_false(any(c("stuck_end", "stuck_start") %in% al$ids))
  expect_false(any(c("stuck_end", "stuck_start") %in% dimnames(al$warped)[[1]]))
  expect_identical(rownames(al$dropped_warps), al$degenerate$id)
  expect_equal(dim(al$warped)[1], 12)
  # the stall is where the planted data stop: the last (resp. first) frame
  expect_equal(max(rle(al$dropped_warps["stuck_end", ])$lengths),
               al$degenerate$stall[al$degenerate$id == "stuck_end"])
  expect_equal(unname(utils::tail(al$dropped_warps["stuck_end", ], 3)), rep(30, 3))
  expect_equal(unname(al$dropped_warps["stuck_start", 1:3]), rep(1, 3))
  # a looser max_stall keeps them
  loose <- align_recordings(recs, max_stall = 0.9, features = "raw", degenerate_warps = "drop")
  expect_equal(nrow(loose$degenerate), 0)
  expect_true(all(c("stuck_end", "stuck_start") %in% loose$ids))
  # by default they are kept with a slope-constrained warp, the others unchanged
  kept <- align_recordings(recs, features = "raw")
  expect_identical(kept$ids, names(recs))
  expect_setequal(kept$degenerate$id, c("stuck_end", "stuck_start"))
  expect_true(all(kept$degenerate$fallback %in% c("slope", "linear")))
  expect_true(all(handmotion:::stall_lengths(kept$warps) <= 0.25 * L))
  expect_equal(kept$warped[al$ids, , ], al$warped)
  expect_equal(kept$warps[al$ids, ], al$warps)
})

# Real glove recordings rest before and hold after the grasp. Where the
# template holds still every path costs about the same, and DTW's cheapest
# holds one recording frame over the plateau: a degenerate warp. Planted: a
# 40-frame motion after a rest and before a hold of known lengths; four
# recordings of another object (a 20 smaller closing on DoF a) have rests
# of 5 to 40 frames where the others have 20.
plateau_set <- function(rest, hold, offset, noise = 1, seed = 1) {
  withr::with_seed(seed, {
    recs <- lapply(seq_along(rest), function(k) {
      u <- seq(0, 1, length.out = 40)
      m <- grasp_curve(u)
      m[, "a"] <- m[, "a"] + offset[k] * stats::plogis((u - 0.45) / 0.07)
      x <- rbind(m[rep(1, rest[k]), ], m, m[rep(40, hold[k]), ])
      x + stats::rnorm(length(x), sd = noise)
    })
  })
  names(recs) <- sprintf("r%02d", seq_along(rest))
  recs
}

test_that("recordings stalled on a rest or hold plateau are kept with a sensible warp", {
  rest <- c(rep(20, 10), 5, 8, 35, 40)
  hold <- c(rep(20, 10), 40, 35, 5, 8)
  recs <- plateau_set(rest, hold, offset = c(rep(0, 10), rep(-20, 4)))
  thesis <- align_recordings(recs, features = "raw", degenerate_warps = "drop")
  odd <- sprintf("r%02d", 11:14)
  # the thesis' rule drops the four (they stall on one frame over > 25% of L)
  expect_setequal(thesis$degenerate$id, odd)
  expect_false(any(odd %in% thesis$ids))
  al <- align_recordings(recs, features = "raw")
  L <- al$target_length
  expect_identical(al$ids, names(recs))
  expect_setequal(al$degenerate$id, odd)
  expect_true(all(al$degenerate$fallback == "slope"))
  expect_true(all(al$degenerate$stall > 0.25 * L))   # what DTW did
  for (id in odd) {
    k <- match(id, names(recs))
    w <- al$warps[id, ]
    expect_true(all(diff(w) >= 0))                     # monotone
    expect_equal(w[c(1, L)], c(1, nrow(recs[[id]])))   # end-pinned
    expect_lte(handmotion:::stall_lengths(al$warps[id, , drop = FALSE]), 3)
    # the planted shift is recovered: the motion's midpoint (frame rest + 20)
    # sits where the other recordings' midpoints sit, within 4 frames (the
    # recordings' noise and the plateaus leave the warp a few frames of play)
    ref <- stats::median(vapply(sprintf("r%02d", 1:10), function(r) which.min(abs(al$warps[r, ] - 40)), numeric(1)))
    expect_lte(abs(which.min(abs(w - (rest[k] + 20))) - ref), 4)
  }
  # and the others are aligned exactly as under the thesis' rule
  expect_equal(al$warps[thesis$ids, ], thesis$warps)
  # both engines give the same fallback path
  ref_al <- align_recordings(recs, features = "raw", engine = "reference")
  expect_equal(ref_al$warps, al$warps, tolerance = 1e-10)
})

test_that("two recordings are enough", {
  pl <- planted_alignment(N = 2, seed = 8)
  al <- align_recordings(pl$recs)
  expect_identical(al$method, "dtw")
  expect_identical(dim(al$warped)[1:2], c(2L, al$target_length))
  expect_true(all(is.finite(al$warped)))
})

test_that("identical recordings give identity warps and unchanged data", {
  x <- grasp_curve(seq(0, 1, length.out = 33))
  al <- align_recordings(list(x, x, x, x))
  expect_identical(al$target_length, 33L)
  expect_equal(unname(al$warps), matrix(rep(1:33, each = 4), 4, 33))
  expect_equal(unname(al$warped[2, , ]), unname(x))
  expect_equal(unname(al$template), unname(x))
  expect_true(al$converged)
  expect_identical(al$ids, c("1", "2", "3", "4"))
})

test_that("failures fall back to linear warping with a recorded reason", {
  pl <- planted_alignment(N = 6, seed = 9)
  bad <- pl$recs
  bad$rec03[5, 2] <- NaN
  expect_warning(al <- align_recordings(bad), class = "handmotion_warning_non_finite")
  expect_identical(al$method, "linear")
  expect_match(al$fallback_reason, "non-finite")
  expect_equal(unname(al$warps["rec01", ]), seq(1, pl$n[1], length.out = al$target_length))
  # forced failure through the internal option, on clean data
  local_failing_alignment()
  expect_warning(forced <- align_recordings(pl$recs), class = "handmotion_warning_linear_fallback")
  expect_identical(forced$method, "linear")
  expect_match(forced$fallback_reason, "forced")
  expect_equal(unname(forced$warped[1, , ]), unname(warp_linear(pl$recs[[1]], forced$target_length)))
  expect_equal(unname(forced$template), unname(apply(forced$warped, c(2, 3), mean)))
  expect_equal(nrow(forced$degenerate), 0)
})

test_that("a window too narrow for any path and a single recording fall back", {
  pl <- planted_alignment(N = 4, seed = 10)
  recs <- pl$recs
  recs$short <- grasp_curve(seq(0, 1, length.out = 5))
  expect_warning(al <- align_recordings(recs, window = 0.1), class = "handmotion_warning_linear_fallback")
  expect_identical(al$method, "linear")
  expect_match(al$fallback_reason, "no warping path")
  expect_warning(one <- align_recordings(pl$recs[1]), class = "handmotion_warning_linear_fallback")
  expect_identical(one$method, "linear")
  expect_match(one$fallback_reason, "fewer than 2")
  expect_identical(dim(one$warped), c(1L, nrow(pl$recs[[1]]), 3L))
})

test_that("broken recordings do not drag good ones down; too few left falls back", {
  x <- grasp_curve(seq(0, 1, length.out = 40))
  x2 <- grasp_curve(seq(0, 1, length.out = 44)^1.2)
  early <- grasp_curve(seq(0, 0.3, length.out = 40))   # stops after 30% of the motion
  late <- grasp_curve(seq(0.7, 1, length.out = 40))    # starts at 70%
  # half the set is broken: the first template is a compromise under which
  # even the good ones stall; they must survive the rounds of dropping
  al <- align_recordings(list(good = x, good2 = x2, early = early, late = late), features = "raw",
                         degenerate_warps = "drop")
  expect_identical(al$method, "dtw")
  expect_identical(al$ids, c("good", "good2"))
  expect_setequal(al$degenerate$id, c("early", "late"))
  # one good recording is not enough to align
  expect_warning(one <- align_recordings(list(good = x, early = early, late = late), features = "raw",
                                         degenerate_warps = "drop"),
                 class = "handmotion_warning_linear_fallback")
  expect_identical(one$method, "linear")
  expect_match(one$fallback_reason, "fewer than 2 recordings left after dropping 2 degenerate")
  expect_identical(one$ids, c("good", "early", "late"))
  # by default a type whose warps mostly stall at once is aligned as a whole
  # by slope-constrained DBA: every recording kept, none held still
  kept <- align_recordings(list(good = x, early = early, late = late), features = "raw")
  expect_identical(kept$method, "dtw")
  expect_identical(kept$step_pattern, "symmetricP05")
  expect_identical(kept$ids, c("good", "early", "late"))
  expect_true(all(c("early", "late") %in% kept$degenerate$id))
  expect_true(all(handmotion:::stall_lengths(kept$warps) <= 3))
  expect_true(all(apply(kept$warps, 1, function(w) all(diff(w) >= 0))))
  expect_output(print(kept), "whole type aligned by slope-constrained DTW")
})

test_that("target_length, L = 1 and one-frame recordings work", {
  pl <- planted_alignment(N = 5, seed = 12)
  al <- align_recordings(pl$recs, target_length = 25)
  expect_identical(dim(al$warped)[2], 25L)
  expect_true(all(al$warps[, 25] == pl$n))
  one <- align_recordings(pl$recs, target_length = 1)
  expect_identical(dim(one$warps), c(5L, 1L))
  expect_identical(one$method, "dtw")
  expect_equal(unname(one$warped[, 1, ]), t(vapply(pl$recs, colMeans, numeric(3))), ignore_attr = TRUE)
  recs <- c(pl$recs, list(dot = matrix(c(1, 2, 3), 1, 3, dimnames = list(NULL, c("a", "b", "c")))))
  expect_warning(dot <- align_recordings(recs), class = "handmotion_warning_one_frame")
  expect_true("dot" %in% dot$degenerate$id)   # (any features: nothing to stretch)   # one frame held for the whole template
})

test_that("align_recordings accepts grasps objects and rejects bad input", {
  pl <- planted_alignment(N = 4, seed = 13)
  g <- grasps(pl$recs)
  al <- align_recordings(g)
  expect_identical(al$ids, names(pl$recs))
  expect_error(align_recordings(list()), class = "handmotion_error_bad_input")
  expect_error(align_recordings(list(matrix(1, 3, 2), matrix(1, 3, 3))),
               class = "handmotion_error_bad_input")
  expect_error(align_recordings(pl$recs, target_length = 2.5), class = "handmotion_error_bad_input")
  expect_error(align_recordings(pl$recs, max_iter = -1), class = "handmotion_error_bad_input")
  expect_error(align_recordings(pl$recs, max_stall = 0), class = "handmotion_error_bad_input")
  expect_error(align_recordings(list(a = matrix(numeric(0), 0, 3), b = matrix(1, 2, 3))),
               class = "handmotion_error_bad_input")
})

test_that("print shows method, iterations and drops", {
  pl <- planted_alignment(N = 6, seed = 14)
  recs <- pl$recs
  recs$stuck <- grasp_curve(seq(0, 0.45, length.out = 30))
  al <- align_recordings(recs, max_iter = 3, features = "raw", degenerate_warps = "drop")
  expect_output(print(al), "6 recordings x 3 DoFs")
  expect_output(print(al), "dropped 1 degenerate warp")
  kept <- align_recordings(recs, max_iter = 3, features = "raw")
  expect_output(print(kept), "7 recordings x 3 DoFs")
  expect_output(print(kept), "kept 1 degenerate warp .* by a fallback: slope-constrained DTW: stuck")
  local_failing_alignment()
  expect_warning(forced <- align_recordings(recs), class = "handmotion_warning_linear_fallback")
  expect_output(print(forced), "LINEAR warping \\(fallback: alignment failure forced")
})

# ---- helpers reused by the model code ---------------------------------------

test_that("apply_warp interpolates linearly, clamps and is exact on frames", {
  x <- cbind(a = c(0, 10, 20, 40), b = c(1, 1, 2, 2))
  expect_equal(handmotion:::apply_warp(x, 1:4), x, ignore_attr = TRUE)
  expect_equal(handmotion:::apply_warp(x, c(1.5, 3.25))[, "a"], c(5, 25))
  expect_equal(handmotion:::apply_warp(x, c(0, 9))[, "a"], c(0, 40))
  expect_identical(colnames(handmotion:::apply_warp(x, 2)), c("a", "b"))
  expect_equal(handmotion:::apply_warp(x[1, , drop = FALSE], c(1, 1.5, 3)), x[c(1, 1, 1), ], ignore_attr = TRUE)
  lin <- warp_linear(x, 7)
  expect_equal(lin[, "a"], c(0, 5, 10, 15, 20, 30, 40))
  expect_equal(warp_linear(x, 4), x, ignore_attr = TRUE)
  # linear functions are reproduced exactly at any resolution
  ramp <- cbind(seq(2, 50, length.out = 37))
  expect_equal(warp_linear(ramp, 11)[, 1], seq(2, 50, length.out = 11))
})

# ---- compiled helpers of the DBA loop (src/dtw.c, src/dba-prep.c) ----------

test_that("ties are broken like dtw::dtw on longer sequences too", {
  # integer values, lengths across the 8-frame blocks of the distance kernel
  withr::local_seed(11)
  for (rep in 1:40) {
    n <- sample(8:30, 1); m <- sample(8:30, 1); p <- sample(c(1, 3, 16), 1)
    x <- matrix(sample(0:2, n * p, TRUE), n, p)
    y <- matrix(sample(0:2, m * p, TRUE), m, p)
    expect_identical(dtw_align_pair(x, y)[1:2], dtw_align_pair(x, y, engine = "reference")[1:2])
  }
})

test_that("a DBA step without the per-recording results has the same sums", {
  pl <- planted_alignment(N = 9, seed = 3)
  recs <- unname(pl$recs)
  tmpl <- mean_linear_template(recs, 40)
  full <- dtw_batch_fast(recs, tmpl, NULL, full = TRUE)
  lean <- dtw_batch_fast(recs, tmpl, NULL, full = FALSE)
  expect_identical(lean$sum, full$sum)
  expect_identical(lean$count, full$count)
  expect_null(lean$warped)
  ref <- dtw_batch_reference(recs, tmpl, NULL)
  expect_equal(full$sum, ref$sum, tolerance = 1e-12)
  expect_identical(full$count, as.integer(ref$count))
})

test_that("compiled shape features, linear mean and stalls equal the R versions", {
  pl <- planted_alignment(N = 7, seed = 4)
  recs <- c(pl$recs, list(one = matrix(c(1, 2, 3), 1), two = rbind(c(1, 2, 3), c(1, 5, 3))))
  sf <- shape_features(recs)
  for (k in seq_along(recs)) {
    nm <- shape_normaliser(recs[[k]])
    expect_identical(sf$centre[k, ], unname(nm$centre))
    expect_identical(sf$scale[k, ], unname(nm$scale))
    expect_identical(sf$features[[k]], unname(normalise_recording(recs[[k]], nm)))
  }
  expect_identical(names(sf$features), names(recs))
  for (L in c(1L, 2L, 37L)) {
    expect_identical(mean_linear_template(recs, L), mean_linear_template_r(recs, L))
  }
  warps <- withr::with_seed(5, t(apply(matrix(sample(1:6, 60, TRUE), 6), 1, sort)))
  storage.mode(warps) <- "double"
  expect_identical(stall_lengths(warps), stall_lengths_r(warps))
  expect_identical(stall_lengths(warps[, 1, drop = FALSE]), rep(1L, 6))
})

test_that("the compiled merge of two arrays' rows is the R expression it replaced", {
  stack_r <- function(a, b, ord) {
    d <- dim(a)
    out <- array(0, c(d[1] + dim(b)[1], d[-1]))
    out[seq_len(d[1]), , ] <- a
    out[d[1] + seq_len(dim(b)[1]), , ] <- b
    out[ord, , , drop = FALSE]
  }
  set.seed(3)
  a <- array(rnorm(7 * 5 * 3), c(7, 5, 3))
  for (nb in 0:2) {
    b <- array(rnorm(nb * 5 * 3), c(nb, 5, 3))
    ord <- sample.int(7 + nb)
    expect_identical(.Call(hm_rows_of_two, a, b, ord), stack_r(a, b, ord))
  }
  expect_error(.Call(hm_rows_of_two, a, array(0, c(1, 4, 3)), 1:8), "same further dimensions")
  expect_error(.Call(hm_rows_of_two, a, array(0, c(1, 5, 3)), c(1:7, 9L)), "positions")
  expect_error(.Call(hm_rows_of_two, a, array(0, c(1, 5, 3)), 1:7), "one position per row")
})

test_that("warped shape features go back to data units as the R expression took them", {
  set.seed(8)
  n_all <- 6; L <- 5; p <- 3
  kept <- c(1L, 3L, 4L, 6L)
  warped <- array(rnorm(length(kept) * L * p), c(length(kept), L, p))
  scale <- matrix(runif(n_all * p, 0.5, 2), n_all, p)
  centre <- matrix(rnorm(n_all * p), n_all, p)
  per_frame <- rep(seq_len(p), each = L)
  want <- warped * as.vector(scale[kept, per_frame, drop = FALSE]) + as.vector(centre[kept, per_frame, drop = FALSE])
  expect_identical(.Call(hm_unshape_warped, warped, scale, centre, kept), want)
  expect_error(.Call(hm_unshape_warped, warped, scale, centre, c(1L, 3L, 4L, 7L)), "rows of 'scale'")
})
