# The boundary into the package's one data class: whatever shape recordings
# arrive in (one matrix, a list of matrices, the long data frame that
# as.data.frame() gives), as_grasps() makes a `grasps` object of it, so the
# functions inside take only `grasps`.

#' Coerce recordings to a grasps object
#'
#' `as_grasps()` turns recordings in any of the shapes users hold them into
#' a [grasps()] object, the class every handmotion function takes:
#'
#' * a `grasps` object is returned as it is;
#' * a numeric matrix (frames x DoF, DoF names as column names; 16 unnamed
#'   columns are taken as the HUST DoFs in order) is one recording;
#' * a list of such matrices is one recording each (names are the ids);
#' * a data frame in the long form of [as.data.frame.grasps()] (columns
#'   `id`, `frame`, `dof`, `angle`, optionally `grasp`, `subject`, `object`,
#'   `trial`) is turned back into recordings, so
#'   `as_grasps(as.data.frame(g))` gives `g` back.
#'
#' @param x Recordings (see above).
#' @param meta,dofs For a list (or matrix): metadata and DoF names, as in
#'   [grasps()].
#' @param rate,unit Sampling rate (Hz) and angle unit, as in [grasps()].
#' @param ... For a matrix: `meta`, `dofs`, `rate`, `unit`. Unused otherwise.
#' @return A [grasps()] object.
#' @export
#' @examples
#' m <- matrix(0, 5, 16, dimnames = list(NULL, hust_dofs$name))
#' as_grasps(m)
#' g <- simulate_grasps(subjects = 1, grasps = 1:2, objects = 1, trials = 1, seed = 1)
#' identical(as_grasps(as.data.frame(g))$recordings, g$recordings)
as_grasps <- function(x, ...) UseMethod("as_grasps")

#' @rdname as_grasps
#' @export
as_grasps.grasps <- function(x, ...) x

#' @rdname as_grasps
#' @export
as_grasps.matrix <- function(x, ...) {
  as_grasps.list(list(x), ...)
}

#' @rdname as_grasps
#' @export
as_grasps.list <- function(x, meta = NULL, dofs = NULL, rate = 50, unit = "deg", ...) {
  if (is.null(dofs) && length(x)) {
    first <- x[[1]]
    if (is.matrix(first) && is.null(colnames(first)) && ncol(first) == 16L) dofs <- handmotion::hust_dofs$name
  }
  grasps(x, meta = meta, dofs = dofs, rate = rate, unit = unit)
}

#' @rdname as_grasps
#' @export
as_grasps.data.frame <- function(x, rate = 50, unit = "deg", ...) {
  call <- rlang::caller_env()
  need <- c("id", "frame", "dof", "angle")
  miss <- setdiff(need, names(x))
  if (length(miss)) {
    hm_abort(c("A long data frame of recordings needs columns {.field {need}}.",
               x = "Missing: {.field {miss}}."), "bad_input", argument = "x", call = call)
  }
  ids <- unique(as.character(x$id))
  dofs <- if (is.factor(x$dof)) levels(droplevels(x$dof)) else unique(as.character(x$dof))
  id_f <- factor(as.character(x$id), levels = ids)
  dof_i <- match(as.character(x$dof), dofs)
  recs <- lapply(split(seq_len(nrow(x)), id_f), function(rows) {
    n <- max(x$frame[rows])
    m <- matrix(NA_real_, n, length(dofs), dimnames = list(NULL, dofs))
    m[cbind(x$frame[rows], dof_i[rows])] <- x$angle[rows]
    m
  })
  first <- match(ids, as.character(x$id))
  keep <- intersect(c("grasp", "subject", "object", "trial"), names(x))
  meta <- data.frame(id = ids, stringsAsFactors = FALSE)
  for (k in keep) meta[[k]] <- if (is.factor(x[[k]])) as.character(x[[k]])[first] else x[[k]][first]
  # (a missing frame or DoF is a missing value: grasps() names the recording)
  grasps(unname(recs), meta = meta, dofs = dofs, rate = rate, unit = unit)
}

#' @export
as_grasps.default <- function(x, ...) {
  hm_abort("Cannot make a {.cls grasps} object of {.obj_type_friendly {x}}.",
           "bad_input", argument = "x", call = rlang::caller_env())
}
