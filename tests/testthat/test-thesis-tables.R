# The table functions on a small fitted design: their shape and columns, the
# thesis columns equal to thesis_results, and our columns equal to the values
# recomputed directly from the fitted objects (so they cannot depend on the
# published numbers).

thesis_rows <- function(tab, ids) tab[match(ids, tab$grasp_id), , drop = FALSE]

test_that("table_5_1 lays our warping and fallbacks beside the thesis'", {
  d <- small_design()
  t51 <- thesis_table("5.1", models = d$ms)
  expect_s3_class(t51, "data.frame")
  expect_named(t51, c("grasp_id", "grasp", "n_used", "n_overlong", "n_degenerate", "target_frames",
                      "warping", "em_fallback_dofs", "thesis_target_frames", "thesis_warping",
                      "thesis_em_failed_dofs"))
  expect_equal(t51$grasp_id, c(3L, 9L, 17L))
  s <- summary(d$ms)
  expect_equal(t51$target_frames, s$target_length)
  expect_equal(t51$warping, s$warping)
  expect_equal(t51$em_fallback_dofs, s$em_fallback)
  expect_equal(t51$n_used, s$n_used)
  th <- thesis_rows(thesis_results$table_5_1, t51$grasp_id)
  expect_equal(t51$thesis_target_frames, th$target_frames)
  expect_equal(t51$thesis_warping, th$warping)
  expect_equal(t51$thesis_em_failed_dofs, th$em_failed_dofs)
})

test_that("table_5_2 summarises variance explained over DoFs, ours beside the thesis'", {
  d <- small_design()
  t52 <- thesis_table("5.2", models = d$ms)
  expect_named(t52, c("grasp_id", "grasp", "min", "thesis_min", "median", "thesis_median", "mean",
                      "thesis_mean", "diff_mean", "max", "thesis_max"))
  expect_equal(nrow(t52), 3L)
  # recomputed from the models themselves: percent of variance of two FPCs per DoF
  ve <- lapply(d$ms, function(m) 100 * rowSums(model_var_explained(m)))
  expect_equal(t52$min, unname(vapply(ve, min, numeric(1))))
  expect_equal(t52$median, unname(vapply(ve, stats::median, numeric(1))))
  expect_equal(t52$mean, unname(vapply(ve, mean, numeric(1))))
  expect_equal(t52$max, unname(vapply(ve, max, numeric(1))))
  expect_true(all(t52$min <= t52$median & t52$median <= t52$max & t52$max <= 100))
  th <- thesis_rows(thesis_results$table_5_2, t52$grasp_id)
  expect_equal(t52$thesis_mean, th$mean)
  expect_equal(t52$thesis_min, th$min)
  expect_equal(t52$diff_mean, t52$mean - t52$thesis_mean)
})

test_that("table_5_3 is the distance table with ids as columns, and its claims count its minima", {
  d <- small_design()
  t53 <- thesis_table("5.3", classification = d$cl)
  expect_named(t53, c("model_id", "model", "3", "9", "17"))
  expect_equal(t53$model_id, c(3L, 9L, 17L))
  dt <- distance_table(d$cl)
  expect_equal(unname(as.matrix(t53[c("3", "9", "17")])), unname(unclass(dt)))
  # a model passed with its data gives the same table
  expect_equal(thesis_table("5.3", classification = d$ms, x = d$g), t53)

  claims <- thesis_table("5.3 claims", classification = d$cl)
  expect_named(claims, c("claim", "description", "ours", "thesis"))
  expect_equal(claims$claim, thesis_results$table_5_3_claims$claim)
  expect_equal(claims$thesis, thesis_results$table_5_3_claims$thesis)
  mins <- distance_minima(dt)
  expect_equal(claims$ours, as.integer(unlist(mins[claims$claim])))
  # recomputed by hand: models whose row minimum is their own type
  own_row <- sum(colnames(dt)[apply(dt, 1, which.min)] == rownames(dt))
  expect_equal(claims$ours[claims$claim == "model_min_own_type"], own_row)
})

test_that("tables 5.6 and 5.8 hold the confusion diagonal, with the held-out recall when given", {
  d <- small_design()
  t56 <- thesis_table("5.6", confusion = d$cl)
  expect_named(t56, c("grasp_id", "grasp", "correct", "total", "recall", "thesis_correct",
                      "thesis_total", "thesis_recall"))
  p <- d$cl$predictions
  truth <- as.character(p$truth)
  ok <- truth == as.character(p$predicted)
  expect_equal(t56$correct, as.integer(tapply(ok, factor(truth, levels = t56$grasp), sum)))
  expect_equal(t56$total, as.integer(table(factor(truth, levels = t56$grasp))))
  expect_equal(t56$recall, t56$correct / t56$total)
  th <- thesis_rows(thesis_results$table_5_6_diagonal, t56$grasp_id)
  expect_equal(t56$thesis_correct, th$correct)
  expect_equal(t56$thesis_recall, th$correct / th$total)

  t58 <- thesis_table("5.8", confusion = d$cl_lf, held_out = d$ev$confusion)
  expect_named(t58, c("grasp_id", "grasp", "correct", "total", "recall", "recall_held_out",
                      "thesis_correct", "thesis_total", "thesis_recall"))
  held <- d$ev$predictions
  held_ok <- as.character(held$truth) == as.character(held$predicted)
  held_ok[is.na(held_ok)] <- FALSE
  expect_equal(t58$recall_held_out,
               as.numeric(tapply(held_ok, factor(as.character(held$truth), levels = t58$grasp), mean)))
  th8 <- thesis_rows(thesis_results$table_5_8_diagonal, t58$grasp_id)
  expect_equal(t58$thesis_total, th8$total)
})

test_that("thesis_results' confusion matrices agree with its diagonals, totals and accuracies", {
  for (k in c("5_6", "5_8")) {
    cells <- thesis_results[[paste0("table_", k, "_cells")]]
    diag <- thesis_results[[paste0("table_", k, "_diagonal")]]
    expect_equal(nrow(cells), 33L * 33L)
    expect_setequal(unique(cells$confidence), c("clean", "decoded", "probable", "na"))
    # NA exactly where nothing could be read
    expect_equal(is.na(cells$count), cells$confidence == "na")
    on_diag <- cells[cells$model_id == cells$true_id, ]
    expect_equal(on_diag$count[order(on_diag$true_id)], diag$correct)
    # a total is the column sum with unreadable cells counted as 0: a lower bound
    col_sum <- tapply(ifelse(is.na(cells$count), 0, cells$count), cells$true_id, sum)
    expect_equal(as.integer(col_sum), diag$total)
    expect_equal(as.integer(tapply(is.na(cells$count), cells$true_id, sum)), diag$total_na_cells)
  }
  # the overall accuracies are derived from the diagonals and the lower-bound totals
  d6 <- thesis_results$table_5_6_diagonal
  expect_equal(thesis_results$accuracy$accuracy[1], sum(d6$correct) / sum(d6$total))
  expect_equal(sort(d6$grasp_id[d6$confidence != "high"]), c(2L, 3L))
  expect_true(all(thesis_results$table_5_8_diagonal$confidence == "high"))
})

test_that("table_5_7 interleaves our cumulative variance with the thesis'", {
  d <- small_design()
  t57 <- thesis_table("5.7", fit = d$lf, pcs = 1:3)
  expect_named(t57, c("grasp_id", "grasp", "pc1", "thesis_pc1", "pc2", "thesis_pc2", "pc3", "thesis_pc3"))
  cv <- cumulative_variance(d$lf)
  expect_equal(t57$pc3, cv$pc3[match(t57$grasp_id, cv$grasp_id)])
  expect_equal(t57$thesis_pc2, thesis_rows(thesis_results$table_5_7, t57$grasp_id)$pc2)
  expect_true(all(diff(unlist(t57[1, c("pc1", "pc2", "pc3")])) >= 0))
})

test_that("table functions reject the wrong objects with a classed error", {
  expect_error(thesis_table("5.1", models = list()), class = "handmotion_error_bad_input")
  expect_error(thesis_table("5.2", models = "models"), class = "handmotion_error_bad_input")
  expect_error(thesis_table("5.7", fit = list()), class = "handmotion_error_bad_input")
})

test_that("printed tables are stable", {
  d <- small_design()
  t51 <- thesis_table("5.1", models = d$ms)
  expect_snapshot(print(t51[c("grasp", "target_frames", "thesis_target_frames", "warping", "thesis_warping")],
                        row.names = FALSE))
  expect_snapshot(print(thesis_table("5.3 claims", classification = d$cl)[c("claim", "thesis")], row.names = FALSE))
})

test_that("thesis_table() refuses unknown tables and arguments", {
  d <- small_design()
  # not a guess at the nearest id ("5.9" is as near "5.1" as "5.8"): the tables there are
  cnd <- expect_error(thesis_table("5.9", models = d$ms), class = "handmotion_error_bad_input")
  expect_false(grepl("Did you mean", conditionMessage(cnd)))
  for (id in c("5.1", "5.2", "5.3", "5.3 claims", "5.6", "5.7", "5.8")) {
    expect_match(conditionMessage(cnd), sprintf('"%s": ', id), fixed = TRUE)
  }
  expect_snapshot(thesis_table("5.9"), error = TRUE)
  expect_identical(thesis_table(5.1, models = d$ms), thesis_table("5.1", models = d$ms))
  expect_error(thesis_table("5.1", d$ms), class = "handmotion_error_bad_input")
  expect_error(thesis_table("5.1", model = d$ms), class = "handmotion_error_bad_input")
  expect_identical(attr(thesis_table("5.3 claims", classification = d$cl), "most_attracting"),
                   distance_minima(distance_table(d$cl))$most_attracting)
})
