# Animation of a recording as one self-contained HTML file: every frame is an
# SVG group of finger polylines, and a few lines of JavaScript show one group
# at a time (play/pause and a frame slider). No external assets, so the file
# opens offline and can be attached or embedded anywhere.

#' Animate a hand recording as a self-contained HTML file
#'
#' @param x A recording (numeric frames x DoF matrix with DoF column names),
#'   a [grasps()] object (see `recording`) or an array from
#'   [forward_kinematics()].
#' @param file Output path (`.html`).
#' @param skeleton A [hand_skeleton()].
#' @param view See [autoplot.hand_pose()].
#' @param recording For a `grasps` with several recordings: which one (index
#'   or id).
#' @param fps Playback rate in frames per second of the recording; defaults
#'   to the `grasps` rate, else 50.
#' @param max_frames Longer recordings are thinned evenly to at most this
#'   many frames (playback time is kept).
#' @param size Width and height of the drawing in pixels.
#' @param title Title shown above the drawing.
#' @param ... Passed to [forward_kinematics()] (`mapping`, `mode`,
#'   `deactivate`, `unit`).
#' @return `file`, invisibly.
#' @export
#' @examples
#' rec <- matrix(0, 40, 16, dimnames = list(NULL, hust_dofs$name))
#' rec[, 5:16] <- outer(sin(seq(0, pi, length.out = 40)), rep(80, 12))
#' f <- animate_hand(rec, tempfile(fileext = ".html"))
#' file.exists(f)
animate_hand <- function(x, file, skeleton = hand_skeleton(), view = "oblique", recording = 1L,
                         fps = NULL, max_frames = 300L, size = 420L, title = NULL, ...) {
  call <- rlang::caller_env()
  check_skeleton(skeleton, call = call)
  if (inherits(x, "grasps")) {
    if (is.character(recording)) recording <- match(recording, x$meta$id)
    if (length(recording) != 1L || is.na(recording) || recording < 1L || recording > length(x)) {
      hm_abort("{.arg recording} must pick one of the {length(x)} recording{?s} by index or id, not {describe_value(recording)}.",
               "bad_input", argument = "recording", call = call)
    }
    m <- x$meta[recording, ]
    if (is.null(title)) title <- paste0(m$id, if (!is.na(m$grasp)) paste0(" (", m$grasp, ")") else "")
    if (is.null(fps)) fps <- x$rate
    pos <- forward_kinematics(x$recordings[[recording]], skeleton, unit = x$unit, ...)
  } else if (is.array(x) && length(dim(x)) == 3L) {
    pos <- x
  } else {
    pos <- forward_kinematics(x, skeleton, ...)
  }
  if (is.null(fps)) fps <- 50
  if (is.null(title)) title <- "hand motion"
  check_rate(fps, call = call)
  n <- dim(pos)[1]
  keep <- unique(round(seq(1, n, length.out = min(n, max_frames))))
  pose <- pose_long(structure(pos[keep, , , drop = FALSE], frames = keep), "x", skeleton, call)
  pose <- project_pose(pose, view, call)
  html <- hand_animation_html(pose, skeleton, keep, interval_ms = 1000 * (n / length(keep)) / fps,
                              fps = fps, size = size, title = title)
  writeLines(html, file, useBytes = TRUE)
  invisible(file)
}

hand_animation_html <- function(pose, skeleton, keep, interval_ms, fps, size, title) {
  pad <- 12
  rx <- range(pose$sx)
  ry <- range(pose$sy)
  s <- (size - 2 * pad) / max(diff(rx), diff(ry), 1e-9)
  # centre the hand along its shorter extent (it used to hug the left edge)
  ox <- (size - 2 * pad - diff(rx) * s) / 2
  oy <- (size - 2 * pad - diff(ry) * s) / 2
  px <- function(v) pad + ox + (v - rx[1]) * s
  py <- function(v) size - pad - oy - (v - ry[1]) * s          # SVG y grows downwards
  chains <- skeleton_finger_paths(skeleton)
  groups <- vapply(seq_along(keep), function(k) {
    p <- pose[pose$frame == keep[k], , drop = FALSE]
    lines <- vapply(names(chains), function(f) {
      idx <- match(chains[[f]], p$joint)
      pts <- paste(sprintf("%.1f,%.1f", px(p$sx[idx]), py(p$sy[idx])), collapse = " ")
      sprintf('<polyline points="%s" stroke="%s"/>', pts, finger_colours[[f]])
    }, character(1))
    # the shaded palm, as in the static pictures (autoplot.hand_pose)
    palm <- pose_palm(p)
    palm_svg <- if (nrow(palm)) {
      sprintf('<polygon class="palm" points="%s"/>',
              paste(sprintf("%.1f,%.1f", px(palm$sx), py(palm$sy)), collapse = " "))
    } else ""
    sprintf('<g class="f" data-frame="%d" style="display:none">%s%s</g>', keep[k], palm_svg,
            paste(lines, collapse = ""))
  }, character(1))
  esc <- function(t) gsub("<", "&lt;", gsub("&", "&amp;", t, fixed = TRUE), fixed = TRUE)
  c("<!DOCTYPE html>", "<html><head><meta charset=\"utf-8\">",
    paste0("<title>", esc(title), "</title>"),
    "<style>body{font-family:sans-serif} polyline{fill:none;stroke-width:5;stroke-linecap:round;stroke-linejoin:round} polygon.palm{fill:#e5e5e5;stroke:#b3b3b3;stroke-width:1}</style>",
    "</head><body>", paste0("<h3>", esc(title), "</h3>"),
    sprintf('<svg id="hand" xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">',
            size, size, size, size),
    groups, "</svg>",
    sprintf('<div><button id="pp">pause</button> <input id="slider" type="range" min="0" max="%d" value="0" style="width:%dpx"> <span id="lab"></span></div>',
            length(keep) - 1L, size - 120L),
    "<script>",
    "(function(){var f=document.querySelectorAll('#hand g.f'),i=0,n=f.length,play=true;",
    "var s=document.getElementById('slider'),b=document.getElementById('pp'),l=document.getElementById('lab');",
    sprintf("function show(k){f[i].style.display='none';i=k;f[i].style.display='';s.value=i;l.textContent='frame '+f[i].getAttribute('data-frame')+' ('+((f[i].getAttribute('data-frame')-1)/%s).toFixed(2)+' s)';}", format(fps)),
    "show(0);",
    sprintf("setInterval(function(){if(play)show((i+1)%%n);},%.1f);", interval_ms),
    "b.onclick=function(){play=!play;b.textContent=play?'pause':'play';};",
    "s.oninput=function(){play=false;b.textContent='play';show(+s.value);};",
    "})();", "</script>", "</body></html>")
}

# Joint names from the root out to each fingertip, named by finger.
skeleton_finger_paths <- function(skeleton) {
  j <- skeleton$joints
  pidx <- skeleton_parent_index(skeleton)
  tips <- which(!seq_len(nrow(j)) %in% pidx)
  chains <- skeleton_chains(skeleton)
  paths <- lapply(tips, function(t) {
    path <- t
    while (!is.na(pidx[path[1]])) path <- c(pidx[path[1]], path)
    j$name[path]
  })
  names(paths) <- chains[tips]
  paths
}
