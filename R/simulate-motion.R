# The simulator's engine: one grasp type at a time, vectorised over all its
# recordings (frames of every recording are stacked into one long vector, so
# the full 8910-recording set is a few dozen vector operations per DoF).
#
# Time course of a driven DoF (see ?simulate_grasps):
#   x(t) = rest + (peak - rest) * mj(s1(t)) + (final - peak) * mj(s2(t))
# with mj(s) = 10 s^3 - 15 s^4 + 6 s^5 (minimum jerk), s1 rising from 0 to 1
# between the finger's onset and its peak-aperture time, s2 between the peak
# time and the end of the closing. Before the onset the hand rests, after
# the closing it holds the final posture.

# (0 and 1 are fixed points, so only the moving frames are computed)
sim_min_jerk <- function(s) {
  i <- which(s > 0 & s < 1)
  x <- s[i]
  s[i] <- x * x * x * (10 + x * (-15 + 6 * x))
  s
}

sim_clamp01 <- function(x) pmin(pmax(x, 0), 1)

# Evaluate `expr` with a fixed RNG kind and seed, restoring the caller's RNG
# (kind and state) afterwards, so results never depend on global RNG settings.
with_sim_seed <- function(seed, expr) {
  with_seed(seed, {
    set.seed(seed, kind = "Mersenne-Twister", normal.kind = "Inversion", sample.kind = "Rejection")
    expr
  })
}

# Independent child seeds derived from the user's seed: one per Feix type
# (1-33) and one (34) for the subjects. Always all 34, so a type's stream is
# the same whichever subset of types is requested.
sim_streams <- function(seed) {
  with_sim_seed(seed, sample.int(.Machine$integer.max, 34L))
}

# Subject-level draws, one row per subject in subject order: latent factors z
# (k), own per-DoF offsets u (12) and a tempo factor. z and u are whitened in
# sample (see sim_whiten()), so every seed's population of hands has exactly
# the calibrated spread; the seed decides which hand is whose. (A subject's
# hand therefore depends on the number of subjects.)
sim_subject_draws <- function(stream, subjects, k) {
  nd <- length(sim_driven_dofs)
  x <- with_sim_seed(stream, rnorm_matrix(subjects, k + nd + 1L, byrow = TRUE))
  x[, seq_len(k + nd)] <- sim_whiten(x[, seq_len(k + nd), drop = FALSE])
  list(z = x[, seq_len(k), drop = FALSE], u = x[, k + seq_len(nd), drop = FALSE],
       tempo = x[, k + nd + 1L])
}

# Centre the columns of `x` and make their sample covariance the identity
# exactly (when there are more rows than columns; otherwise `x` unchanged).
sim_whiten <- function(x) {
  if (nrow(x) <= ncol(x) + 1L) return(x)
  x <- sweep(x, 2L, colMeans(x))
  x %*% solve(chol(stats::cov(x)))
}

# The design of one type: subject x object x trial, trial fastest.
sim_design <- function(subjects, objects, trials, params) {
  sizes <- if (objects == 1L) 1 else exp(seq(log(params$object_sizes[1]), log(params$object_sizes[2]),
                                             length.out = objects))
  names <- switch(as.character(objects), `1` = "medium", `2` = c("small", "large"),
                  `3` = c("small", "medium", "large"), sprintf("size%d", seq_len(objects)))
  d <- data.frame(subject = rep(seq_len(subjects), each = objects * trials),
                  object = rep(rep(seq_len(objects), each = trials), subjects),
                  trial = rep(seq_len(trials), subjects * objects))
  d$object_name <- names[d$object]
  d$size <- sizes[d$object]
  d
}

# Scale `x` so it sums to `total` (an integer) and round it so the sum is kept
# exactly: floor everything, then add one frame to the entries with the
# largest remainders (largest-remainder rounding; deterministic).
sim_round_to_total <- function(x, total) {
  x <- x * total / sum(x)
  fl <- floor(x)
  k <- total - sum(fl)
  if (k > 0) {
    o <- order(x - fl, decreasing = TRUE)[seq_len(k)]
    fl[o] <- fl[o] + 1
  }
  as.integer(fl)
}

# Simulate every recording of Feix type `g` for the given design. Must be
# called inside with_sim_seed(stream of g); the draws come in a fixed order
# whose sizes depend only on the design, never on the data.
sim_one_type <- function(g, design, subj, params, rate, overlong) {
  p <- params
  N <- nrow(design)
  S <- nrow(subj$z)
  O <- max(design$object)
  nd <- length(sim_driven_dofs)
  rr <- rate / p$reference_rate
  rnorm <- stats::rnorm
  runif <- stats::runif

  # ---- all random draws, fixed order --------------------------------------
  # (e_*: standard normal, u_*: uniform; each draw_blocks() call is one draw)
  e_subtype <- sim_whiten(rnorm_matrix(S, nd, byrow = TRUE))
  dr <- c(draw_blocks(rnorm, N, c(e_tempo = 1, e_post = nd, e_rest = nd, e_ap = 1)),
          draw_blocks(runif, N, c(u_lead = 1, u_hold = 1)),
          draw_blocks(rnorm, N, c(e_peak = 1, e_on = 5, e_pk = 5)))
  n_over <- round(p$overlong_fraction * N)
  over_idx <- sample.int(N, n_over)
  dr <- c(dr, draw_blocks(runif, n_over, c(u_mult = 1, u_hes = 1)),
          list(u_stall_n = runif(O)),
          draw_blocks(runif, N, c(u_stall_pri = 1, u_stall_frac = 1, u_stall_pos = 1)),
          draw_blocks(rnorm, N, c(e_dip = 4, e_drift_a = 16, e_drift_b = 16)))

  # ---- frame counts ---------------------------------------------------------
  sd_tot <- sqrt(p$tempo_subject_sd^2 + p$tempo_trial_sd^2)
  lt <- p$tempo_subject_sd * subj$tempo[design$subject] + p$tempo_trial_sd * dr$e_tempo
  lt <- pmin(pmax(lt, -p$tempo_clip * sd_tot), p$tempo_clip * sd_tot) + p$object_tempo * log(design$size)
  target <- p$target_frames$frames[g] * rr
  raw <- target * exp(lt)
  is_over <- logical(N)
  if (overlong) is_over[over_idx] <- TRUE
  normal <- !is_over
  n <- integer(N)
  # ordinary recordings: mean exactly `target` (an integer at the reference rate)
  n[normal] <- sim_round_to_total(raw[normal], round(target * sum(normal)))
  m <- n                                   # length of the motion timeline
  shift <- numeric(N)                      # frames of hesitation before it
  if (any(is_over)) {
    med <- stats::median(n[normal])
    k <- which(is_over)
    j <- match(k, over_idx)
    base <- pmax(round(raw[k]), 3L)
    mult <- p$overlong_multiplier[1] + dr$u_mult[j] * diff(p$overlong_multiplier)
    n[k] <- as.integer(pmax(round(mult * med), base + 1L))
    m[k] <- base
    hes <- dr$u_hes[j] < p$overlong_hesitation_share
    shift[k[hes]] <- n[k[hes]] - base[hes] # otherwise: a long final hold
  }

  # ---- stalls: the hand holds still mid-closing, ordinary length -------------
  stall_len <- numeric(N)
  stalled <- logical(N)
  lo <- p$stall_per_object[1]
  hi <- p$stall_per_object[2]
  for (o in seq_len(O)) {
    cand <- which(design$object == o & normal)
    # uniform integer in lo..hi, but never more than a tenth of the object's
    # recordings (a stall is an anomaly, not the rule, even in small designs)
    cnt <- min(floor(lo + dr$u_stall_n[o] * (hi - lo + 1)), floor(hi), floor(length(cand) / 10))
    if (cnt > 0) stalled[cand[order(dr$u_stall_pri[cand])][seq_len(cnt)]] <- TRUE
  }
  frac <- p$stall_fraction[1] + dr$u_stall_frac * diff(p$stall_fraction)
  stall_len[stalled] <- round(frac[stalled] * n[stalled])
  m[stalled] <- n[stalled] - stall_len[stalled]

  # ---- phase times on the motion timeline (frames 1..m) ----------------------
  lead <- (p$lead_frames[1] + dr$u_lead * diff(p$lead_frames)) * rr
  hold <- (p$hold_frames[1] + dr$u_hold * diff(p$hold_frames)) * rr
  avail <- pmax(m - 1, 1)
  squeeze <- pmin(1, 0.4 * avail / pmax(lead + hold, 1e-9)) # keep >= 60% for the motion
  lead <- lead * squeeze
  hold <- hold * squeeze
  f0 <- 1 + lead
  fend <- m - hold
  motion <- pmax(fend - f0, 1e-6)
  pf <- pmin(pmax(p$peak_time[[g]] + p$peak_time_sd * dr$e_peak, 0.2), 0.8)
  fpk <- f0 + pf * motion
  jit <- p$onset_jitter * p$jitter_scale[[g]] * motion
  on_f <- pmin(pmax(f0 + jit * dr$e_on, 1), fpk - 0.1 * motion)
  pk_f <- pmin(pmax(fpk + jit * dr$e_pk, on_f + 0.1 * motion), fend - 0.1 * motion)
  stall_start <- fpk + dr$u_stall_pos * 0.8 * (fend - fpk)

  # ---- postures (recordings x 12 driven DoFs) --------------------------------
  L <- p$loadings
  s_idx <- design$subject
  factors <- subj$z %*% t(L)                                        # S x 12: the subject's hand
  own <- p$subject_dof_sd * subj$u                                  # S x 12: the subject's own offsets
  # the type's posture, its distance from the mean posture of all types scaled
  # by posture_spread (calibration: how distinct final postures are), and
  # the subject's factors scaled per type (calibration: Table 5.7's shape)
  centre <- colMeans(p$postures)
  base <- centre + p$posture_spread[[g]] * (p$postures[g, ] - centre)
  type_offset <- p$factor_scale[[g]] * factors + own
  logsize <- log(design$size)
  # grasp_variability (per type) scales every within-type variation of the
  # final posture, the subject's own offsets included: an object that fixes
  # the hand's shape (a flat palm, a prismatic pinch) leaves a hand's
  # idiosyncrasies less room. At rest they are whole (below).
  final <- rep_row(base, N) + p$grasp_variability[[g]] * (type_offset[s_idx, , drop = FALSE] +
    p$subject_type_sd * e_subtype[s_idx, , drop = FALSE] +
    outer(logsize, p$object_response[g, ]) + p$trial_posture_sd * dr$e_post)
  # the glove's fit (the subject's own offsets) is there from the first frame;
  # the hand's style factors show partly at rest and fully in the grasp
  rest <- rep_row(p$rest, N) + p$subject_rest_share * factors[s_idx, , drop = FALSE] +
    own[s_idx, , drop = FALSE] + p$rest_sd * dr$e_rest
  # the opening's amplitude: wider for larger objects and varying from grasp
  # to grasp, both scaled by the type's aperture_variability
  amp <- p$aperture_scale[g] *
    exp(p$aperture_variability[[g]] * (p$object_aperture * logsize + p$aperture_sd * dr$e_ap))
  # pre-shaping: on the way, the open hand already leans towards the type's
  # final posture (a share `preshape` of its distance from the mean posture)
  peak <- rest + outer(amp, p$aperture) + rep_row(p$preshape[[g]] * (base - centre), N)

  # ---- trajectories -----------------------------------------------------------
  Ft <- sum(n)
  rec <- rep.int(seq_len(N), n)
  frame <- sequence(n)
  tau <- frame - shift[rec]
  tau <- tau - pmin(pmax(tau - stall_start[rec], 0), stall_len[rec])
  h1 <- h2 <- matrix(0, Ft, 5)
  for (f in 1:5) {
    a <- on_f[rec, f]
    b <- pk_f[rec, f]
    h1[, f] <- sim_min_jerk(sim_clamp01((tau - a) / (b - a)))
    h2[, f] <- sim_min_jerk(sim_clamp01((tau - b) / (fend[rec] - b)))
  }
  dofs <- handmotion::hust_dofs$name
  out <- matrix(0, Ft, length(dofs), dimnames = list(NULL, dofs))
  finger <- sim_finger_of_dof(sim_driven_dofs)
  for (j in seq_len(nd)) {
    f <- finger[j]
    out[, sim_driven_dofs[j]] <- rest[rec, j] + (peak[rec, j] - rest[rec, j]) * h1[, f] +
      (final[rec, j] - peak[rec, j]) * h2[, f]
  }
  for (k in seq_along(sim_dip_of_pip)) {
    out[, names(sim_dip_of_pip)[k]] <- p$dip_pip_ratio * out[, sim_dip_of_pip[k]] + p$dip_sd * dr$e_dip[rec, k]
  }
  u <- (frame - 1) / pmax(n[rec] - 1, 1)
  if (p$drift_sd > 0) {
    out <- out + p$drift_sd * (dr$e_drift_a[rec, , drop = FALSE] * (u - 0.5) + dr$e_drift_b[rec, , drop = FALSE] * sin(pi * u))
  }
  if (p$noise_sd > 0) out <- out + p$noise_sd * stats::rnorm(length(out))

  starts <- c(0L, cumsum(n)[-N])
  recs <- lapply(seq_len(N), function(i) out[starts[i] + seq_len(n[i]), , drop = FALSE])
  width <- max(2L, nchar(S))
  subj_id <- sprintf("S%0*d", width, design$subject)
  ids <- sprintf("T%02d-%s-O%d-R%d", g, subj_id, design$object, design$trial)
  names(recs) <- ids
  meta <- data.frame(id = ids, grasp = factor(rep(feix_levels()[g], N), levels = feix_levels()),
                     subject = subj_id, object = design$object_name, trial = design$trial,
                     n_frames = n, source = "simulated", overlong = is_over, stalled = stalled,
                     object_size = design$size, stringsAsFactors = FALSE)
  list(recordings = recs, meta = meta)
}

rep_row <- function(x, n) matrix(x, n, length(x), byrow = TRUE)
