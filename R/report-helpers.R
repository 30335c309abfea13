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

# The groups of types the thesis names as hard to tell apart (Jeppsson 2017,
# section 5.2; shared/thesis-tables/claims.md, G6), as Feix ids. A comparison
# constant for the report (and data-raw/calibration-report.R), never an input
# of the simulator.
thesis_confusion_groups <- function() {
  list(`adducted thumb, light tool, fixed hook` = c(4L, 5L, 15L),
       `prismatic 4/3/2 finger, writing tripod` = c(6L, 7L, 8L, 20L),
       `precision disk, precision sphere, tripod` = c(12L, 13L, 14L))
}

# Which of the groups have a cell (truth, predicted) with both in the group
# among the `top` largest off-diagonal cells of the confusion matrix `conf`
# (rows = truth, columns = predicted, dimnames = type names): one logical per
# group. confusion_groups_found() counts them.
confusion_groups_hit <- function(conf, groups = thesis_confusion_groups(), top = 10L) {
  ids <- match(rownames(conf), feix_levels())
  off <- which(row(conf) != col(conf), arr.ind = FALSE)
  o <- off[order(conf[off], decreasing = TRUE)][seq_len(min(top, length(off)))]
  o <- o[conf[o] > 0]
  ti <- ids[row(conf)[o]]
  pj <- ids[col(conf)[o]]
  vapply(groups, function(g) any(ti %in% g & pj %in% g), logical(1))
}

# The thesis' own Table 5.6 as recovered (best-guess reading; unreadable
# cells count 0), laid out as the report's confusion: rows = true
# type, columns = model, Feix names. Measured by the same rules as ours, it
# shows what the thesis' figures are on its own matrix: its ten largest
# off-diagonal cells hold only the first of its three hard-to-discern groups
# (most are types drawn to the palmar pinch model), so the confusion-group
# figure is compared with that, not with 3.
thesis_confusion_fpca <- function() {
  cells <- handmotion::thesis_results$table_5_6_cells
  lv <- feix_levels()
  m <- matrix(0, length(lv), length(lv), dimnames = list(truth = lv, predicted = lv))
  ok <- !is.na(cells$count)
  m[cbind(cells$true_id[ok], cells$model_id[ok])] <- cells$count[ok]
  m
}
