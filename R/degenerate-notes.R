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
    notes <- add_degenerate_note(notes, "one_frame", as.character(cli::pluralize(
      "{single} of {length(n_frames)} recordings {cli::qty(single)}ha{?s/ve} a single frame{which_ones(n_frames < 2L)}: no motion to align or model")))
  }
  short <- n_frames >= 2L & n_frames < min_motion_frames
  if (any(short)) {
    notes <- add_degenerate_note(notes, "short_recordings", as.character(cli::pluralize(paste(
      "{sum(short)} of {length(n_frames)} recordings {cli::qty(sum(short))}ha{?s/ve} fewer than {min_motion_frames}",
      "frames{which_ones(short)}: too short to show a motion, fitted all the same"))))
  }
  fb <- model$fallbacks
  # channels flagged stuck when the data were built were said once there
  const <- setdiff(fb$dof[fb$step == "fpca"], model$stuck)
  if (length(const) == length(model$dofs) && isTRUE(model$warp$constant)) {
    notes <- add_degenerate_note(notes, "identical_recordings",
      "the recordings do not vary: every DoF and the warps are constant, so every generated grasp is the mean")
  } else if (length(const)) {
    notes <- add_degenerate_note(notes, "constant_dofs", as.character(cli::pluralize(
      "{length(const)} DoF{?s} do{?es/} not vary ({name_list(const)}): FPCs set to zero")))
  }
  rank <- fb$dof[fb$step == "fpca_rank"]
  if (length(rank)) {
    notes <- add_degenerate_note(notes, "rank_deficient", as.character(cli::pluralize(paste(
      "more FPCs ({as.integer(model$settings$ncomp)}) than the rank of the curves for {length(rank)} DoF{?s}",
      "({name_list(rank)}): the extra components are zero"))))
  }
  lin <- fb$reason[fb$step == "warping"]
  if (length(lin)) notes <- add_degenerate_note(notes, "linear_fallback", lin[1])
  small <- fb$step %in% c("mixture", "warp_mixture") &
    grepl("too few points|all points identical|singular sample covariance", fb$reason)
  if (any(small)) {
    where <- ifelse(is.na(fb$dof[small]), "warps", fb$dof[small])
    why <- sub("^single Gaussian: ", "", fb$reason[small][1])
    notes <- add_degenerate_note(notes, "small_mixture", as.character(cli::pluralize(paste(
      "{sum(small)} mixture{?s} cannot carry {as.integer(model$settings$mixture_components)} components",
      "and {cli::qty(sum(small))}{?is/are} one Gaussian ({name_list(where)}): {why}"))))
  }
  notes
}

# What of an alignment (align_recordings()) came from degenerate data.
alignment_degeneracies <- function(al, recs, window) {
  notes <- empty_degenerate_notes()
  n_frames <- vapply(recs, nrow, integer(1))
  single <- sum(n_frames < 2L)
  if (single > 0L) {
    notes <- add_degenerate_note(notes, "one_frame", as.character(cli::pluralize(
      "{single} of {length(recs)} recordings {cli::qty(single)}ha{?s/ve} a single frame: no motion to align")))
  }
  bad <- names(recs)[!recordings_finite(recs)]
  if (length(bad)) {
    notes <- add_degenerate_note(notes, "non_finite", as.character(cli::pluralize(paste(
      "{length(bad)} of {length(recs)} recordings {cli::qty(length(bad))}hold{?s/} NaN or infinite values",
      "({name_list(bad)}): their warped curves do too"))))
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
