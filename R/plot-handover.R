# Pictures for sparse-marker hand-over, after the figures of Wheatland, Joerg
# and Zordan: markers on the hand (Fig. 3), PCA error against components
# (Fig. 1), marker-set comparison (Figs. 2 and 4), component trajectories
# (Fig. 5). The hand itself is drawn by autoplot.hand_pose() (R/plot-hand.R).

# Marker sets on the hand in its rest pose (the paper's Figure 3), drawn by
# autoplot(<hand_skeleton>, markers = ): the full marker set with open
# symbols, each set's markers filled, one panel per set. The marker layer's
# data has columns `set`, `marker` and `selected`.
plot_marker_sets <- function(sets, skeleton = hand_skeleton(), view = "back", forearm = TRUE,
                             call = rlang::caller_env()) {
  if (is.character(sets)) sets <- list(sets)
  if (!is.list(sets) || !length(sets)) {
    hm_abort("{.arg sets} must be a named list of marker-name vectors.", "bad_input",
             argument = "sets", call = call)
  }
  if (is.null(names(sets))) names(sets) <- paste("set", seq_along(sets))
  for (s in sets) check_marker_names(s, arg = "sets", call = call)
  rest <- skeleton_rest_positions(skeleton)
  pos <- array(rest, c(1, dim(rest)), dimnames = list(NULL, rownames(rest), c("x", "y", "z")))
  ms <- resolve_marker_set(NULL, forearm = forearm, call = call)
  mk <- matrix(place_markers(pos, ms, call = call), ncol = 3, byrow = TRUE)
  pose <- hand_pose(skeleton)
  panels <- lapply(names(sets), function(nm) {
    p <- as.data.frame(unclass(pose), stringsAsFactors = FALSE)
    p$id <- nm
    m <- data.frame(id = nm, set = nm, marker = ms$marker, x = mk[, 1], y = mk[, 2], z = mk[, 3],
                    selected = ms$marker %in% sets[[nm]], stringsAsFactors = FALSE)
    list(pose = p, markers = m)
  })
  pose_all <- structure(do.call(rbind, lapply(panels, `[[`, "pose")), class = c("hand_pose", "data.frame"),
                        skeleton = skeleton)
  marks <- do.call(rbind, lapply(panels, `[[`, "markers"))
  marks <- project_pose(marks, view, call)
  marks$panel <- factor(marks$id, levels = names(sets))
  g <- ggplot2::autoplot(pose_all, view = view)
  # autoplot.hand_pose facets by `panel` built from the ids in set order
  # (fill is the hand's own, shaded by depth: the markers use shape)
  marks$recorded <- factor(ifelse(marks$selected, "recorded", "not recorded"),
                           levels = c("recorded", "not recorded"))
  g + ggplot2::geom_point(data = marks, ggplot2::aes(x = .data$sx, y = .data$sy, shape = .data$recorded),
                          size = 3, colour = "black", fill = "white", stroke = 0.6) +
    ggplot2::scale_shape_manual(values = c(recorded = 16, `not recorded` = 21), name = NULL) +
    ggplot2::theme(legend.position = "bottom")
}

#' Plot the PCA reconstruction error against the number of components
#'
#' The paper's Figure 1.
#'
#' @param object A `handover_pca_error` from `handover_error(by = "ncomp")`.
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @method autoplot handover_pca_error
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:5, objects = 1, trials = 1)
#' ggplot2::autoplot(handover_error(g, by = "ncomp"))
autoplot.handover_pca_error <- function(object, ...) {
  df <- as.data.frame(unclass(object)[names(object)])
  ggplot2::ggplot(df, ggplot2::aes(x = .data$ncomp, y = .data$error)) +
    ggplot2::geom_line() +
    ggplot2::geom_point() +
    ggplot2::labs(x = "number of principal components",
                  y = "mean joint-angle error per frame (degrees)") +
    ggplot2::theme_minimal()
}

#' Plot a marker-set comparison
#'
#' A bar per marker set and method with the mean joint-angle error per frame
#' and +- one standard deviation over test recordings (the paper's Figures 2
#' and 4).
#'
#' @param object A `handover_comparison` from `handover_error(by = "markers")`.
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @method autoplot handover_comparison
#' @examples
#' g <- simulate_grasps(subjects = 3, grasps = 1:4, objects = 1, trials = 1)
#' cmp <- handover_error(g[g$meta$subject == "S03"], by = "markers",
#'                       reference = g[g$meta$subject != "S03"], search = FALSE)
#' ggplot2::autoplot(cmp)
autoplot.handover_comparison <- function(object, ...) {
  df <- as.data.frame(unclass(object)[names(object)])
  df$method <- ifelse(df$method == "pca", "PCA + LWR", "no PCA (direct)")
  ggplot2::ggplot(df, ggplot2::aes(x = .data$set, y = .data$error, fill = .data$method)) +
    ggplot2::geom_col(width = 0.7) +
    ggplot2::geom_errorbar(ggplot2::aes(ymin = pmax(0, .data$error - .data$error_sd),
                                        ymax = .data$error + .data$error_sd), width = 0.2) +
    ggplot2::labs(x = NULL, y = "joint-angle error (degrees)", fill = NULL) +
    ggplot2::theme_minimal() +
    ggplot2::theme(axis.text.x = ggplot2::element_text(angle = 20, hjust = 1),
                   legend.position = "bottom")
}

#' Plot reconstructed principal-component trajectories against the truth
#'
#' For one recording, the component trajectories of the original joint
#' angles ("ground truth", projected onto the model's reference PCA) and of
#' one or more reconstructions (the paper's Figure 5).
#'
#' @param object A `handover_model` ([fit_handover()]) whose PCA defines the
#'   components.
#' @param truth A [grasps()] object with the original recordings.
#' @param reconstructions A named list of [grasps()] reconstructions of
#'   `truth`, e.g. `list("6 markers" = r6, "3 markers" = r3)`.
#' @param recording Recording to show (index or id).
#' @param components Components to show.
#' @param ... Unused.
#' @return A ggplot object; its data has columns `time`, `component`,
#'   `score` and `source`.
#' @export
#' @method autoplot handover_model
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:3, objects = 1, trials = 1)
#' fit <- fit_handover(g[-1], n_markers = 3)
#' ggplot2::autoplot(fit, g[1], list(`3 markers` = predict(fit, g[1])))
autoplot.handover_model <- function(object, truth, reconstructions, recording = 1, components = 1:4, ...) {
  model <- object
  call <- rlang::caller_env()
  check_grasps(truth, "truth", call = call)
  if (inherits(reconstructions, "grasps")) reconstructions <- list(reconstruction = reconstructions)
  if (!is.list(reconstructions) || is.null(names(reconstructions))) {
    hm_abort("{.arg reconstructions} must be a named list of grasps objects.", "bad_input",
             argument = "reconstructions", call = call)
  }
  one <- function(g) {
    g <- g[recording]
    s <- handover_scores(model, g)[[1]]
    components <- intersect(components, seq_len(ncol(s)))
    data.frame(time = rep((seq_len(nrow(s)) - 1) / g$rate, length(components)),
               component = factor(rep(colnames(s)[components], each = nrow(s)),
                                  levels = colnames(s)[components]),
               score = as.vector(s[, components, drop = FALSE]))
  }
  parts <- c(list(`ground truth` = truth), reconstructions)
  df <- do.call(rbind, lapply(names(parts), function(nm) cbind(one(parts[[nm]]), source = nm)))
  df$source <- factor(df$source, levels = names(parts))
  ggplot2::ggplot(df, ggplot2::aes(x = .data$time, y = .data$score, colour = .data$source,
                                   linetype = .data$source)) +
    ggplot2::geom_line() +
    ggplot2::facet_wrap(~component, scales = "free_y") +
    ggplot2::labs(x = "time (s)", y = "component score", colour = NULL, linetype = NULL) +
    ggplot2::theme_minimal() +
    ggplot2::theme(legend.position = "bottom")
}

#' Plot a marker ranking
#'
#' Bars of each marker's share of the total influence (the `"ranking"` of a
#' [select_markers()] result).
#'
#' @param object A `marker_ranking`: `attr(select_markers(x), "ranking")`.
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @method autoplot marker_ranking
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:3, objects = 1, trials = 1)
#' ggplot2::autoplot(attr(select_markers(g), "ranking"))
autoplot.marker_ranking <- function(object, ...) {
  df <- as.data.frame(unclass(object)[names(object)])
  df$marker <- factor(df$marker, levels = rev(df$marker))
  ggplot2::ggplot(df, ggplot2::aes(x = .data$share, y = .data$marker)) +
    ggplot2::geom_col() +
    ggplot2::labs(x = sprintf("share of influence (%s-weighted)", attr(object, "weighting")), y = NULL) +
    ggplot2::theme_minimal()
}
