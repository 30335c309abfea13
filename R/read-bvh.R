# Reading BVH files (those write_bvh() writes, and most others), and the
# joint positions their motion implies, to check an export against
# forward_kinematics().

#' Read a BVH file
#'
#' A small parser for the BVH files [write_bvh()] writes (and most others).
#' The motion comes back as a one-recording [grasps()] object whose DoFs are
#' the joints' rotation channels (`<joint>:<channel>`, in degrees) at the
#' file's frame rate, so every verb that takes recordings takes it; the
#' hierarchy stays with it, and [write_bvh()] writes it back unchanged.
#'
#' @param file Path to a `.bvh` file.
#' @return A [grasps()] object with one recording (id: the file name without
#'   extension, no grasp label) and the attribute `bvh`: a list with
#'   `joints` (data frame `name`, `parent`, `end_site`; end sites are named
#'   `<parent>_End`), `offsets` (matrix, one row per joint), `channels` (list
#'   of channel names per joint), `frame_time` (seconds) and `position` (the
#'   root's position channels, frames x 3, in the file's length unit).
#' @export
#' @examples
#' rec <- matrix(0, 3, 16, dimnames = list(NULL, hust_dofs$name))
#' rec[, "PIP2"] <- c(0, 45, 90)
#' f <- write_bvh(rec, tempfile(fileext = ".bvh"))
#' b <- read_bvh(f)
#' b
#' b$recordings[[1]][, "if-pip:Xrotation"]
#' str(attr(b, "bvh")$joints)
read_bvh <- function(file) {
  call <- rlang::caller_env()
  parts <- parse_bvh(file, call)
  rot <- grepl("rotation$", colnames(parts$motion))
  rec <- parts$motion[, rot, drop = FALSE]
  id <- sub("\\.[^.]*$", "", basename(file))
  x <- grasps(list(rec), meta = data.frame(id = id, stringsAsFactors = FALSE), dofs = colnames(rec),
              rate = 1 / parts$frame_time)
  attr(x, "bvh") <- list(joints = parts$joints, offsets = parts$offsets, channels = parts$channels,
                         frame_time = parts$frame_time, position = parts$motion[, !rot, drop = FALSE])
  x
}

# The parts of a BVH read back (joints, offsets, channels, motion with every
# channel in file order, `position`: which motion columns are lengths), for
# write_bvh() (and the tests' bvh_positions(), helper-bvh.R).
bvh_parts <- function(x, recording = 1L) {
  b <- attr(x, "bvh")
  cols <- unlist(Map(function(n, ch) if (length(ch)) paste0(n, ":", ch) else character(0),
                     b$joints$name, b$channels), use.names = FALSE)
  rec <- x$recordings[[recording]]
  motion <- matrix(0, nrow(rec), length(cols), dimnames = list(NULL, cols))
  motion[, colnames(rec)] <- rec
  motion[, colnames(b$position)] <- b$position
  list(joints = b$joints, offsets = b$offsets, channels = b$channels, motion = motion,
       position = colnames(b$position), frames = nrow(rec))
}

# The BVH file as its parts: joints, offsets, channels, frames, frame_time,
# motion (frames x channels, columns `joint:channel`).
# The six channels a BVH joint may have.
bvh_channel_names <- c("Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation")

parse_bvh <- function(file, call) {
  file <- check_string(file, "file", call = call)
  if (!file.exists(file) && !is_symlink(file)) {
    hm_abort("BVH file {.file {file}} does not exist.", "file_not_found", file = file,
             argument = "file", call = call)
  }
  check_readable_file(file, call = call)
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
      if (nm %in% names) bad("Joint name {.val {nm}} is used twice.", tline[i])
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
      if (!all(is.finite(v)) || !length(stack)) bad("OFFSET needs three finite numbers inside a joint.", tline[i])
      offsets[[stack[length(stack)]]] <- v
      i <- i + 4L
    } else if (t == "CHANNELS") {
      k <- suppressWarnings(as.numeric(tok[i + 1L]))
      if (!is.finite(k) || k < 0 || k != round(k) || !length(stack)) {
        bad("CHANNELS needs a whole count (0 or more) inside a joint, not {.val {tok[i + 1L]}}.", tline[i])
      }
      ch <- tok[i + 1L + seq_len(k)]
      unknown <- setdiff(ch, bvh_channel_names)
      if (length(unknown)) {
        bad(paste("Unknown channel{?s} {.val {unknown}}; BVH channels are", paste(bvh_channel_names, collapse = ", "), "."), tline[i])
      }
      channels[[stack[length(stack)]]] <- ch
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
  if (!is.finite(ft) || ft <= 0) bad("The frame time must be a positive number of seconds, not {ft}.", ft_line)
  if (nfr < 1L) bad("The MOTION section has no frames.", frames_line)
  body <- lines[-seq_len(ft_line)]
  body <- body[nzchar(trimws(body))]
  nch <- sum(lengths(channels))
  vals <- suppressWarnings(as.numeric(unlist(strsplit(trimws(body), "\\s+"))))
  if (length(body) != nfr || length(vals) != nfr * nch || anyNA(vals)) {
    bad("The MOTION section should hold {nfr} line{?s} of {nch} number{?s}.", ft_line + 1L)
  }
  if (!all(is.finite(vals))) {
    bad("The MOTION section holds an infinite value.", ft_line + as.integer(ceiling(which(!is.finite(vals))[1] / max(nch, 1L))))
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
