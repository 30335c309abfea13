# Recordings packed for a future's worker (R/transport.R) come back identical.

test_that("a packed set unpacks to the identical set, and odd sets travel as they are", {
  g <- simulate_grasps(subjects = 2, grasps = c("Tripod", "Lateral"), seed = 3)
  future::plan(future::multisession, workers = 2)
  on.exit(future::plan(future::sequential), add = TRUE)
  p <- pack_for_worker(g)
  expect_s3_class(p, "handmotion_packed")
  expect_lt(length(unclass(p)$shell$recordings), 1)
  expect_identical(unpack_on_worker(p), g)
  # a recording with row names is not plain: the set goes whole
  odd <- g
  rownames(odd$recordings[[2]]) <- seq_len(nrow(odd$recordings[[2]]))
  expect_identical(pack_for_worker(odd), odd)
  expect_identical(unpack_on_worker(odd), odd)
})

test_that("under a sequential plan nothing is packed", {
  future::plan(future::sequential)
  g <- simulate_grasps(subjects = 1, grasps = "Tripod", seed = 3)
  expect_identical(pack_for_worker(g), g)
})

test_that("the compiled stacking is unlist() of plain recordings, NULL for any other", {
  dofs <- c("x", "y")
  plain <- function(m) { dimnames(m) <- list(NULL, dofs); m }
  recs <- list(a = plain(matrix(1:6 + 0.5, 3)), b = plain(matrix(numeric(0), 0, 2)), c = plain(matrix(c(-1, 2), 1)))
  expect_identical(.Call(hm_stack_values, recs, dofs), unlist(recs, use.names = FALSE))
  # each way a recording can differ from what the worker rebuilds
  odd <- list(
    integer = plain(matrix(1:4, 2)),
    other_names = { m <- recs$a; colnames(m) <- c("x", "z"); m },
    row_names = { m <- recs$a; rownames(m) <- 1:3; m },
    named_dimnames = { m <- recs$a; names(dimnames(m)) <- c("frame", "dof"); m },
    extra_attribute = structure(recs$a, unit = "deg"),
    no_dimnames = matrix(1:6 + 0.5, 3),
    three_columns = { m <- matrix(0, 2, 3); dimnames(m) <- list(NULL, c(dofs, "z")); m },
    a_vector = c(x = 1, y = 2)
  )
  for (k in names(odd)) {
    expect_null(.Call(hm_stack_values, c(recs, list(odd[[k]])), dofs), label = k)
  }
  # the same names as different (but equal) strings still match
  expect_identical(.Call(hm_stack_values, recs, paste0(c("x", "y"), "")), unlist(recs, use.names = FALSE))
})

test_that("the compiled unstacking rebuilds the recordings, each with its own values", {
  dofs <- c("x", "y")
  plain <- function(m) { dimnames(m) <- list(NULL, dofs); m }
  recs <- list(a = plain(matrix(1:6 + 0.5, 3)), b = plain(matrix(numeric(0), 0, 2)), c = plain(matrix(c(-1, 2), 1)))
  values <- .Call(hm_stack_values, recs, dofs)
  back <- .Call(hm_unstack_values, values, vapply(recs, nrow, integer(1)), dofs, names(recs))
  expect_identical(back, recs)
  expect_identical(.Call(hm_unstack_values, values, c(3L, 0L, 1L), dofs, NULL), unname(recs))
  # the recordings share one dimnames list: renaming one column leaves the others as they were
  colnames(back$a) <- c("x", "z")
  expect_identical(colnames(back$c), dofs)
  back$c[1, 1] <- 99
  expect_identical(values[7], -1)
  # counts that do not add up to the values, or are not counts, are refused
  expect_error(.Call(hm_unstack_values, values, c(3L, 0L, 2L), dofs, NULL), "values for")
  expect_error(.Call(hm_unstack_values, values, c(3L, NA, 1L), dofs, NULL), "not a count")
  expect_error(.Call(hm_unstack_values, values, c(3L, 0L, 1L), dofs, "a"), "expected")
})

test_that("a set fitted without a temperature sample travels to workers (calibrate = FALSE)", {
  future::plan(future::multisession, workers = 2)
  on.exit(future::plan(future::sequential), add = TRUE)
  expect_null(pack_for_worker(NULL))
  g <- simulate_grasps(subjects = 3, grasps = c("Tripod", "Lateral"), seed = 3)
  ev <- evaluate_loso(g, folds = 3)
  expect_s3_class(ev, "grasp_evaluation")
})
