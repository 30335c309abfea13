# Labels are the user's: any string or factor level is a class; Feix names
# and ids still become the Feix factor the thesis' tables need.

recs6 <- function(k = 6, p = 4) {
  set.seed(3)
  lapply(seq_len(k), function(i) matrix(rnorm(10 * p, mean = i %% 3 * 20), 10, p,
                                        dimnames = list(NULL, paste0("c", seq_len(p)))))
}

test_that("user labels are kept as given: strings sorted, factors keep their levels", {
  g <- grasps(recs6(), meta = data.frame(grasp = rep(c("mug", "bottle", "key"), 2)))
  expect_equal(levels(g$meta$grasp), c("bottle", "key", "mug"))
  f <- factor(rep(c("mug", "bottle", "key"), 2), levels = c("mug", "key", "bottle"))
  h <- grasps(recs6(), meta = data.frame(grasp = f))
  expect_equal(levels(h$meta$grasp), c("mug", "key", "bottle"))
  expect_equal(as.character(h$meta$grasp), as.character(f))
})

test_that("Feix names in any spelling and Feix ids become the 33-level Feix factor", {
  g <- grasps(recs6(), meta = data.frame(grasp = rep(c("power sphere", "Tripod", "3"), 2)))
  expect_equal(levels(g$meta$grasp), feix_levels())
  expect_equal(as.character(g$meta$grasp[1:3]), c("Power Sphere", "Tripod", feix_levels()[3]))
  expect_true(is_feix_levels(levels(g$meta$grasp)))
})

test_that("a mix of Feix names and other labels keeps them all, with a classed warning", {
  expect_warning(g <- grasps(recs6(), meta = data.frame(grasp = rep(c("Tripod", "Tripd", "mug"), 2))),
                 class = "handmotion_warning_mixed_labels")
  expect_setequal(levels(g$meta$grasp), c("mug", "Tripd", "Tripod"))
  expect_false(is_feix_levels(levels(g$meta$grasp)))
})

test_that("every verb keys on the user's labels", {
  x <- simulate_grasps(subjects = 3, grasps = c(mug = 9, bottle = 3), objects = 1, trials = 3, seed = 2)
  expect_equal(levels(x$meta$grasp), c("mug", "bottle"))
  ms <- fit_grasp_models(x, seed = 1, mixture_components = 1)
  expect_setequal(names(ms), c("mug", "bottle"))
  new <- generate(ms, grasps = "bottle", n = 3, seed = 1)
  expect_equal(levels(new$meta$grasp), c("mug", "bottle"))
  expect_true(all(new$meta$grasp == "bottle"))
  expect_error(generate(ms, grasps = "cup"), class = "handmotion_error_unknown_grasp")
  cm <- grasp_confusion(classify(ms, x))
  expect_setequal(rownames(cm$table), c("mug", "bottle"))
  clf <- fit_grasp_classifier(x)
  expect_setequal(as.character(unique(classify(clf, x)$predictions$predicted)), c("mug", "bottle"))
  expect_s3_class(ggplot2::autoplot(x[1:2]), "ggplot")
})

test_that("the thesis' tables refuse other labels with a classed error naming the argument", {
  x <- simulate_grasps(subjects = 3, grasps = c(mug = 9, bottle = 3), objects = 1, trials = 2, seed = 2)
  ms <- fit_grasp_models(x, seed = 1, mixture_components = 1)
  err <- expect_error(thesis_table("5.1", models = ms), class = "handmotion_error_not_feix_labels")
  expect_equal(err$argument, "models")
  expect_match(conditionMessage(err), "Feix")
})
