# Every recording of a set checked in one compiled pass
# (src/recording-checks.c): each fault planted in one recording of a set
# edited after construction is named, with how many more share it.

edited_set <- function() simulate_grasps(subjects = 2, grasps = 1:2, objects = 1, trials = 2, seed = 1)

test_that("each fault of a recording is named, first by check, then by recording", {
  g <- edited_set()
  ids <- g$meta$id
  plant <- function(k, f) { x <- g; for (i in k) x$recordings[[i]] <- f(x$recordings[[i]]); x }
  expect_error(check_grasps(plant(3, as.data.frame)), paste0(ids[3], ".*is not a numeric matrix"),
               class = "handmotion_error_bad_recording")
  expect_error(check_grasps(plant(c(2, 5), function(r) r[0, , drop = FALSE])),
               paste0(ids[2], ".*\\(and 1 more\\) has no frames"), class = "handmotion_error_bad_recording")
  expect_error(check_grasps(plant(4, function(r) r[, -1])), paste0(ids[4], ".*one column per DoF"),
               class = "handmotion_error_bad_recording")
  expect_error(check_grasps(plant(6, function(r) { colnames(r)[2] <- "other"; r })),
               paste0(ids[6], ".*columns other than"), class = "handmotion_error_bad_recording")
  expect_error(check_grasps(plant(6, unname)), paste0(ids[6], ".*columns other than"),
               class = "handmotion_error_bad_recording")
  x <- g
  x$meta$n_frames[7] <- x$meta$n_frames[7] + 1L
  expect_error(check_grasps(x), paste0(ids[7], ".*other than its frame count"), class = "handmotion_error_bad_recording")
  # missing and infinite values: the first recording, frame and DoF named
  bad <- plant(c(5, 8), function(r) { r[4, 3] <- NA; r })
  cnd <- expect_error(check_grasps(bad), "2 recordings with missing or infinite values", class = "handmotion_error_bad_recording")
  expect_match(conditionMessage(cnd), paste0(ids[5], ".*frame 4.*", g$dofs[3]))
  expect_error(check_grasps(plant(1, function(r) { r[2, 1] <- -Inf; r })), ids[1], class = "handmotion_error_bad_recording")
  # the check that comes first wins, whatever the recordings' order
  both <- plant(2, function(r) { r[1, 1] <- NaN; r })
  both$recordings[[8]] <- both$recordings[[8]][, -1]
  expect_error(check_grasps(both), paste0(ids[8], ".*one column per DoF"), class = "handmotion_error_bad_recording")
  # as-built sets pass; integer recordings are numeric, an integer NA is caught
  expect_invisible(check_grasps(g))
  int <- plant(1:3, function(r) { storage.mode(r) <- "integer"; r })
  expect_invisible(check_grasps(int))
  int$recordings[[2]][3, 1] <- NA_integer_
  expect_error(check_grasps(int), ids[2], class = "handmotion_error_bad_recording")
  expect_identical(recordings_finite(int$recordings), seq_along(ids) != 2)
})

test_that("the share of training frames outside each limit is counted as on the stacked frames", {
  g <- simulate_grasps(subjects = 2, grasps = 1, objects = 2, trials = 3, seed = 2)
  lim0 <- recorded_limits(g, g$dofs)
  k <- which(!is.na(lim0$col))[1:2]
  # plant frames beyond the first limit's upper and the second's lower bound
  x <- g
  for (i in 1:3) x$recordings[[i]][1:4, lim0$col[k[1]]] <- lim0$hi[k[1]] + 1
  x$recordings[[5]][, lim0$col[k[2]]] <- lim0$lo[k[2]] - 1
  lim <- recorded_limits(x, x$dofs)
  X <- do.call(rbind, x$recordings)
  expected <- colMeans(sweep(X[, lim$col[k]], 2, lim$lo[k], "<") | sweep(X[, lim$col[k]], 2, lim$hi[k], ">"))
  expect_equal(lim$recorded_outside[k], unname(expected), tolerance = 1e-15)
  # at least the planted frames (12 of them, and a whole recording)
  expect_gte(lim$recorded_outside[k[1]] * nrow(X), 12)
  expect_gte(lim$recorded_outside[k[2]] * nrow(X), nrow(x$recordings[[5]]))
  expect_identical(lim[setdiff(seq_len(nrow(lim)), k), ], lim0[setdiff(seq_len(nrow(lim0)), k), ])
})
