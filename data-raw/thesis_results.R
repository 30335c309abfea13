# Builds data/thesis_results.rda from the thesis' published tables, as recovered
# into ../shared/thesis-tables/ (see its README.md for how each value was read
# and how reliable it is). These numbers are a comparison column only: no
# computation in the package takes them as input.
#
# Source: Jeppsson, J. (2017). Modeling Natural Human Hand Motion for Grasp
# Animation. Master's thesis, KTH Royal Institute of Technology, chapter 5.
# Run from the package root: Rscript data-raw/thesis_results.R [path/to/thesis-tables]
args <- commandArgs(trailingOnly = TRUE)
src <- if (length(args)) args[1] else file.path("..", "shared", "thesis-tables")
stopifnot(dir.exists(src))
rd <- function(f) utils::read.csv(file.path(src, f), stringsAsFactors = FALSE, check.names = FALSE)

t51 <- rd("table_5_1.csv")
table_5_1 <- data.frame(
  grasp_id = t51$grasp_id, grasp = t51$grasp_name, target_frames = t51$target_frames,
  warping = t51$warping,
  em_failed_dofs = ifelse(is.na(t51$em_failed_dofs) | t51$em_failed_dofs == "", "",
                          gsub(";", ", ", t51$em_failed_dofs)),
  stringsAsFactors = FALSE)

t52 <- rd("table_5_2.csv")
table_5_2 <- data.frame(grasp_id = t52$grasp_id, grasp = t52$grasp_name, min = t52$min,
                        median = t52$median, mean = t52$mean, max = t52$max)

t57 <- rd("table_5_7.csv")
table_5_7 <- data.frame(grasp_id = t57$grasp_id, grasp = t57$grasp_name,
                        t57[paste0("pc", 1:16)], check.names = FALSE)

dg <- rd("diagonals.csv")
table_5_6_diagonal <- data.frame(grasp_id = dg$grasp_id, grasp = dg$grasp_name,
                                 correct = dg$fpca_correct, total = dg$fpca_total,
                                 confidence = dg$fpca_correct_confidence)
table_5_8_diagonal <- data.frame(grasp_id = dg$grasp_id, grasp = dg$grasp_name,
                                 correct = dg$lastframe_pca_correct, total = dg$lastframe_pca_total,
                                 confidence = dg$lastframe_pca_correct_confidence)

thesis_results <- list(
  table_5_1 = table_5_1,
  table_5_2 = table_5_2,
  table_5_6_diagonal = table_5_6_diagonal,
  table_5_7 = table_5_7,
  table_5_8_diagonal = table_5_8_diagonal,
  accuracy = data.frame(
    classifier = c("fpca", "last_frame"),
    correct = c(sum(dg$fpca_correct), sum(dg$lastframe_pca_correct)),
    total = c(sum(dg$fpca_total), sum(dg$lastframe_pca_total)),
    accuracy = c(sum(dg$fpca_correct) / sum(dg$fpca_total),
                 sum(dg$lastframe_pca_correct) / sum(dg$lastframe_pca_total))),
  # Section 5.2's counts about Table 5.3, whose cell values did not survive
  # the extraction (../shared/thesis-tables/claims.md).
  table_5_3_claims = data.frame(
    claim = c("model_min_own_type", "type_min_own_model", "both", "n_attracted",
              "models_never_min"),
    description = c("models whose lowest mean distance is for their own grasp type",
                    "grasp types whose lowest mean distance is in their own model",
                    "both at once",
                    "grasp types whose lowest mean distance is in the most attracting model",
                    "models that are the lowest mean distance of no grasp type"),
    thesis = c(28L, 14L, 12L, 9L, 16L), stringsAsFactors = FALSE),
  source = paste("Jeppsson, J. (2017). Modeling Natural Human Hand Motion for Grasp Animation.",
                 "Master's thesis, KTH Royal Institute of Technology. Chapter 5.")
)
save(thesis_results, file = "data/thesis_results.rda", compress = "xz", version = 2)
