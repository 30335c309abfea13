# The simulator's second protocol: recordings as a researcher's own glove
# delivers them. The HUST-like joint angles of simulate_grasps() are read
# through a glove profile (each channel takes the angle of the joint axis it
# drives; channels no HUST DoF drives get a plausible motion of their own),
# framed by a rest phase before the motion and a hold phase after it,
# converted to the channel's unit (raw counts through the profile's nominal
# map, with a per-session offset and gain, sensor noise and quantisation), and
# stuck channels are held at one count. The true motion onset and end are kept
# in the metadata (`motion_start`, `motion_end`) so segmentation can be tested
# against them.

sim_glove_protocol <- function(x, glove, rest, hold, stuck, session_sd, seed) {
  glove <- glove_profile(glove)
  ch <- glove$channels
  hust <- hust_joint_map()
  key <- function(j, a, f) paste(j, a, f)
  src <- match(key(ch$joint, ch$axis, ch$frame), key(hust$joint, hust$axis, hust$frame))
  # applied angle sign*scale*value is the same for the channel and its HUST DoF
  conv <- (hust$sign[src] * hust$scale[src]) / (ch$sign * ch$scale)
  subjects <- unique(x$meta$subject)
  n_ch <- nrow(ch)
  with_seed(seed, {
    # per subject (one glove session each): spread style, count offset and gain
    sess <- lapply(subjects, function(s) list(
      offset = stats::rnorm(n_ch, 0, session_sd), gain = exp(stats::rnorm(n_ch, 0, 0.05)),
      spread0 = stats::rnorm(n_ch, 12, 3), spread1 = stats::rnorm(n_ch, -10, 2)))
    names(sess) <- subjects
    stuck_value <- stats::runif(n_ch, 0.2, 0.8)
    onset <- integer(length(x))
    end <- integer(length(x))
    recs <- lapply(seq_along(x), function(i) {
      r <- x$recordings[[i]]
      n <- nrow(r)
      s <- sess[[x$meta$subject[i]]]
      closure <- rowMeans(r[, c("MCP2", "MCP3", "MCP4", "MCP5"), drop = FALSE]) / 90
      out <- matrix(0, n, n_ch, dimnames = list(NULL, ch$channel))
      for (k in seq_len(n_ch)) {
        out[, k] <- if (!is.na(src[k])) r[, hust$dof[src[k]]] * conv[k]
          else if (!is.na(ch$axis[k]) && ch$axis[k] == "z") s$spread0[k] + s$spread1[k] * closure
          else 5 * closure + cumsum(stats::rnorm(n, 0, 0.05))
      }
      # rest before and hold after the motion: the first and last posture,
      # with physiological tremor
      n_rest <- max(0L, round(rest * x$rate * stats::runif(1, 0.7, 1.3)))
      n_hold <- max(0L, round(hold * x$rate * stats::runif(1, 0.7, 1.3)))
      still <- function(row, m) {
        if (m == 0L) return(NULL)
        matrix(row, m, n_ch, byrow = TRUE) + matrix(stats::rnorm(m * n_ch, 0, 0.15), m, n_ch)
      }
      out <- rbind(still(out[1, ], n_rest), out, still(out[n, ], n_hold))
      onset[i] <<- n_rest + 1L
      end[i] <<- n_rest + n
      to_unit(out, ch, s, stuck_value, stuck)
    })
    names(recs) <- names(x$recordings)
    meta <- x$meta
    meta$motion_start <- onset
    meta$motion_end <- end
    ch$stuck <- ch$channel %in% stuck
    new_grasps(recs, meta, ch$channel, x$rate, if (all(ch$unit == ch$unit[1])) ch$unit[1] else "raw",
               glove = new_glove_profile(glove$name, ch))
  })
}

# Degrees to each channel's unit; raw counts through the nominal map with the
# session's offset and gain, noise of about one count, quantised and clipped
# to the converter's range. Stuck channels read one count throughout.
to_unit <- function(deg, ch, session, stuck_value, stuck) {
  out <- deg
  for (k in seq_len(ncol(deg))) {
    u <- ch$unit[k]
    if (u == "rad") out[, k] <- deg[, k] * pi / 180
    if (u == "raw") {
      lo <- ch$min[k]
      hi <- ch$max[k]
      a0 <- if (is.na(ch$angle_min[k])) -20 else ch$angle_min[k]
      a1 <- if (is.na(ch$angle_max[k])) 120 else ch$angle_max[k]
      v <- lo + (deg[, k] - a0) / (a1 - a0) * (hi - lo) * session$gain[k] + session$offset[k]
      v <- v + stats::rnorm(length(v), 0, 1)
      out[, k] <- pmin(pmax(round(v), lo), hi)
      if (ch$channel[k] %in% stuck) out[, k] <- round(lo + stuck_value[k] * (hi - lo))
    } else if (ch$channel[k] %in% stuck) {
      out[, k] <- stuck_value[k] * 10
    }
  }
  out
}
