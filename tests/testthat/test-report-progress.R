# A machine measured as the reference one, quiet; and the same machine busy:
# the calibration's process got a third of a core, with six other jobs on
# two cores (fed, never timed).
quiet_pace <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu, load = 0, cores = 2L)

test_that("the step counter counts each step once, the page included", {
  settings <- list(subjects = 2, grasps = c(17, 25), folds = 2)
  lines <- character()
  con <- textConnection("lines", "w", local = TRUE)
  t <- 0
  bar <- report_progress(TRUE, out = con, every = 0, clock = function() t, pace = function() quiet_pace)
  bar$begin(settings)
  steps <- report_step_model$step
  # the report signals every step but the last; the page's chunks start it
  for (label in steps[-length(steps)]) {
    bar$chunk(1, 10)
    bar$step(label)
    t <- t + 1
  }
  bar$chunk(8, 10)
  bar$chunk(9, 10)
  bar$done("/somewhere/reproduce-thesis.html")
  close(con)
  counters <- regmatches(lines, regexpr("\\[ *[0-9]+/[0-9]+\\]", lines))
  n <- length(steps)
  expect_identical(gsub(" ", "", counters), sprintf("[%d/%d]", seq_len(n), n))
  expect_match(lines[grep(sprintf("\\[%d/%d\\]", n, n), lines)], "the figures and the page", fixed = TRUE)
})
