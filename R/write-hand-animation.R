# Hand motion as a video file: the solid hands of the still pictures (the
# shape of hand_geometry(), cut into polygons by solid_polygons()) drawn
# frame by frame with grid by a renderer made for frames (R/write-hand-animation-frames.R),
# assembled into a GIF by magick or an MP4 by ffmpeg. Several hands stand
# side by side and keep one clock, so a recorded and a generated grasp can
# be compared in one file.

#' Write hand motion as a GIF or MP4 video, or a light HTML page
#'
#' Draws each frame as [autoplot.hand_pose()] does (the same solid hand,
#' shaded by depth and light) and writes the animation: a GIF (with the
#' magick package) or an MP4 (with the `ffmpeg` program, where it is
#' installed). Several hands (a named list, e.g. recorded against generated)
#' stand side by side, seen from the same view and named underneath, and
#' run on one clock at their real timing; a hand whose recording has ended
#' holds its last pose. The frames are drawn straight onto a PNG device, not
#' through a plot rebuilt per frame: a GIF of one grasp takes about a second.
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
#' neither magick nor WebGL ([hand_3d()] is the interactive 3D view).
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
#' @param hand_colour `"skin"` (default) or `"fingers"` (each finger in its
#'   own colour).
#' @param overwrite Replace `file` if it exists? If not, an existing file is
#'   an error of class `handmotion_error_file_exists` naming it.
#' @param ... Passed to [forward_kinematics()].
#' @return `file`, invisibly.
#' @seealso [hand_3d()] to turn the hand interactively.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 2, seed = 1)
#' if (requireNamespace("magick", quietly = TRUE)) {
#'   f <- write_hand_animation(list(first = g[1], second = g[2]), tempfile(fileext = ".gif"),
#'                             max_frames = 12, width = 320, height = 240)
#'   length(magick::image_read(f))   # frames
#' }
#' h <- write_hand_animation(g[1], tempfile(fileext = ".html"), max_frames = 40)
#' file.exists(h)
write_hand_animation <- function(x, file, recording = 1L, view = "oblique", width = 480L, height = 480L,
                                 max_frames = 150L, rate = NULL, skeleton = hand_skeleton(),
                                 hand_colour = c("skin", "fingers"), overwrite = FALSE, ...) {
  call <- rlang::caller_env()
  check_skeleton(skeleton, call = call)
  hand_colour <- check_choice(hand_colour, arg = "hand_colour", call = rlang::current_env())
  check_flag(overwrite, "overwrite", call = call)
  if (!is.character(file) || length(file) != 1L || is.na(file) || !grepl("\\.(gif|mp4|html)$", tolower(file))) {
    hm_abort("{.arg file} must be one path ending in {.file .gif}, {.file .mp4} or {.file .html}.", "bad_input",
             argument = "file", call = call)
  }
  if (!overwrite && file.exists(file)) {
    hm_abort(c("File {.file {file}} already exists.", i = "Use {.code overwrite = TRUE} to replace it."),
             "file_exists", file = file, argument = "file", call = call)
  }
  if (grepl("\\.html$", tolower(file))) {
    if (is.list(x) && !inherits(x, "grasps")) {
      hm_abort(c("An HTML page draws one hand; {.arg x} is a list of {length(x)}.",
                 i = "Write a {.file .gif} or {.file .mp4} to compare hands, or use {.fn hand_3d}."),
               "bad_input", argument = "x", call = call)
    }
    check_whole(width, "width", min = 16, max = 4096, call = call)
    check_whole(max_frames, "max_frames", min = 2, max = 10000, call = call)
    write_hand_html(x, file, skeleton = skeleton, view = view, recording = recording, fps = rate,
                    max_frames = max_frames, size = width, call = call, ...)
    return(invisible(file))
  }
  check_whole(width, "width", min = 16, max = 4096, call = call)
  check_whole(height, "height", min = 16, max = 4096, call = call)
  check_whole(max_frames, "max_frames", min = 2, max = 10000, call = call)
  format <- tolower(sub(".*\\.", "", file))
  if (format == "gif" && !requireNamespace("magick", quietly = TRUE)) {
    hm_abort("Writing a GIF needs the magick package.", "missing_dependency", call = call)
  }
  if (format == "mp4" && !nzchar(Sys.which("ffmpeg"))) {
    hm_abort(c("Writing an MP4 needs the {.code ffmpeg} program, which is not installed.",
               i = "Install ffmpeg, or write a {.file .gif}."), "missing_dependency", call = call)
  }
  pick <- if (inherits(x, "grasps")) {
    check_some_recordings(x, call = call)
    check_recording_pick(recording, x, call = call)
  }
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
  at <- 1 + (seq_len(ticks) - 1) * (n_max - 1) / (ticks - 1)
  geometry <- hand_geometry(skeleton, hand_colour)
  # every hand at every video frame, projected: one array [frames x hands, joints, 3]
  S <- NULL
  for (i in seq_along(hands)) {
    h <- hands[[i]]
    fr <- pmin(as.integer(round(at)), nrow(h$angles))
    pos <- fk_mapped(h$angles, skeleton, h$unit, h$mapping, frames = fr, ...)[, geometry$joints, , drop = FALSE]
    S <- if (is.null(S)) project_array(pos, view, call) else abind_hands(S, project_array(pos, view, call))
  }
  frame_of <- rep(seq_len(ticks), length(hands))
  hand_of <- rep(seq_along(hands), each = ticks)
  sp <- solid_polygons(S, geometry)
  labels <- NULL
  if (length(hands) > 1L) {
    # side by side, a hand's width apart, each named underneath
    xr <- vapply(seq_along(hands), function(i) range(sp$x[hand_vertices(sp, hand_of == i)]), numeric(2))
    gap <- max(xr[2, ] - xr[1, ]) * 1.1
    shift <- (seq_along(hands) - 1) * gap - xr[1, ] + xr[1, 1]
    sp$x <- sp$x + rep(shift[hand_of[sp$poly$hand]], sp$poly$n)
    labels <- data.frame(x = (xr[1, ] + xr[2, ]) / 2 + shift,
                         # on two lines ("recorded: id" / "(type)")
                         text = sub(" (", "\n(", vapply(hands, `[[`, "", "label"), fixed = TRUE))
  }
  title <- if (length(hands) == 1L) hands[[1]]$label else NULL
  subtitle <- paste0(sprintf("%.2f s", (at - 1) / rates), "; ", view_label(view))
  write_frames(file, format, ticks, timing$fps, width, height, function() {
    draw_hand_frames(sp, frame_of, ticks, if (is.null(title)) NULL else rep(title, ticks), subtitle, labels,
                     width, height)
  }, call)
  invisible(file)
}

# Hands stacked along the first dimension.
abind_hands <- function(a, b) {
  out <- array(0, c(dim(a)[1] + dim(b)[1], dim(a)[2], 3))
  out[seq_len(dim(a)[1]), , ] <- a
  out[dim(a)[1] + seq_len(dim(b)[1]), , ] <- b
  out
}

# Vertex indices of the polygons of the hands `which` (logical over hands).
hand_vertices <- function(sp, which) {
  p <- sp$poly[which[sp$poly$hand], , drop = FALSE]
  rep(p$start, p$n) + sequence(p$n) - 1L
}

# Draw the frames (`draw()`, one page each) as PNG files in a temporary
# folder, then assemble them: a GIF with magick, an MP4 with ffmpeg. The
# GIF's frames share one palette (taken from the first, middle and last
# frames, mapped without dithering: flat shades need none): with a palette
# per frame ImageMagick's GIF writer quantised every frame again, 4.5 of the
# 5 s the assembly took for 40 frames; with one, 0.5 s.
write_frames <- function(file, format, n, fps, width, height, draw, call) {
  dir <- tempfile("hand-frames")
  dir.create(dir)
  on.exit(unlink(dir, recursive = TRUE), add = TRUE)
  pattern <- file.path(dir, "frame%04d.png")
  grDevices::png(pattern, width = width, height = height, res = 72, type = png_type())
  ok <- FALSE
  on.exit(if (!ok) grDevices::dev.off(), add = TRUE, after = FALSE)
  draw()
  grDevices::dev.off()
  ok <- TRUE
  frames <- sprintf(pattern, seq_len(n))
  if (format == "gif") {
    im <- magick::image_read(frames)
    key <- unique(c(1L, (n + 1L) %/% 2L, n))
    palette <- magick::image_quantize(magick::image_append(im[key]), max = 128, dither = FALSE,
                                        colorspace = "sRGB")  # (the default, linear RGB, maps skin to grey)
    im <- magick::image_map(im, palette, dither = FALSE)
    im <- magick::image_animate(im, fps = fps, loop = 0, optimize = TRUE)
    magick::image_write(im, file, format = "gif")
  } else {
    status <- system2(Sys.which("ffmpeg"), c("-y", "-loglevel", "error", "-framerate", format(fps, digits = 10),
                                             "-i", shQuote(pattern), "-c:v", "libx264", "-pix_fmt", "yuv420p",
                                             "-vf", shQuote("pad=ceil(iw/2)*2:ceil(ih/2)*2"), shQuote(file)),
                      stdout = FALSE, stderr = FALSE)
    if (!identical(as.integer(status), 0L) || !file.exists(file)) {
      hm_abort("ffmpeg could not write {.file {file}} (exit status {status}).", "unwritable_file",
               file = file, call = call)
    }
  }
  invisible(file)
}

# The fastest PNG device here: cairo where R has it (anti-aliased), else the default.
png_type <- function() if (capabilities("cairo")) "cairo" else getOption("bitmapType")

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
