# Animation of a recording as one self-contained HTML file: every frame is an
# SVG group of finger polylines, and a few lines of JavaScript show one group
# at a time, with play/pause, frame steps, a speed choice and a frame slider.
# No external assets, so the file opens offline and can be attached, and its
# <div class="handmotion-animation"> pasted into another page.

# One recording as a self-contained HTML page (write_hand_animation() with a
# .html file, which documents it; a light 2D page without WebGL: play/pause,
# one-frame steps, also by arrow keys and space, a 0.1x-2x speed and a frame
# slider, in one <div> with its own styles and no element ids, so several
# copies play side by side in one page): x a grasps (one recording picked), a
# frames x DoF matrix or a forward_kinematics() array; at most `max_frames`
# frames (thinned evenly, playback time kept), `size` pixels square.
write_hand_html <- function(x, file, skeleton = hand_skeleton(), view = "oblique", recording = 1L,
                            fps = NULL, max_frames = 300L, size = 420L, title = NULL, ...,
                            call = rlang::caller_env()) {
  check_skeleton(skeleton, call = call)
  if (inherits(x, "grasps")) {
    check_some_recordings(x, call = call)
    recording <- check_recording_pick(recording, x, call = call)
    m <- x$meta[recording, ]
    if (is.null(title)) title <- paste0(m$id, if (!is.na(m$grasp)) paste0(" (", m$grasp, ")") else "")
    if (is.null(fps)) fps <- x$rate
    rec <- as_recording_matrix(x$recordings[[recording]], m$id, call)  # names the recording
    pos <- forward_kinematics(rec, skeleton, unit = x$unit, ...)
  } else if (is.array(x) && length(dim(x)) == 3L) {
    pos <- x
    bad <- which(apply(!is.finite(pos), 1, any))
    if (length(bad)) {
      hm_abort("{.arg x} has missing or infinite positions in {length(bad)} frame{?s}, first frame {bad[1]}.",
               "bad_recording", argument = "x", call = call)
    }
  } else {
    pos <- forward_kinematics(x, skeleton, ...)
  }
  if (is.null(fps)) fps <- 50
  if (is.null(title)) title <- "hand motion"
  check_rate(fps, call = call)
  n <- dim(pos)[1]
  keep <- evenly_spread(n, max_frames)
  pose <- pose_long(structure(pos[keep, , , drop = FALSE], frames = keep), "x", skeleton, call)
  pose <- project_pose(pose, view, call)
  html <- hand_animation_html(pose, skeleton, keep, interval_ms = 1000 * (n / length(keep)) / fps,
                              fps = fps, size = size, title = title)
  writeLines(html, file, useBytes = TRUE)
  invisible(structure(file, frames = length(keep), fps = fps * length(keep) / n))
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
  geometry <- hand_geometry(skeleton)
  groups <- vapply(seq_along(keep), function(k) {
    p <- pose[pose$frame == keep[k], , drop = FALSE]
    lines <- vapply(names(chains), function(f) {
      idx <- match(chains[[f]], p$joint)
      pts <- paste(sprintf("%.1f,%.1f", px(p$sx[idx]), py(p$sy[idx])), collapse = " ")
      sprintf('<polyline points="%s" stroke="%s"/>', pts, finger_colours[[f]])
    }, character(1))
    # the palm's outline of the static pictures (hand_geometry())
    palm_svg <- if (!is.null(geometry$palm)) {
      palm <- palm_points(pose_screen_array(p, geometry)$S, geometry)[1, , ]
      sprintf('<polygon class="palm" points="%s" fill="#e5e5e5" stroke="#b3b3b3" stroke-width="1"/>',
              paste(sprintf("%.1f,%.1f", px(palm[, 1]), py(palm[, 2])), collapse = " "))
    } else ""
    sprintf('<g class="f" data-frame="%d" style="display:none">%s%s</g>', keep[k], palm_svg,
            paste(lines, collapse = ""))
  }, character(1))
  esc <- function(t) gsub("<", "&lt;", gsub("&", "&amp;", t, fixed = TRUE), fixed = TRUE)
  # The drawing and its controls are one <div class="handmotion-animation">
  # that needs nothing from the page around it: the look of the lines is in
  # SVG presentation attributes on the <svg> (inherited, so a page that
  # embeds only the <div> does not lose `fill: none` and draw the fingers
  # as black blobs), and the script finds its own <div> (no element ids, so
  # several animations on one page each play by themselves).
  svg_style <- paste('fill="none" stroke-width="5" stroke-linecap="round" stroke-linejoin="round"',
                     'style="display:block"')
  c("<!DOCTYPE html>", "<html><head><meta charset=\"utf-8\">",
    paste0("<title>", esc(title), "</title>"),
    "<style>body{font-family:sans-serif}</style>",
    "</head><body>",
    sprintf('<div class="handmotion-animation" style="display:inline-block;font:13px sans-serif">'),
    # a bold line, not a heading: copied into a document it must not join its outline
    paste0("<div class=\"hm-title\" style=\"font-weight:bold;font-size:15px;margin:6px 0\">", esc(title), "</div>"),
    sprintf('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" %s>',
            size, size, size, size, svg_style),
    groups, "</svg>",
    paste0('<div style="display:flex;gap:6px;align-items:center;flex-wrap:wrap">',
           '<button class="hm-play" title="play or pause (space)">pause</button>',
           '<button class="hm-back" title="one frame back">&#9664;</button>',
           '<button class="hm-next" title="one frame on">&#9654;</button>',
           '<select class="hm-speed" title="playback speed">',
           paste0('<option value="', animation_speeds, '"', ifelse(animation_speeds == 1, " selected", ""), ">",
                  animation_speeds, "x</option>", collapse = ""),
           "</select></div>"),
    sprintf('<div><input class="hm-slider" type="range" min="0" max="%d" value="0" style="width:%dpx" aria-label="frame"> <span class="hm-label"></span></div>',
            length(keep) - 1L, max(120L, size - 130L)),
    "<script>",
    "(function(root){",
    "var q=function(c){return root.querySelector(c);};",
    "var f=root.querySelectorAll('g.f'),n=f.length,i=0,play=true,acc=0,last=null;",
    "var s=q('.hm-slider'),b=q('.hm-play'),sp=q('.hm-speed'),l=q('.hm-label');",
    sprintf("var dt=%.3f,fps=%s;", interval_ms, format(fps)),
    "function show(k){f[i].style.display='none';i=(k+n)%n;f[i].style.display='';s.value=i;var fr=+f[i].getAttribute('data-frame');l.textContent='frame '+fr+' ('+((fr-1)/fps).toFixed(2)+' s)';}",
    "function setPlay(p){play=p;b.textContent=p?'pause':'play';last=null;acc=0;}",
    "show(0);",
    # a steady clock: frames advance by elapsed time x speed, whatever the timer's jitter
    "setInterval(function(){if(!play)return;var now=performance.now();if(last!==null){acc+=(now-last)*(+sp.value);var k=Math.floor(acc/dt);if(k>0){acc-=k*dt;show(i+k);}}last=now;},15);",
    "b.onclick=function(){setPlay(!play);};",
    "q('.hm-back').onclick=function(){setPlay(false);show(i-1);};",
    "q('.hm-next').onclick=function(){setPlay(false);show(i+1);};",
    "s.oninput=function(){setPlay(false);show(+s.value);};",
    "root.tabIndex=0;root.onkeydown=function(e){if(e.key===' '){setPlay(!play);e.preventDefault();}else if(e.key==='ArrowLeft'){setPlay(false);show(i-1);}else if(e.key==='ArrowRight'){setPlay(false);show(i+1);}};",
    "})(document.currentScript.parentNode);", "</script>", "</div>", "</body></html>")
}

# Playback speeds offered by write_hand_animation()'s HTML page.
animation_speeds <- c(0.1, 0.25, 0.5, 1, 2)

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
