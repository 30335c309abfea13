# Helpers of the thesis report (inst/report/reproduce-thesis.Rmd), kept here
# so that the report reads as text and figures, and so that what it computes
# is tested. The report is knitted in an environment whose parent is this
# namespace (reproduce_thesis(), vignettes/reproduce-thesis.Rmd), so it calls
# these by name.

# Column alignment for a table of the report: numbers, and text that is a
# number with its marks ("31.9%", ">=245", "61?", "0.64 / 0.54", "-"), to the
# right, so that a count and a percentage side by side read as two cells;
# words to the left.
report_align <- function(d) {
  vapply(d, function(v) {
    if (is.numeric(v)) return("r")
    v <- as.character(v)
    v <- v[!is.na(v) & nzchar(trimws(v))]
    if (length(v) && all(grepl("[0-9]", v) | trimws(v) == "-") && !any(grepl("[A-Za-z]", v))) "r" else "l"
  }, character(1), USE.NAMES = FALSE)
}

# The report's confusion matrices: the heat map of autoplot.grasp_confusion()
# with text large enough to read at the page's width (counts and the key of
# grasp-type ids at 9 points and more, about 12 CSS pixels in a figure shown
# at its natural size) and a colour bar long enough that its labels stand
# apart.
report_confusion_plot <- function(x, title = NULL, normalise = FALSE, cell_pt = 9) {
  p <- ggplot2::autoplot(x, normalise = normalise)
  for (i in seq_along(p$layers)) {
    if (inherits(p$layers[[i]]$geom, "GeomText")) p$layers[[i]]$aes_params$size <- cell_pt / ggplot2::.pt
  }
  p + ggplot2::labs(title = title) +
    ggplot2::guides(fill = ggplot2::guide_colourbar(barwidth = ggplot2::unit(12, "lines"),
                                                    title.position = "top")) +
    ggplot2::theme(text = ggplot2::element_text(size = 12),
                   axis.text = ggplot2::element_text(size = 10),
                   axis.text.x = ggplot2::element_text(angle = 90, hjust = 1, vjust = 0.5),
                   legend.text = ggplot2::element_text(size = 10),
                   plot.caption = ggplot2::element_text(hjust = 0, size = 10, colour = "grey30"),
                   legend.position = "bottom")
}

# Figures drawn in parts (Appendix A: eleven grasp types a part) on one
# common scale: each part's axes cover what every part needs, so a hand is
# drawn the same size in every part (otherwise one part with an extended
# finger draws all of its hands smaller).
report_same_scale <- function(plots) {
  ranges <- lapply(plots, function(p) {
    pp <- ggplot2::ggplot_build(p)$layout$panel_params
    list(x = range(unlist(lapply(pp, `[[`, "x.range"))), y = range(unlist(lapply(pp, `[[`, "y.range"))))
  })
  x <- range(unlist(lapply(ranges, `[[`, "x")))
  y <- range(unlist(lapply(ranges, `[[`, "y")))
  out <- lapply(plots, function(p) {
    # (replacing the plot's own coord_equal(): ggplot2 says so, nothing else)
    suppressMessages(p + ggplot2::coord_equal(xlim = x, ylim = y, expand = FALSE))
  })
  # height over width of every panel, to size the figures so that the panels
  # fill the page's width
  attr(out, "aspect") <- diff(y) / diff(x)
  out
}

# How much a grasp type's recordings vary, relative to the simulator's common
# level (1): the report names types whose variation was shrunk when the
# simulator was tuned to the thesis.
report_type_variability <- function(type) {
  simulator_params()$grasp_variability[[type]]
}
