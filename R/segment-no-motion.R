# Recordings in which find_motion() found no motion are kept whole and said
# (trim_motion()). A call that trims the same recordings many times (each
# type's fit, the temperature sample, each fold's fit and projection, on
# the workers too) says them once, for the set it was given: the flexglove
# article printed the same rest-only recording eight times, as "1 of 45",
# "1 of 264", "1 of 90", ..., and a message relayed from a future's worker
# lost its line end, so the next output ran on behind it.

# The message of trim_motion(): `ids` and `status` of the recordings kept
# whole, `n` the recordings looked at. The ids and statuses travel with the
# condition, so say_no_motion_once() can merge messages from many calls.
inform_no_motion <- function(ids, status, n) {
  shown <- utils::head(paste0(ids, " (", status, ")"), 10)
  more <- if (length(ids) > 10) " ..." else ""
  cli::cli_inform(c(i = "No motion found in {length(ids)} of {n} recording{?s}, kept whole: {.val {shown}}{more}."),
                  class = "handmotion_message_no_motion", ids = ids, status = status)
}

# Evaluate `expr`, holding back every no-motion message it raises (also
# those relayed from futures), then say them as one for the `n` recordings
# of the caller's set. Returns `expr`'s value.
say_no_motion_once <- function(expr, n) {
  held <- list()
  value <- withCallingHandlers(expr, handmotion_message_no_motion = function(m) {
    held[[length(held) + 1L]] <<- data.frame(id = m$ids, status = m$status, stringsAsFactors = FALSE)
    invokeRestart("muffleMessage")
  })
  if (length(held)) {
    d <- do.call(rbind, held)
    d <- d[!duplicated(d$id), , drop = FALSE]
    inform_no_motion(d$id, d$status, n)
  }
  value
}
