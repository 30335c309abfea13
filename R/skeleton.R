# Hand skeletons: the kinematic tree that forward kinematics, pictures and
# BVH export hang joint angles on. The on-disk format is GraspDB14's
# `.xmlskel` (Stollenwerk et al., sections 4.2.3 and 5.2.1): nested <joint>
# elements, each with <name>, <id>, <position> and <limits>, under a
# <skeleton> that also gives the angle and length <units>.
#
# One fact about the format is not written down anywhere but decides the
# geometry: <position> holds the joint's position in the flat rest pose
# *relative to the root* (the GraspDB14 parser stores it as the absolute
# position and derives offsets from it). Read as parent offsets, the middle
# finger of default.xmlskel would be 671 mm long. `read_skeleton()` therefore
# reads absolute positions by default and stores parent offsets in `joints`.

skeleton_length_units <- c(mm = 1, cm = 10, m = 1000, `in` = 25.4)
skeleton_angle_units <- c(deg = 1, rad = 180 / pi)
skeleton_limit_cols <- c("rotx_min", "rotx_max", "roty_min", "roty_max", "rotz_min", "rotz_max")

#' Read a hand skeleton (`.xmlskel`)
#'
#' Parses a GraspDB14 skeleton file: a tree of joints rooted at the wrist,
#' each with an id, a name, a rest position and rotation limits about its
#' local x (flexion), y and z (abduction) axes, plus the angle and length
#' units of the file. Lengths are converted to millimetres and angles to
#' degrees.
#'
#' Joints may be nested (`<joint>` inside `<joint>`, the GraspDB14 layout) or
#' listed flat with a `<parent>` element holding the parent's id.
#'
#' @param file Path to an `.xmlskel` file.
#' @param positions How `<position>` is to be read: `"absolute"` (the
#'   GraspDB14 convention: rest position relative to the root) or
#'   `"relative"` (offset from the parent joint).
#' @return A `hand_skeleton`: a list with `joints`, a data frame with one row
#'   per joint (`id`, `name`, `parent` (parent id, `NA` for the root), `x`,
#'   `y`, `z` (offset from the parent in the rest pose, mm), `rotx_min`,
#'   `rotx_max`, `roty_min`, `roty_max`, `rotz_min`, `rotz_max` (degrees)),
#'   parents always before their children; `units`, the units the file used
#'   (`list(angle, length)`); and `file`.
#' @section Errors:
#' Malformed XML, unknown units, joints without a name, id or position,
#' duplicated ids or names, a parent id that no joint has, several roots and
#' cycles all raise an error of class `handmotion_error_bad_skeleton` naming
#' the file, the joint and, where it can be found, the line.
#' @seealso [hand_skeleton()] for the package's own hand, [write_skeleton()],
#'   [forward_kinematics()].
#' @export
#' @examples
#' skel <- read_skeleton(system.file("extdata", "handmotion-hand.xmlskel",
#'                                   package = "handmotion"))
#' skel
#' head(skel$joints)
read_skeleton <- function(file, positions = c("absolute", "relative")) {
  call <- rlang::caller_env()
  positions <- check_choice(positions, arg = "positions", call = rlang::current_env())
  check_string(file, "file", what = "one file path", call = call)
  if (!file.exists(file) && !is_symlink(file)) {
    hm_abort("Skeleton file {.file {file}} does not exist.", "file_not_found", file = file,
             argument = "file", call = call)
  }
  check_readable_file(file, call = call)
  doc <- tryCatch(xml2::read_xml(file), error = function(e) {
    hm_abort(c("Skeleton file {.file {file}} is not well-formed XML.",
               x = "{conditionMessage(e)}"), c("bad_skeleton", "bad_file"), file = file, call = call)
  })
  lines <- readLines(file, warn = FALSE)
  parse_skeleton_xml(doc, file, lines, positions, call)
}

#' The package's default hand skeleton
#'
#' A right hand of 25 joints in the GraspDB14 layout (root = wrist; thumb
#' `th-tmc`, `th-mcp`, `th-ip`, `th-tip`; index, middle, ring and little
#' fingers `if-`, `mf-`, `rf-`, `lf-` each with `cmc`, `mcp`, `pip`, `dip`,
#' `tip`), shipped as `inst/extdata/handmotion-hand.xmlskel`. Flat rest pose
#' in the x-y plane, fingers along -y, thumb towards +x, palm facing -z;
#' positive rotation about a joint's x axis is flexion.
#'
#' Bone lengths are the segment-length coefficients of Buchholz, Armstrong
#' and Goldstein (1992) times a hand length HL (wrist crease to middle
#' fingertip) of 189 mm and a hand breadth HB (across the metacarpal heads) of
#' 84 mm, both about the adult 50th percentile; the middle fingertip lies
#' exactly one hand length from the wrist.
#'
#' Which coefficients: the metacarpals of the index, ring and little finger
#' have Buchholz's hand-breadth term, `sqrt((a * HL)^2 + (b * HB)^2)` with
#' `(a, b)` = (0.374, 0.126), (0.336, 0.077) and (0.295, 0.179) (the middle
#' metacarpal is 0.373 HL); the proximal phalanges of the index, middle, ring
#' and little finger are Buchholz's 0.245, 0.266, 0.244 and 0.204 HL. The
#' other proximal values in circulation (0.265, 0.277, 0.259, 0.206) are not
#' Buchholz's: they are An et al.'s (1979) proximal-to-middle phalanx ratios
#' times Buchholz's middle phalanges, the combination used by the hand model
#' of Sancho-Bru and colleagues, whose published source code writes both next
#' to each other. Rotation limits are typical active
#' ranges of motion (American Academy of Orthopaedic Surgeons 1965). The file
#' is generated by `data-raw/handmotion-hand.R`.
#'
#' @references Buchholz, B., Armstrong, T. J. and Goldstein, S. A. (1992).
#'   Anthropometric data for describing the kinematics of the human hand.
#'   *Ergonomics* 35(3), 261-273.
#'
#'   An, K. N., Chao, E. Y., Cooney, W. P. and Linscheid, R. L. (1979).
#'   Normative model of human hand for biomechanical analysis. *Journal of
#'   Biomechanics* 12(10), 775-788 (only to explain the other transcription).
#'
#'   American Academy of Orthopaedic Surgeons (1965). *Joint Motion: Method of
#'   Measuring and Recording*. Chicago: AAOS.
#' @return A `hand_skeleton` (see [read_skeleton()]).
#' @export
#' @examples
#' skel <- hand_skeleton()
#' skel
#' ggplot2::autoplot(skel)
hand_skeleton <- function() {
  path <- system.file("extdata", "handmotion-hand.xmlskel", package = "handmotion")
  if (!nzchar(path)) {
    hm_abort("The default skeleton file {.file handmotion-hand.xmlskel} is missing from the installation.",
             "bad_file")
  }
  # read once per session and installation: every model fitted asks for its
  # joint limits (dof_limits()), and parsing the file each time cost 8 ms a
  # grasp type (0.3 s of fitting the default data's 33 types, 6%)
  if (!identical(default_skeleton$path, path)) {
    default_skeleton$skeleton <- read_skeleton(path)
    default_skeleton$path <- path
  }
  default_skeleton$skeleton
}

# The default skeleton as hand_skeleton() last read it, with its file's path.
default_skeleton <- new.env(parent = emptyenv())

# ---- parsing --------------------------------------------------------------

parse_skeleton_xml <- function(doc, file, lines, positions, call) {
  top <- xml2::xml_name(doc)
  if (!identical(top, "skeleton")) {
    hm_abort(c("Skeleton file {.file {file}} has root element {.val <{top}>}, not {.val <skeleton>}."),
             c("bad_skeleton", "bad_file"), file = file, call = call)
  }
  units <- parse_skeleton_units(doc, file, lines, call)
  nodes <- xml2::xml_find_all(doc, "//joint")
  if (length(nodes) == 0L) {
    hm_abort("Skeleton file {.file {file}} has no {.val <joint>} elements.", c("bad_skeleton", "bad_file"),
             file = file, call = call)
  }
  field <- function(tag) trimws(xml2::xml_text(xml2::xml_find_first(nodes, paste0("./", tag))))
  name <- field("name")
  id_txt <- field("id")
  pos_txt <- field("position")
  parent_txt <- field("parent")
  nested_parent <- trimws(xml2::xml_text(xml2::xml_find_first(nodes, "./parent::joint/id")))
  n <- length(nodes)

  bad <- which(is.na(name) | name == "")
  if (length(bad)) {
    skel_abort("Joint number {bad[1]} (with id {.val {id_txt[bad[1]]}}) has no {.val <name>}.",
               file, lines, "id", id_txt[bad[1]], joint = NA_character_, call = call)
  }
  id <- suppressWarnings(as.integer(id_txt))
  bad <- which(is.na(id) | id != suppressWarnings(as.numeric(id_txt)))
  if (length(bad)) {
    skel_abort("Joint {.val {name[bad[1]]}} has a missing or non-integer {.val <id>} ({.val {id_txt[bad[1]]}}).",
               file, lines, "name", name[bad[1]], joint = name[bad[1]], call = call)
  }
  xyz <- lapply(seq_len(n), function(i) {
    v <- suppressWarnings(as.numeric(strsplit(pos_txt[i] %|na|% "", "[[:space:],]+")[[1]]))
    if (is.na(pos_txt[i]) || length(v) != 3L || !all(is.finite(v))) {
      skel_abort("Joint {.val {name[i]}} needs a {.val <position>} of three finite numbers, not {.val {pos_txt[i]}}.",
                 file, lines, "name", name[i], joint = name[i], call = call)
    }
    v
  })
  xyz <- do.call(rbind, xyz) * skeleton_length_units[[units$length]]
  limits <- parse_skeleton_limits(nodes, name, file, lines, call) * skeleton_angle_units[[units$angle]]

  # Duplicates: an id met again inside its own subtree is a cycle in the tree.
  dup <- which(duplicated(id))
  if (length(dup)) {
    i <- dup[1]
    first <- which(id == id[i])[1]
    inside <- id[i] %in% ancestor_ids(nodes[[i]])
    msg <- if (inside) {
      "Joint id {.val {id[i]}} is referenced twice: {.val {name[i]}} lies inside the subtree of {.val {name[first]}}, a cycle in the joint tree."
    } else {
      "Joint id {.val {id[i]}} is used twice ({.val {name[first]}} and {.val {name[i]}})."
    }
    skel_abort(msg, file, lines, "name", name[i], joint = name[i], call = call)
  }
  dup <- which(duplicated(name))
  if (length(dup)) {
    skel_abort("Joint name {.val {name[dup[1]]}} is used twice (ids {.val {id[name == name[dup[1]]]}}).",
               file, lines, "name", name[dup[1]], occurrence = 2L, joint = name[dup[1]], call = call)
  }

  parent <- suppressWarnings(as.integer(ifelse(is.na(parent_txt), nested_parent, parent_txt)))
  bad <- which(!is.na(parent_txt) & is.na(suppressWarnings(as.integer(parent_txt))))
  if (length(bad)) {
    skel_abort("Joint {.val {name[bad[1]]}} has a non-integer {.val <parent>} ({.val {parent_txt[bad[1]]}}).",
               file, lines, "name", name[bad[1]], joint = name[bad[1]], call = call)
  }
  bad <- which(!is.na(parent) & !parent %in% id)
  if (length(bad)) {
    skel_abort("Joint {.val {name[bad[1]]}} names parent id {.val {parent[bad[1]]}}, but no joint has that id (missing joint).",
               file, lines, "name", name[bad[1]], joint = name[bad[1]], call = call)
  }
  roots <- which(is.na(parent))
  if (length(roots) != 1L) {
    what <- if (length(roots) == 0L) "no root joint (every joint has a parent)" else
      "{length(roots)} root joints ({.val {name[roots]}}); a hand skeleton is one tree rooted at the wrist"
    skel_abort(paste0("Skeleton has ", what, "."), file, lines, "name",
               name[if (length(roots)) roots[2] else 1], joint = name[if (length(roots)) roots else 1],
               call = call)
  }
  order <- topological_order(id, parent, name, file, lines, call)

  joints <- data.frame(id = id, name = name, parent = parent, stringsAsFactors = FALSE)
  abs_xyz <- xyz
  if (positions == "absolute") {
    pidx <- match(parent, id)
    rel <- xyz
    has_parent <- !is.na(pidx)
    rel[has_parent, ] <- xyz[has_parent, , drop = FALSE] - xyz[pidx[has_parent], , drop = FALSE]
    xyz <- rel
  }
  joints$x <- xyz[, 1]
  joints$y <- xyz[, 2]
  joints$z <- xyz[, 3]
  joints <- cbind(joints, limits)
  joints <- joints[order, , drop = FALSE]
  rownames(joints) <- NULL
  new_hand_skeleton(joints, units, file = normalizePath(file, mustWork = FALSE))
}

`%|na|%` <- function(x, y) if (is.na(x)) y else x

parse_skeleton_units <- function(doc, file, lines, call) {
  assumed <- character(0)
  get <- function(tag, default) {
    node <- xml2::xml_find_first(doc, paste0("/skeleton/units/", tag))
    if (inherits(node, "xml_missing")) {
      assumed <<- c(assumed, paste(tag, default))
      return(default)
    }
    trimws(xml2::xml_text(node))
  }
  angle <- get("angle", "deg")
  length <- get("length", "mm")
  if (length(assumed)) {
    hm_warn("Skeleton file {.file {file}} gives no units for {assumed}; assuming the GraspDB14 defaults.",
            "skeleton_default_unit")
  }
  if (!angle %in% names(skeleton_angle_units)) {
    skel_abort("Unknown angle unit {.val {angle}}; use one of {.val {names(skeleton_angle_units)}}.",
               file, lines, "angle", angle, joint = NA_character_, call = call)
  }
  if (!length %in% names(skeleton_length_units)) {
    skel_abort("Unknown length unit {.val {length}}; use one of {.val {names(skeleton_length_units)}}.",
               file, lines, "length", length, joint = NA_character_, call = call)
  }
  list(angle = angle, length = length)
}

# Limits default to 0 0 (not a degree of freedom) when an axis is absent, as in
# the GraspDB14 files where every unused axis is written as "0 0".
parse_skeleton_limits <- function(nodes, name, file, lines, call) {
  out <- matrix(0, length(nodes), 6, dimnames = list(NULL, skeleton_limit_cols))
  for (a in c("x", "y", "z")) {
    got <- xml2::xml_find_first(nodes, paste0("./limits/rot", a))
    txt <- trimws(xml2::xml_text(got))
    for (i in which(!is.na(txt))) {
      v <- suppressWarnings(as.numeric(strsplit(txt[i], "[[:space:],]+")[[1]]))
      if (length(v) != 2L || anyNA(v) || v[1] > v[2]) {
        skel_abort("Joint {.val {name[i]}}: {.val <rot{a}>} limits must be two numbers min max, not {.val {txt[i]}}.",
                   file, lines, "name", name[i], joint = name[i], call = call)
      }
      out[i, paste0("rot", a, c("_min", "_max"))] <- v
    }
  }
  out
}

ancestor_ids <- function(node) {
  trimws(xml2::xml_text(xml2::xml_find_all(node, "./ancestor::joint/id")))
}

# Parents before children; a parent chain that never reaches the root is a
# cycle (possible with flat files that give <parent> explicitly).
topological_order <- function(id, parent, name, file, lines, call) {
  n <- length(id)
  depth <- rep(NA_integer_, n)
  pidx <- match(parent, id)
  for (i in seq_len(n)) {
    seen <- integer(0)
    j <- i
    while (!is.na(pidx[j]) && is.na(depth[j])) {
      if (j %in% seen) {
        loop <- name[c(seen[match(j, seen):length(seen)], j)]
        skel_abort("Cycle in the joint tree: {paste(loop, collapse = ' -> ')}.",
                   file, lines, "name", name[j], joint = name[j], call = call)
      }
      seen <- c(seen, j)
      j <- pidx[j]
    }
    base <- if (is.na(pidx[j])) 0L else depth[j]
    if (is.na(depth[j])) depth[j] <- base
    path <- rev(seen)
    for (k in seq_along(path)) depth[path[k]] <- base + k
  }
  # stable: keeps file order within a depth-first nesting when it is valid
  ord <- seq_len(n)
  ok <- all(is.na(pidx) | pidx < seq_len(n))
  if (ok) ord else order(depth, seq_len(n))
}

# Line of the first (or n-th) <tag>value</tag> in the file, for messages.
skeleton_line <- function(lines, tag, value, occurrence = 1L) {
  if (is.null(lines) || is.na(value)) return(NA_integer_)
  pat <- paste0("<", tag, ">\\s*", gsub("([][{}()+*^$|\\\\?.])", "\\\\\\1", value), "\\s*</", tag, ">")
  hit <- grep(pat, lines)
  if (length(hit) >= occurrence) hit[occurrence] else if (length(hit)) hit[1] else NA_integer_
}

skel_abort <- function(message, file, lines, tag, value, joint, occurrence = 1L, call,
                       .envir = parent.frame()) {
  line <- skeleton_line(lines, tag, value, occurrence)
  where <- if (is.na(line)) "In {.file {file}}." else "In {.file {file}}, line {line}."
  msg <- c(message, i = where)
  hm_abort(msg, c("bad_skeleton", "bad_file"), file = file, line = line, joint = joint, call = call,
           .envir = list2env(list(file = file, line = line), parent = .envir))
}

# ---- class ----------------------------------------------------------------

new_hand_skeleton <- function(joints, units, file = NA_character_) {
  structure(list(joints = joints, units = units, file = file), class = "hand_skeleton")
}

check_skeleton <- function(x, arg = "skeleton", call = rlang::caller_env()) {
  if (!inherits(x, "hand_skeleton")) {
    hm_abort("{.arg {arg}} must be a {.cls hand_skeleton} (see {.fn read_skeleton}), not {.obj_type_friendly {x}}.",
             "bad_input", argument = arg, call = call)
  }
  # finite offsets: an edited skeleton with a NaN position gave base R's
  # "missing value where TRUE/FALSE needed" in the kinematics, or a file
  # write_skeleton() wrote and read_skeleton() refuses
  j <- x$joints
  xyz <- if (is.data.frame(j) && all(c("name", "x", "y", "z") %in% names(j))) as.matrix(j[c("x", "y", "z")])
  if (is.null(xyz) || !is.numeric(xyz) || !all(is.finite(xyz))) {
    bad <- if (is.null(xyz) || !is.numeric(xyz)) character() else j$name[rowSums(!is.finite(xyz)) > 0]
    hm_abort(c("{.arg {arg}} must hold finite joint positions ({.field joints$x}, {.field y}, {.field z}).",
               x = if (length(bad)) "Not finite for joint{?s} {.val {bad}}." else "They are missing or not numeric."),
             "bad_skeleton", argument = arg, joint = bad, call = call)
  }
  # one tree: a joint whose parent was dropped from the table (an edited
  # skeleton) would otherwise fail deep inside the drawing code
  pidx <- skeleton_parent_index(x)
  orphan <- x$joints$name[!is.na(x$joints$parent) & is.na(pidx)]
  if (length(orphan)) {
    hm_abort("{.arg {arg}} has joint{?s} {.val {orphan}} whose parent joint is missing (the skeleton must be one tree).",
             "bad_skeleton", argument = arg, joint = orphan, call = call)
  }
  invisible(x)
}

# Rest-pose positions relative to the root (mm): a joints x 3 matrix.
skeleton_rest_positions <- function(skeleton) {
  j <- skeleton$joints
  pidx <- match(j$parent, j$id)
  pos <- as.matrix(j[c("x", "y", "z")])
  for (i in seq_len(nrow(j))) {
    if (!is.na(pidx[i])) pos[i, ] <- pos[i, ] + pos[pidx[i], ]
  }
  dimnames(pos) <- list(j$name, c("x", "y", "z"))
  pos
}

# Index of each joint's parent row (NA for the root).
skeleton_parent_index <- function(skeleton) {
  match(skeleton$joints$parent, skeleton$joints$id)
}

# The finger (chain below the root) a joint belongs to, named by its first joint.
skeleton_chains <- function(skeleton) {
  j <- skeleton$joints
  pidx <- skeleton_parent_index(skeleton)
  root <- which(is.na(pidx))
  chain <- rep(NA_character_, nrow(j))
  for (i in seq_len(nrow(j))) {
    k <- i
    while (!is.na(pidx[k]) && pidx[k] != root) k <- pidx[k]
    chain[i] <- if (k == root) j$name[root] else sub("-.*$", "", j$name[k])
  }
  chain
}

#' @export
print.hand_skeleton <- function(x, ...) {
  j <- x$joints
  pidx <- skeleton_parent_index(x)
  n_child <- tabulate(pidx[!is.na(pidx)], nbins = nrow(j))
  pos <- skeleton_rest_positions(x)
  root <- which(is.na(pidx))
  reach <- sqrt(rowSums(sweep(pos, 2, pos[root, ])^2))
  cli::cat_line(cli::pluralize(
    "<hand_skeleton> {nrow(j)} joint{?s} ({sum(n_child == 0L)} end effector{?s}), root {j$name[root]}"))
  cli::cat_line("  file units: angle ", x$units$angle, ", length ", x$units$length, " (stored in deg and mm)")
  if (!is.na(x$file)) cli::cat_line("  file: ", basename(x$file))
  chains <- skeleton_chains(x)
  for (ch in setdiff(unique(chains), j$name[root])) {
    idx <- which(chains == ch)
    cli::cat_line(sprintf("  %-4s %s (%.0f mm from root)", ch, paste(j$name[idx], collapse = " > "), max(reach[idx])))
  }
  invisible(x)
}

#' Draw a hand skeleton in its rest pose
#'
#' With `markers`, the hand-over marker sets instead (the figure of
#' Wheatland, Joerg and Zordan's Figure 3): the full marker set (13 hand
#' markers and 3 on the forearm, see [select_markers()]) with open symbols
#' and each set's markers filled, one panel per set.
#'
#' @param object A [hand_skeleton()].
#' @param view Viewing direction, see [autoplot.hand_pose()].
#' @param labels Label the joints with their names? (Not with `markers`.)
#' @param markers `NULL`, or marker sets to draw: a named list of marker-name
#'   vectors (one panel each), e.g. `list("ranked (3)" = select_markers(ref,
#'   3), "hand-picked (6)" = select_markers(method = "handpicked"))`, or one
#'   vector.
#' @param ... Passed to [autoplot.hand_pose()].
#' @return A ggplot object. With `markers`, its marker layer's data has
#'   columns `set`, `marker` and `selected`.
#' @export
#' @method autoplot hand_skeleton
#' @examples
#' ggplot2::autoplot(hand_skeleton(), view = "back")
#' ggplot2::autoplot(hand_skeleton(), markers = list(
#'   `hand-picked (6)` = select_markers(method = "handpicked"),
#'   `tips (3)` = c("thumb_tip", "index_tip", "middle_tip")))
autoplot.hand_skeleton <- function(object, view = "back", labels = TRUE, markers = NULL, ...) {
  if (!is.null(markers)) {
    return(plot_marker_sets(markers, skeleton = object, view = view, call = rlang::caller_env()))
  }
  pose <- skeleton_rest_pose(object)
  ggplot2::autoplot(pose, view = view, labels = labels, ...)
}

#' Write a hand skeleton as `.xmlskel`
#'
#' Writes the GraspDB14 format read by [read_skeleton()]: nested joints with
#' absolute rest positions (mm) and limits (degrees).
#'
#' @param skeleton A [hand_skeleton()].
#' @param file Output path.
#' @param comment Optional text for an XML comment at the top (e.g. sources).
#' @param overwrite Replace existing file? By default an existing file is
#'   an error of class `handmotion_error_file_exists` naming it, and nothing
#'   is written.
#' @return `file`, invisibly.
#' @export
#' @examples
#' f <- tempfile(fileext = ".xmlskel")
#' write_skeleton(hand_skeleton(), f)
#' nrow(read_skeleton(f)$joints)
write_skeleton <- function(skeleton, file, comment = NULL, overwrite = FALSE) {
  call <- rlang::caller_env()
  check_skeleton(skeleton, call = call)
  file <- check_string(file, "file", call = call)
  check_overwrite(file, overwrite, call = call)
  j <- skeleton$joints
  pos <- skeleton_rest_positions(skeleton)
  pidx <- skeleton_parent_index(skeleton)
  fmt <- function(v) paste(format(round(v, 4), trim = TRUE, scientific = FALSE), collapse = " ")
  out <- character(0)
  if (!is.null(comment)) out <- c("<!--", gsub("--", "- -", comment, fixed = TRUE), "-->")
  out <- c(out, "<skeleton>", "  <units>", "    <angle>deg</angle>", "    <length>mm</length>", "  </units>")
  emit <- function(i, depth) {
    pad <- strrep("  ", depth)
    lim <- unlist(j[i, skeleton_limit_cols])
    txt <- c(paste0(pad, "<joint>"),
             paste0(pad, "  <name>", j$name[i], "</name>"),
             paste0(pad, "  <id>", j$id[i], "</id>"),
             paste0(pad, "  <position>", fmt(pos[i, ]), "</position>"),
             paste0(pad, "  <limits>"),
             paste0(pad, "    <rotx>", fmt(lim[1:2]), "</rotx>"),
             paste0(pad, "    <roty>", fmt(lim[3:4]), "</roty>"),
             paste0(pad, "    <rotz>", fmt(lim[5:6]), "</rotz>"),
             paste0(pad, "  </limits>"))
    for (k in which(pidx == i)) txt <- c(txt, emit(k, depth + 1L))
    c(txt, paste0(pad, "</joint>"))
  }
  out <- c(out, emit(which(is.na(pidx)), 1L), "</skeleton>")
  write_text_file(out, file, call = call)
  invisible(file)
}
