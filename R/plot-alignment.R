# Pictures of a time alignment, after Jeppsson (2017) Figures 5.1 and 5.2:
# the frame counts before warping, and the warping paths (original frame as a
# function of warped frame), where degenerate warps show as long flat stretches.

#' Plot a time alignment
#'
#' Reproduces Jeppsson (2017) Figures 5.1/5.2: a histogram of the original
#' frame counts and the warping paths, one line per recording (original frame
#' against warped frame). Degenerate DTW warps (Figure 5.1) are drawn in red:
#' the recordings dropped for them (`degenerate_warps = "drop"`, the
#' thesis' rule) or, by default, kept with a slope-constrained or linear warp,
#' drawn in orange. Under the linear fallback the paths are straight lines.
#'
#' @param object A `grasp_alignment`: the `alignment` a fitted model keeps
#'   ([fit_grasp_model()] with `keep_data = TRUE`, the default); also drawn by
#'   `autoplot(model, type = "alignment")`.
#' @param type `"both"` (two panels), `"histogram"` or `"paths"`.
#' @param ... Unused.
#' @return A ggplot object.
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' m$alignment
#' ggplot2::autoplot(m$alignment)
#' ggplot2::autoplot(m$alignment, type = "paths")
#' @method autoplot grasp_alignment
#' @export
autoplot.grasp_alignment <- function(object, type = c("both", "histogram", "paths"), ...) {
  type <- check_choice(type, arg = "type", call = rlang::current_env())
  hist_df <- alignment_length_data(object)
  path_df <- alignment_path_data(object)
  colours <- c(kept = "grey35", `kept by a fallback` = "darkorange", degenerate = "red")
  subtitle <- if (object$method == "dtw") {
    how <- alignment_fallbacks(object)
    sprintf("DTW barycenter averaging, L = %d; %d dropped as degenerate%s",
            object$target_length, sum(how == "dropped"),
            if (any(how != "dropped")) sprintf(", %d kept by a slope-constrained or linear warp", sum(how != "dropped")) else "")
  } else {
    sprintf("linear warping (fallback: %s), L = %d", object$fallback_reason,
            object$target_length)
  }
  hist_layer <- ggplot2::geom_histogram(
    data = hist_df, mapping = ggplot2::aes(x = .data$n_frames, fill = .data$status),
    binwidth = 1, colour = "white", inherit.aes = FALSE)
  path_layer <- ggplot2::geom_line(
    data = path_df,
    mapping = ggplot2::aes(x = .data$warped_frame, y = .data$original_frame,
                           group = .data$id, colour = .data$status),
    alpha = 0.6, inherit.aes = FALSE)
  p <- ggplot2::ggplot() +
    ggplot2::scale_colour_manual(values = colours, drop = TRUE, name = NULL) +
    ggplot2::scale_fill_manual(values = colours, drop = TRUE, name = NULL) +
    ggplot2::labs(subtitle = subtitle) +
    ggplot2::theme_minimal()
  switch(type,
    histogram = p + hist_layer +
      ggplot2::labs(x = "frames before warping", y = "recordings"),
    paths = p + path_layer +
      ggplot2::labs(x = "warped frame", y = "original frame"),
    # the two panels have different axes: each strip names its own, rather
    # than one "left: ...; right: ..." axis title for both
    both = p + hist_layer + path_layer +
      ggplot2::facet_wrap(ggplot2::vars(.data$panel), scales = "free",
                          labeller = ggplot2::as_labeller(alignment_panel_titles)) +
      ggplot2::labs(x = NULL, y = NULL)
  )
}

alignment_panel_levels <- c("frame counts before warping", "warping paths")
alignment_panel_titles <- c(`frame counts before warping` = "Frame counts: recordings (y) by frames before warping (x)",
                            `warping paths` = "Warping paths: original frame (y) by warped frame (x)")

# What became of each degenerate DTW warp ("dropped", the thesis' rule, or
# the "slope" or "linear" warp that kept the recording).
alignment_fallbacks <- function(object) {
  object$degenerate$fallback %||% rep("dropped", NROW(object$degenerate))
}

status_levels <- c("kept", "kept by a fallback", "degenerate")

# kept recordings, those kept by a fallback warp, and the dropped ones
alignment_status <- function(object) {
  how <- alignment_fallbacks(object)
  rescued <- object$degenerate$id[how != "dropped"]
  ifelse(object$ids %in% rescued, "kept by a fallback", "kept")
}

alignment_length_data <- function(object) {
  deg <- object$degenerate
  deg <- deg[alignment_fallbacks(object) == "dropped", , drop = FALSE]
  data.frame(
    n_frames = c(as.numeric(object$n_frames), as.numeric(deg$n_frames)),
    status = factor(c(alignment_status(object), rep("degenerate", nrow(deg))),
                    levels = status_levels),
    panel = factor(alignment_panel_levels[1], levels = alignment_panel_levels),
    stringsAsFactors = FALSE)
}

alignment_path_data <- function(object) {
  L <- object$target_length
  w <- rbind(object$warps, object$dropped_warps)
  ids <- c(object$ids, rownames(object$dropped_warps) %||% object$degenerate$id)
  # (the degenerate DTW warps are drawn also when a fallback replaced them:
  # the id then has its stalled path in red and its kept path in orange)
  ids <- paste0(ids, c(rep("", nrow(object$warps)), rep(" (DTW)", nrow(object$dropped_warps))))
  status <- c(alignment_status(object), rep("degenerate", nrow(object$dropped_warps)))
  data.frame(
    id = rep(ids, times = L),
    warped_frame = rep(seq_len(L), each = nrow(w)),
    original_frame = as.vector(w),
    status = factor(rep(status, times = L), levels = status_levels),
    panel = factor(alignment_panel_levels[2], levels = alignment_panel_levels),
    stringsAsFactors = FALSE)
}
