# Hand motion as a video file: the solid still pictures (pose_layers()) drawn
# frame by frame by gganimate, written as a GIF with the magick renderer (both
# in Debian) or, where ffmpeg is installed, as an MP4. Several hands stand
# side by side and keep one clock, so a recorded and a generated grasp can be
# compared in one file.

#' Write hand motion as a GIF or MP4 video, or a light HTML page
#'
#' Draws each frame as [autoplot.hand_pose()] does (solid hands, shaded by
#' depth) and writes the animation with gganimate: a GIF through the magick
#' renderer, or an MP4 through ffmpeg (when the `ffmpeg` program is
#' installed). Several hands (a named list, e.g. recorded against generated)
#' stand side by side and run on one clock at their real timing; a hand
#' whose recording has ended holds its last pose.
#'
#' **Frames and rate.** An MP4 has one frame per recorded frame of the
#' longest recording, thinned evenly to at most `max_frames`, at the
#' recording's rate times the share of frames kept, so it lasts as long as
#' the motion did: a 60-frame recording at 50 Hz gives 60 frames at 50 frames
#' per second (1.2 s); with `max_frames = 30`, 30 frames at 25 per second. A
#' GIF stores each frame's delay in hundredths of a second, so its rate is
#' the highest of 50, 25, 20, 10, 5, 4, 2 and 1 frames per second (at most
#' the recording's rate) that needs no more than `max_frames` frames, and it
#' has `round(n * fps / rate)` frames for `n` recorded frames (at least 2):
#' the same 60-frame recording gives 60 frames at 50 per second, or with
#' `max_frames = 30`, 30 frames at 25 per second. The picture is `width` x
#' `height` pixels.
#'
#' **HTML.** A file ending in `.html` gets one self-contained page instead:
#' every frame an SVG drawing of the finger chains and the palm, shown in
#' turn by a few lines of JavaScript at the recording's rate, with
#' play/pause, one-frame steps back and on (also the arrow keys, and space for
#' play/pause, once the drawing has focus), a playback speed (0.1x to 2x) and
#' a frame slider; no external assets, so it opens offline and can be
#' attached anywhere. Everything sits in one `<div
#' class="handmotion-animation">` that carries its own styles and script and
#' uses no element ids, so it can be copied into another page, several to a
#' page, each playing by itself. It draws one hand (`x` a `grasps`, a matrix, or
#' an array from [forward_kinematics()]), `width` pixels square, and needs
#' neither gganimate nor WebGL ([hand_3d()] is the interactive 3D view).
#'
#' @param x A [grasps()] object (the recording picked by `recording`), one
#'   recording (a frames x DoF matrix), or a named list of these (each one
#'   hand; not for HTML).
#' @param file Output path ending in `.gif`, `.mp4` or `.html`.
#' @param recording For a `grasps`, which recording (index or id).
#' @param view See [autoplot.hand_pose()].
#' @param width,height Size in pixels.
#' @param max_frames Most frames to draw (longer motions are thinned).
#' @param rate Frames per second for matrix input (a `grasps` carries its
#'   own).
#' @param skeleton A [hand_skeleton()].
#' @param ... Passed to [forward_kinematics()].
#' @return `file`, with attributes `frames` (number of video
#'   frames) and `fps`.
#' @seealso [hand_3d()] to turn the hand interactively.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 2, seed = 1)
#' \donttest{
#' f <- write_hand_animation(list(first = g[1], second = g[2]), tempfile(fileext = ".gif"),
#'                           max_frames = 12, width = 320, height = 240)
#' attr(f, "frames")
#' }
#' h <- write_hand_animation(g[1], tempfile(fileext = ".html"), max_frames = 40)
#' file.exists(h)
write_hand_animation <- function(x, file, recording = 1L, view = "oblique", width = 480L, height = 480L,
                                 max_frames = 150L, rate = NULL, skeleton = hand_skeleton(), ...) {
  call <- rlang::caller_env()
  check_skeleton(skeleton, call = call)
  if (!is.character(file) || length(file) != 1L || is.na(file) || !grepl("\\.(gif|mp4|html)$", tolower(file))) {
    hm_abort("{.arg file} must be one path ending in {.file .gif}, {.file .mp4} or {.file .html}.", "bad_input",
             argument = "file", call = call)
  }
  if (grepl("\\.html$", tolower(file))) {
    if (is.list(x) && !inherits(x, "grasps")) {
      hm_abort(c("An HTML page draws one hand; {.arg x} is a list of {length(x)}.",
                 i = "Write a {.file .gif} or {.file .mp4} to compare hands, or use {.fn hand_3d}."),
               "bad_input", argument = "x", call = call)
    }
    check_whole(width, "width", min = 16, max = 4096, call = call)
    check_whole(max_frames, "max_frames", min = 2, max = 10000, call = call)
    return(write_hand_html(x, file, skeleton = skeleton, view = view, recording = recording, fps = rate,
                           max_frames = max_frames, size = width, call = call, ...))
  }
  check_whole(width, "width", min = 16, max = 4096, call = call)
  check_whole(height, "height", min = 16, max = 4096, call = call)
  check_whole(max_frames, "max_frames", min = 2, max = 10000, call = call)
  format <- tolower(sub(".*\\.", "", file))
  if (!requireNamespace("gganimate", quietly = TRUE) || !requireNamespace("magick", quietly = TRUE)) {
    hm_abort("Writing a video needs the gganimate and magick packages.", "missing_dependency", call = call)
  }
  if (format == "mp4" && !nzchar(Sys.which("ffmpeg"))) {
    hm_abort(c("Writing an MP4 needs the {.code ffmpeg} program, which is not installed.",
               i = "Install ffmpeg, or write a {.file .gif}."), "missing_dependency", call = call)
  }
  pick <- if (inherits(x, "grasps")) recording else NULL
  hands <- hand_3d_inputs(x, pick, rate, call)
  rates <- unique(vapply(hands, `[[`, numeric(1), "rate"))
  if (length(rates) > 1L) {
    hm_abort("The hands are recorded at different rates ({.val {rates}} Hz); resample them to one.",
             "bad_input", argument = "x", call = call)
  }
  n_max <- max(vapply(hands, function(h) nrow(h$angles), integer(1)))
  if (n_max < 2L) {
    hm_abort("A video needs recordings of two or more frames; draw a single frame with {.code autoplot(x, type = \"hand\")}.",
             "bad_recording", argument = "x", call = call)
  }
  timing <- video_timing(n_max, rates, max_frames, format)
  ticks <- timing$frames
  fps <- timing$fps
  at <- if (ticks > 1L) 1 + (seq_len(ticks) - 1) * (n_max - 1) / (ticks - 1) else 1
  time_label <- sprintf("%.2f s", (at - 1) / rates)
  poses <- lapply(seq_along(hands), function(i) {
    h <- hands[[i]]
    fr <- pmin(as.integer(round(at)), nrow(h$angles))
    p <- hand_pose(h$angles, frame = unique(fr), skeleton = skeleton, unit = h$unit, ...)
    p <- as.data.frame(unclass(p), stringsAsFactors = FALSE)
    # one copy of the pose per video frame that shows it
    rows <- unlist(lapply(seq_len(ticks), function(k) which(p$frame == fr[k])))
    out <- p[rows, , drop = FALSE]
    out$tick <- rep(seq_len(ticks), each = sum(p$frame == fr[1]))
    out$set <- h$label
    out$id <- paste(h$label, out$tick)
    out$frame <- out$tick
    out
  })
  p <- do.call(rbind, poses)
  pr <- project_pose(p, view, call)
  if (length(hands) > 1L) {
    gap <- diff(range(pr$sx)) * 1.1
    pr$sx <- pr$sx + (match(pr$set, unique(pr$set)) - 1L) * gap
  }
  pr$time <- factor(time_label[pr$tick], levels = time_label)
  g <- ggplot2::ggplot() + pose_layers(pr)
  if (length(hands) == 1L) {
    title <- hands[[1]]$label
  } else {
    # each hand named underneath, as in plot_pose_grid()
    title <- NULL
    labels <- do.call(rbind, lapply(unique(pr$set), function(s) {
      # on two lines ("recorded: id" / "(type)"): side by side, one line each runs into the next
      data.frame(set = sub(" (", "\n(", s, fixed = TRUE), sx = mean(range(pr$sx[pr$set == s])),
                 stringsAsFactors = FALSE)
    }))
    labels$sy <- min(pr$sy) - 0.12 * diff(range(pr$sy))
    g <- g + ggplot2::geom_text(data = labels, ggplot2::aes(x = .data$sx, y = .data$sy, label = .data$set),
                                size = 3, colour = "grey30")
  }
  g <- g + ggplot2::labs(title = title, subtitle = paste0("{current_frame}; ", view_label(view))) +
    gganimate::transition_manual(!!rlang::sym("time"))
  renderer <- if (format == "gif") gganimate::magick_renderer(loop = TRUE) else
    gganimate::ffmpeg_renderer(format = "mp4")
  anim <- gganimate::animate(g, nframes = ticks, fps = fps, width = width, height = height,
                             renderer = renderer, device = "png")
  gganimate::anim_save(file, anim)
  structure(file, frames = ticks, fps = fps)
}

# Frames and frame rate of a video of `n` recorded frames at `rate` Hz (see
# write_hand_animation()'s documentation).
video_timing <- function(n, rate, max_frames, format) {
  if (format == "gif") {
    ok <- c(50, 25, 20, 10, 5, 4, 2, 1)
    ok <- ok[ok <= rate & n * ok / rate <= max_frames]
    fps <- if (length(ok)) ok[1] else 1
    frames <- max(2L, min(as.integer(max_frames), as.integer(round(n * fps / rate))))
    return(list(frames = frames, fps = fps))
  }
  frames <- max(2L, min(n, as.integer(max_frames)))
  list(frames = frames, fps = rate * frames / n)
}
