# Pictures of a time alignment, after Jeppsson (2017) Figures 5.1 and 5.2:
# the frame counts before warping, and the warping paths (original frame as a
# function of warped frame), where degenerate warps show as long flat stretches.

#' Plot a time alignment
#'
#' Reproduces Jeppsson (2017) Figures 5.1/5.2: a histogram of the original
#' frame counts and the warping paths, one line per recording (original frame
#' against warped frame). Recordings dropped for a degenerate warp are drawn
#' in red; under the linear fallback the paths are straight lines.
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
  colours <- c(kept = "grey35", degenerate = "red")
  subtitle <- if (object$method == "dtw") {
    sprintf("DTW barycenter averaging, L = %d; %d dropped as degenerate",
            object$target_length, nrow(object$degenerate))
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

alignment_length_data <- function(object) {
  deg <- object$degenerate
  data.frame(
    n_frames = c(as.numeric(object$n_frames), as.numeric(deg$n_frames)),
    status = factor(c(rep("kept", length(object$n_frames)), rep("degenerate", nrow(deg))),
                    levels = c("kept", "degenerate")),
    panel = factor(alignment_panel_levels[1], levels = alignment_panel_levels),
    stringsAsFactors = FALSE)
}

alignment_path_data <- function(object) {
  L <- object$target_length
  w <- rbind(object$warps, object$dropped_warps)
  ids <- c(object$ids, object$degenerate$id)
  status <- c(rep("kept", nrow(object$warps)), rep("degenerate", nrow(object$dropped_warps)))
  data.frame(
    id = rep(ids, times = L),
    warped_frame = rep(seq_len(L), each = nrow(w)),
    original_frame = as.vector(w),
    status = factor(rep(status, times = L), levels = c("kept", "degenerate")),
    panel = factor(alignment_panel_levels[2], levels = alignment_panel_levels),
    stringsAsFactors = FALSE)
}
