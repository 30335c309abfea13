# Work spread over the user's future plan in chunks, each chunk's elements
# packed for the workers (pack_for_worker(), R/transport.R) just before its
# future is created.
#
# Why not future.apply::future_mapply(): it evaluates every element before
# the first future starts, so at ten times the default data the main process
# packed all 89,100 recordings (600 MB copied, two seconds of a two-worker
# fit) while both workers waited. Here the first worker starts after one
# chunk is packed, and the later chunks are packed while the first ones run
# (a multisession future is created when a worker is free, so the main
# process packs chunk three during chunks one and two).
#
# Chunks: `chunks_per_worker` per worker (three measured best at ten times
# the default data: the worker that finishes first takes the next chunk, so
# neither idles long while the other finishes; see fit_model_set() for the
# figures), balanced on `work` by
# placing the largest elements first, each in the chunk with the least work
# so far. Each element runs with its own RNG stream (`streams`, L'Ecuyer-CMRG
# seeds as element_streams() makes them), set as future.apply sets them, so
# the results do not depend on the plan, the chunks or their order.
#
# `FUN(element, ...)` must be a top-level function (its environment the
# namespace: a closure would carry its frame to every worker); `more` are
# further arguments for every element, `each` (a named list of vectors as
# long as `elements`) arguments of each element. Returns the results in the
# order of `elements`.
future_map_chunks <- function(elements, FUN, more = list(), each = list(), streams = NULL,
                              work = rep(1, length(elements)), chunks_per_worker = 3L) {
  n <- length(elements)
  if (n == 0L) return(list())
  stopifnot(is.function(FUN), is.list(more), is.list(each), all(lengths(each) == n),
            is.null(streams) || length(streams) == n, length(work) == n)
  # (under a sequential plan the streams are set in this session: give the
  # caller back their RNG)
  if (!is.null(streams)) {
    old_rng <- save_rng()
    on.exit(restore_rng(old_rng), add = TRUE)
  }
  chunks <- balanced_chunks(work, min(n, chunks_per_worker * future::nbrOfWorkers()))
  more <- lapply(more, pack_for_worker)
  fs <- vector("list", length(chunks))
  for (k in seq_along(chunks)) {
    i <- chunks[[k]]
    # (`.run_chunk`, not `run_chunk`: under future, a global named as one of
    # the package's functions is left to the worker's loaded package, where
    # an internal function is not found from the future's environment)
    fs[[k]] <- future::future(
      quote(.run_chunk(FUN, payload, each_k, streams_k, more)), substitute = FALSE,
      globals = list(.run_chunk = run_chunk, FUN = FUN, payload = lapply(elements[i], pack_for_worker),
                     each_k = lapply(each, `[`, i), streams_k = streams[i], more = more),
      packages = "handmotion", seed = NULL, label = sprintf("handmotion-%d", k))
  }
  # (value() of the list polls every future, so each relays its progress as
  # it comes, not when the futures before it are done)
  values <- future::value(fs)
  out <- vector("list", n)
  for (k in seq_along(chunks)) out[chunks[[k]]] <- values[[k]]
  out
}

# One chunk on its worker: unpack what was packed, then each element under
# its own stream (assigned as future.apply assigns `future.seed`'s streams).
run_chunk <- function(FUN, payload, each, streams, more) {
  more <- lapply(more, unpack_on_worker)
  # FUN is called with symbols, not values: do.call() would put the whole
  # type's recordings into the call, and every condition signalled inside the
  # fit would carry (and rlang's backtraces walk) that call; the workers of a
  # two-worker fit spent a third more CPU than with future_mapply()'s calls
  call <- as.call(c(list(quote(FUN), quote(.element)),
                    sapply(c(names(each), names(more)), as.name, simplify = FALSE)))
  env <- list2env(more, parent = environment())
  lapply(seq_along(payload), function(j) {
    if (!is.null(streams)) assign(".Random.seed", streams[[j]], envir = globalenv(), inherits = FALSE)
    assign(".element", unpack_on_worker(payload[[j]]), envir = env)
    for (a in names(each)) assign(a, each[[a]][[j]], envir = env)
    on.exit(rm(".element", envir = env))
    eval(call, env)
  })
}

# `m` chunks of the indices of `work`, about equal in total work: the
# largest first, each into the chunk with the least work so far (the
# longest-processing-time rule); within a chunk, largest first.
balanced_chunks <- function(work, m) {
  load <- numeric(m)
  chunks <- vector("list", m)
  for (i in order(-work)) {
    k <- which.min(load)
    chunks[[k]] <- c(chunks[[k]], i)
    load[k] <- load[k] + work[i]
  }
  chunks[lengths(chunks) > 0L]
}
