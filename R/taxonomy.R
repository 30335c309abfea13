#' The 33 grasp types of the Feix GRASP taxonomy
#'
#' One row per grasp type, numbered 1-33 as in Jeppsson (2017, Table 5.1),
#' with the classification of Feix et al. (2016): power, intermediate or
#' precision grasp; the opposition type (palm, pad or side); the virtual-finger
#' assignment (`vf1`, `vf2`, `vf3`: "palm", or finger numbers 1 = thumb to
#' 5 = little finger); and whether the thumb is abducted or adducted.
#'
#' The columns are those of Feix et al. (2016), Fig. 4, the overview of the
#' 33 types. Checked against that figure: Extension Type (18) has VF2 2-4;
#' Tripod Variation (21) is intermediate; Sphere 4 Finger (26) and Sphere 3
#' Finger (28) are pad opposition with VF1 the thumb; Ventral (32) has VF2 2.
#' In Adduction Grip (23) the object sits between the sides of index and
#' middle finger; the one virtual finger the taxonomy lists for it is 3, in
#' the place other types give VF2 (so read in a third-party annotation tool
#' built on the taxonomy; the figure itself was not at hand), so VF1 is the
#' index (2) and VF2 the middle finger (3). The simulated posture would be
#' the same either way (both fingers take the `side` role).
#'
#' @format A data frame with 33 rows and 8 columns: `id`, `name`, `class`,
#'   `opposition`, `vf1`, `vf2`, `vf3`, `thumb`.
#' @source Feix, T., Romero, J., Schmiedmayer, H.-B., Dollar, A. M. and Kragic,
#'   D. (2016). The GRASP taxonomy of human grasp types. *IEEE Transactions on
#'   Human-Machine Systems* 46(1), 66-77, Fig. 4. Built by
#'   `data-raw/feix_taxonomy.R`.
#' @examples
#' feix_taxonomy[feix_taxonomy$class == "precision", c("id", "name", "vf2")]
"feix_taxonomy"

#' The 16 joint angles (DoFs) of the HUST data glove
#'
#' In the column order of the HUST files (Jeppsson 2017, Figure 4.1). Finger
#' numbering: 1 = thumb, 2 = index, 3 = middle, 4 = ring, 5 = little finger.
#' `ABD1` is thumb abduction; every other DoF is a flexion angle.
#'
#' @format A data frame with 16 rows: `index`, `name`, `finger`, `joint`,
#'   `motion`.
#' @source Jeppsson, J. (2017). *Modeling Natural Human Hand Motion for Grasp
#'   Animation*, Figure 4.1. Built by `data-raw/feix_taxonomy.R`.
#' @examples
#' hust_dofs
"hust_dofs"

#' Published results of Jeppsson (2017), chapter 5, for comparison
#'
#' The thesis' published values, kept only as a comparison column beside the
#' package's own results ([thesis_table()]). No computation in the package
#' takes these numbers as input.
#'
#' No clean copy of the thesis was available: every value was read from a
#' PDF-to-text extraction of it. Tables 5.1, 5.2 and 5.7 came through cleanly
#' and are exact. The confusion matrices of Tables 5.6 and 5.8 were printed
#' rotated and came through garbled: single digits appear as look-alike glyphs
#' that were decoded, a few cells are "probable" readings and some could not be
#' read at all (`NA`). Their diagonals are the most reliable part (all of Table
#' 5.8's are clean; Table 5.6's types 2 and 3, 61 and 81, are medium
#' confidence: they could be 16 and 18). The per-type totals are column sums
#' with unreadable cells counted as 0, so they are lower bounds, and the
#' overall accuracies (35.1% and 64.0%) are derived from them, not stated in
#' the thesis. Table 5.3's values did not survive the extraction at all; only
#' the counts the text states about it remain.
#'
#' @format A list:
#' \describe{
#'   \item{table_5_1}{Per grasp type: `target_frames` (warping target length),
#'     `warping` ("dtw" or "linear" fallback) and `em_failed_dofs` (DoFs whose
#'     mixture fell back to a single Gaussian, numbered 1-16 as in [hust_dofs]:
#'     13 is DIP4). Exact.}
#'   \item{table_5_2}{Variance explained (percent) by two FPCs per DoF, summarised
#'     over the 16 DoFs of each model: `min`, `median`, `mean`, `max`. Exact.}
#'   \item{table_5_6_diagonal}{FPCA classifier (Table 5.6): correctly classified
#'     recordings per true type (`correct`, the diagonal cell), the column total
#'     (`total`, a lower bound: unreadable cells count as 0),
#'     `total_na_cells` (how many cells of the column could not be read) and the
#'     diagonal's `confidence` ("high" or "medium").}
#'   \item{table_5_7}{Cumulative proportion of variance explained by the 16 PCs of
#'     last-frame PCA per grasp type (`pc1` ... `pc16`). Exact.}
#'   \item{table_5_8_diagonal}{Last-frame PCA classifier (Table 5.8), as for 5.6.}
#'   \item{table_5_6_cells, table_5_8_cells}{The whole confusion matrices, one
#'     row per cell: `model_id` (row of the printed table), `true_id` (the true
#'     grasp type), `count` (best-guess reading, `NA` where nothing could be read)
#'     and `confidence` of the reading: "clean" (plain digits), "decoded" (a
#'     look-alike glyph confirmed by the table's own labels), "probable" (a
#'     plausible but unconfirmed reading) or "na".}
#'   \item{table_5_3_claims}{The counts section 5.2 states about Table 5.3
#'     (whose cell values did not survive): in how many cases a model is
#'     closest for its own type, and so on.}
#'   \item{accuracy}{Overall in-sample accuracy of both classifiers, derived by us
#'     (not stated in the thesis): the sum of the diagonals over the sum of the
#'     lower-bound totals.}
#'   \item{source}{The citation.}
#' }
#' @source Jeppsson, J. (2017). *Modeling Natural Human Hand Motion for Grasp
#'   Animation*. Master's thesis, KTH Royal Institute of Technology, Tables 5.1,
#'   5.2, 5.6, 5.7 and 5.8 and the text of section 5.2, as recovered from a text
#'   extraction (built by `data-raw/thesis_results.R`, which says how each value
#'   was read; Table 5.3's values did not survive the extraction).
#' @examples
#' thesis_results$accuracy
#' head(thesis_results$table_5_2)
#' # the diagonals of Table 5.6 that are less certain
#' subset(thesis_results$table_5_6_diagonal, confidence != "high")
"thesis_results"
