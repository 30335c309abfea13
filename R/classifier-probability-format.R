# Probabilities as people read them. A discriminant's softmax is often 1 -
# 1e-21 for one class and 1e-21 for the rest: stored as such (callers
# compute with them), printed as "1" and "0" or as 1.000000e+00
# 1.715671e-21, which claims a certainty or a precision the model does not
# have. Printed here with three decimals, and beyond them as "<0.001" and
# ">0.999", as format.pval() does for p-values; the numbers are not changed.

# Character probabilities, three decimals, the ends bounded.
format_probability <- function(p, digits = 3L) {
  eps <- 10^-digits
  p <- as.vector(p)  # (the numbers only: formatC() would keep a vector's attributes)
  out <- formatC(p, format = "f", digits = digits)
  out[!is.na(p) & p < eps / 2] <- paste0("<", formatC(eps, format = "f", digits = digits))
  out[!is.na(p) & p >= 1 - eps / 2] <- paste0(">", formatC(1 - eps, format = "f", digits = digits))
  out[is.na(p)] <- NA_character_
  out
}

# The class probabilities update() of a recognition stream returns: a named
# double vector (attributes `frames`, `ms`, `motion`) whose print() reads.
new_grasp_probabilities <- function(p, ...) {
  structure(p, ..., class = "grasp_probabilities")
}

# A subset (sort(), head(), p[1:3]) keeps the class, so the most likely
# types print as the whole vector does.
#' @export
`[.grasp_probabilities` <- function(x, i) {
  new_grasp_probabilities(unclass(x)[i], frames = attr(x, "frames"), ms = attr(x, "ms"),
                          motion = attr(x, "motion"))
}

#' @export
format.grasp_probabilities <- function(x, ...) {
  stats::setNames(format_probability(unclass(x)), names(x))
}

#' @export
print.grasp_probabilities <- function(x, ...) {
  print(format(x), quote = FALSE, right = TRUE)
  ms <- attr(x, "ms")
  if (!is.null(ms)) {
    frames <- as.integer(attr(x, "frames"))
    cli::cat_line(cli::pluralize("# after {frames} frame{?s} ({sprintf('%.0f', ms)} ms)"),
                  if (isFALSE(attr(x, "motion"))) ", before the motion started: the prior")
  }
  invisible(x)
}
