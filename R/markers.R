# Virtual optical markers for sparse-marker hand-over (Wheatland, Joerg and
# Zordan). Markers are computed from joint angles by forward kinematics
# (R/kinematics.R); this file only places them on the skeleton and ranks them
# (the paper's Algorithm 1). Reconstruction lives in R/handover.R.

#' The virtual optical marker set of the hand
#'
#' The full marker set used to record the reference database in the hand-over
#' method of Wheatland, Joerg and Zordan (their Figure 3, "full set"): 13
#' markers on the hand and 3 on the lower forearm, which acts as the root link.
#'
#' The paper shows the markers only in a drawing, so the placement is our
#' reading of it: the five fingertips, the five middle knuckles (the thumb's
#' IP joint and the PIP joints of the four fingers) and three base knuckles
#' (thumb MCP, index MCP and little-finger MCP, which outline the palm).
#'
#' Forward kinematics gives joint centres only, so a marker is placed on the
#' bone from `joint` toward `toward` at `fraction` of its length (0 = on the
#' joint), plus a fixed offset `x`, `y`, `z` (mm) in the root frame. The base
#' knuckle markers of the index and little fingers sit at 0.2 along the
#' proximal phalanx: a marker exactly on a finger's MCP centre would not move
#' relative to the root in a skeleton without palm joints, and a skin marker
#' over the knuckle does follow the phalanx.
#'
#' The three forearm markers ride the root link. Marker positions are
#' expressed relative to the root link (the paper's correction for gross arm
#' motion), so the forearm markers are constant; they are kept for drawing and
#' completeness but excluded from ranking and reconstruction.
#'
#' @return A data frame with one row per marker: `marker` (name), `segment`
#'   (`"hand"` or `"forearm"`), `joint` (skeleton joint it rides on), `toward`
#'   (joint the bone points to, or `NA`), `fraction`, and `x`, `y`, `z`
#'   (offset in mm).
#' @noRd
#' @examples
#' hand_marker_set()
hand_marker_set <- function() {
  hand <- data.frame(
    marker = c("thumb_tip", "index_tip", "middle_tip", "ring_tip", "little_tip",
               "thumb_ip", "index_pip", "middle_pip", "ring_pip", "little_pip",
               "thumb_mcp", "index_mcp", "little_mcp"),
    joint = c("th-tip", "if-tip", "mf-tip", "rf-tip", "lf-tip",
              "th-ip", "if-pip", "mf-pip", "rf-pip", "lf-pip",
              "th-mcp", "if-mcp", "lf-mcp"),
    toward = c(rep(NA, 10), NA, "if-pip", "lf-pip"),
    fraction = c(rep(0, 11), 0.2, 0.2),
    stringsAsFactors = FALSE
  )
  hand$segment <- "hand"
  hand$x <- 0
  hand$y <- 0
  hand$z <- 0
  # Three markers on the lower forearm, proximal to the wrist (the skeleton's
  # fingers point along -y, so the forearm lies along +y).
  arm <- data.frame(marker = c("forearm_radial", "forearm_ulnar", "forearm_dorsal"),
                    joint = "root", toward = NA_character_, fraction = 0,
                    segment = "forearm", x = c(25, -25, 0), y = c(60, 60, 80),
                    z = c(0, 0, 15), stringsAsFactors = FALSE)
  out <- rbind(hand, arm)
  out[c("marker", "segment", "joint", "toward", "fraction", "x", "y", "z")]
}

#' Hand-picked six-marker set (after Hoyet et al. 2012)
#'
#' The manually chosen baseline the hand-over paper compares against: the tips
#' of the thumb, index and little finger, the thumb IP joint and the index and
#' little-finger base knuckles. Like the set in the paper it has no marker on
#' the middle and ring fingers, whose motion must then be inferred.
#'
#' @return A character vector of six marker names from `hand_marker_set()`.
#' @noRd
#' @examples
#' handpicked_markers()
handpicked_markers <- function() {
  c("thumb_tip", "index_tip", "little_tip", "thumb_ip", "index_mcp", "little_mcp")
}

#' Virtual marker positions from joint angles
#'
#' Runs [forward_kinematics()] and places each marker of `markers` on the
#' skeleton (see `hand_marker_set()`). Positions are in mm, relative to the
#' root link.
#'
#' @param x A frames x DoF matrix of joint angles, or a [grasps()] object.
#' @param skeleton A `hand_skeleton` (default [hand_skeleton()]).
#' @param markers The marker set: a data frame like `hand_marker_set()`, or
#'   marker names (rows of `hand_marker_set()`). By default the 13 hand
#'   markers; the forearm markers are constant in the root frame and are only
#'   included when asked for by name or with `forearm = TRUE`.
#' @param forearm Include the three forearm markers.
#' @param ... Passed to [forward_kinematics()] (e.g. `mapping`).
#' @return For a matrix, a frames x (3 * markers) matrix with columns
#'   `<marker>.x`, `<marker>.y`, `<marker>.z`; for a grasps object a list of
#'   such matrices, named by recording id. Users reach it as
#'   `forward_kinematics(x, markers = )`.
#' @noRd
#' @examples
#' ang <- matrix(0, 2, 16, dimnames = list(NULL, hust_dofs$name))
#' ang[2, ] <- 40
#' m <- markers_from_angles(ang)
#' m[, c("index_tip.x", "index_tip.y", "index_tip.z")]
markers_from_angles <- function(x, skeleton = hand_skeleton(), markers = NULL,
                                forearm = FALSE, ...) {
  call <- rlang::caller_env()
  check_dots_for(list(...), forward_kinematics, "forward_kinematics", exclude = c("x", "skeleton"),
                 call = call)
  forearm <- check_flag(forearm, "forearm", call = call)
  ms <- resolve_marker_set(markers, forearm = forearm, call = call)
  if (inherits(x, "grasps")) {
    pos <- forward_kinematics(x, skeleton = skeleton, ...)
    out <- lapply(pos, place_markers, ms = ms, call = call)
    names(out) <- x$meta$id
    return(out)
  }
  if (!is.matrix(x) || !is.numeric(x)) {
    hm_abort("{.arg x} must be a frames x DoF numeric matrix or a {.cls grasps} object, not {.obj_type_friendly {x}}.",
             "bad_input", argument = "x", call = call)
  }
  place_markers(forward_kinematics(x, skeleton = skeleton, ...), ms, call = call)
}

# Marker set as a data frame, from NULL (13 hand markers), names or a data frame.
resolve_marker_set <- function(markers, forearm = FALSE, call = rlang::caller_env()) {
  full <- hand_marker_set()
  if (is.null(markers)) {
    return(if (forearm) full else full[full$segment == "hand", , drop = FALSE])
  }
  if (is.data.frame(markers)) {
    need <- c("marker", "joint", "toward", "fraction", "x", "y", "z")
    miss <- setdiff(need, names(markers))
    if (length(miss)) {
      hm_abort("The marker set {.arg markers} lacks column{?s} {.val {miss}}.", "bad_markers",
               argument = "markers", column = miss, call = call)
    }
    return(markers)
  }
  check_marker_names(markers, call = call)
  full[match(markers, full$marker), , drop = FALSE]
}

# Marker names must be known, unique and non-empty.
check_marker_names <- function(markers, arg = "markers", call = rlang::caller_env()) {
  full <- hand_marker_set()$marker
  if (!is.character(markers) || length(markers) == 0L || anyNA(markers)) {
    hm_abort("{.arg {arg}} must be marker names from {.fn hand_marker_set}, not {.obj_type_friendly {markers}}.",
             "bad_markers", argument = arg, call = call)
  }
  bad <- setdiff(markers, full)
  if (length(bad)) {
    hm_abort(c("{.arg {arg}} has unknown marker{?s} {.val {bad}}.", i = "Known markers: {.val {full}}."),
             "bad_markers", argument = arg, call = call)
  }
  if (anyDuplicated(markers)) {
    hm_abort("{.arg {arg}} gives marker{?s} {.val {unique(markers[duplicated(markers)])}} more than once.",
             "bad_markers", argument = arg, call = call)
  }
  invisible(markers)
}

# Column names of a marker matrix for the given marker names.
marker_columns <- function(markers) {
  paste0(rep(markers, each = 3), c(".x", ".y", ".z"))
}

# Place markers on an FK array [frames, joints, 3].
place_markers <- function(pos, ms, call = rlang::caller_env()) {
  jn <- dimnames(pos)[[2]]
  need <- unique(c(ms$joint, stats::na.omit(ms$toward)))
  miss <- setdiff(need, jn)
  if (length(miss)) {
    hm_abort(c("{.arg skeleton} has no joint{?s} {.val {miss}} for the markers.",
               i = "Markers ride on the joints of GraspDB14's default skeleton."),
             "bad_markers", argument = "skeleton", joint = miss, call = call)
  }
  nf <- dim(pos)[1]
  out <- matrix(0, nf, 3 * nrow(ms), dimnames = list(NULL, marker_columns(ms$marker)))
  for (i in seq_len(nrow(ms))) {
    p <- matrix(pos[, ms$joint[i], ], nf, 3)
    if (!is.na(ms$toward[i]) && ms$fraction[i] != 0) {
      q <- matrix(pos[, ms$toward[i], ], nf, 3)
      p <- p + ms$fraction[i] * (q - p)
    }
    out[, 3 * i - (2:0)] <- sweep(p, 2, c(ms$x[i], ms$y[i], ms$z[i]), "+")
  }
  out
}

# Stack the marker matrices of a grasps object (or accept a matrix, a data
# frame or a list of marker matrices with the same columns).
stack_markers <- function(x, skeleton, arg = "reference", call = rlang::caller_env(), ...) {
  if (inherits(x, "grasps")) x <- markers_from_angles(x, skeleton = skeleton, ...)
  if (is.data.frame(x)) x <- as.matrix(x)
  what <- "a {.cls grasps} object or a numeric frames x (3 * markers) marker matrix (or a list of them),"
  if (is.list(x)) {
    if (length(x) == 0L) {
      hm_abort(paste("{.arg {arg}} must be", what, "not an empty list."), "bad_input",
               argument = arg, call = call)
    }
    for (i in seq_along(x)) {
      if (!is.matrix(x[[i]]) || !is.numeric(x[[i]])) {
        hm_abort(paste("{.arg {arg}[[{i}]]} must be a numeric marker matrix, not {describe_value(x[[i]])}."),
                 "bad_markers", argument = arg, recording = i, call = call)
      }
      if (!identical(colnames(x[[i]]), colnames(x[[1]]))) {
        hm_abort("{.arg {arg}[[{i}]]} has other columns than {.arg {arg}[[1]]}: every marker matrix needs the same markers in the same order.",
                 "bad_markers", argument = arg, recording = i, call = call)
      }
    }
    x <- do.call(rbind, x)
  }
  if (!is.matrix(x) || !is.numeric(x)) {
    hm_abort(paste("{.arg {arg}} must be", what, "not {describe_value(x)}."),
             "bad_input", argument = arg, call = call)
  }
  x
}

# select_markers(method = "ranked")'s ranking (the paper's Algorithm 1,
# documented there): a data frame of class marker_ranking, most influential
# marker first, with the eigenvalues and the weighting as attributes.
rank_markers <- function(reference, weighting = c("eigenvalue", "equal"),
                         n_components = NULL, skeleton = hand_skeleton(), ..., arg = "reference",
                         call = rlang::caller_env()) {
  weighting <- check_choice(weighting, c("eigenvalue", "equal"), arg = "weighting", call = call)
  check_dots_for(list(...), forward_kinematics, "forward_kinematics", exclude = c("x", "skeleton"),
                 call = call)
  m <- stack_markers(reference, skeleton, arg = arg, call = call, ...)
  markers <- marker_names_of(m, arg = arg, call = call)
  check_marker_names(markers, arg = arg, call = call)
  # the forearm markers are constant on the root link (documented)
  keep <- markers %in% hand_marker_set()$marker[hand_marker_set()$segment == "hand"]
  if (!any(keep)) {
    hm_abort("{.arg {arg}} has no hand markers to rank, only {.val {markers}}.",
             "bad_markers", argument = arg, call = call)
  }
  if (!all(keep)) {
    m <- m[, marker_columns(markers[keep]), drop = FALSE]
    markers <- markers[keep]
  }
  if (nrow(m) < 2L) {
    hm_abort("Ranking needs at least two frames of marker positions; {.arg {arg}} has {nrow(m)}.",
             "reference_too_small", argument = arg, call = call)
  }
  bad <- which(!is.finite(m), arr.ind = TRUE)
  if (nrow(bad)) {
    hm_abort(c("{.arg {arg}} has {nrow(bad)} missing or infinite marker coordinate{?s}.",
               x = "First in column {.val {colnames(m)[bad[1, 2]]}}, frame {bad[1, 1]}."),
             "bad_markers", argument = arg, column = colnames(m)[bad[1, 2]],
             line = bad[1, 1], call = call)
  }
  e <- eigen(stats::cov(m), symmetric = TRUE)
  val <- pmax(e$values, 0)
  d <- length(val)
  w <- if (weighting == "eigenvalue") val else {
    nc <- check_whole(n_components, "n_components", max = d, allow_null = TRUE, call = call) %||%
      floor(d / 2)
    rep(c(1, 0), c(nc, d - nc))
  }
  # |coefficient x weight| summed over components, then over x, y, z
  per_coord <- abs(e$vectors) %*% w
  influence <- colSums(matrix(per_coord, nrow = 3))
  o <- order(-influence, seq_along(influence))
  out <- data.frame(rank = seq_along(o), marker = markers[o], influence = influence[o],
                    share = influence[o] / sum(influence), stringsAsFactors = FALSE)
  structure(out, class = c("marker_ranking", "data.frame"), eigenvalues = val,
            weighting = weighting)
}

# Marker names from a marker matrix's column names (<marker>.x/.y/.z triples).
marker_names_of <- function(m, arg = "reference", call = rlang::caller_env()) {
  cn <- colnames(m)
  if (is.null(cn) || ncol(m) %% 3L != 0L) {
    hm_abort("{.arg {arg}} needs 3 named columns per marker ({.val index_tip.x}, ...), not {describe_value(m)}{if (is.null(cn)) ' without column names' else ''}.",
             "bad_markers", argument = arg, call = call)
  }
  mk <- sub("\\.[xyz]$", "", cn[c(TRUE, FALSE, FALSE)])
  wrong <- which(cn != marker_columns(mk))
  if (length(wrong)) {
    hm_abort(c("The columns of {.arg {arg}} must come in {.val .x}, {.val .y}, {.val .z} triples per marker.",
               x = "Column {wrong[1]} is {.val {cn[wrong[1]]}}, expected {.val {marker_columns(mk)[wrong[1]]}}."),
             "bad_markers", argument = arg, column = cn[wrong[1]], call = call)
  }
  mk
}

#' @export
print.marker_ranking <- function(x, ...) {
  cli::cat_line(cli::pluralize(paste(
    "<marker_ranking> {nrow(x)} marker{?s}, {attr(x, 'weighting')}-weighted PCA of",
    "{length(attr(x, 'eigenvalues'))} coordinate{?s}")))
  print(as.data.frame(unclass(x)[names(x)]), digits = 3, row.names = FALSE)
  invisible(x)
}

#' Select a sparse marker set
#'
#' The hand carries 13 virtual markers (after Figure 3 of Wheatland, Joerg
#' and Zordan: the five fingertips `thumb_tip`, `index_tip`, `middle_tip`,
#' `ring_tip`, `little_tip`; the middle knuckles `thumb_ip`, `index_pip`,
#' `middle_pip`, `ring_pip`, `little_pip`; the base knuckles `thumb_mcp`,
#' `index_mcp`, `little_mcp`), plus three forearm markers on the root link
#' (`forearm_radial`, `forearm_ulnar`, `forearm_dorsal`), which are constant
#' relative to it and only drawn. `select_markers()` chooses `n` of the hand
#' markers by one of three methods:
#'
#' * `"ranked"` (the paper's, Wheatland et al.'s Algorithm 1): the top `n`
#'   of a ranking of the hand markers by their influence on the principal
#'   components of the marker positions of the reference `x` (relative to
#'   the root link). Each marker's influence is the sum over components of
#'   the absolute eigenvector coefficients of its x, y and z coordinates,
#'   each weighted by the component's eigenvalue (`weighting =
#'   "eigenvalue"`); `weighting = "equal"` treats the first `n_components`
#'   components (default half the dimension) as equally important and ignores
#'   the rest (the paper found both similar for `n_components` between a
#'   quarter and three quarters of the dimension, and worse results when all
#'   components are used equally). The forearm markers are constant relative
#'   to the root link and are not ranked. The whole ranking comes with the
#'   result (attribute `"ranking"`); because the sets are prefixes of one
#'   ranking they are nested: the 3-marker set is inside the 6-marker set, so
#'   recording more markers only adds markers (the paper's Section 5).
#' * `"handpicked"`: the manually chosen six-marker baseline after Hoyet et
#'   al. (2012): the tips of the thumb, index and little finger, the thumb IP
#'   joint and the index and little-finger base knuckles. Like the paper's set
#'   it has no marker on the middle and ring fingers. `x` is not needed and
#'   `n` must be 6.
#' * `"search"` (after Kang et al. 2012): the set with the least
#'   reconstruction error on held-out reference data. The reference `x` is
#'   split by a metadata column (`holdout`, by default grasp type, so the
#'   search rewards generalisation to unseen motions): alternate values (after
#'   a seeded shuffle) form the validation part. The search is greedy forward
#'   selection (add the marker that lowers the validation error most, `n`
#'   times; about `13 n` reconstructions), or with `exhaustive = TRUE` every
#'   `choose(13, n)` set (1,716 for six markers: slow).
#'
#' @param x A [grasps()] reference (for `"ranked"` also a frames x (3 *
#'   markers) marker matrix with columns named `<marker>.x` etc., or the
#'   `"ranking"` of an earlier result, to take another prefix without
#'   recomputing it; `NULL` for `"handpicked"`).
#' @param n Number of markers, 1 to 13.
#' @param method `"ranked"`, `"handpicked"` or `"search"`.
#' @param ... For `"ranked"`: `weighting` (`"eigenvalue"`, the paper's
#'   choice, or `"equal"`), `n_components` (for `"equal"`), `skeleton` and
#'   the [forward_kinematics()] arguments;
#'   for `"search"`: `holdout` (metadata column split between fitting and
#'   validation, default `"grasp"`), `exhaustive` (default `FALSE`),
#'   `max_frames` (validation frames per evaluation, whole recordings, a
#'   seeded sample; default 1500), `seed` (default 1; the global RNG is left
#'   untouched), `neighbours` and `ridge` (passed to [fit_handover()]) and `skeleton`
#'   and the [forward_kinematics()] arguments.
#' @return A character vector of `n` marker names, most influential (or, for
#'   the search, first added) first. The ranking adds attribute `"ranking"`:
#'   a data frame of class `marker_ranking` of all hand markers, most
#'   influential first (`rank`, `marker`, `influence`, `share` = influence /
#'   total; attributes `eigenvalues` and `weighting`). The search adds
#'   attribute `"search"`: a data frame of the evaluated sets and their
#'   validation errors (degrees).
#' @seealso [fit_handover()]; `handover_error(by = "markers")` compares
#'   marker sets.
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 2, grasps = 1:4, objects = 1, trials = 1)
#' six <- select_markers(g, 6)
#' six
#' attr(six, "ranking")
#' select_markers(attr(six, "ranking"), 3)
#' select_markers(g, 6, weighting = "equal")
#' select_markers(method = "handpicked")
#' select_markers(g, n = 2, method = "search", max_frames = 200)
select_markers <- function(x = NULL, n = 6, method = c("ranked", "handpicked", "search"), ...) {
  call <- rlang::caller_env()
  method <- check_choice(method, arg = "method", call = rlang::current_env())
  n_max <- sum(hand_marker_set()$segment == "hand")
  check_whole(n, "n", max = n_max, class = "bad_markers", call = call)  # (n kept as given, as search_markers() logs it)
  switch(method,
    handpicked = {
      if (n != 6) {
        hm_abort("The hand-picked set has 6 markers; {.arg n} is {n}.", "bad_markers",
                 argument = "n", call = call)
      }
      handpicked_markers()
    },
    search = search_markers(x, n = n, ..., call = call),
    ranked = {
      if (is.null(x)) {
        hm_abort("Ranking markers needs a reference {.arg x}.", "bad_input", argument = "x", call = call)
      }
      rk <- if (inherits(x, "marker_ranking")) x else rank_markers(x, ..., arg = "x", call = call)
      if (n > nrow(rk)) {
        hm_abort("{.arg n} must be a whole number from 1 to {nrow(rk)}, not {.val {format(n)}}.",
                 "bad_markers", argument = "n", call = call)
      }
      structure(rk$marker[seq_len(n)], ranking = rk)
    })
}
