# autoplot.grasps(): the pictures of a recorded or generated grasps set,
# beside the other plot-*.R files.

#' Plot a grasps set: joint angles, hands, frame strips, frame counts
#'
#' * `type = "curves"` (default): one panel per DoF, one line per recording,
#'   coloured by grasp type or subject.
#' * `type = "poses"`: one solid hand per group (by default per grasp type)
#'   at one frame, the way the thesis' Appendix A shows the last frame of a
#'   recorded and a generated grasp for each of the 33 types. With `compare`
#'   the sets' hands stand side by side in each panel, in order, named
#'   underneath; several recordings of one group and set are overlaid.
#' * `type = "strip"`: one recording of each set as a row of hands at equally
#'   spaced fractions of its duration (0%, 20%, ..., 100% for `n_frames =
#'   6`), the way the thesis' Tables 5.4 and 5.5 compare a recorded grasp
#'   with a generated one (the columns are fractions of each grasp's own
#'   duration, since the two rarely have the same number of frames); with
#'   `compare` one row per set.
#' * `type = "hand"`: every recording's hand at the given frame(s) (by
#'   default its last), one panel per recording and frame: a time strip of
#'   chosen frames, or the final postures of a few recordings. The drawing is
#'   described in [autoplot.hand_pose()].
#' * `type = "frame_counts"`: a histogram of the number of frames of every
#'   recording, one panel per grasp type, coloured by whether the over-long
#'   rule of [fit_grasp_model()] (`overlong`) removes the recording before
#'   alignment; the rule's threshold is a dashed line (the left half of
#'   Jeppsson (2017) Figure 5.1; [autoplot.grasp_alignment()] shows the
#'   aligned recordings and their warping paths).
#'
#' @param object A [grasps()] object.
#' @param type `"curves"`, `"poses"`, `"hand"`, `"strip"` or `"frame_counts"`.
#' @param colour For `"curves"`: metadata column to colour by, `"grasp"`
#'   (default) or `"subject"` (or any other metadata column).
#' @param dofs For `"curves"`: DoFs to show (names or indices); all by
#'   default.
#' @param max_recordings For `"curves"`: draw at most this many recordings (a
#'   random sample, seeded) so large sets stay readable and fast.
#' @param compare For `"poses"` and `"strip"`: a named list of further
#'   [grasps()] sets drawn beside `object`, e.g. `list(generated =
#'   generate(models))`.
#' @param label For `"poses"` and `"strip"`: the name of `object`'s set
#'   (shown with `compare`; default `"x"`).
#' @param frame For `"poses"`: frame to draw, `"last"` (default), `"first"` or
#'   an index. For `"hand"`: the same, or several frame indices (one panel
#'   each).
#' @param by For `"poses"`: metadata column to group by (one panel per value).
#' @param per_group For `"poses"`: recordings drawn per group and set (the
#'   first ones).
#' @param ncol For `"poses"`: columns of panels; `NULL` (default) lets
#'   [ggplot2::facet_wrap()] choose. Fewer columns give larger hands: the
#'   hands keep their shape, so a grid fills the width of a figure only when
#'   its height allows (about 1.5 times the panel width per row).
#' @param recording For `"strip"`: which recording of each set to draw, an
#'   index or an id (recycled over the sets).
#' @param n_frames For `"strip"`: number of frames drawn per recording (at
#'   least 2).
#' @param grasps For `"frame_counts"`: grasp types to show (names or ids
#'   1-33); all labelled types by default.
#' @param overlong For `"frame_counts"`: the over-long rule, as in
#'   [fit_grasp_model()].
#' @param binwidth For `"frame_counts"`: width of the histogram bins, in
#'   frames.
#' @param skeleton,view For `"poses"`, `"hand"` and `"strip"`: a
#'   [hand_skeleton()] and the viewing direction (see [autoplot.hand_pose()]).
#' @param hand_colour For `"poses"`, `"hand"` and `"strip"`: `"skin"`
#'   (default) or `"fingers"` (one colour per finger, with a legend).
#' @param ... For `"poses"`, `"hand"` and `"strip"`, passed to
#'   [forward_kinematics()].
#' @return A ggplot object. For `"poses"` its layers' data have columns `set`
#'   and `group`; for `"strip"` `set`, `id`, `frame` and `time` (the
#'   fraction of the recording's duration, as a label); for
#'   `"frame_counts"` `id`, `grasp`, `n_frames` and `status` (`"kept"` or
#'   `"over-long"`).
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 3, grasps = c(1, 17), objects = 1, trials = 1, seed = 1)
#' ggplot2::autoplot(g)
#' ggplot2::autoplot(g, type = "poses", view = "radial")
#' ggplot2::autoplot(g, type = "poses", label = "recorded", compare = list(again = g))
#' ggplot2::autoplot(g[1], type = "hand", frame = c(1, 20, 40), view = "palm")
#' ggplot2::autoplot(g, type = "strip", n_frames = 4)
#' ggplot2::autoplot(g, type = "frame_counts")
#' @method autoplot grasps
autoplot.grasps <- function(object, type = c("curves", "poses", "hand", "strip", "frame_counts"),
                            colour = "grasp", dofs = NULL, max_recordings = 200,
                            compare = NULL, label = NULL, frame = "last", by = "grasp", per_group = 1L,
                            ncol = NULL, recording = 1L, n_frames = 6L, grasps = NULL,
                            overlong = c(iqr_mult = 3, median_mult = 1.5), binwidth = 1,
                            skeleton = hand_skeleton(), view = "oblique", hand_colour = c("skin", "fingers"),
                            ...) {
  call <- rlang::caller_env()
  # (the old `grasp = ` would otherwise reach `grasps` by partial matching;
  # `markers` of forward_kinematics() may come through `...`)
  check_renamed_args(names(sys.call()), "autoplot.grasps",
                     own = c(names(formals(autoplot.grasps)), names(formals(forward_kinematics))), call = call)
  type <- check_choice(type, arg = "type", call = rlang::current_env())
  hand_colour <- check_choice(hand_colour, arg = "hand_colour", call = rlang::current_env())
  check_grasps(object, "object", call = call)
  # (the hand pictures check it themselves)
  if (!type %in% c("hand", "poses")) check_some_recordings(object, "object", call = call)
  sets <- function() {
    if (is.null(compare)) return(if (is.null(label)) object else stats::setNames(list(object), label))
    if (!is.list(compare) || inherits(compare, "grasps") || is.null(names(compare)) ||
        any(!nzchar(names(compare))) || !all(vapply(compare, inherits, logical(1), "grasps"))) {
      hm_abort("{.arg compare} must be a named list of {.cls grasps} objects.", "bad_input",
               argument = "compare", call = call)
    }
    c(stats::setNames(list(object), label %||% "x"), compare)
  }
  switch(type,
    curves = plot_grasp_curves(object, colour, dofs, max_recordings, call),
    poses = plot_pose_grid(sets(), frame = frame, by = by, per_group = per_group, skeleton = skeleton,
                           view = view, ncol = ncol, hand_colour = hand_colour, ..., call = call),
    hand = autoplot.hand_pose(hand_pose(object, frame = frame, skeleton = skeleton, ..., call = call),
                              view = view, hand_colour = hand_colour),
    strip = plot_frame_strip(sets(), recording = recording, n_frames = n_frames, skeleton = skeleton,
                             view = view, hand_colour = hand_colour, ..., call = call),
    frame_counts = plot_frame_counts(object, grasps = grasps, rule = as_overlong_rule(overlong, call = call),
                                     binwidth = binwidth, call = call))
}

# Joint-angle curves: one panel per DoF, one line per recording.
plot_grasp_curves <- function(object, colour, dofs, max_recordings, call) {
  if (!colour %in% names(object$meta)) {
    hm_abort("{.arg colour} must name a metadata column ({.val {names(object$meta)}}), not {.val {colour}}.",
             "bad_input", argument = "colour", call = call)
  }
  if (length(object) > max_recordings) {
    keep <- sort(sample_seeded(length(object), max_recordings, seed = 1L))
    object <- object[keep]
  }
  df <- as.data.frame(object)
  df$colour <- object$meta[[colour]][match(df$id, object$meta$id)]
  if (!is.null(dofs)) {
    sel <- if (is.numeric(dofs)) object$dofs[dofs] else dofs
    df <- df[df$dof %in% sel, , drop = FALSE]
  }
  ylab <- switch(object$unit, deg = "angle (degrees)", rad = "angle (radians)", raw = "sensor value")
  ggplot2::ggplot(df, ggplot2::aes(x = .data$time, y = .data$angle, group = .data$id,
                                   colour = .data$colour)) +
    ggplot2::geom_line(alpha = 0.6, linewidth = 0.4) +
    ggplot2::facet_wrap(~dof, scales = "free_y") +
    # few time breaks: with 16 narrow panels the default ones ran together
    ggplot2::scale_x_continuous(n.breaks = 3) +
    ggplot2::labs(x = "time (s)", y = ylab, colour = colour) +
    ggplot2::theme_minimal() +
    ggplot2::theme(legend.position = "bottom")
}

# Draw `k` of `n` indices with a fixed seed without disturbing the caller's RNG.
sample_seeded <- function(n, k, seed) {
  with_seed(seed, sample.int(n, k))
}
