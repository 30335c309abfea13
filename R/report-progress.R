# Progress of reproduce_thesis(): the report's step() helper
# (inst/report/reproduce-thesis.Rmd) signals a condition as each step starts;
# reproduce_thesis() catches it around rmarkdown::render() and prints one line
# per step: what it does, the time so far and an estimate of the time left.
# The lines go straight to standard error because a message() raised inside
# knitr's chunks would be captured by knitr, not shown.

# Signalled by the report as a step starts; nothing happens unless
# reproduce_thesis() is listening (the vignette renders silently).
report_step_signal <- function(label) {
  rlang::signal("", class = "handmotion_report_step", label = label)
}

# Signalled by every chunk of the report as it starts (a knitr chunk hook
# that reproduce_thesis() sets while it renders): after the last step, the
# remaining chunks (tables, figures, the page) are the work left.
report_chunk_signal <- function(label) {
  labels <- knitr::all_labels()
  rlang::signal("", class = "handmotion_report_chunk", label = label,
                index = match(label, labels), total = length(labels))
}

# The work of each step, as a cost model of the design (issue 36: the time
# left is estimated from measured rates, not from fixed shares of one
# design): `seconds` is the step's time on the default design (30 subjects x
# 33 types, leave-one-subject-out) on one worker, from its start to the next
# step's (so with the tables and figures drawn in between: most of them
# after the frame-PCA step): `make demo` on the 2-core machine after the
# speed-ups of issue 36 (214 s on 2 workers, shared machine), parallel steps
# counted twice (the FPCA folds: 30 refits of the 33 models with one
# Gaussian, saved for the weighted FPCA folds, which read them, are more
# than half of it); `scale` says how it
# grows with the design (recordings N, types T, folds F) and `parallel`
# whether its folds or types share the future workers. While the report
# runs, the seconds are rescaled by the measured rate: the time the finished
# steps took against what the model predicted for them, and within a step
# by the rate of its own progress steps (folds, types, horizons, chunks).
report_step_model <- data.frame(
  step = c("simulate the data", "fit the grasp models", "classify by FPCA distance (in-sample)",
           "fit last-frame PCA", "classify by last-frame PCA (in-sample)", "generate three grasps per type",
           "held-out evaluation, FPCA", "held-out evaluation, last-frame PCA",
           "held-out evaluation, weighted FPCA distance", "held-out evaluation, shrinkage LDA",
           "re-align two example types (Figures 5.1, 5.2)", "frame-PCA alternative (Figure 5.3)",
           "natural grasps: thesis model on the training subjects",
           "natural grasps: copula model on the training subjects",
           "natural grasps: evaluate_generation()", "natural grasps: thesis model with the mixture guard",
           "recognition: weighted FPCA distance (learn weights)", "recognition: shrinkage LDA (fit)",
           "recognition: classify the held-out subjects", "recognition: early recognition, held out by subject",
           "the figures and the page"),
  seconds = c(1, 12, 1.2, 0.2, 0.3, 0.1, 248, 12, 36, 36, 1, 12, 12, 12, 4, 12, 1, 3, 3, 6, 6),
  scale = c("N", "N", "NT", "N", "N", "T", "NF", "NF", "NF", "NF", "const", "T", "N", "N", "NT", "N",
            "NT", "N", "NT", "NF", "T"),
  parallel = c(FALSE, TRUE, FALSE, FALSE, FALSE, FALSE, TRUE, TRUE, TRUE, TRUE, FALSE, FALSE, TRUE, TRUE,
               FALSE, TRUE, FALSE, FALSE, FALSE, TRUE, FALSE),
  stringsAsFactors = FALSE)

# Predicted seconds of every step for a design on `workers` workers, before
# any rate is measured (named by step, in report order).
report_step_costs <- function(settings, workers = 1L) {
  m <- report_step_model
  S <- settings$subjects
  T <- length(settings$grasps)
  N <- S * T * 9                      # simulate_grasps(): 3 objects x 3 trials
  F <- if (is.null(settings$loso_folds)) S else settings$loso_folds
  units <- c(const = 1, N = N / 8910, T = T / 33, NT = N * T / (8910 * 33),
             NF = N * (F - 1) / (8910 * 29))
  per <- m$seconds * units[m$scale]
  # folds and types share the workers (never more workers than folds)
  share <- ifelse(m$parallel, pmin(max(1L, workers), ifelse(m$scale == "NF", F, T)), 1)
  stats::setNames(per / share, m$step)
}

# A progress printer for one report: `begin(settings)`, `step(label)` as each
# step starts, `tick(p)` for each progressr progression inside a step,
# `chunk(index, total)` for each chunk of the report, `done(path)` at the
# end. Lines go to `out`; within a step a line at most every `every`
# seconds.
report_progress <- function(enabled = TRUE, out = stderr(), every = 15) {
  now <- function() proc.time()[["elapsed"]]
  start <- now()
  say <- function(...) if (enabled) cat(..., "\n", sep = "", file = out)
  clock <- function(s) if (s < 90) sprintf("%.0f s", s) else sprintf("%.1f min", s / 60)
  cost <- NULL          # predicted seconds per step
  done <- character()   # steps finished
  taken <- numeric()    # their measured seconds
  current <- NULL       # the step running, its start, its progress steps
  step_start <- start
  ticks <- c(done = 0, total = 0)
  last_line <- start
  # the measured rate: what the finished steps took against their prediction
  rate <- function() {
    pred <- sum(cost[done])
    if (pred <= 0 || sum(taken) < 1) return(1)
    sum(taken) / pred
  }
  # seconds left: the rest of the current step (from its own progress rate
  # once it has one) and the steps after it at the measured rate
  left <- function() {
    r <- rate()
    rest <- setdiff(names(cost), c(done, current))
    in_step <- now() - step_start
    cur <- 0
    if (!is.null(current)) {
      by_model <- max(0, cost[[current]] * r - in_step)
      # the step's own pace, trusted as far as the step has gone (its first
      # folds also carry the workers' start)
      f <- if (ticks[["total"]] > 0) min(1, ticks[["done"]] / ticks[["total"]]) else 0
      cur <- if (f > 0 && in_step > 1) {
        (1 - f) * by_model + f * in_step * (ticks[["total"]] - ticks[["done"]]) / ticks[["done"]]
      } else by_model
    }
    cur + r * sum(cost[rest])
  }
  finish_current <- function() {
    if (!is.null(current)) {
      done <<- c(done, current)
      taken <<- c(taken, now() - step_start)
    }
  }
  begin_step <- function(label) {
    finish_current()
    if (!label %in% names(cost)) cost[[label]] <<- stats::median(cost)
    current <<- label
    step_start <<- now()
    last_line <<- step_start
    ticks[] <<- 0
  }
  n_steps <- function() length(cost) - 1L
  list(
    begin = function(settings) {
      workers <- if (requireNamespace("future", quietly = TRUE)) future::nbrOfWorkers() else 1L
      cost <<- report_step_costs(settings, workers)
      say(sprintf("handmotion: reproducing the thesis' chapter 5 (%d subjects x %d grasp types, %s) on %d worker%s",
                  settings$subjects, length(settings$grasps),
                  if (is.null(settings$loso_folds)) "leave-one-subject-out" else paste(settings$loso_folds, "folds"),
                  workers, if (workers == 1L) "" else "s"))
      say(sprintf("  (about %s by the design; the estimate follows the measured pace)", clock(sum(cost))))
    },
    step = function(label) {
      begin_step(label)
      el <- now() - start
      est <- if (length(done)) sprintf(", about %s left", clock(left())) else ""
      say(sprintf("  [%2d/%d] %s (%s so far%s)", min(length(done) + 1L, n_steps()), n_steps(), label,
                  clock(el), est))
    },
    tick = function(p) {
      if (is.null(current)) return(invisible())
      type <- p$type %||% "update"
      if (identical(type, "initiate")) {
        ticks[["total"]] <<- ticks[["total"]] + (p$steps %||% 0)
      } else if (identical(type, "update")) {
        ticks[["done"]] <<- ticks[["done"]] + (p$amount %||% 1)
      }
      if (now() - last_line >= every && ticks[["total"]] > 0) {
        last_line <<- now()
        say(sprintf("         %s: %.0f%% (%s so far, about %s left)", current,
                    100 * min(1, ticks[["done"]] / ticks[["total"]]), clock(now() - start), clock(left())))
      }
    },
    chunk = function(index, total) {
      # after the last step, the remaining chunks are "the figures and the page"
      last <- names(cost)[length(cost)]
      if (!is.null(current) && current == names(cost)[length(cost) - 1L] && index > 0 &&
          now() - step_start > 0) {
        # the last step's chunk ended when a later chunk starts
        begin_step(last)
        say(sprintf("  [%d/%d] %s (%s so far, about %s left)", n_steps(), n_steps(), last,
                    clock(now() - start), clock(left())))
        ticks[["total"]] <<- total - index + 1
      } else if (identical(current, last)) {
        ticks[["done"]] <<- ticks[["done"]] + 1
        if (now() - last_line >= every) {
          last_line <<- now()
          say(sprintf("         %s: chunk %d of %d (%s so far, about %s left)", last, index, total,
                      clock(now() - start), clock(left())))
        }
      }
    },
    done = function(path) {
      say(sprintf("handmotion: report written in %s: %s", clock(now() - start), path))
      say("  tables in ", file.path(dirname(path), "tables"), ", figures in ", file.path(dirname(path), "figures"))
    }
  )
}
