# calibration_report() and its parts are a maintainer's tool of the simulator's
# calibration (data-raw/calibration-report.R), not installed: the tests that
# use them source it from the source tree and skip where it is absent (an
# installed package, R CMD check).
# (from tests/testthat/, where tests run, or from the package root, where
# pkgload::load_all() sources the helpers)
calibration_report_file <- Filter(file.exists, c(file.path("..", "..", "data-raw", "calibration-report.R"),
                                                  file.path("data-raw", "calibration-report.R")))[1]
if (!is.na(calibration_report_file)) source(calibration_report_file, local = TRUE)

skip_without_calibration_report <- function() {
  skip_if(is.na(calibration_report_file), "data-raw/ not available (installed package)")
}
