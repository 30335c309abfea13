# Work spread over futures in chunks (R/future-chunks.R).

test_that("chunks hold about equal work, every element once", {
  work <- c(10, 1, 7, 3, 3, 9, 2, 5)
  ch <- balanced_chunks(work, 3)
  expect_setequal(unlist(ch), seq_along(work))
  expect_false(anyDuplicated(unlist(ch)) > 0)
  loads <- vapply(ch, function(i) sum(work[i]), numeric(1))
  # the longest-processing-time rule: the loads differ by at most the
  # largest element placed last (here 14, 13, 13 out of 40)
  expect_lte(max(loads) - min(loads), max(work))
  expect_equal(sum(loads), sum(work))
  # within a chunk, largest first
  for (i in ch) expect_identical(i, i[order(-work[i])])
  # more chunks than elements: one each
  expect_length(balanced_chunks(c(1, 2), 4), 2)
})

test_that("results come back in the elements' order, each under its own stream, whatever the plan", {
  draw <- function(x, offset, scale) offset + scale * x + stats::runif(1)
  environment(draw) <- asNamespace("handmotion")  # a top-level function, as the contract asks
  # (each stream switches the session to L'Ecuyer-CMRG: give the files after
  # this one the RNG they expect)
  old <- save_rng()
  on.exit(restore_rng(old), add = TRUE)
  streams <- element_streams(11, 5)
  # what each element should give: its own stream, set alone
  expected <- vapply(1:5, function(i) {
    assign(".Random.seed", streams[[i]], envir = globalenv())
    10 * i + 100 + stats::runif(1)
  }, numeric(1))
  set.seed(1, kind = "Mersenne-Twister")
  kind_before <- RNGkind()
  for (plan in c("sequential", "multisession")) {
    if (plan == "sequential") future::plan(future::sequential) else future::plan(future::multisession, workers = 2)
    got <- future_map_chunks(as.list(1:5), draw, more = list(scale = 10), each = list(offset = rep(100, 5)),
                             streams = streams, work = c(1, 5, 2, 4, 3))
    expect_equal(unlist(got), expected, label = plan)
    # the caller's RNG as it was, whatever the plan
    expect_identical(RNGkind(), kind_before, label = plan)
  }
  future::plan(future::sequential)
  expect_identical(future_map_chunks(list(), draw), list())
  restore_rng(old)
  expect_identical(RNGkind(), old$kind)
})
