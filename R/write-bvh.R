# BVH export: a hand animation Blender (and most motion tools) can import.
# HIERARCHY: the skeleton's tree with rest offsets from each parent; joints
# without children become "End Site"s. MOTION: per frame the root's position
# (always 0: the wrist stays put) and every joint's rotation relative to its
# parent as Z X Y Euler angles in degrees, BVH's usual channel order. All rest
# frames in BVH are the root's axes, which is how forward_kinematics()
# expresses each joint's rotation, so the export is exact.

#' Write a recording as a BVH hand animation
#'
#' @param x A recording (numeric frames x DoF matrix with DoF column names)
#'   or a [grasps()] object (see `recording`); a generated grasp is a
#'   `grasps` too.
#' @param file Output path (`.bvh`).
#' @param skeleton A [hand_skeleton()].
#' @param recording For a `grasps` with several recordings: which one
#'   (index or id).
#' @param rate Frames per second of a matrix `x` (a `grasps` has its own).
#' @param scale Factor applied to lengths (the skeleton is in mm; `0.001`
#'   writes metres).
#' @param ... Passed to [forward_kinematics()]'s angle handling: `mapping`,
#'   `mode`, `deactivate`, `unit`.
#' @return `file`, invisibly.
#' @seealso [read_bvh()]
#' @export
#' @examples
#' rec <- matrix(0, 10, 16, dimnames = list(NULL, hust_dofs$name))
#' rec[, "PIP2"] <- seq(0, 90, length.out = 10)
#' f <- tempfile(fileext = ".bvh")
#' write_bvh(rec, f)
#' b <- read_bvh(f)
#' b$frames
#' nrow(b$joints)
write_bvh <- function(x, file, skeleton = hand_skeleton(), recording = 1L, rate = 50,
                      scale = 1, ...) {
  call <- rlang::caller_env()
  check_skeleton(skeleton, call = call)
  scale <- check_number(scale, "scale", min = 0, min_open = TRUE, call = call)
  dots <- list(...)
  if (inherits(x, "grasps")) {
    if (is.character(recording)) recording <- match(recording, x$meta$id)
    if (length(recording) != 1L || is.na(recording) || recording < 1L || recording > length(x)) {
      hm_abort("{.arg recording} must pick one of the {length(x)} recording{?s} by index or id.",
               "bad_input", argument = "recording", call = call)
    }
    rate <- x$rate
    unit <- x$unit
    x <- x$recordings[[recording]]
  } else {
    unit <- if (is.null(dots$unit)) "deg" else dots$unit
  }
  check_rate(rate, call = call)
  input <- fk_input(if (is.data.frame(x)) as.matrix(x) else x, unit, call)
  mode <- if (is.null(dots$mode)) "plain" else check_choice(dots$mode, c("plain", "full", "fixed-root"), arg = "mode", call = call)
  plan <- fk_plan(input$dofs, skeleton, dots$mapping, mode, dots$deactivate, call)
  rec <- input$recordings[[1]]
  ang <- fk_angles(plan, rec, input$factor)
  n <- nrow(rec)

  j <- skeleton$joints
  pidx <- skeleton_parent_index(skeleton)
  kids <- lapply(seq_len(nrow(j)), function(i) which(pidx == i))
  off <- as.matrix(j[c("x", "y", "z")]) * scale
  num <- function(v) paste(format(round(v, 5), trim = TRUE, scientific = FALSE), collapse = " ")
  hier <- character(0)
  order <- integer(0)
  emit <- function(i, depth) {
    pad <- strrep("  ", depth)
    if (!length(kids[[i]])) {
      hier <<- c(hier, paste0(pad, "End Site"), paste0(pad, "{"),
                 paste0(pad, "  OFFSET ", num(off[i, ])), paste0(pad, "}"))
      return(invisible())
    }
    root <- is.na(pidx[i])
    hier <<- c(hier, paste0(pad, if (root) "ROOT " else "JOINT ", j$name[i]), paste0(pad, "{"),
               paste0(pad, "  OFFSET ", num(if (root) c(0, 0, 0) else off[i, ])),
               paste0(pad, "  CHANNELS ", if (root) "6 Xposition Yposition Zposition " else "3 ",
                      "Zrotation Xrotation Yrotation"))
    order <<- c(order, i)
    for (k in kids[[i]]) emit(k, depth + 1L)
    hier <<- c(hier, paste0(pad, "}"))
  }
  emit(which(is.na(pidx)), 0L)

  motion <- matrix(0, n, 3 + 3 * length(order))
  for (k in seq_along(order)) {
    L <- fk_local(plan, ang, order[k])
    if (!is.null(L)) motion[, 3 + 3 * (k - 1) + 1:3] <- euler_zxy(L)
  }
  body <- apply(round(motion, 5), 1, function(r) paste(format(r, trim = TRUE, scientific = FALSE), collapse = " "))
  writeLines(c("HIERARCHY", hier, "MOTION", paste("Frames:", n),
               paste("Frame Time:", format(1 / rate, digits = 10)), body), file)
  invisible(file)
}

# Z X Y Euler angles (degrees) of a batch of rotations R = Rz(a) Rx(b) Ry(c).
euler_zxy <- function(R) {
  b <- asin(pmin(1, pmax(-1, R[, 6])))
  a <- atan2(-R[, 4], R[, 5])
  c <- atan2(-R[, 3], R[, 9])
  cbind(a, b, c) * 180 / pi
}

#' Read a BVH file
#'
#' A small parser for the BVH files [write_bvh()] writes (and most others):
#' the joint tree with offsets and channels, and the motion table.
#'
#' @param file Path to a `.bvh` file.
#' @return A list: `joints` (data frame `name`, `parent`, `end_site`; end
#'   sites are named `<parent>_End`), `offsets` (matrix, one row per joint),
#'   `channels` (list of channel names per joint), `frames` (number of
#'   frames), `frame_time` (seconds) and `motion` (frames x channels matrix,
#'   columns named `joint:channel`).
#' @export
#' @examples
#' rec <- matrix(0, 3, 16, dimnames = list(NULL, hust_dofs$name))
#' f <- write_bvh(rec, tempfile(fileext = ".bvh"))
#' str(read_bvh(f)$joints)
read_bvh <- function(file) {
  call <- rlang::caller_env()
  if (!is.character(file) || length(file) != 1L || !file.exists(file)) {
    hm_abort("BVH file {.file {file}} does not exist.", "bad_file", file = file, argument = "file", call = call)
  }
  lines <- readLines(file, warn = FALSE)
  bad <- function(msg, line, .envir = parent.frame()) {
    env <- list2env(list(bvh_line = line, bvh_file = file), parent = .envir)
    hm_abort(c(msg, i = "In {.file {bvh_file}}, line {bvh_line}."), "bad_file", file = file, line = line,
             call = call, .envir = env)
  }
  mline <- grep("^\\s*MOTION\\s*$", lines)
  if (!length(grep("^\\s*HIERARCHY", lines)) || !length(mline)) {
    bad("Not a BVH file: it needs a HIERARCHY and a MOTION section.", 1L)
  }
  toks <- strsplit(trimws(lines[seq_len(mline[1] - 1L)]), "\\s+")
  tok <- unlist(toks)
  tline <- rep(seq_along(toks), lengths(toks))
  keep <- nzchar(tok)
  tok <- tok[keep]
  tline <- tline[keep]
  names <- character(0)
  parent <- integer(0)
  end_site <- logical(0)
  offsets <- list()
  channels <- list()
  stack <- integer(0)
  i <- 1L
  while (i <= length(tok)) {
    t <- tok[i]
    if (t %in% c("ROOT", "JOINT") || (t == "End" && identical(tok[i + 1L], "Site"))) {
      is_end <- t == "End"
      nm <- if (is_end) paste0(names[stack[length(stack)]], "_End") else tok[i + 1L]
      names <- c(names, nm)
      parent <- c(parent, if (length(stack)) stack[length(stack)] else NA_integer_)
      end_site <- c(end_site, is_end)
      offsets[[length(names)]] <- c(NA_real_, NA_real_, NA_real_)
      channels[[length(names)]] <- character(0)
      if (!identical(tok[i + 2L], "{")) bad("Expected an opening brace after {t} {.val {nm}}.", tline[i])
      stack <- c(stack, length(names))
      i <- i + 3L
    } else if (t == "OFFSET") {
      v <- suppressWarnings(as.numeric(tok[i + 1:3]))
      if (anyNA(v) || !length(stack)) bad("OFFSET needs three numbers inside a joint.", tline[i])
      offsets[[stack[length(stack)]]] <- v
      i <- i + 4L
    } else if (t == "CHANNELS") {
      k <- suppressWarnings(as.integer(tok[i + 1L]))
      if (is.na(k) || !length(stack)) bad("CHANNELS needs a count inside a joint.", tline[i])
      channels[[stack[length(stack)]]] <- tok[i + 1L + seq_len(k)]
      i <- i + 2L + k
    } else if (t == "}") {
      if (!length(stack)) bad("Unbalanced closing brace.", tline[i])
      stack <- stack[-length(stack)]
      i <- i + 1L
    } else if (t == "HIERARCHY") {
      i <- i + 1L
    } else {
      bad("Unexpected token {.val {t}} in the HIERARCHY.", tline[i])
    }
  }
  if (length(stack)) bad("The HIERARCHY has unclosed braces.", mline[1])
  frames_line <- mline[1] + 1L
  ft_line <- mline[1] + 2L
  nfr <- suppressWarnings(as.integer(sub("^\\s*Frames:\\s*", "", lines[frames_line])))
  ft <- suppressWarnings(as.numeric(sub("^\\s*Frame Time:\\s*", "", lines[ft_line])))
  if (is.na(nfr) || !grepl("Frames:", lines[frames_line])) bad("Expected {.val Frames: n}.", frames_line)
  if (is.na(ft) || !grepl("Frame Time:", lines[ft_line])) bad("Expected {.val Frame Time: t}.", ft_line)
  body <- lines[-seq_len(ft_line)]
  body <- body[nzchar(trimws(body))]
  nch <- sum(lengths(channels))
  vals <- suppressWarnings(as.numeric(unlist(strsplit(trimws(body), "\\s+"))))
  if (length(body) != nfr || length(vals) != nfr * nch || anyNA(vals)) {
    bad("The MOTION section should hold {nfr} line{?s} of {nch} number{?s}.", ft_line + 1L)
  }
  motion <- matrix(vals, nfr, nch, byrow = TRUE)
  colnames(motion) <- unlist(Map(function(n, ch) if (length(ch)) paste0(n, ":", ch) else character(0),
                                 names, channels))
  off <- do.call(rbind, offsets)
  dimnames(off) <- list(names, c("x", "y", "z"))
  names(channels) <- names
  list(joints = data.frame(name = names, parent = names[parent], end_site = end_site,
                           stringsAsFactors = FALSE),
       offsets = off, channels = channels, frames = nfr, frame_time = ft, motion = motion)
}

# World positions of every BVH joint over the frames (frames x joints x 3),
# for checking an export against forward_kinematics().
bvh_positions <- function(bvh) {
  j <- bvh$joints
  n <- bvh$frames
  pidx <- match(j$parent, j$name)
  M <- vector("list", nrow(j))
  out <- array(0, c(n, nrow(j), 3), dimnames = list(NULL, j$name, c("x", "y", "z")))
  for (i in seq_len(nrow(j))) {
    p <- pidx[i]
    pos <- if (is.na(p)) matrix(0, n, 3) else out[, p, ] + M[[p]] %*% kronecker(bvh$offsets[i, ], diag(3))
    ch <- bvh$channels[[i]]
    if (is.na(p)) {
      tr <- match(c("Xposition", "Yposition", "Zposition"), ch)
      if (!anyNA(tr)) pos <- pos + bvh$motion[, paste0(j$name[i], ":", ch[tr]), drop = FALSE]
    }
    out[, i, ] <- pos
    R <- if (is.na(p)) rot_batch("x", rep(0, n)) else M[[p]]
    for (a in ch[grepl("rotation$", ch)]) {
      ax <- tolower(substr(a, 1, 1))
      R <- bmul(R, rot_batch(ax, bvh$motion[, paste0(j$name[i], ":", a)] * pi / 180))
    }
    M[[i]] <- R
  }
  out
}
