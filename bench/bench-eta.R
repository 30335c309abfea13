# How good is reproduce_thesis()'s time left (issue 36: within 25% once a
# tenth of the work is done)? Runs the report as `make demo` does (the full
# default design, 2 multicore workers) and logs, at every progress update
# (each step, each fold or horizon, each chunk of the page; printed or not),
# the time so far and the estimate of the time left. After the run the real
# time left at each update is known: the script prints the estimate beside
# it at each tenth of the run, each step's time against the cost model,
# and the largest relative error from 10% of the work on while 15 s or more
# remain (the error allowed: 25%), and the error in seconds after that.
# Run from the repository root: Rscript bench/bench-eta.R (BENCH_QUICK=1: 4
# subjects, 3 types, 2 folds; seconds: too short to say much)
source("bench/_common.R")

design <- if (bench_quick) list(subjects = 4, grasps = c(9, 17, 22), folds = 2) else list()
if (future::supportsMulticore()) future::plan(future::multicore, workers = 2)
log <- data.frame(t = numeric(), left = numeric())
events <- data.frame(t = numeric(), left = numeric(), event = character(), cpu = numeric())
# CPU seconds of this process and its finished children (the multicore
# workers, pandoc): the cost model is in CPU seconds (R/report-progress.R)
cpu_now <- function() sum(proc.time()[c("user.self", "sys.self", "user.child", "sys.child")], na.rm = TRUE)
# every estimate the printer makes (R/report-progress.R: signalled as
# handmotion_report_estimate conditions), and every event (saved with
# BENCH_ETA_EVENTS=file.rds, to replay them through report_eta())
options(handmotion.progress = TRUE)
trace <- function(e) {
  events[nrow(events) + 1L, ] <<- list(e$so_far, e$left, e$event, cpu_now())
  if (!is.na(e$left)) log[nrow(log) + 1L, ] <<- c(e$so_far, e$left)
}
out <- tempfile("report")
load0 <- load_avg()
cpu0 <- proc.time()
lines <- utils::capture.output(html <- withCallingHandlers(do.call(reproduce_thesis, c(list(out), design)),
                                                           handmotion_report_estimate = trace),
                               type = "message")
cpu <- proc.time() - cpu0
load1 <- load_avg()
# each step's time against the cost model (on 2 workers) it started from
settings <- list(subjects = design$subjects %||% 30, grasps = design$grasps %||% 1:33, folds = design$folds)
model <- report_step_costs(settings, workers = future::nbrOfWorkers())
tim <- utils::read.csv(file.path(out, "tables", "timings.csv"))
unlink(out, recursive = TRUE)
future::plan(future::sequential)

if (nzchar(Sys.getenv("BENCH_ETA_EVENTS"))) saveRDS(events, Sys.getenv("BENCH_ETA_EVENTS"))
total <- log$t[nrow(log)]
log$real <- total - log$t
log$share <- log$t / total
log$error <- log$left / log$real - 1
# judged from a tenth of the work on while at least 15 s remain (the lines
# say whole seconds; in the last seconds any error is a large share), the
# last 15 s in seconds
judged <- log[log$share >= 0.1 & log$real >= 15, ]
tail_err <- log[log$share >= 0.1 & log$real < 15, ]
cat(paste(lines, collapse = "\n"), "\n\n")
cat(sprintf("%d estimates in a run of %.1f s (CPU %.1f s with the workers); load average %s before, %s after\n",
            nrow(log), total, cpu[["user.self"]] + cpu[["sys.self"]] + cpu[["user.child"]] + cpu[["sys.child"]],
            format(load0), format(load1)))
cat(sprintf("\n%8s %6s %10s %10s %8s\n", "so far", "done", "said left", "real left", "error"))
# one row per tenth of the run (the estimate nearest after it) and the worst
rows <- unique(c(vapply(seq(0, 0.9, by = 0.1), function(s) which(log$share >= s)[1], integer(1)),
                 if (nrow(judged)) as.integer(rownames(judged)[which.max(abs(judged$error))])))
rows <- sort(rows[!is.na(rows)])
for (i in rows) {
  cat(sprintf("%7.1fs %5.0f%% %9.1fs %9.1fs %+7.0f%%\n", log$t[i], 100 * log$share[i], log$left[i],
              log$real[i], 100 * log$error[i]))
}
cat(sprintf("\n%-52s %9s %9s\n", "step", "model (s)", "took (s)"))
for (i in seq_len(nrow(tim))) {
  cat(sprintf("%-52s %9.1f %9.1f\n", tim$step[i], if (tim$step[i] %in% names(model)) model[[tim$step[i]]] else NA,
              tim$seconds[i]))
}
# each step's CPU seconds (this process and the workers), from the events
# that start the steps to the end: the cost model's `cpu` column is these,
# on the default design, with the calibration's CPU as pace_reference_cpu
starts <- events[grepl("^(step |chunks )", events$event) | events$event == "done", ]
pace_line <- events$event[grepl("^pace ", events$event)]
cat("\ncalibration:", if (length(pace_line)) pace_line[1] else "none", "\n")
step_names <- c(sub("^step ", "", starts$event[grepl("^step ", starts$event)]), "the figures and the page")
step_cpu <- diff(starts$cpu)
step_wall <- diff(starts$t)
cat(sprintf("%-52s %9s %9s %9s\n", "step", "model", "CPU (s)", "took (s)"))
for (i in seq_along(step_cpu)) {
  cat(sprintf("%-52s %9.1f %9.1f %9.1f\n", step_names[i],
              if (step_names[i] %in% names(model)) model[[step_names[i]]] else NA, step_cpu[i], step_wall[i]))
}
cat("cpu = c(", paste(sprintf("%.1f", step_cpu), collapse = ", "), ")\n")
cat(sprintf("first estimate %.1f s; the run took %.1f s (%+.0f%%)\n", events$left[!is.na(events$left)][1] + 0,
            total, 100 * ((events$left[!is.na(events$left)][1]) / total - 1)))
worst <- if (nrow(judged)) max(abs(judged$error)) else NA_real_
cat(sprintf("\nin the last 15 s the estimate was off by at most %.1f s", max(abs(tail_err$left - tail_err$real))))
cat(sprintf("\nlargest error of the time left from 10%% of the work on (while 15 s or more remain): %.0f%% over %d estimates (allowed 25%%: %s)\n",
            100 * worst, nrow(judged), if (isTRUE(worst <= 0.25)) "met" else "MISSED"))
bench_record("report, elapsed", total, "s")
bench_record("time left, largest relative error after 10% of the work (15 s or more left)", worst, "x")
