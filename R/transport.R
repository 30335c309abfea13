# Recordings on their way to a future's worker. A type of ten times the
# default data is 2,700 small matrices, each with its dimnames; serialised to
# a worker's socket, every matrix is a handful of small writes, and the main
# process of a two-worker fit spent 5.5 s of system time in a million of
# them while both workers waited for their next type. Packed, a type is one
# vector of all its values and the frame counts: a few large writes. The
# worker unpacks it into the same recordings, identical to the bit.
# Sequential plans evaluate in the main process: nothing is packed there.

# A grasps set for a worker: the set without its recordings, plus their
# values one recording after the other (`values`) and frame counts. Sets whose recordings are not all
# double matrices named as the set's DoFs (nothing else), and anything that
# is not a set (NULL: no temperature sample), go as they are.
pack_for_worker <- function(x) {
  if (!inherits(x, "grasps") || !ships_to_workers()) return(x)
  recs <- x$recordings
  # each matrix's values one after the other, copied in C
  # (src/stack-values.c, NULL unless every recording is plain; rbind() of
  # 2,700 matrices with column names took as long as serialising them,
  # unlist() a second for the 33 types)
  values <- .Call(hm_stack_values, recs, x$dofs)
  if (is.null(values)) return(x)
  shell <- unclass(x)
  shell$recordings <- list()       # (kept in its place among the fields)
  structure(list(shell = shell, class = class(x), values = values,
                 n_frames = vapply(recs, nrow, integer(1)), ids = names(recs)),
            class = "handmotion_packed")
}

# The set pack_for_worker() packed (any other argument as it is).
unpack_on_worker <- function(p) {
  if (!inherits(p, "handmotion_packed")) return(p)
  p <- unclass(p)
  x <- p$shell
  # (in C, src/stack-values.c: each recording allocated and copied once)
  x$recordings <- .Call(hm_unstack_values, p$values, p$n_frames, x$dofs, p$ids)
  structure(x, class = p$class)
}

# Whether futures run outside this R process under the current plan.
ships_to_workers <- function() !inherits(future::plan("next"), "uniprocess")
