# Pictures of a fitted grasp model, after the thesis' figures: 5.4 (warped
# samples with the mean and mean +- FPCs), 5.5 (a sample and its projection),
# 5.6 (mixture density contours of every DoF) and the warping functions of
# 5.1/5.2. Data layers need the model's kept alignment (keep_data = TRUE).

#' Plot a grasp model
#'
#' * `type = "fpca"` (thesis Figure 5.4): the warped training curves in grey,
#'   the mean curve in red and the mean plus and minus two standard deviations
#'   of each FPC's scores times that FPC (dashed), one panel per DoF.
#' * `type = "projection"` (Figure 5.5): one recording warped to the model's
#'   time (grey) and its projection on the FPCs (red), one panel per DoF. The
#'   recording is one of the model's training recordings, or from `new_data`.
#' * `type = "mixture"` (Figure 5.6): density contours of each DoF's Gaussian
#'   mixture over its two FPC scores (levels relative to each DoF's peak
#'   density), with the training scores as points.
#' * `type = "warps"`: the warping functions (original frame against template
#'   frame) in grey, their mean in red.
#' * `type = "alignment"` (Figures 5.1 and 5.2): the frame counts of the
#'   aligned recordings and their warping paths, degenerate ones in red;
#'   [autoplot.grasp_alignment()] of `object$alignment` draws one panel.
#' * `type = "dependence"`: the correlation between the DoFs' first FPC
#'   scores the model generates with, as a heat map: the Gaussian copula's
#'   for `dependence = "copula"`, the kernel density's shrunk score
#'   correlation for `dependence = "kernel"`, the identity for the thesis' independent
#'   model (see [fit_grasp_model()]).
#'
#' @param object A `grasp_model` from [fit_grasp_model()].
#' @param type `"fpca"`, `"projection"`, `"mixture"`, `"warps"`,
#'   `"alignment"` or `"dependence"`.
#' @param dof DoFs to show (names or indices); all by default.
#' @param recording For `"projection"`: which recording (index or id) of the
#'   training data, or of `new_data` when given.
#' @param new_data Optional [grasps()] object holding the recording to project.
#' @param max_recordings Draw at most this many training curves.
#' @param ... Unused.
#' @return A ggplot object.
#' @export
#' @method autoplot grasp_model
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 3, objects = 2, trials = 2, seed = 1)
#' m <- fit_grasp_model(g, seed = 1)
#' ggplot2::autoplot(m, dof = c("MCP2", "PIP2"))
#' ggplot2::autoplot(m, type = "projection", dof = 1:4)
#' ggplot2::autoplot(m, type = "mixture", dof = 1:4)
#' mc <- fit_grasp_model(g, seed = 1, dependence = "copula")
#' ggplot2::autoplot(mc, type = "dependence")
autoplot.grasp_model <- function(object, type = c("fpca", "projection", "mixture", "warps", "alignment",
                                                  "dependence"),
                                 dof = NULL, recording = 1, new_data = NULL, max_recordings = 100, ...) {
  check_renamed_args(...names(), "autoplot.grasp_model", call = rlang::current_env())
  type <- check_choice(type, arg = "type", call = rlang::current_env())
  check_grasp_model(object, "object", "be drawn", call = rlang::current_env())
  dofs <- plot_model_dofs(object, dof)
  switch(type,
    fpca = plot_model_fpca(object, dofs, max_recordings),
    projection = plot_model_projection(object, dofs, recording, new_data),
    mixture = plot_model_mixture(object, dofs),
    warps = plot_model_warps(object, max_recordings),
    alignment = {
      plot_model_needs_data(object, "alignment")
      autoplot.grasp_alignment(object$alignment)
    },
    dependence = plot_model_dependence(object, dofs))
}

plot_model_dependence <- function(object, dofs) {
  R <- dependence_matrix(object)[dofs, dofs, drop = FALSE]
  d <- data.frame(a = factor(rep(dofs, length(dofs)), levels = dofs),
                  b = factor(rep(dofs, each = length(dofs)), levels = rev(dofs)), r = as.vector(R))
  how <- switch(object$dependence$type %||% "independent", copula = "Gaussian copula",
                kernel = "kernel density (shrunk score correlation)", "independent (the thesis' model)")
  ggplot2::ggplot(d, ggplot2::aes(.data$a, .data$b, fill = .data$r)) +
    ggplot2::geom_tile(colour = "white") +
    ggplot2::scale_fill_gradient2(low = "#2166ac", mid = "white", high = "#b2182b", limits = c(-1, 1),
                                  name = "r") +
    ggplot2::coord_equal() +
    ggplot2::labs(x = NULL, y = NULL,
                  title = object$grasp,
                  subtitle = paste("correlation of the DoFs' first FPC scores:",
                                   how)) +
    ggplot2::theme_minimal(base_size = 11) +
    ggplot2::theme(axis.text.x = ggplot2::element_text(angle = 90, vjust = 0.5, hjust = 1))
}

plot_model_dofs <- function(object, dof) {
  if (is.null(dof)) return(object$dofs)
  sel <- if (is.numeric(dof)) object$dofs[dof] else as.character(dof)
  bad <- is.na(sel) | !sel %in% object$dofs
  if (any(bad)) {
    unknown <- as.character(dof[bad])
    hm_abort(c("Unknown DoF{?s} {.val {unknown}}.", i = "The model has {.val {object$dofs}}."),
             "bad_input", argument = "dof")
  }
  sel
}

plot_model_needs_data <- function(object, what) {
  if (is.null(object$alignment)) {
    hm_abort(c("This plot needs the model's {what}, but the model was fitted with {.code keep_data = FALSE}.",
               i = "Refit with {.code keep_data = TRUE}, or give {.arg new_data}."),
             "bad_input", argument = "object")
  }
}

# Long data frame of L x (selected DoFs) curves.
curves_long <- function(M, dofs, frame, group, kind) {
  data.frame(frame = rep(frame, times = length(dofs)), dof = factor(rep(dofs, each = length(frame)), levels = dofs),
             value = as.vector(M[, dofs, drop = FALSE]), group = group, kind = kind,
             stringsAsFactors = FALSE)
}

plot_model_fpca <- function(object, dofs, max_recordings) {
  L <- object$target_length
  frame <- seq_len(L)
  parts <- list()
  if (!is.null(object$alignment)) {
    W <- object$alignment$warped
    keep <- seq_len(min(dim(W)[1], max_recordings))
    parts <- lapply(keep, function(i) {
      M <- matrix(W[i, , ], L, dimnames = list(NULL, object$dofs))
      curves_long(M, dofs, frame, paste0("rec", i), "sample")
    })
  }
  B <- model_basis(object)
  scores <- model_scores(object)
  parts[[length(parts) + 1L]] <- curves_long(B$mean, dofs, frame, "mean", "mean")
  for (c in seq_len(object$settings$ncomp)) {
    sdv <- apply(matrix(scores[, , c], object$n_used), 2, stats::sd)
    names(sdv) <- object$dofs
    P <- matrix(B$components[, , c], L, dimnames = list(NULL, object$dofs))
    for (sgn in c(1, -1)) {
      M <- B$mean + sgn * 2 * sweep(P, 2, sdv, "*")
      parts[[length(parts) + 1L]] <- curves_long(M, dofs, frame, sprintf("FPC%d%s", c, if (sgn > 0) "+" else "-"),
                                                 sprintf("mean \u00b1 2 sd x FPC%d", c))
    }
  }
  df <- do.call(rbind, parts)
  samples <- df[df$kind == "sample", , drop = FALSE]
  model <- df[df$kind != "sample", , drop = FALSE]
  model$kind <- factor(model$kind, levels = unique(model$kind))
  ggplot2::ggplot(mapping = ggplot2::aes(x = .data$frame, y = .data$value, group = .data$group)) +
    ggplot2::geom_line(data = samples, colour = "grey70", linewidth = 0.3) +
    # one colour per curve kind: two red dash patterns were hard to tell apart
    ggplot2::geom_line(data = model, ggplot2::aes(linetype = .data$kind, colour = .data$kind), linewidth = 0.6) +
    ggplot2::scale_colour_manual(values = stats::setNames(
      c("red", rep_len(c("#E69F00", "#0072B2", "#009E73", "#CC79A7"), nlevels(model$kind) - 1L)),
      levels(model$kind))) +
    ggplot2::scale_linetype_manual(values = stats::setNames(
      c("solid", rep_len(c("dashed", "dotdash", "dotted", "longdash"), nlevels(model$kind) - 1L)),
      levels(model$kind))) +
    ggplot2::facet_wrap(~dof, scales = "free_y") +
    ggplot2::labs(x = "warped frame", y = plot_angle_label(object$unit), linetype = NULL, colour = NULL,
                  title = sprintf("%s: FPCA of each DoF", object$grasp),
                  subtitle = "grey: warped training recordings") +
    ggplot2::theme_minimal() + ggplot2::theme(legend.position = "bottom")
}

plot_model_projection <- function(object, dofs, recording, new_data) {
  if (is.null(new_data)) {
    plot_model_needs_data(object, "training recordings")
    ids <- object$ids
    i <- if (is.character(recording)) match(recording, ids) else recording
    if (length(i) != 1L || is.na(i) || i < 1 || i > length(ids)) {
      hm_abort("{.arg recording} must pick one of the model's {length(ids)} training recording{?s}.",
               "bad_input", argument = "recording")
    }
    warped <- matrix(object$alignment$warped[i, , ], object$target_length, dimnames = list(NULL, object$dofs))
    S <- matrix(model_scores(object)[i, , ], length(object$dofs))
    id <- ids[i]
  } else {
    check_grasps(new_data, arg = "new_data")
    pr <- project(object, new_data[recording])
    warped <- pr$warped[[1]]
    S <- matrix(pr$scores[1, , ], length(object$dofs))
    id <- pr$ids[1]
  }
  L <- object$target_length
  B <- model_basis(object)
  fitted <- B$mean
  for (j in seq_along(object$dofs)) {
    fitted[, j] <- fitted[, j] + matrix(B$components[, j, ], L) %*% S[j, ]
  }
  frame <- seq_len(L)
  df <- rbind(curves_long(warped, dofs, frame, "sample", "sample (warped)"),
              curves_long(fitted, dofs, frame, "projection", "projection on the FPCs"))
  df$kind <- factor(df$kind, levels = c("sample (warped)", "projection on the FPCs"))
  ggplot2::ggplot(df, ggplot2::aes(x = .data$frame, y = .data$value, colour = .data$kind)) +
    ggplot2::geom_line(linewidth = 0.6) +
    ggplot2::scale_colour_manual(values = c("grey50", "red")) +
    ggplot2::facet_wrap(~dof, scales = "free_y") +
    ggplot2::labs(x = "warped frame", y = plot_angle_label(object$unit), colour = NULL,
                  title = sprintf("%s: recording %s and its projection", object$grasp, id)) +
    ggplot2::theme_minimal() + ggplot2::theme(legend.position = "bottom")
}

plot_model_mixture <- function(object, dofs, grid = 50L) {
  if (object$settings$ncomp < 2L) {
    hm_abort("Mixture contours need 2 FPCs per DoF; this model has {object$settings$ncomp}.",
             "bad_input", argument = "type")
  }
  pts <- list()
  dens <- list()
  for (d in dofs) {
    S <- matrix(object$fpca[[d]]$scores[, 1:2], object$n_used)
    pts[[d]] <- data.frame(dof = d, a1 = S[, 1], a2 = S[, 2])
    g <- object$gmm[[d]]
    if (isTRUE(g$point_mass)) next
    r1 <- range(S[, 1]) + c(-0.25, 0.25) * max(diff(range(S[, 1])), 1e-8)
    r2 <- range(S[, 2]) + c(-0.25, 0.25) * max(diff(range(S[, 2])), 1e-8)
    xy <- expand.grid(a1 = seq(r1[1], r1[2], length.out = grid), a2 = seq(r2[1], r2[2], length.out = grid))
    gm <- g
    if (ncol(gm$means) > 2L) {
      gm$means <- gm$means[, 1:2, drop = FALSE]
      gm$covs <- gm$covs[1:2, 1:2, , drop = FALSE]
    }
    z <- gmm_density(gm, as.matrix(xy))
    # relative to each DoF's peak, so one set of levels suits every panel
    dens[[d]] <- data.frame(dof = d, xy, density = z / max(z))
  }
  pts <- do.call(rbind, pts)
  pts$dof <- factor(pts$dof, levels = dofs)
  p <- ggplot2::ggplot(mapping = ggplot2::aes(x = .data$a1, y = .data$a2))
  if (length(dens)) {
    dens <- do.call(rbind, dens)
    dens$dof <- factor(dens$dof, levels = dofs)
    p <- p + ggplot2::geom_contour(data = dens, ggplot2::aes(z = .data$density), colour = "steelblue",
                                   breaks = c(0.02, 0.1, 0.25, 0.5, 0.75, 0.95))
  }
  p + ggplot2::geom_point(data = pts, size = 0.6, colour = "grey40") +
    ggplot2::facet_wrap(~dof, scales = "free") +
    ggplot2::labs(x = "score on FPC1", y = "score on FPC2",
                  title = sprintf("%s: Gaussian mixtures of the FPC scores", object$grasp)) +
    ggplot2::theme_minimal()
}

plot_model_warps <- function(object, max_recordings) {
  L <- object$target_length
  frame <- seq_len(L)
  df <- data.frame(frame = frame, value = warp_basis(object)$mean, group = "mean", kind = "mean")
  if (!is.null(object$alignment)) {
    W <- object$alignment$warps
    keep <- seq_len(min(nrow(W), max_recordings))
    df <- rbind(data.frame(frame = rep(frame, times = length(keep)), value = as.vector(t(W[keep, , drop = FALSE])),
                           group = rep(rownames(W)[keep], each = L), kind = "recording"), df)
  }
  ggplot2::ggplot(df, ggplot2::aes(x = .data$frame, y = .data$value, group = .data$group)) +
    ggplot2::geom_line(data = df[df$kind == "recording", , drop = FALSE], colour = "grey60", linewidth = 0.3) +
    ggplot2::geom_line(data = df[df$kind == "mean", , drop = FALSE], colour = "red", linewidth = 0.8) +
    ggplot2::labs(x = "template frame", y = "original frame",
                  title = sprintf("%s: warping functions (%s)", object$grasp, object$warping$method)) +
    ggplot2::theme_minimal()
}

plot_angle_label <- function(unit) {
  switch(unit, deg = "angle (degrees)", rad = "angle (radians)", raw = "sensor value", "value")
}
