# A reference database of some grasp types and subjects, and a test set of
# unseen types performed by unseen subjects (the paper's letters vs words).
handover_split <- function() {
  g <- simulate_grasps(subjects = 6, grasps = 1:12, objects = 1, trials = 1, seed = 2,
                       plant_overlong = FALSE)
  types <- levels(droplevels(g$meta$grasp))
  subj <- unique(g$meta$subject)
  list(ref = g[g$meta$grasp %in% types[1:9] & g$meta$subject %in% subj[1:4]],
       test = g[!g$meta$grasp %in% types[1:9] & !g$meta$subject %in% subj[1:4]])
}
