# Degenerate data: input a fit accepts with a documented fallback but which is
# almost never what the user meant (one-frame or identical recordings, more
# components than the data's rank, a mixture with more components than the
# recordings can carry, an alignment that fell back to linear warping). The
# fallback stays where it is the right answer (the result is usable), and it
# is said at the top level: the result carries a `degenerate_data` table (`class`,
# `message`) that print() shows, and the user-facing function raises one
# warning of family handmotion_warning_degenerate (?handmotion_errors) whose
# classes are every class in the table.

empty_degenerate_notes <- function() {
  data.frame(class = character(), message = character(), stringsAsFactors = FALSE)
}

add_degenerate_note <- function(notes, class, message) {
  rbind(notes, data.frame(class = class, message = message, stringsAsFactors = FALSE))
}

# One classed warning for all notes of one result, `headline` saying which
# result. Silent without notes.
warn_degenerate <- function(notes, headline) {
  if (is.null(notes) || nrow(notes) == 0L) return(invisible(notes))
  # the notes go into a cli template: escape braces
  esc <- function(s) gsub("([{}])", "\\1\\1", s)
  bullets <- stats::setNames(esc(notes$message), rep("!", nrow(notes)))
  hm_warn(c(esc(headline), bullets,
            i = "{.code print()} of the result lists them; {.code $degenerate_data} holds them."),
          unique(notes$class), degenerate_data = notes)
}

# The lines print() methods show for the notes.
format_degenerate <- function(notes, indent = "  ") {
  if (is.null(notes) || nrow(notes) == 0L) return(character())
  paste0(indent, "degenerate data: ", notes$message)
}

# What of a fitted grasp model came from degenerate data. `n_frames` are the
# frame counts of the recordings the fit was given.
model_degeneracies <- function(model, n_frames) {
  notes <- empty_degenerate_notes()
  single <- sum(n_frames < 2L)
  # (n_frames named by recording id: the notes name the recordings)
  which_ones <- function(sel) if (is.null(names(n_frames))) "" else paste0(" (", name_list(names(n_frames)[sel]), ")")
  if (single > 0L) {
    notes <- add_degenerate_note(notes, "one_frame", sprintf(
      "%d of %d recordings ha%s a single frame%s: no motion to align or model",
      single, length(n_frames), if (single == 1L) "s" else "ve", which_ones(n_frames < 2L)))
  }
  short <- n_frames >= 2L & n_frames < min_motion_frames
  if (any(short)) {
    notes <- add_degenerate_note(notes, "short_recordings", sprintf(
      "%d of %d recordings ha%s fewer than %d frames%s: too short to show a motion, fitted all the same",
      sum(short), length(n_frames), if (sum(short) == 1L) "s" else "ve", min_motion_frames, which_ones(short)))
  }
  fb <- model$fallbacks
  # channels flagged stuck when the data were built were said once there
  const <- setdiff(fb$dof[fb$step == "fpca"], model$stuck)
  if (length(const) == length(model$dofs) && isTRUE(model$warp$constant)) {
    notes <- add_degenerate_note(notes, "identical_recordings",
      "the recordings do not vary: every DoF and the warps are constant, so every generated grasp is the mean")
  } else if (length(const)) {
    notes <- add_degenerate_note(notes, "constant_dofs", sprintf(
      "%d DoF%s do%s not vary (%s): FPCs set to zero", length(const),
      if (length(const) == 1L) "" else "s", if (length(const) == 1L) "es" else "", name_list(const)))
  }
  rank <- fb$dof[fb$step == "fpca_rank"]
  if (length(rank)) {
    notes <- add_degenerate_note(notes, "rank_deficient", sprintf(
      "more FPCs (%d) than the rank of the curves for %d DoF%s (%s): the extra components are zero",
      model$settings$ncomp, length(rank), if (length(rank) == 1L) "" else "s", name_list(rank)))
  }
  lin <- fb$reason[fb$step == "warping"]
  if (length(lin)) notes <- add_degenerate_note(notes, "linear_fallback", lin[1])
  small <- fb$step %in% c("mixture", "warp_mixture") &
    grepl("too few points|all points identical|singular sample covariance", fb$reason)
  if (any(small)) {
    where <- ifelse(is.na(fb$dof[small]), "warps", fb$dof[small])
    notes <- add_degenerate_note(notes, "small_mixture", sprintf(
      "%d mixture%s cannot carry %d components and %s one Gaussian (%s): %s",
      sum(small), if (sum(small) == 1L) "" else "s", model$settings$mixture_components,
      if (sum(small) == 1L) "is" else "are", name_list(where), sub("^single Gaussian: ", "", fb$reason[small][1])))
  }
  notes
}

# What of an alignment (align_recordings()) came from degenerate data.
alignment_degeneracies <- function(al, recs, window) {
  notes <- empty_degenerate_notes()
  n_frames <- vapply(recs, nrow, integer(1))
  single <- sum(n_frames < 2L)
  if (single > 0L) {
    notes <- add_degenerate_note(notes, "one_frame", sprintf(
      "%d of %d recordings ha%s a single frame: no motion to align", single, length(recs),
      if (single == 1L) "s" else "ve"))
  }
  bad <- names(recs)[!vapply(recs, function(r) all(is.finite(r)), logical(1))]
  if (length(bad)) {
    notes <- add_degenerate_note(notes, "non_finite", sprintf(
      "%d of %d recordings hold%s NaN or infinite values (%s): their warped curves do too",
      length(bad), length(recs), if (length(bad) == 1L) "s" else "", name_list(bad)))
  }
  if (!is.null(window) && window == 0) {
    notes <- add_degenerate_note(notes, "zero_window",
      "`window = 0` leaves dynamic time warping only the diagonal path: the warps are linear")
  }
  if (identical(al$method, "linear")) {
    notes <- add_degenerate_note(notes, "linear_fallback", paste("linear warping:", al$fallback_reason))
  }
  notes
}

# "a, b, c" or "a, b, c and 4 more".
name_list <- function(x, max = 3L) {
  x <- as.character(x)
  if (length(x) <= max) return(paste(x, collapse = ", "))
  sprintf("%s and %d more", paste(x[seq_len(max)], collapse = ", "), length(x) - max)
}
