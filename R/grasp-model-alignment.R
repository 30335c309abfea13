# Steps 1-2 of a grasp model: over-long removal and alignment, with what was
# removed and what fell back recorded (never dropped silently).

# Steps 1-2 (also used by the frame-PCA alternative): over-long removal, then
# alignment to the mean frame count, with degenerate warps dropped and a
# linear fallback if the aligner itself fails.
prepare_alignment <- function(x, settings, engines, call) {
  meta <- x$meta
  recs <- x$recordings
  type <- as.character(meta$grasp[1])
  removed <- empty_removed()
  fallbacks <- empty_fallbacks()
  long <- find_overlong(meta$n_frames, rule = settings$overlong)
  if (any(long)) {
    removed <- rbind(removed, data.frame(id = meta$id[long], n_frames = meta$n_frames[long],
                                         reason = "overlong", detail = NA_real_, stringsAsFactors = FALSE))
  }
  keep <- !long
  if (sum(keep) < 2L) {
    hm_abort(c("Grasp type {.val {type}} has {sum(keep)} recording{?s} left after over-long removal; alignment needs 2 or more.",
               i = "Recordings in: {length(recs)}."),
             "too_few_recordings", grasp = type, call = call)
  }
  recs <- recs[keep]
  L <- max(2L, as.integer(round(mean(meta$n_frames[keep]))))
  if (identical(settings$warping, "linear")) {
    aln <- align_linear_fallback(recs, L, engines$align, reason = "requested")
  } else {
    # (the model records degenerate data itself, see model_degeneracies())
    aln <- tryCatch(
      withCallingHandlers(
        align_recordings(recs, target_length = L, engine = engines$align, max_stall = settings$max_stall,
                         degenerate_warps = settings$degenerate_warps %||% "constrain"),
        handmotion_warning_degenerate = function(w) invokeRestart("muffleWarning")),
      error = function(e) e
    )
    if (inherits(aln, "error")) {
      reason <- paste("alignment failed:", cli::ansi_strip(conditionMessage(aln)))
      aln <- align_linear_fallback(recs, L, engines$align, reason = reason)
    }
  }
  if (identical(aln$method, "linear") && !identical(settings$warping, "linear")) {
    fallbacks <- add_fallback(fallbacks, "warping", NA_character_,
                              paste("linear warping:", (aln$fallback_reason %||% "unspecified")))
  }
  deg <- aln$degenerate %||% empty_degenerate()
  # Only the recordings dropped by the thesis' rule are removed; those kept
  # with a slope-constrained or linear warp (degenerate_warps = "constrain") are listed
  # per recording (`kept_degenerate`) and as one fallback of the warping step.
  how <- deg$fallback %||% rep("dropped", nrow(deg))
  kept_degenerate <- deg[how != "dropped", c("id", "stall", "fallback"), drop = FALSE]
  rownames(kept_degenerate) <- NULL
  if (nrow(kept_degenerate)) {
    nl <- sum(kept_degenerate$fallback == "linear")
    stall <- sprintf("%g", aln$max_stall)
    linear <- if (nl) sprintf(" (%d linear: no such path)", nl) else ""
    fallbacks <- add_fallback(fallbacks, "degenerate_warp", NA_character_, as.character(cli::pluralize(paste(
      "{nrow(kept_degenerate)} recording{?s} held still > {stall} L by DTW kept with a slope-constrained DTW",
      "warp{linear}: {paste(kept_degenerate$id, collapse = ', ')}"))))
    if (identical(aln$step_pattern, "symmetricP05")) {
      fallbacks <- add_fallback(fallbacks, "slope_warping", NA_character_,
                                "most warps stalled at once: every recording aligned by slope-constrained DTW")
    }
  }
  deg <- deg[how == "dropped", , drop = FALSE]
  if (nrow(deg) > 0L) {
    removed <- rbind(removed, data.frame(id = as.character(deg$id),
                                         n_frames = meta$n_frames[match(deg$id, meta$id)],
                                         reason = "degenerate warp", detail = as.numeric(deg$stall),
                                         stringsAsFactors = FALSE))
  }
  ids <- dimnames(aln$warped)[[1]]
  if (is.null(ids)) ids <- setdiff(names(recs), removed$id)
  list(alignment = aln, ids = ids, removed = removed, fallbacks = fallbacks,
       n_input = length(x$recordings), kept_degenerate = kept_degenerate)
}

empty_removed <- function() {
  data.frame(id = character(), n_frames = integer(), reason = character(), detail = numeric(),
             stringsAsFactors = FALSE)
}

empty_fallbacks <- function() {
  data.frame(step = character(), dof = character(), reason = character(), stringsAsFactors = FALSE)
}

add_fallback <- function(fallbacks, step, dof, reason) {
  rbind(fallbacks, data.frame(step = step, dof = dof, reason = reason, stringsAsFactors = FALSE))
}
