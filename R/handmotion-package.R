#' handmotion: modelling natural human hand motion for grasp animation
#'
#' One data class flows through the package: [grasps()], a set of joint-angle
#' recordings with their metadata. Recordings come from the embedded simulator
#' [simulate_grasps()] or from real files; models fitted per grasp type
#' generate new recordings of the same class.
#'
#' The methods follow Jeppsson, J. (2017). *Modeling Natural Human Hand Motion
#' for Grasp Animation*. Master's thesis, KTH Royal Institute of Technology.
#'
#' @keywords internal
#' @useDynLib handmotion, .registration = TRUE
"_PACKAGE"

#' @importFrom rlang .data
#' @importFrom ggplot2 autoplot
NULL

#' @export
ggplot2::autoplot
