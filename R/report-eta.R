# The time left of reproduce_thesis() (issue 36: within 25% once a tenth of
# the work is done, from measured rates, not fixed weights). The estimator
# is given the times (it reads no clock), so its logic is tested on planted
# step costs (tests/testthat/test-report-eta.R) and the printer
# (R/report-progress.R) feeds it the real clock.
#
# What it knows: the predicted seconds of every step (the cost model of the
# design, report_step_costs()) and each step's kind (how it grows and
# whether it runs on the workers: steps of one kind share their error
# against the model). What it measures:
#
# * each finished step's time: the rate of the model (measured / predicted)
#   over all finished steps, and per kind, shrunk towards the rate of the
#   steps run the same way (on the future workers or in the main process)
#   and that towards the overall rate while they have little predicted
#   time behind them (`prior` seconds), so that the pace of the long
#   held-out folds is not applied unchanged to the quick fits and tables
#   after them. The prior is a tenth of the run's predicted time, not a
#   fixed number of seconds: a short step's rate is poor evidence for the
#   long steps after it (its start-up, the workers' progress arriving in
#   bursts). With 20 s on a run of 570 s, the model fit (7 s by the model,
#   35 s taken, mostly before its first type came back) raised the rate of
#   every step on the workers to 1.9 and the time left from 8.5 to 17 min,
#   where 12.8 remained (bench-eta.R's trace replayed; at load 10 it went
#   from 24 to 93 min, issue 42); with a tenth of the run it said 9-13.5
#   min. From a tenth of the work on the measured rates outweigh the prior;
# * within a step, the times of its progress steps (folds, horizons,
#   chunks): the time per progress step is the least-squares slope of
#   their times (from six on), so the workers' start before the first one
#   is not counted as if every fold paid it; this rate is trusted as far as the
#   step has gone or more with every progress step (tick_weight()), the
#   rest comes from the model at the kind's rate; as far as it is trusted,
#   the step's projected time also counts in the rates of the steps after
#   it.
report_eta <- function(cost, kind = stats::setNames(rep("all", length(cost)), names(cost)),
                       prior = 0.1 * sum(cost)) {
  force(prior)  # (the run's predicted time before step() adds unknown steps)
  done <- character()       # finished steps, in order
  taken <- numeric()        # their measured seconds
  current <- NULL
  step_start <- 0
  total_ticks <- 0
  ticks <- numeric()        # progress steps done at each update of the current step
  tick_t <- numeric()       # and their times
  phase_start <- 0          # when the step's current count of progress steps began

  # steps on the future workers share the machine with each other (on a
  # busy machine they slow down more than the steps of the main process
  # alone): a kind's rate is shrunk towards that of its mode (on the
  # workers or not), the mode's towards the overall rate
  mode_of <- function(k) ifelse(grepl("/workers$", k), "workers", "main")
  # `now`: the current step's projection (its time so far and the rest by
  # its own pace) counts as far as that pace is trusted, so a long step
  # running faster or slower than the model says so for the steps after it
  rates <- function(now = NULL) {
    pred <- cost[done]
    taken <- taken
    k <- kind[done]
    if (!is.null(now)) {
      pred <- c(pred, now$w * cost[[current]])
      taken <- c(taken, now$w * now$total)
      k <- c(k, kind[[current]])
    }
    overall <- (sum(taken) + prior) / (sum(pred) + prior)
    m <- mode_of(k)
    per_mode <- c(workers = (sum(taken[m == "workers"]) + prior * overall) / (sum(pred[m == "workers"]) + prior),
                  main = (sum(taken[m == "main"]) + prior * overall) / (sum(pred[m == "main"]) + prior))
    kinds <- unique(kind)
    per_kind <- vapply(kinds, function(kk) {
      (sum(taken[k == kk]) + prior * per_mode[[mode_of(kk)]]) / (sum(pred[k == kk]) + prior)
    }, numeric(1))
    list(overall = overall, kind = stats::setNames(per_kind, kinds))
  }
  # the rest of the current step from its own progress steps, or NA
  by_ticks <- function(t) {
    m <- length(ticks)
    if (!m || total_ticks <= 0 || ticks[m] <= 0) return(NA_real_)
    # (folds on two workers end in pairs: the slope is fitted to all of
    # them, least squares, once there are a few pairs)
    per <- if (m >= 6L && ticks[m] > ticks[1]) {
      x <- ticks - mean(ticks)
      sum(x * (tick_t - mean(tick_t))) / sum(x^2)
    } else (tick_t[m] - phase_start) / ticks[m]
    max(0, per * (total_ticks - ticks[m]) - (t - tick_t[m]))
  }
  # how far the progress steps' pace is trusted: as far as the step has
  # gone, and from the sixth progress step on more with every one (their
  # slope)
  tick_weight <- function() {
    m <- length(ticks)
    f <- if (total_ticks > 0 && m) min(1, ticks[m] / total_ticks) else 0
    # (fewer than six: a pace with the start-up in it, trusted only as far
    # as the step has gone)
    if (m < 6L) f else max(f, (m - 1) / (m + 2))
  }
  list(
    # `label` starts at time t (the step before it ends then)
    step = function(label, t) {
      if (!is.null(current)) {
        done <<- c(done, current)
        taken <<- c(taken, t - step_start)
      }
      if (!label %in% names(cost)) {
        cost[[label]] <<- stats::median(cost)
        kind[[label]] <<- "other"
      }
      current <<- label
      step_start <<- t
      phase_start <<- t
      total_ticks <<- 0
      ticks <<- numeric()
      tick_t <<- numeric()
      invisible()
    },
    # the current step has `steps` progress steps more to do from time t; a
    # count that starts after the step's earlier ones have all been done is
    # a new phase of the step (the in-sample fit after the held-out folds):
    # its own pace, not the folds', says how long it takes
    initiate = function(steps, t = NULL) {
      m <- length(ticks)
      if (m && total_ticks > 0 && ticks[m] >= total_ticks) {
        phase_start <<- t %||% tick_t[m]
        total_ticks <<- 0
        ticks <<- numeric()
        tick_t <<- numeric()
      }
      total_ticks <<- total_ticks + steps
      invisible()
    },
    # `amount` progress steps of the current step were done at time t
    tick = function(t, amount = 1) {
      ticks <<- c(ticks, (if (length(ticks)) ticks[length(ticks)] else 0) + amount)
      tick_t <<- c(tick_t, t)
      invisible()
    },
    # the current step's share done by its progress steps
    fraction = function() {
      if (total_ticks <= 0 || !length(ticks)) 0 else min(1, ticks[length(ticks)] / total_ticks)
    },
    # seconds left at time t
    left = function(t) {
      rest <- setdiff(names(cost), c(done, current))
      if (is.null(current)) {
        r <- rates()
        return(sum(r$kind[kind[rest]] * cost[rest]))
      }
      own <- by_ticks(t)
      w <- if (is.na(own)) 0 else tick_weight()
      # (into the rates only a pace from the slope of six or more)
      r <- rates(if (w > 0 && length(ticks) >= 6L) list(w = w, total = t - step_start + own))
      model <- max(0, r$kind[[kind[[current]]]] * cost[[current]] - (t - step_start))
      cur <- if (is.na(own)) model else (1 - w) * model + w * own
      cur + sum(r$kind[kind[rest]] * cost[rest])
    },
    # the rest of the current step by its own pace alone (NA: no pace yet)
    by_ticks = by_ticks,
    current = function() current,
    steps_done = function() length(done),
    costs = function() cost
  )
}
