# How the tables people read print: thesis_table() and summary(<grasp_evaluation>)
# return numbers (shares as fractions, so that they can be computed with); a person reading the printed
# table reads shares as percentages and needs no more decimals than the
# thesis printed. The data frame itself is unchanged: only print() formats.

# Mark a thesis table for printing: `percent` names the columns holding
# shares (0-1) printed as percentages, `digits` the decimals of the other
# numeric columns.
new_thesis_table <- function(x, id, percent = character(), digits = 1L) {
  attr(x, "thesis_table") <- list(id = id, percent = percent, digits = digits)
  class(x) <- unique(c("thesis_table", class(x)))
  x
}

#' @export
print.thesis_table <- function(x, ...) {
  fmt <- attr(x, "thesis_table")
  out <- as.data.frame(unclass_thesis_table(x), stringsAsFactors = FALSE)
  for (nm in names(out)) {
    v <- out[[nm]]
    if (!is.numeric(v)) next
    if (nm %in% fmt$percent) {
      out[[nm]] <- ifelse(is.na(v), NA_character_, sprintf("%.1f%%", 100 * v))
    } else if (!is.integer(v) && !all(is.na(v) | v == round(v))) {
      out[[nm]] <- ifelse(is.na(v), NA_character_, formatC(v, format = "f", digits = fmt$digits))
    }
  }
  # one row per grasp type, named in its own columns: no row names
  args <- list(...)
  if (is.null(args$row.names)) args$row.names <- FALSE
  do.call(print, c(list(out), args))
  invisible(x)
}

unclass_thesis_table <- function(x) {
  attr(x, "thesis_table") <- NULL
  class(x) <- setdiff(class(x), "thesis_table")
  x
}

# summary(<grasp_evaluation>): every metric is a share (accuracy, recall,
# precision), held out beside in-sample, printed as percentages.
#' @export
print.grasp_evaluation_summary <- function(x, ...) {
  out <- as.data.frame(x[c(".metric", "class", "held_out", "in_sample")])
  class(out) <- "data.frame"
  out$class[is.na(out$class)] <- ""
  # words left-aligned (padded), percentages right-aligned
  for (i in 1:2) {
    w <- max(nchar(c(names(out)[i], out[[i]])))
    out[[i]] <- formatC(out[[i]], width = -w)
    names(out)[i] <- formatC(names(out)[i], width = -w)
  }
  for (nm in c("held_out", "in_sample")) {
    out[[nm]] <- ifelse(is.na(out[[nm]]), "-", sprintf("%.1f%%", 100 * out[[nm]]))
  }
  print(out, row.names = FALSE, right = TRUE, ...)
  invisible(x)
}
