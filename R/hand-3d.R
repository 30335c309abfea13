# The interactive 3D hand: an htmlwidget (inst/htmlwidgets/hand3d.js, on
# three.js vendored from the npm registry) that draws each recording as a
# solid hand and plays it at its own rate. Forward kinematics is done here,
# once; the page only places meshes, so a long recording stays smooth.

#' An interactive 3D hand
#'
#' Draws one or more recordings as solid hands that play at the recordings'
#' real timing: the shape every hand picture of the package draws (see
#' [autoplot.hand_pose()]), a palm spanning the metacarpals from their bases
#' across the carpus, the thumb from its carpometacarpal joint, finger
#' segments that taper, in skin tone or one colour per finger. Hands side by
#' side are seen through one orthographic camera (so from exactly the same
#' direction), each named underneath, in a page you can turn and zoom with the
#' mouse (drag to orbit, wheel to zoom, right-drag to pan), with
#' play/pause, a time slider and a playback speed. It is an
#' [htmlwidget][htmlwidgets::htmlwidgets-package]: it shows in the RStudio or
#' Positron viewer, in knitted HTML documents and in Shiny
#' ([hand_3d_output()], [render_hand_3d()]), and
#' [htmlwidgets::saveWidget()] writes it as a standalone page.
#'
#' @param x What to show: a [grasps()] object (its recordings, see
#'   `recording`), one recording (a frames x DoF matrix of joint angles), or
#'   a named list of these (for example `list(recorded = g[1], generated =
#'   new[1])`), each element one hand.
#' @param recording For a `grasps`, which recordings (indices or ids); by
#'   default all of them. At most 8 hands are drawn.
#' @param layout `"side"` puts the hands side by side; `"overlay"` draws
#'   them on top of each other, each after the first in its own colour and
#'   half transparent (recorded against generated, say).
#' @param limits Colour the joints red in the frames where one of their
#'   DoFs is outside the skeleton's joint limits (the limits of its
#'   `.xmlskel` joints, see [hand_skeleton()]).
#' @param markers Hand-over markers to draw on the hand as small spheres:
#'   marker names (see [select_markers()]; for instance
#'   `select_markers(method = "handpicked")` or the markers a [fit_handover()]
#'   model uses), or
#'   `NULL` for none.
#' @param speed Initial playback speed (0.1, 0.25, 0.5, 1 or 2).
#' @param autoplay,loop Start playing at once; start again at the end. The
#'   viewer draws only while something changes (playing, turning, resizing):
#'   at rest, paused or finished, it costs the browser nothing, and playback
#'   pauses while the widget is scrolled out of view or its tab is hidden (a
#'   widget that autoplays further down a page starts when first seen). So
#'   by default a recording plays once and rests on its last frame; with
#'   `loop = TRUE` it plays on while in view.
#' @param rate Frames per second for matrix input (a `grasps` carries its
#'   own).
#' @param skeleton The [hand_skeleton()] that poses the hands.
#' @param hand_colour `"skin"` (default) or `"fingers"` (each finger in its
#'   own colour).
#' @param view The first view, as in the still pictures (see
#'   [autoplot.hand_pose()]; the default `"oblique"` is their default).
#' @param background Background colour of the scene.
#' @param width,height Size of the widget (CSS units or pixels); `NULL` for
#'   the htmlwidgets defaults.
#' @param elementId Optional id of the widget's element.
#' @param ... Passed to [forward_kinematics()] (`mapping`, `mode`,
#'   `deactivate`).
#' @return An htmlwidget of class `hand3d`.
#' @seealso [write_hand_animation()] for videos and a 2D page without WebGL,
#'   [autoplot.hand_pose()] for still pictures.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 1, grasps = c(2, 17), objects = 1, trials = 1, seed = 1)
#' w <- hand_3d(g, limits = TRUE)
#' w
#' # recorded against generated, one on the other
#' ms <- fit_grasp_models(simulate_grasps(subjects = 4, grasps = 17, seed = 1), seed = 1)
#' hand_3d(list(recorded = g[2], generated = generate(ms, n = 1, seed = 2)), layout = "overlay")
#' # a standalone page
#' f <- tempfile(fileext = ".html")
#' htmlwidgets::saveWidget(w, f, selfcontained = FALSE)
hand_3d <- function(x, recording = NULL, layout = c("side", "overlay"), limits = FALSE, markers = NULL,
                    speed = 1, autoplay = TRUE, loop = FALSE, rate = NULL, skeleton = hand_skeleton(),
                    hand_colour = c("skin", "fingers"), view = "oblique", background = "#f7f7f5",
                    width = NULL, height = NULL, elementId = NULL, ...) {
  call <- rlang::caller_env()
  check_skeleton(skeleton, call = call)
  hand_colour <- check_choice(hand_colour, arg = "hand_colour", call = rlang::current_env())
  layout <- check_choice(layout, arg = "layout", call = call)
  check_flag(limits, "limits", call = call)
  check_flag(autoplay, "autoplay", call = call)
  check_flag(loop, "loop", call = call)
  speed <- check_choice(speed, animation_speeds, "speed", call = call)
  bg <- if (is.character(background) && length(background) == 1L) {
    tryCatch(grDevices::col2rgb(background), error = function(e) NULL)
  }
  if (is.null(bg)) {
    hm_abort("{.arg background} must be one colour (an R colour name or #rrggbb).", "bad_input",
             argument = "background", call = call)
  }
  background <- grDevices::rgb(t(bg), maxColorValue = 255)  # R names ("grey90") are not CSS colours
  # a widget size: NULL, a positive number of pixels or one CSS size ("100%",
  # "30em"); -1 or "a" reached the page as a broken style without a word
  for (arg in c("width", "height")) {
    v <- get(arg)
    ok <- is.null(v) || (is.numeric(v) && length(v) == 1L && is.finite(v) && v > 0) ||
      (is.character(v) && length(v) == 1L && !is.na(v) &&
         grepl("^(auto|inherit|fit-content|[0-9]*\\.?[0-9]+(px|%|em|rem|vh|vw|pt|cm|mm|in|ex|ch)?)$", v))
    if (!ok) {
      hm_abort("{.arg {arg}} must be {.code NULL}, a positive number of pixels or one CSS size such as {.val 100%}, not {describe_value(v)}.",
               "bad_input", argument = arg, call = call)
    }
  }
  rate <- check_number(rate, "rate", min = 0, min_open = TRUE, allow_null = TRUE, call = call)
  # (the unit comes with each hand, so it is not one of the arguments passed on)
  check_dots_for(list(...), forward_kinematics, "forward_kinematics", exclude = c("x", "skeleton", "unit"),
                 call = call)
  hands <- hand_3d_inputs(x, recording, rate, call)
  if (length(hands) > hand_3d_max) {
    hm_abort(c("{length(hands)} hands are too many to show at once; at most {hand_3d_max}.",
               i = "Pick some with {.arg recording} or subset {.arg x}."),
             "bad_input", argument = "recording", call = call)
  }
  rates <- vapply(hands, `[[`, numeric(1), "rate")
  if (length(unique(rates)) > 1L) {
    hm_abort("The hands are recorded at different rates ({.val {unique(rates)}} Hz); resample them to one.",
             "bad_input", argument = "x", call = call)
  }
  marker_set <- if (is.null(markers)) NULL else resolve_marker_set(markers, call = call)
  joints <- skeleton$joints
  pidx <- skeleton_parent_index(skeleton)
  geometry <- hand_geometry(skeleton, hand_colour)
  palette <- c("#4477aa", "#cc6677", "#228833", "#aa3377", "#66ccee", "#ccbb44", "#ee6677", "#bbbbbb")
  recs <- lapply(seq_along(hands), function(i) {
    h <- hands[[i]]
    pos <- fk_mapped(h$angles, skeleton, h$unit, h$mapping, ...)
    pos <- pos[, joints$name, , drop = FALSE]
    list(label = h$label, n = dim(pos)[1],
         colour = if (layout == "overlay" && i > 1L) palette[(i - 2L) %% length(palette) + 1L] else NULL,
         opacity = if (layout == "overlay" && i > 1L) 0.5 else 1,
         pos = round(as.vector(aperm(pos, c(3, 2, 1))), 2),
         outside = if (limits) joint_limit_flags(h, joints$name, skeleton) else NULL,
         markers = if (is.null(marker_set)) NULL else {
           m <- place_markers(pos, marker_set, call = call)
           round(as.vector(t(m)), 2)
         },
         extent = apply(pos, 3, range))
  })
  # the first view is the still pictures' `view` (rows: screen right, up,
  # towards the viewer); side by side, the hands stand a hand's width apart
  # along the screen's right, so at one depth, seen from one direction
  V <- view_matrix(view, call)
  width_mm <- max(vapply(recs, function(r) diff(r$extent[, 1]), numeric(1)),
                  vapply(recs, function(r) diff(r$extent[, 2]), numeric(1)))
  for (i in seq_along(recs)) {
    recs[[i]]$offset <- if (layout == "side") round((i - 1) * 1.1 * width_mm * V[1, ], 2) else c(0, 0, 0)
    recs[[i]]$extent <- NULL
  }
  data <- list(joints = joints$name, parent = ifelse(is.na(pidx), -1L, pidx - 1L),
               # the hand's solid shape, as every picture draws it (colours as
               # #rrggbb: three.js knows no R colour names)
               geometry = hand_geometry_json(geometry),
               marker_radius = round(0.025 * geometry$hand_length, 2),
               camera = list(towards = round(V[3, ], 6), up = round(V[2, ], 6)),
               layout = layout, rate = rates[[1]], speed = speed, autoplay = autoplay, loop = loop,
               background = background, recordings = recs)
  htmlwidgets::createWidget("hand3d", data, width = width, height = height, package = "handmotion",
                            elementId = elementId,
                            sizingPolicy = htmlwidgets::sizingPolicy(defaultWidth = 640, defaultHeight = 420,
                                                                     browser.fill = TRUE, padding = 0))
}

hand_3d_max <- 8L

# Each hand to draw: its angles, unit, rate and label, from a grasps object,
# a matrix, or a named list of either.
hand_3d_inputs <- function(x, recording, rate, call) {
  from_grasps <- function(g, label_prefix = NULL, pick = NULL) {
    check_some_recordings(g, if (is.null(label_prefix)) "x" else paste0("x$", label_prefix), call = call)
    idx <- if (is.null(pick)) seq_along(g) else check_recording_pick(pick, g, several = TRUE, call = call)
    lapply(idx, function(i) {
      m <- g$meta[i, ]
      lab <- paste0(m$id, if (!is.null(m$grasp) && !is.na(m$grasp)) paste0(" (", m$grasp, ")") else "")
      if (!is.null(label_prefix)) lab <- paste0(label_prefix, ": ", lab)
      v <- glove_recording(g, i)   # degrees and joints through the set's glove
      list(angles = v$angles, unit = v$unit, mapping = v$mapping, rate = g$rate, label = lab)
    })
  }
  from_matrix <- function(m, label) {
    if (!is.numeric(m) || !is.matrix(m) || is.null(colnames(m))) {
      hm_abort("{.arg x} must hold recordings: numeric frames x DoF matrices with DoF column names.",
               "bad_input", argument = "x", call = call)
    }
    r <- rate %||% 50
    check_rate(r, call = call)
    list(list(angles = m, unit = NULL, rate = r, label = label))
  }
  hands <- if (inherits(x, "grasps")) {
    check_grasps(x, call = call)
    from_grasps(x, pick = recording)
  } else if (is.matrix(x)) {
    from_matrix(x, "recording")
  } else if (is.list(x) && length(x) && !is.null(names(x)) && all(nzchar(names(x)))) {
    unlist(Map(function(el, nm) {
      if (inherits(el, "grasps")) from_grasps(el, label_prefix = nm) else from_matrix(el, nm)
    }, x, names(x)), recursive = FALSE)
  } else {
    hm_abort("{.arg x} must be a {.cls grasps} object, a recording matrix or a named list of them, not {.obj_type_friendly {x}}.",
             "bad_input", argument = "x", call = call)
  }
  if (!length(hands)) hm_abort("There is no recording to show.", "bad_recording", argument = "x", call = call)
  # every hand has frames and finite angles, checked before any page or
  # video is made (the error names the hand, the frame and the DoF)
  for (h in hands) as_recording_matrix(h$angles, h$label, call)
  hands
}


# Per frame and joint, 1 where a DoF turning that joint is outside its limit.
joint_limit_flags <- function(h, joint_names, skeleton) {
  dofs <- colnames(h$angles)
  factor <- if (identical(h$unit, "rad")) 180 / pi else 1
  lim <- tryCatch(dof_limits(dofs, factor, skeleton, h$mapping), handmotion_error = function(e) NULL)
  n <- nrow(h$angles)
  out <- matrix(0L, length(joint_names), n)
  if (is.null(lim) || !nrow(lim)) return(as.vector(out))
  X <- h$angles[, lim$col, drop = FALSE]
  bad <- sweep(X, 2, lim$lo, "<") | sweep(X, 2, lim$hi, ">")
  for (a in seq_len(nrow(lim))) {
    j <- match(lim$joint[a], joint_names)
    if (!is.na(j)) out[j, bad[, a]] <- 1L
  }
  as.vector(out)
}

#' Shiny bindings for the 3D hand
#'
#' @param outputId Output variable to read the widget from.
#' @param width,height Size (CSS units).
#' @param expr An expression that returns a [hand_3d()] widget.
#' @param env The environment in which to evaluate `expr`.
#' @param quoted Is `expr` a quoted expression?
#' @return An output element (`hand_3d_output()`) or a render function
#'   (`render_hand_3d()`) for a Shiny app.
#' @export
#' @examples
#' if (interactive() && requireNamespace("shiny", quietly = TRUE)) {
#'   g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
#'   shiny::shinyApp(hand_3d_output("hand"), function(input, output) {
#'     output$hand <- render_hand_3d(hand_3d(g))
#'   })
#' }
hand_3d_output <- function(outputId, width = "100%", height = "420px") {
  htmlwidgets::shinyWidgetOutput(outputId, "hand3d", width, height, package = "handmotion")
}

#' @rdname hand_3d_output
#' @export
render_hand_3d <- function(expr, env = parent.frame(), quoted = FALSE) {
  if (!quoted) expr <- substitute(expr)
  htmlwidgets::shinyRenderWidget(expr, hand_3d_output, env, quoted = TRUE)
}
