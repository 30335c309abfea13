# Builds R/sysdata.rda: `simulator_defaults`, every default parameter of the
# HUST-like simulator (see ?simulate_grasps), including its calibration: the
# per-type target frame counts of Table 5.1 of Jeppsson (2017), the mean frame
# count of each grasp type's recordings after over-long ones were removed.
# Only the simulator uses these numbers; the modelling pipeline never sees them.
#
# Run from the package root:  Rscript data-raw/simulator-params.R
# The thesis tables live in the project's shared folder (no licence, never
# copied into the package); set HANDMOTION_SHARED to point elsewhere.
# Later calibration steps should change the parameters here (after the call to
# sim_default_params()) so that R/sysdata.rda stays reproducible.

pkgload::load_all(".", quiet = TRUE)

shared <- Sys.getenv("HANDMOTION_SHARED", file.path("..", "shared"))
tab <- utils::read.csv(file.path(shared, "thesis-tables", "table_5_1.csv"), stringsAsFactors = FALSE)
stopifnot(identical(tab$grasp_id, 1:33), all(tab$target_frames == round(tab$target_frames)))
stopifnot(identical(tab$grasp_name, feix_taxonomy$name))

target_frames <- data.frame(id = tab$grasp_id, name = tab$grasp_name,
                            frames = as.integer(tab$target_frames), stringsAsFactors = FALSE)

simulator_defaults <- sim_default_params(target_frames)

# --- calibration: the values data-raw/calibrate-simulator.R found -----------
# (simulator parameters only; see the Calibration section of ?simulate_grasps)
cal_file <- file.path("data-raw", "simulator-calibration.csv")
if (file.exists(cal_file)) {
  cal <- utils::read.csv(cal_file, stringsAsFactors = FALSE)
  for (el in unique(cal$parameter)) {
    rows <- cal[cal$parameter == el, ]
    if (!el %in% names(simulator_defaults)) stop("unknown simulator parameter in ", cal_file, ": ", el)
    if (all(is.na(rows$grasp_id))) {
      simulator_defaults[[el]][] <- rows$value
    } else {
      stopifnot(length(simulator_defaults[[el]]) == 33L, all(rows$grasp_id %in% 1:33))
      simulator_defaults[[el]][rows$grasp_id] <- rows$value
    }
  }
  cat("applied", nrow(cal), "calibrated values from", cal_file, "\n")
}

usethis_free_save <- function(..., file) save(..., file = file, compress = "xz", version = 2)
usethis_free_save(simulator_defaults, file = file.path("R", "sysdata.rda"))
cat("wrote R/sysdata.rda: simulator_defaults with", length(simulator_defaults), "elements\n")
