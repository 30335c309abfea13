# A renderer made for video frames: the solid hands of every frame are cut
# into polygons at once (solid_polygons(), the shape of hand_geometry(), as
# in the still pictures), then each frame is one grid.polygon() call on a
# PNG or magick device. Rebuilding a ggplot per frame (gganimate) cost most
# of the 16-28 s a GIF of one grasp took (building, guides, gtable and
# viewports per frame; see bench/bench-animation.R).

# Screen coordinates of posed hands: `pos` [hands, joints, 3] -> [hands,
# joints, 3] of screen x, screen y and depth for `view`.
project_array <- function(pos, view, call = rlang::caller_env()) {
  V <- view_matrix(view, call)
  out <- pos
  for (k in 1:3) out[, , k] <- V[k, 1] * pos[, , 1] + V[k, 2] * pos[, , 2] + V[k, 3] * pos[, , 3]
  out
}

# Draw frames: `sp` from solid_polygons() over all hands, `frame_of` the
# frame of each hand, on the current device of `width` x `height` pixels,
# one page per frame, the same data window on every page (so the hands do
# not jump). `titles`: a title per frame; `labels`: text under the hands
# (data frame x, text), or NULL.
draw_hand_frames <- function(sp, frame_of, n_frames, titles, subtitle, labels = NULL, width, height) {
  poly <- sp$poly
  xr <- range(sp$x)
  yr <- range(sp$y)
  top <- if (is.null(titles)) 26 else 44
  bottom <- if (is.null(labels)) 8 else 34
  side <- 8
  s <- min((width - 2 * side) / diff(xr), (height - top - bottom) / diff(yr))
  # the data window, centred in the space under the titles
  w_px <- diff(xr) * s
  h_px <- diff(yr) * s
  vp <- grid::viewport(x = grid::unit(side + (width - 2 * side) / 2, "points"),
                       y = grid::unit(bottom + (height - top - bottom) / 2, "points"),
                       width = grid::unit(w_px, "points"), height = grid::unit(h_px, "points"),
                       xscale = xr, yscale = yr, clip = "off")
  outline <- grDevices::adjustcolor(hand_outline_colour, 0.55)
  col <- ifelse(poly$lwd > 0, outline, NA)
  # points are pixels: the devices are opened at 72 dpi
  lwd <- pmax(poly$lwd, 0.01) * 2.5
  by_frame <- split(seq_len(nrow(poly)), factor(frame_of[poly$hand], levels = seq_len(n_frames)))
  for (f in seq_len(n_frames)) {
    grid::grid.newpage()
    grid::grid.rect(gp = grid::gpar(col = NA, fill = "white"))
    rows <- by_frame[[f]]
    v <- rep(poly$start[rows], poly$n[rows]) + sequence(poly$n[rows]) - 1L
    grid::pushViewport(vp)
    grid::grid.polygon(sp$x[v], sp$y[v], id = rep(seq_along(rows), poly$n[rows]), default.units = "native",
                       gp = grid::gpar(fill = poly$fill[rows], col = col[rows], lwd = lwd[rows]))
    if (!is.null(labels)) {
      grid::grid.text(labels$text, x = grid::unit(labels$x, "native"), y = grid::unit(0, "npc") - grid::unit(6, "points"),
                      just = c("centre", "top"), gp = grid::gpar(fontsize = 11, col = "grey25", lineheight = 0.95))
    }
    grid::popViewport()
    if (!is.null(titles)) {
      grid::grid.text(titles[f], x = grid::unit(side, "points"), y = grid::unit(1, "npc") - grid::unit(6, "points"),
                      just = c("left", "top"), gp = grid::gpar(fontsize = 13))
    }
    grid::grid.text(subtitle[f], x = grid::unit(side, "points"),
                    y = grid::unit(1, "npc") - grid::unit(if (is.null(titles)) 6 else 26, "points"),
                    just = c("left", "top"), gp = grid::gpar(fontsize = 11, col = "grey30"))
  }
  invisible(NULL)
}
