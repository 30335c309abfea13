#' The 33 grasp types of the Feix GRASP taxonomy
#'
#' One row per grasp type, numbered 1-33 as in Jeppsson (2017, Table 5.1),
#' with the classification of Feix et al. (2016): power, intermediate or
#' precision grasp; the opposition type (palm, pad or side); the virtual-finger
#' assignment (`vf1`, `vf2`, `vf3`: "palm", or finger numbers 1 = thumb to
#' 5 = little finger); and whether the thumb is abducted or adducted.
#'
#' @format A data frame with 33 rows and 8 columns: `id`, `name`, `class`,
#'   `opposition`, `vf1`, `vf2`, `vf3`, `thumb`.
#' @source Feix, T., Romero, J., Schmiedmayer, H.-B., Dollar, A. M. and Kragic,
#'   D. (2016). The GRASP taxonomy of human grasp types. *IEEE Transactions on
#'   Human-Machine Systems* 46(1), 66-77. Built by `data-raw/feix_taxonomy.R`.
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
