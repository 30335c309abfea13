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
# Chunks: `chunks_per_worker` rounds of one per worker, falling in size
# (guided_chunks()): the worker that finishes first takes the next chunk,
# and the last chunks are the smallest, so neither worker idles long while
# the other finishes (four rounds measured best; see fit_model_set() for
# the figures). Each element runs with its own RNG
# stream (`streams`, L'Ecuyer-CMRG seeds as element_streams() makes them),
# set as future.apply sets them, so the results do not depend on the plan,
# the chunks or their order.
#
# A chunk travels as one global: future sends each global to the worker as
# its own message, and a message of many small writes (a namespace
# function's environment, a list of strings) waits about 40 ms on the
# socket for the worker's delayed acknowledgement (Nagle's algorithm). With
# the function, the chunk runner and the data as separate globals, every
# future paid 85-95 ms before its worker could start.
#
# `FUN(element, ...)` must be a top-level function (its environment the
# namespace: a closure would carry its frame to every worker); `more` are
# further arguments for every element, `each` (a named list of vectors as
# long as `elements`) arguments of each element. Returns the results in the
# order of `elements`.
future_map_chunks <- function(elements, FUN, more = list(), each = list(), streams = NULL,
                              work = rep(1, length(elements)), chunks_per_worker = 4L) {
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
  chunks <- guided_chunks(work, future::nbrOfWorkers(), chunks_per_worker)
  # future polls its workers every `future.wait.interval` seconds while the
  # main process waits for a free worker or the last results, and each poll
  # of two multisession futures costs 2-3 ms of CPU: at future's 0.01 s,
  # 6-7% of a core, taken from the two workers that share the machine's two
  # cores (1.4-1.6 s of a ten-times fit). At 0.05 s a poll finds a finished
  # worker about 0.02 s later and costs a third of the CPU. A user's own
  # setting is kept.
  if (is.null(getOption("future.wait.interval"))) {
    old_wait <- options(future.wait.interval = 0.05)
    on.exit(options(old_wait), add = TRUE)
  }
  more <- lapply(more, pack_for_worker)
  fs <- vector("list", length(chunks))
  for (k in seq_along(chunks)) {
    i <- chunks[[k]]
    # (`.hm_chunk`, not a name of the package's: under future, a global named
    # as one of the package's functions is left to the worker's loaded
    # package, where an internal function is not found from the future's
    # environment)
    fs[[k]] <- future::future(
      quote(.hm_chunk$run(.hm_chunk)), substitute = FALSE,
      globals = list(.hm_chunk = list(run = run_chunk, FUN = FUN, payload = lapply(elements[i], pack_for_worker),
                                      each = lapply(each, `[`, i), streams = streams[i], more = more)),
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
run_chunk <- function(chunk) {
  FUN <- chunk$FUN
  payload <- chunk$payload
  each <- chunk$each
  streams <- chunk$streams
  more <- lapply(chunk$more, unpack_on_worker)
  rm(chunk)
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

# The indices of `work` in chunks for `workers` workers, `per_worker` rounds
# of one chunk per worker, the rounds' shares of the work falling
# (per_worker, ..., 2, 1: with three rounds, each of the first two chunks
# holds a quarter of the work and each of the last two a twelfth). The
# futures start in this order, so the last chunks to finish are the
# smallest: the worker done first idles at most a small chunk's time while
# the other finishes (with equal chunks, one worker idled 1-3 s at ten times
# the default data), and the last models to come back are few. Elements go
# largest first, each into the chunk furthest below its share (the
# longest-processing-time rule, weighted); within a chunk, largest first.
guided_chunks <- function(work, workers, per_worker) {
  # (a plan may have unlimited workers: then one chunk per element)
  workers <- min(workers, length(work))
  m <- min(length(work), workers * per_worker)
  share <- rep(seq(per_worker, 1), each = workers)[seq_len(m)]
  load <- numeric(m)
  chunks <- vector("list", m)
  for (i in order(-work)) {
    k <- which.min(load / share)
    chunks[[k]] <- c(chunks[[k]], i)
    load[k] <- load[k] + work[i]
  }
  chunks[lengths(chunks) > 0L]
}
