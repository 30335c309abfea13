# Figures of the thesis' chapter 5 that belong to no model class: the frame
# counts of one grasp type before anything is removed (the left half of
# Figure 5.1, with the over-long recordings the model drops marked) and the
# temporal comparisons of Tables 5.4 and 5.5 (a recorded and a generated grasp
# drawn as hands at the same fractions of their durations). The drawing
# itself reuses the hand-pose helpers of R/plot-hand.R.

# Frame counts per grasp type with the over-long recordings marked (the left
# half of Figure 5.1); autoplot(<grasps>, type = "frame_counts").
plot_frame_counts <- function(x, grasps = NULL, rule = overlong_rule(), binwidth = 1,
                              call = rlang::caller_env()) {
  check_grasps(x, call = call)
  binwidth <- check_number(binwidth, "binwidth", min = 0, min_open = TRUE, call = call)
  types <- thesis_plot_types(x, grasps, call)
  parts <- lapply(types, function(type) {
    m <- x$meta[!is.na(x$meta$grasp) & as.character(x$meta$grasp) == type, , drop = FALSE]
    long <- find_overlong(m$n_frames, rule = rule)
    data.frame(id = m$id, grasp = type, n_frames = m$n_frames,
               status = ifelse(long, "over-long", "kept"),
               threshold = overlong_threshold(m$n_frames, rule = rule), stringsAsFactors = FALSE)
  })
  d <- do.call(rbind, parts)
  d$grasp <- factor(d$grasp, levels = types)
  d$status <- factor(d$status, levels = c("kept", "over-long"))
  fences <- unique(d[c("grasp", "threshold")])
  ggplot2::ggplot(d, ggplot2::aes(x = .data$n_frames, fill = .data$status)) +
    ggplot2::geom_histogram(binwidth = binwidth, colour = "white") +
    ggplot2::geom_vline(data = fences, ggplot2::aes(xintercept = .data$threshold),
                        linetype = "dashed", colour = "red") +
    ggplot2::scale_fill_manual(values = c(kept = "grey35", `over-long` = "red"), drop = FALSE,
                               name = NULL) +
    ggplot2::facet_wrap(ggplot2::vars(.data$grasp), scales = "free_y") +
    ggplot2::labs(x = "frames before warping", y = "recordings") +
    ggplot2::theme_minimal()
}

# One recording of each set as a row of hands at equally spaced fractions of
# its duration (Tables 5.4 and 5.5); autoplot(<grasps>, type = "strip").
plot_frame_strip <- function(x, recording = 1L, n_frames = 6L, skeleton = hand_skeleton(),
                             view = "oblique", hand_colour = "skin", ..., call = rlang::caller_env()) {
  geometry <- pose_geometry(NULL, hand_colour, skeleton, call = call)
  sets <- if (inherits(x, "grasps")) list(x) else x
  if (!is.list(sets) || !length(sets) || !all(vapply(sets, inherits, logical(1), "grasps"))) {
    hm_abort("{.arg x} must be a {.cls grasps} object or a list of them, not {.obj_type_friendly {x}}.",
             "bad_input", argument = "x", call = call)
  }
  # (a strip shows at least its first and last frame)
  check_whole(n_frames, "n_frames", min = 2, call = call)
  if (is.null(names(sets))) names(sets) <- if (length(sets) == 1L) "" else paste("set", seq_along(sets))
  recording <- rep_len(as.list(recording), length(sets))
  fractions <- seq(0, 1, length.out = n_frames)
  time_labels <- sprintf("%.0f%%", 100 * fractions)
  poses <- lapply(seq_along(sets), function(k) {
    g <- sets[[k]]
    i <- strip_recording_index(g, recording[[k]], names(sets)[k], call)
    n <- g$meta$n_frames[i]
    frames <- 1L + as.integer(round((n - 1) * fractions))
    keep <- !duplicated(frames)  # a recording shorter than n_frames
    p <- hand_pose(g[i], frame = frames[keep], skeleton = skeleton, ...)
    p <- as.data.frame(unclass(p), stringsAsFactors = FALSE)
    p$set <- names(sets)[k]
    # label by the nominal fraction, so the columns line up across sets
    p$time <- time_labels[keep][match(p$frame, frames[keep])]
    p
  })
  common <- Reduce(intersect, lapply(poses, names))
  p <- do.call(rbind, lapply(poses, function(d) d[common]))
  p$set <- factor(p$set, levels = names(sets))
  p$time <- factor(p$time, levels = unique(time_labels))
  p$id <- paste(p$set, p$id)
  pr <- project_pose(p, view, call)
  grasp <- unique(stats::na.omit(as.character(p$grasp)))
  g <- ggplot2::ggplot() + pose_layers(pr, geometry = geometry) +
    ggplot2::labs(title = if (length(grasp) == 1L) grasp else NULL,
                  subtitle = paste0("columns: fraction of each recording's duration\n", view_label(view)))
  if (length(sets) > 1L) {
    g + ggplot2::facet_grid(set ~ time, switch = "y") +
      ggplot2::theme(strip.text.y.left = ggplot2::element_text(angle = 0, hjust = 1))
  } else {
    g + ggplot2::facet_wrap(~time, nrow = 1)
  }
}

# One recording of a set, by index or id; errors name the set.
strip_recording_index <- function(g, which, set, call) {
  if (is.character(which)) {
    i <- match(which, g$meta$id)
    if (is.na(i)) {
      hm_abort("No recording {.val {which}} in set {.val {set}}.", "bad_input",
               argument = "recording", call = call)
    }
    return(i)
  }
  check_indices(which, length(g), "recording", "recording", where = sprintf(" or an id of set \"%s\"", set),
                one = TRUE, call = call)
}

# Grasp types to draw: the requested ones (present in x) or every labelled one.
thesis_plot_types <- function(x, grasps, call) {
  present <- levels(droplevels(x$meta$grasp))
  if (is.null(grasps)) {
    if (!length(present)) {
      hm_abort("{.arg x} has no labelled recordings.", "no_labels", argument = "x", call = call)
    }
    return(present)
  }
  types <- resolve_labels(grasps, levels(x$meta$grasp), "grasps", call = call)
  absent <- setdiff(types, present)
  if (length(absent)) {
    hm_abort("No recordings of grasp type{?s} {.val {absent}} in {.arg x}.", "too_few_recordings",
             argument = "grasps", call = call)
  }
  types
}
