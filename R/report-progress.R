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

# Each step's time in a full report (tables/timings.csv of reproduce_thesis()
# on the default design: 30 subjects x 33 types, leave-one-subject-out, one
# worker on a shared machine, 17 min wall clock for 4.7 min of CPU; the
# figures, tables and pandoc between and after the steps as "the figures and
# the page"). Only the shares matter: the time left is the time so far scaled
# by what remains. A step not listed counts with the median share.
report_step_weights <- c(
  "simulate the data" = 3,
  "fit the grasp models" = 20,
  "classify by FPCA distance (in-sample)" = 4,
  "fit last-frame PCA" = 0.1,
  "classify by last-frame PCA (in-sample)" = 0.4,
  "generate three grasps per type" = 0.1,
  "held-out evaluation, FPCA" = 203,
  "held-out evaluation, last-frame PCA" = 24,
  "held-out evaluation, weighted FPCA distance" = 455,
  "held-out evaluation, shrinkage LDA" = 75,
  "re-align two example types (Figures 5.1, 5.2)" = 1,
  "frame-PCA alternative (Figure 5.3)" = 0.2,
  "natural grasps: thesis model on the training subjects" = 15,
  "natural grasps: copula model on the training subjects" = 10,
  "natural grasps: evaluate_generation()" = 53,
  "natural grasps: thesis model with the mixture guard" = 26,
  "recognition: weighted FPCA distance (learn weights)" = 0.1,
  "recognition: shrinkage LDA (fit)" = 1,
  "recognition: classify the held-out subjects" = 6,
  "recognition: early recognition, held out by subject" = 104,
  "the figures and the page" = 33
)

# A progress printer for one report: `step(label)` as each step starts,
# `done(path)` at the end.
report_progress <- function(enabled = TRUE, out = stderr()) {
  start <- proc.time()[["elapsed"]]
  w <- report_step_weights
  total <- sum(w)
  n_steps <- length(w) - 1L
  seen <- character()
  say <- function(...) if (enabled) cat(..., "\n", sep = "", file = out)
  clock <- function(s) if (s < 90) sprintf("%.0f s", s) else sprintf("%.1f min", s / 60)
  # weight of the work finished when `label` starts: the steps seen before it
  weight_of <- function(l) if (l %in% names(w)) w[[l]] else stats::median(w)
  list(
    begin = function(settings) {
      workers <- if (requireNamespace("future", quietly = TRUE)) future::nbrOfWorkers() else 1L
      say(sprintf("handmotion: reproducing the thesis' chapter 5 (%d subjects x %d grasp types, %s) on %d worker%s",
                  settings$subjects, length(settings$grasps),
                  if (is.null(settings$loso_folds)) "leave-one-subject-out" else paste(settings$loso_folds, "folds"),
                  workers, if (workers == 1L) "" else "s"))
      if (workers == 1L) {
        say("  (one worker: the full design needs about 5 minutes of one core; future::plan(\"multisession\") ",
            "first runs the held-out folds in parallel)")
      }
    },
    step = function(label) {
      now <- proc.time()[["elapsed"]] - start
      done <- sum(vapply(seen, weight_of, numeric(1)))
      seen <<- c(seen, label)
      left <- if (done > 0 && now > 0.5) sprintf(", about %s left", clock(now * (total - done) / done)) else ""
      say(sprintf("  [%2d/%d] %s (%s so far%s)", min(length(seen), n_steps), n_steps, label, clock(now), left))
    },
    done = function(path) {
      say(sprintf("handmotion: report written in %s: %s", clock(proc.time()[["elapsed"]] - start), path))
      say("  tables in ", file.path(dirname(path), "tables"), ", figures in ", file.path(dirname(path), "figures"))
    }
  )
}
