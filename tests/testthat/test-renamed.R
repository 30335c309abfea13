# The user API: every export is a verb a user meets in the README, a
# vignette or the reference index, and every name of ?handmotion-renamed is
# gone from the exports (it is an alias of that help page only).

source_root <- function() test_path("..", "..")

test_that("every export appears in the README, a vignette or the reference index", {
  root <- source_root()
  skip_if_not(file.exists(file.path(root, "_pkgdown.yml")), "needs the source tree")
  exports <- setdiff(getNamespaceExports("handmotion"), "autoplot")  # autoplot: ggplot2's generic
  rmd <- list.files(file.path(root, "vignettes"), pattern = "\\.Rmd$", recursive = TRUE, full.names = TRUE)
  prose <- paste(unlist(lapply(c(file.path(root, "README.md"), rmd), readLines, warn = FALSE)), collapse = "\n")
  index <- trimws(sub("^\\s*-\\s*", "", grep("^\\s*-\\s*[A-Za-z_.`]", readLines(file.path(root, "_pkgdown.yml")),
                                             value = TRUE)))
  seen <- vapply(exports, function(f) grepl(paste0(f, "("), prose, fixed = TRUE) || f %in% index, logical(1))
  expect_equal(exports[!seen], character(0))
})

test_that("the renamed names are not exported and the surface stays small", {
  rd <- tools::Rd_db(dir = source_root())
  skip_if(length(rd) == 0L, "needs the source tree")
  renamed <- rd[["handmotion-renamed.Rd"]]
  aliases <- unlist(lapply(renamed[vapply(renamed, attr, "", "Rd_tag") == "\\alias"], as.character))
  exports <- getNamespaceExports("handmotion")
  expect_equal(intersect(aliases, exports), character(0))
  expect_true(all(c("fit_last_frame_pca", "fit_weighted_fpca", "rank_markers", "compare_marker_sets",
                    "hand_pose") %in% aliases))
  # about 35 verbs, the seven of your own glove (profiles, reading, calibration,
  # motion) and the Python front end's one entry (issue 41: at most 48)
  expect_lte(length(exports), 48L)
})

test_that("an argument renamed by what it counts is a classed error giving the new name", {
  g <- simulate_grasps(subjects = 3, grasps = 1:2, objects = 1, trials = 2, seed = 1)
  one <- g[g$meta$grasp == levels(droplevels(g$meta$grasp))[1]]
  # fit_grasp_model(k = 2) would otherwise set keep_data by partial matching
  expect_error(fit_grasp_model(one, k = 2), "mixture_components", class = "handmotion_error_bad_input")
  expect_error(fit_grasp_models(g, k = 2), "mixture_components", class = "handmotion_error_bad_input")
  expect_error(fit_grasp_classifier(g, method = "last_frame", k = 2), "ncomp",
               class = "handmotion_error_bad_input")
  expect_error(fit_handover(g, n_markers = 3, k = 40), "neighbours", class = "handmotion_error_bad_input")
  # and the new names do what the old ones did
  expect_equal(fit_grasp_model(one, mixture_components = 1)$settings$mixture_components, 1L)
  expect_equal(fit_grasp_classifier(g, method = "last_frame", ncomp = 2)$ncomp, 2L)
  expect_equal(fit_handover(g, n_markers = 3, neighbours = 40)$neighbours_used, 40L)
})

test_that("newdata is new_data everywhere: the old name is a classed error naming the new one", {
  g <- simulate_grasps(subjects = 3, grasps = 17, objects = 1, trials = 2, seed = 1)
  ho <- fit_handover(g, n_markers = 3)
  expect_error(predict(ho, newdata = g), "new_data", class = "handmotion_error_bad_input")
  m <- fit_grasp_model(g, seed = 1)
  expect_error(ggplot2::autoplot(m, type = "projection", newdata = g), "new_data",
               class = "handmotion_error_bad_input")
  # and the new name does what the old one did
  expect_equal(predict(ho, new_data = g[1])$recordings, predict(ho, g[1])$recordings)
  expect_s3_class(ggplot2::autoplot(m, type = "projection", new_data = g), "ggplot")
})

test_that("one word, one meaning: each old argument name is a classed error naming the new one", {
  g <- simulate_grasps(subjects = 3, grasps = c(17, 31), objects = 1, trials = 2, seed = 1)
  ms <- fit_grasp_models(g, seed = 1)
  # grasp -> grasps (selecting types); `grasp =` would reach `grasps` by partial matching
  expect_error(generate(ms, grasp = 17, n = 1), "grasps", class = "handmotion_error_bad_input")
  expect_error(generate(ms[[1]], grasp = 17, n = 1), "grasps", class = "handmotion_error_bad_input")
  expect_error(simulate(ms, grasp = 17), "grasps", class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(g, type = "frame_counts", grasp = 17), "grasps",
               class = "handmotion_error_bad_input")
  expect_identical(generate(ms, grasps = 31, n = 2, seed = 3), generate(ms, grasps = "Ring", n = 2, seed = 3))
  # fit_grasp_model()'s own `grasp` (the one type's label) is no rename
  expect_equal(fit_grasp_model(g, grasp = "Ring", seed = 1)$grasp, "Ring")
  # overlong (flag of the simulator) -> plant_overlong; the rule keeps `overlong`
  expect_error(simulate_grasps(subjects = 2, grasps = 17, overlong = FALSE), "plant_overlong",
               class = "handmotion_error_bad_input")
  planted <- simulate_grasps(subjects = 2, grasps = 17, objects = 1, trials = 2, seed = 2, plant_overlong = TRUE)
  none <- simulate_grasps(subjects = 2, grasps = 17, objects = 1, trials = 2, seed = 2, plant_overlong = FALSE)
  expect_false(any(none$meta$overlong))
  expect_identical(planted$meta$id, none$meta$id)
  # markers: a marker set everywhere; a count is n_markers
  expect_error(fit_handover(g, markers = 3), "n_markers", class = "handmotion_error_bad_markers")
  ho <- fit_handover(g, n_markers = 3)
  expect_identical(fit_handover(g, markers = ho$markers)$markers, ho$markers)
  expect_error(fit_handover(g, n_markers = 0), class = "handmotion_error_bad_markers")
  # loso_folds -> folds
  expect_error(reproduce_thesis(tempfile(), subjects = 2, loso_folds = 2), "folds",
               class = "handmotion_error_bad_input")
})
