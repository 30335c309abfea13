# Cutting continuous glove recordings by the CyberGlove switch state
# (GraspDB14 report, sections 3.5 and 3.7): the actor pressed the glove's
# button before and after each task, so runs of constant switch state are the
# trials (ON) and the breaks between them (OFF). A calibration stream has
# 20 or 21 such ON/OFF runs.

#' Runs of constant switch state
#'
#' @param switch An integer or logical vector of switch states, one per frame
#'   (0/1, `FALSE`/`TRUE`).
#' @return A data frame with one row per run: `segment` (running number),
#'   `state` (0 or 1), `start` and `end` (frames, inclusive), `n_frames`.
#' @seealso [segment_by_switch()]
#' @noRd
#' @examples
#' switch_segments(c(1, 1, 1, 0, 0, 1, 1, 0))
switch_segments <- function(switch) {
  call <- rlang::caller_env()
  check_switch(switch, call = call)
  s <- as.integer(switch)
  r <- rle(s)
  end <- cumsum(r$lengths)
  data.frame(segment = seq_along(end), state = r$values, start = end - r$lengths + 1L,
             end = end, n_frames = r$lengths)
}

check_switch <- function(switch, n = NULL, call = rlang::caller_env()) {
  if (!(is.numeric(switch) || is.logical(switch)) || length(switch) == 0L ||
      anyNA(switch) || !all(switch %in% c(0, 1))) {
    hm_abort("{.arg switch} must be a vector of 0/1 switch states without missing values.",
             "bad_input", argument = "switch", call = call)
  }
  if (!is.null(n) && length(switch) != n) {
    hm_abort("{.arg switch} has {length(switch)} state{?s} but the recording has {n} frame{?s}.",
             "bad_input", argument = "switch", call = call)
  }
  invisible(switch)
}

#' Cut continuous recordings into trials by the glove switch state
#'
#' Splits every recording at each change of the CyberGlove switch state.
#' Recordings read by [read_graspdb14()] carry their per-frame switch state
#' (attribute `"switch"` of each recording matrix); for other recordings pass
#' `switch`.
#'
#' @param x A [grasps()] object.
#' @param keep Which runs to keep: `"all"` (default: every ON and every OFF
#'   run, e.g. the 20 or 21 segments of a GraspDB14 calibration stream),
#'   `"on"` (the task executions, i.e. the motion trials) or `"off"`.
#' @param min_frames Runs shorter than this are not returned; they are
#'   counted in the attribute `"dropped"` (a data frame of parent, segment,
#'   state, start, end, n_frames), never silently lost.
#' @param switch Optional switch states: a 0/1 vector when `x` has one
#'   recording, or a list of such vectors, one per recording. Overrides the
#'   recordings' own `"switch"` attributes.
#' @return A `grasps` object with one recording per kept run, ids
#'   `<parent id>_seg<NN>`, the parent's metadata plus columns `parent`,
#'   `segment` (run number within the parent), `switch` (0/1), `start_frame`,
#'   `end_frame` and, when the parent has time stamps, `start_time_s`
#'   (seconds since the parent's first frame). Each segment keeps the matching
#'   slices of the `"switch"` and `"time"` attributes. A recording whose
#'   switch never changes is not cut, with a warning of class
#'   `handmotion_warning_switch_unchanged` naming it (field `recording`).
#' @seealso `switch_segments()`, [read_graspdb14()]
#' @export
#' @examples
#' g <- read_graspdb14(system.file("extdata", "graspdb14", "00_calib-rad-su01.txt",
#'                                 package = "handmotion"))
#' s <- segment_by_switch(g)
#' length(s)
#' table(s$meta$switch)
#' trials <- segment_by_switch(g, keep = "on")
segment_by_switch <- function(x, keep = c("all", "on", "off"), min_frames = 1L, switch = NULL) {
  call <- rlang::caller_env()
  check_grasps(x, call = call)
  keep <- check_choice(keep, arg = "keep", call = call)
  min_frames <- check_whole(min_frames, "min_frames", call = call)
  n <- length(x)
  if (!is.null(switch) && !is.list(switch)) switch <- list(switch)
  if (!is.null(switch) && length(switch) != n) {
    hm_abort("{.arg switch} must give one switch vector per recording ({n}), not {length(switch)}.",
             "bad_input", argument = "switch", call = call)
  }
  recs <- x$recordings
  pieces <- vector("list", n)
  metas <- vector("list", n)
  dropped <- vector("list", n)
  unchanged <- character()
  for (i in seq_len(n)) {
    rec <- recs[[i]]
    id <- x$meta$id[i]
    sw <- if (!is.null(switch)) switch[[i]] else attr(rec, "switch", exact = TRUE)
    if (is.null(sw)) {
      hm_abort(c("Recording {.val {id}} has no switch states.",
                 i = "Read it with {.fn read_graspdb14} or pass {.arg switch}."),
               "no_switch", recording = id, call = call)
    }
    check_switch(sw, n = nrow(rec), call = call)
    seg <- switch_segments(sw)
    if (nrow(seg) == 1L) unchanged <- c(unchanged, id)
    # (the argument `switch` shadows base::switch here, so plain ifs)
    wanted <- if (keep == "all") rep(TRUE, nrow(seg)) else seg$state == as.integer(keep == "on")
    short <- wanted & seg$n_frames < min_frames
    if (any(short)) dropped[[i]] <- cbind(parent = id, seg[short, , drop = FALSE])
    seg <- seg[wanted & !short, , drop = FALSE]
    if (nrow(seg) == 0L) next
    time <- attr(rec, "time", exact = TRUE)
    pieces[[i]] <- lapply(seq_len(nrow(seg)), function(k) {
      rows <- seg$start[k]:seg$end[k]
      out <- rec[rows, , drop = FALSE]
      attr(out, "switch") <- as.integer(sw[rows])
      if (!is.null(time)) attr(out, "time") <- time[rows] - time[rows[1]]
      out
    })
    m <- x$meta[rep(i, nrow(seg)), , drop = FALSE]
    m$id <- sprintf("%s_seg%02d", id, seg$segment)
    m$parent <- id
    m$segment <- seg$segment
    m$switch <- seg$state
    m$start_frame <- seg$start
    m$end_frame <- seg$end
    if (!is.null(time)) m$start_time_s <- time[seg$start]
    metas[[i]] <- m
  }
  # a switch that never changes cuts nothing: the recording comes back whole
  # (or not at all, for the other state), which is rarely what was meant
  if (length(unchanged)) {
    hm_warn(c("The switch never changes in {length(unchanged)} recording{?s}, so {?it was/they were} not cut: {.val {cli::cli_vec(unchanged, list('vec-trunc' = 5))}}.",
              i = "Was the switch pressed while recording? Pass {.arg switch} with its states; otherwise such a recording is one segment."),
            "switch_unchanged", recording = unchanged)
  }
  drop_tab <- do.call(rbind, dropped)
  if (all(vapply(pieces, is.null, logical(1)))) {
    hm_abort(c("No {keep} switch segment{?s} of at least {min_frames} frame{?s} in {.arg x}.",
               i = "{if (is.null(drop_tab)) 0 else nrow(drop_tab)} shorter segment{?s} left out."),
             "no_segments", call = call)
  }
  meta <- do.call(rbind, metas)
  out <- new_grasps(unlist(pieces, recursive = FALSE), meta, x$dofs, x$rate, x$unit, glove = x$glove)
  names(out$recordings) <- out$meta$id
  attr(out, "dropped") <- if (is.null(drop_tab)) NULL else {
    rownames(drop_tab) <- NULL
    drop_tab
  }
  out
}
