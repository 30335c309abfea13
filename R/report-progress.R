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

# Signalled by reproduce_thesis() at every update of its printer (a step, a
# progress step, a chunk; printed or not) with the time so far and the
# estimate of the time left (NA when none is made): nothing happens unless
# someone listens (bench/bench-eta.R does, to judge the estimates).

# Signalled by every chunk of the report as it starts (a knitr chunk hook
# that reproduce_thesis() sets while it renders): after the last step, the
# remaining chunks (tables, figures, the page) are the work left.
report_estimate_signal <- function(so_far, left, event) {
  rlang::signal("", class = "handmotion_report_estimate", so_far = so_far, left = left, event = event)
}

report_chunk_signal <- function(label) {
  labels <- knitr::all_labels()
  rlang::signal("", class = "handmotion_report_chunk", label = label,
                index = match(label, labels), total = length(labels))
}

# The work of each step, as a cost model of the design (issue 36: the time
# left is estimated from measured rates, not from fixed shares of one
# design): `cpu` is the step's CPU seconds (the main process and the
# workers together) on the default design (30 subjects x 33 types,
# leave-one-subject-out) on the reference machine, quiet (the 2-core machine
# the package is developed on), from its start to the next step's (so with
# the tables and figures drawn in between: most of them after the frame-PCA
# step). They are bench/bench-eta.R's `cpu = c(...)` line (`make demo`'s
# run, the installed -O2 build, 2 workers) scaled from that run's calibrated
# pace to the reference one (pace_reference_cpu): issue 42 re-measured them
# when the report's steps had drifted 2-4x from an older table (the
# subclass discriminant made the LDA folds 4x dearer), which left the time
# left 37-71% short from a fifth of the run on although the first estimate
# was right. At another machine's pace (machine_pace())
# report_step_costs() scales them. `scale` says how a step grows with the
# design (recordings N, types T, folds F) beyond its `fixed` CPU seconds,
# which a design of any size pays (forking the workers, first calls, the
# figures' set-up): bench-eta.R's quick run (4 subjects x 3 types, 2 folds)
# at its calibration's pace. `parallel` says whether its folds, types or
# repetitions share the future workers (a parallel step's elapsed time is
# its CPU over the workers). While the report runs, report_eta() rescales
# the seconds by the measured rates: the time the finished steps took
# against what the model predicted for them (per kind of step), and within
# a step the rate of its own progress steps (folds, types, horizons,
# chunks).
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
  cpu = c(1.0, 24.1, 0.93, 1.2, 0.37, 0.1, 153, 37, 57, 127, 0.93, 6.6, 23.3, 32.3, 32.9, 26.3, 0.2, 4.2,
          4.5, 17.8, 2.4),
  fixed = c(0.1, 1.9, 0.05, 0.05, 0, 0, 2.7, 0.9, 3.0, 1.1, 0.6, 3.0, 2.3, 2.3, 0.6, 2.9, 0, 0, 0.05, 0.8, 1.6),
  scale = c("N", "N", "NT", "N", "N", "T", "NF", "NF", "NF", "NF", "const", "T", "N", "N", "NT", "N",
            "NT", "N", "NT", "NF", "T"),
  parallel = c(FALSE, TRUE, FALSE, FALSE, FALSE, FALSE, TRUE, TRUE, TRUE, TRUE, FALSE, FALSE, TRUE, TRUE,
               TRUE, TRUE, FALSE, FALSE, FALSE, TRUE, FALSE),
  stringsAsFactors = FALSE)

# Predicted seconds of every step for a design on `workers` workers, before
# any rate is measured (named by step, in report order), at the machine's
# `pace` (machine_pace(); NULL: the reference machine, quiet).
report_step_costs <- function(settings, workers = 1L, pace = NULL) {
  m <- report_step_model
  S <- settings$subjects
  T <- length(settings$grasps)
  N <- S * T * 9                      # simulate_grasps(): 3 objects x 3 trials
  F <- if (is.null(settings$folds)) S else settings$folds
  units <- c(const = 1, N = N / 8910, T = T / 33, NT = N * T / (8910 * 33),
             NF = N * (F - 1) / (8910 * 29))
  # (the fixed part does not shrink with the design: see `fixed`)
  per <- m$fixed + (m$cpu - m$fixed) * units[m$scale]
  # folds and types share the workers (never more workers than folds)
  share <- ifelse(m$parallel, pmin(max(1L, workers), ifelse(m$scale == "NF", F, T)), 1)
  # CPU seconds of the reference machine -> elapsed seconds here and now
  f <- if (is.null(pace)) c(main = 1, workers = 1) else pace_factors(pace, workers)
  slow <- ifelse(m$parallel & workers > 1L, f[["workers"]], f[["main"]])
  stats::setNames(per / share * slow, m$step)
}

# The kind of every step (steps of one kind share their error against the
# model, report_eta()): how it grows and whether it runs on the workers.
report_step_kinds <- function(steps) {
  m <- report_step_model
  kind <- paste0(m$scale, ifelse(m$parallel, "/workers", ""))
  stats::setNames(kind[match(steps, m$step)], steps)
}

# A progress printer for one report: `begin(settings)`, `step(label)` as each
# step starts, `tick(p)` for each progressr progression inside a step,
# `chunk(index, total)` for each chunk of the report, `done(path)` at the
# end. Lines go to `out`; within a step a line at most every `every`
# seconds. The time left comes from report_eta(), fed by `clock` (seconds);
# `trace`, if a function, is called with the time so far, the estimate of
# the time left (NA when none is made) and the event (a step, a progress
# step, a chunk) at every update, printed or not: reproduce_thesis() passes
# report_estimate_signal(), whose conditions bench/bench-eta.R catches to
# compare the estimates with the real time left. `pace` measures the
# machine's pace at begin() (machine_pace(); tests feed a fixed one), which
# scales the cost model's first estimate and is said in the first line.
report_progress <- function(enabled = TRUE, out = stderr(), every = 15,
                            clock = function() proc.time()[["elapsed"]],
                            trace = NULL, pace = machine_pace) {
  now <- clock
  start <- now()
  say <- function(...) if (enabled) cat(..., "\n", sep = "", file = out)
  clock_text <- function(s) if (s < 90) sprintf("%.0f s", s) else sprintf("%.1f min", s / 60)
  eta <- NULL
  last_line <- start
  left <- function(event = "") {
    t <- now()
    l <- eta$left(t)
    if (is.function(trace)) trace(t - start, l, event)
    l
  }
  begin_step <- function(label) {
    eta$step(label, now())
    last_line <<- now()
  }
  # every step of the model is counted once, the page's chunks after the
  # last signalled step included (it was left out of the count, so the last
  # step and the page both read [20/20])
  n_steps <- function() length(eta$costs())
  list(
    begin = function(settings) {
      workers <- if (requireNamespace("future", quietly = TRUE)) future::nbrOfWorkers() else 1L
      # (only when the lines are shown: a silent render needs no estimate)
      p <- if (enabled && is.function(pace)) pace() else NULL
      cost <- report_step_costs(settings, workers, p)
      if (is.function(trace) && !is.null(p)) {
        trace(now() - start, NA_real_, sprintf("pace cpu %.3f elapsed %.3f load %.2f cores %d",
                                               p$cpu, p$elapsed, p$load, p$cores))
      }
      eta <<- report_eta(cost, report_step_kinds(names(cost)))
      if (is.function(trace)) trace(now() - start, sum(cost), "begin")
      scheme <- if (is.null(settings$folds)) "leave-one-subject-out" else paste(settings$folds, "folds")
      say(sprintf("handmotion: reproducing the thesis' chapter 5 (%d subjects x %d grasp types, %s) on ",
                  settings$subjects, length(settings$grasps), scheme),
          cli::pluralize("{as.integer(workers)} worker{?s}"))
      say(sprintf("  (about %s by the design at this machine's pace%s; the estimate follows the measured pace)",
                  clock_text(sum(cost)), if (is.null(p)) "" else paste0(": ", pace_text(p))))
    },
    step = function(label) {
      begin_step(label)
      k <- eta$steps_done()
      est <- if (k) sprintf(", about %s left", clock_text(left(paste("step", label)))) else ""
      say(sprintf("  [%2d/%d] %s (%s so far%s)", k + 1L, n_steps(), label,
                  clock_text(now() - start), est))
    },
    tick = function(p) {
      if (is.null(eta) || is.null(eta$current())) return(invisible())
      # the last step counts the page's chunks, not the calls inside them
      steps <- names(eta$costs())
      if (identical(eta$current(), steps[length(steps)])) return(invisible())
      type <- p$type %||% "update"
      if (identical(type, "initiate")) {
        eta$initiate(p$steps %||% 0, now())
        if (is.function(trace)) trace(now() - start, NA_real_, paste("initiate", p$steps %||% 0))
        return(invisible())
      }
      if (!identical(type, "update")) return(invisible())
      eta$tick(now(), p$amount %||% 1)
      l <- left(paste("tick", p$amount %||% 1))
      if (now() - last_line >= every) {
        last_line <<- now()
        say(sprintf("         %s: %.0f%% (%s so far, about %s left)", eta$current(),
                    100 * eta$fraction(), clock_text(now() - start), clock_text(l)))
      }
    },
    chunk = function(index, total) {
      if (is.null(eta)) return(invisible())
      # after the last step, the remaining chunks are "the figures and the page"
      steps <- names(eta$costs())
      last <- steps[length(steps)]
      current <- eta$current()
      if (identical(current, steps[length(steps) - 1L]) && index > 0) {
        # the last step's chunk ended when a later chunk starts
        begin_step(last)
        eta$initiate(total - index + 1, now())
        say(sprintf("  [%2d/%d] %s (%s so far, about %s left)", eta$steps_done() + 1L, n_steps(), last,
                    clock_text(now() - start), clock_text(left(paste("chunks", total - index + 1)))))
      } else if (identical(current, last)) {
        eta$tick(now())
        l <- left("chunk")
        if (now() - last_line >= every) {
          last_line <<- now()
          say(sprintf("         %s: chunk %d of %d (%s so far, about %s left)", last, index, total,
                      clock_text(now() - start), clock_text(l)))
        }
      }
    },
    done = function(path) {
      if (is.function(trace)) trace(now() - start, 0, "done")
      say(sprintf("handmotion: report written in %s: %s", clock_text(now() - start), path))
      say("  tables in ", file.path(dirname(path), "tables"), ", figures in ", file.path(dirname(path), "figures"))
    }
  )
}
