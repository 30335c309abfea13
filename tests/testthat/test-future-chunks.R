# Work spread over futures in chunks (R/future-chunks.R).

test_that("chunks fall in size round by round, every element once", {
  set.seed(3)
  work <- round(stats::runif(33, 80, 120))
  ch <- guided_chunks(work, workers = 2, per_worker = 3)
  expect_length(ch, 6)
  expect_setequal(unlist(ch), seq_along(work))
  expect_false(anyDuplicated(unlist(ch)) > 0)
  loads <- vapply(ch, function(i) sum(work[i]), numeric(1))
  expect_equal(sum(loads), sum(work))
  # the rounds' shares 3, 3, 2, 2, 1, 1 (of 12): each chunk's load within
  # one element of its share
  expect_lte(max(abs(loads - sum(work) * c(3, 3, 2, 2, 1, 1) / 12)), max(work))
  # started in this order, so the last two chunks are the smallest
  expect_true(all(loads[5:6] < min(loads[1:4])))
  # within a chunk, largest first
  for (i in ch) expect_identical(i, i[order(-work[i])])
  # a single round is the plain longest-processing-time rule: the loads
  # differ by at most the largest element (here 14, 13, 13 out of 40)
  w <- c(10, 1, 7, 3, 3, 9, 2, 5)
  loads <- vapply(guided_chunks(w, 3, 1), function(i) sum(w[i]), numeric(1))
  expect_lte(max(loads) - min(loads), max(w))
  # more chunks than elements, or unlimited workers: one element each
  expect_length(guided_chunks(c(1, 2), 2, 3), 2)
  expect_length(guided_chunks(c(1, 2, 3), Inf, 3), 3)
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

test_that("futures are polled every 0.05 s during the chunks unless the user chose otherwise", {
  seen <- function(x) getOption("future.wait.interval")
  environment(seen) <- asNamespace("handmotion")
  future::plan(future::sequential)
  withr::local_options(future.wait.interval = NULL)
  expect_identical(unlist(future_map_chunks(list(1, 2), seen)), c(0.05, 0.05))
  expect_null(getOption("future.wait.interval"))
  withr::local_options(future.wait.interval = 0.2)
  expect_identical(unlist(future_map_chunks(list(1), seen)), 0.2)
  expect_identical(getOption("future.wait.interval"), 0.2)
})
