# Joint limits: generated grasps are sums of functional components and can
# overshoot what a hand can do; generate(limits = TRUE) keeps them inside the
# rotation limits of the joint axis each DoF drives.

# The range each DoF may take, in the DoF's own unit and sign: the limits of
# the joint axis the mapping applies it to (`sign * scale * angle` in
# degrees), converted back. One row per limited DoF: `dof`, `col` (its column
# in `dofs`), `lo`, `hi` and the skeleton `joint` it turns. DoFs without an axis, a turn about the parent's axis
# (the thumb's opposition: no limits in the skeleton) and axes declared "0 0"
# (no range) are left out. Used to clamp, to count violations and to keep
# generated grasps inside the hand (generate(limits = TRUE)).
dof_limits <- function(dofs, factor = 1, skeleton = hand_skeleton(), mapping = NULL,
                       call = rlang::caller_env()) {
  if (is.null(mapping)) mapping <- default_joint_map_impl(dofs, call)
  mapping <- check_mapping(mapping, skeleton, call)
  mapping$col <- match(dof_key(mapping$dof), dof_key(dofs))
  used <- mapping[!is.na(mapping$col) & !is.na(mapping$axis) & mapping$sign * mapping$scale != 0 &
                    mapping$frame == "joint", , drop = FALSE]
  lim <- as.matrix(skeleton$joints[match(used$joint, skeleton$joints$name), skeleton_limit_cols])
  rows <- seq_len(nrow(used))
  lo <- lim[cbind(rows, match(paste0("rot", used$axis, "_min"), skeleton_limit_cols))]
  hi <- lim[cbind(rows, match(paste0("rot", used$axis, "_max"), skeleton_limit_cols))]
  declared <- !(lo == 0 & hi == 0)
  mult <- (used$sign * used$scale * factor)[declared]
  a <- lo[declared] / mult
  b <- hi[declared] / mult
  data.frame(dof = dofs[used$col[declared]], col = used$col[declared],
             lo = pmin(a, b), hi = pmax(a, b), joint = used$joint[declared], stringsAsFactors = FALSE)
}

# Share of recorded frames above which a DoF's limits are not enforced in
# generation: such a DoF is evidently measured differently from the skeleton
# axis it is mapped to (on HUST-like data, ABD1: the glove's thumb-index
# abduction of 0-70 degrees against th-mcp's +-15 degree side-to-side range).
limit_enforce_max_outside <- 0.1

# The joint limits a model generates within (generate(limits = TRUE)): the
# skeleton's ranges of its DoFs (dof_limits(), default hand and mapping), each
# with the share of the training recordings' frames outside it and whether it
# is enforced (that share at most limit_enforce_max_outside). DoFs no default
# mapping knows give an empty table and a note.
recorded_limits <- function(x, dofs) {
  empty <- data.frame(dof = character(), col = integer(), lo = numeric(), hi = numeric(),
                      joint = character(), recorded_outside = numeric(), enforced = logical(),
                      source = character(), stringsAsFactors = FALSE)
  lim <- if (x$unit %in% c("deg", "rad")) {
    tryCatch(dof_limits(dofs, if (identical(x$unit, "rad")) 180 / pi else 1,
                        mapping = if (!is.null(x$glove)) glove_mapping(match_glove(x$glove, dofs, x$unit))),
             handmotion_error = function(e) NULL)
  }
  if (is.null(lim) || !nrow(lim)) lim <- empty[c("dof", "col", "lo", "hi", "joint")]
  recs <- double_recordings(x)
  if (nrow(lim)) {
    # (counted over the recordings in one compiled pass, src/channel-ranges.c:
    # stacking them with rbind() was a twentieth of a fit)
    outside <- .Call(hm_channel_outside, recs, as.integer(lim$col), as.double(lim$lo), as.double(lim$hi))
    lim$recorded_outside <- outside / sum(x$meta$n_frames)
    lim$enforced <- lim$recorded_outside <= limit_enforce_max_outside
    lim$source <- rep("skeleton", nrow(lim))
  } else {
    lim <- empty
  }
  rbind(lim, sensor_limits(x, dofs, recs, exclude = lim$dof))
}

# Limits of a glove's channels that the skeleton does not limit: the
# sensor's range from the profile, narrowed to the training data's range,
# or, for raw channels without a declared range, the training data's range
# (documented under generate()). A sensor cannot read outside its range, so
# these are enforced whenever generation keeps limits at all.
sensor_limits <- function(x, dofs, recs, exclude) {
  ch <- if (!is.null(x$glove)) match_glove(x$glove, dofs, x$unit)$channels else NULL
  if (is.null(ch)) return(NULL)
  range <- channel_ranges(recs)
  rows <- lapply(seq_along(dofs), function(j) {
    if (dofs[j] %in% exclude) return(NULL)
    declared <- !is.na(ch$min[j]) && !is.na(ch$max[j]) && ch$unit[j] == x$unit
    if (!declared && ch$unit[j] != "raw") return(NULL)
    lo <- range$lo[[j]]
    hi <- range$hi[[j]]
    if (declared) {
      lo <- max(lo, ch$min[j])
      hi <- min(hi, ch$max[j])
    }
    data.frame(dof = dofs[j], col = j, lo = lo, hi = hi, joint = ch$joint[j], recorded_outside = 0,
               enforced = hi >= lo, source = if (declared) "glove" else "training", stringsAsFactors = FALSE)
  })
  out <- do.call(rbind, rows)
  if (is.null(out)) NULL else out
}

# Share of frames of a grasps object outside the limits of `lim` (a
# recorded_limits() / dof_limits() table), per DoF and over all limited
# values of all frames.
limit_violations <- function(x, lim) {
  if (!nrow(lim)) return(list(by_dof = stats::setNames(numeric(), character()), frames = NA_real_))
  X <- do.call(rbind, x$recordings)
  cols <- match(lim$dof, x$dofs)
  # column by column: two sweep()s over the stacked frames cost three times
  # as much (evaluate_generation() asks this of every generated batch)
  out <- vapply(seq_along(cols), function(k) {
    v <- X[, cols[k]]
    v < lim$lo[k] | v > lim$hi[k]
  }, logical(nrow(X)))
  dim(out) <- c(nrow(X), length(cols))
  list(by_dof = stats::setNames(colMeans(out), lim$dof), frames = mean(rowSums(out) > 0))
}
