# The time-left estimator of reproduce_thesis() (R/report-eta.R), fed
# planted times (no clock): each test plants how long the steps really
# take against the model and checks the estimate it must then give.

# A machine measured as the reference one, quiet; and the same machine busy:
# the calibration's process got a third of a core, with six other jobs on
# two cores (fed, never timed).
quiet_pace <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu, load = 0, cores = 2L)
busy_pace <- pace_summary(cpu = pace_reference_cpu, elapsed = 3 * pace_reference_cpu, load = 6, cores = 2L)

# Run planted steps through the estimator: `true` seconds per step, `ticks`
# progress steps per step (0: none) taking equal shares of the step after
# a start-up of `startup` seconds. Returns the estimate and the true time
# left at every update.
plant_run <- function(cost, kind, true, ticks = rep(0, length(cost)), startup = rep(0, length(cost)),
                      prior = 20) {
  eta <- report_eta(cost, kind, prior = prior)
  total <- sum(true)
  t <- 0
  log <- data.frame(t = numeric(), est = numeric(), real = numeric())
  note <- function(t) log[nrow(log) + 1L, ] <<- c(t, eta$left(t), total - t)
  for (i in seq_along(cost)) {
    eta$step(names(cost)[i], t)
    if (i > 1) note(t)
    if (ticks[i] > 0) {
      eta$initiate(ticks[i])
      per <- (true[i] - startup[i]) / ticks[i]
      for (j in seq_len(ticks[i])) {
        eta$tick(t + startup[i] + j * per)
        note(t + startup[i] + j * per)
      }
    }
    t <- t + true[i]
  }
  log
}

test_that("steps running at a constant multiple of the model are predicted exactly once one has run", {
  cost <- c(a = 2, b = 10, c = 50, d = 5, e = 20)
  kind <- c(a = "x", b = "x", c = "x", d = "x", e = "x")
  log <- plant_run(cost, kind, true = 1.7 * cost, prior = 5)
  # with a small prior of rate 1 the estimate approaches 1.7 as steps
  # finish; after a tenth of the work it is within 5%
  late <- log[log$t >= 0.1 * sum(1.7 * cost) & log$real > 0, ]
  expect_lt(max(abs(late$est / late$real - 1)), 0.05)
  # the whole estimate with no step finished is the model's
  eta <- report_eta(cost, kind)
  expect_equal(eta$left(0), sum(cost))
  eta$step("a", 0)
  expect_equal(eta$left(1), sum(cost) - 1)
})

test_that("each kind of step keeps its own error against the model", {
  # the held-out folds run 2x slower than the model, the fits at the model's
  # pace: after both kinds have run, the rest of each is predicted at its
  # own rate, not at the average of all
  cost <- c(fit1 = 20, folds1 = 40, fit2 = 20, folds2 = 40, fit3 = 20)
  kind <- c(fit1 = "N", folds1 = "NF", fit2 = "N", folds2 = "NF", fit3 = "N")
  true <- c(20, 80, 20, 80, 20)
  eta <- report_eta(cost, kind, prior = 5)
  t <- 0
  for (i in 1:3) {
    eta$step(names(cost)[i], t)
    t <- t + true[i]
  }
  eta$step("folds2", t)
  # folds kind: (80 + 5 r) / (40 + 5), fits: (40 + 5 r) / (40 + 5), with r
  # the rate of the steps of the main process, (120 + 5 r0) / (80 + 5),
  # itself shrunk to the overall r0 = (120 + 5) / (80 + 5)
  r0 <- 125 / 85
  r <- (120 + 5 * r0) / 85
  expect_equal(eta$left(t), 40 * (80 + 5 * r) / 45 + 20 * (40 + 5 * r) / 45)
  # the single average rate would say 40 * 1.5 + 20 * 1.5 = 90 s for the
  # true 100 s; the kinds say within 3% of it
  expect_lt(abs(eta$left(t) / 100 - 1), 0.03)
})

test_that("a kind not yet seen takes the rate of the steps run the same way", {
  # on a busy machine the steps on the workers run 2x slower than the model,
  # the main process's steps at its pace: a new kind on the workers is
  # predicted at about 2x, a new kind of the main process at about 1x
  cost <- c(fit = 40, table = 20, folds = 50, page = 10)
  kind <- c(fit = "N/workers", table = "T", folds = "NF/workers", page = "const")
  eta <- report_eta(cost, kind, prior = 5)
  eta$step("fit", 0)
  eta$step("table", 80)
  eta$step("folds", 100)
  r0 <- (100 + 5) / (60 + 5)
  workers <- (80 + 5 * r0) / (40 + 5)
  main <- (20 + 5 * r0) / (20 + 5)
  expect_equal(eta$left(100), 50 * workers + 10 * main)
  expect_gt(workers, 1.8)
  expect_lt(main, 1.15)
})

test_that("within a step the pace of its progress steps counts, not the workers' start", {
  # one long step of 30 folds: 10 s of start-up, then 3 s per fold (100 s
  # in all), where the model said 60 s
  cost <- c(sim = 5, folds = 60, page = 10)
  kind <- c(sim = "N", folds = "NF/workers", page = "T")
  log <- plant_run(cost, kind, true = c(5, 100, 10), ticks = c(0, 30, 0), startup = c(0, 10, 0))
  in_folds <- log[log$t > 5 & log$t < 105, ]
  # the slope of the progress steps gives 3 s per fold from the second fold
  # on: the rest of the step is trusted as far as the step has gone, the
  # model (at the pace of the first step: 1) for the rest
  eta <- report_eta(cost, kind)
  eta$step("sim", 0)
  eta$step("folds", 5)
  eta$initiate(30)
  eta$tick(5 + 10 + 3)
  eta$tick(5 + 10 + 6)
  # two progress steps: with fewer than six their pace is the step's time
  # over their count (8 s each: the start-up in it), trusted as far as the
  # step has gone (2 / 30); the slope needs more (two workers end their
  # folds in pairs)
  w <- 2 / 30
  by_ticks <- 8 * 28
  by_model <- 60 - 16
  expect_equal(eta$by_ticks(21), by_ticks)
  expect_equal(eta$left(21), (1 - w) * by_model + w * by_ticks + 10)
  expect_equal(eta$fraction(), 2 / 30)
  # from the sixth fold on, within 25% of the true time left while 15 s
  # or more remain (the page after the folds is predicted at the folds'
  # slower pace: 13.8 s for its 10)
  late <- in_folds[in_folds$t >= 5 + 10 + 6 * 3 & in_folds$real >= 15, ]
  expect_lt(max(abs(late$est / late$real - 1)), 0.25)
  # (counting the start-up in the pace, as a plain time / folds rate does,
  # would have said 20 * (10 + 3 * 10) / 10 = 80 s after the tenth fold for
  # the true 70 s; the slope says 60 s for the step's rest)
  eta2 <- report_eta(cost, kind)
  eta2$step("sim", 0)
  eta2$step("folds", 5)
  eta2$initiate(30)
  for (j in 1:10) eta2$tick(15 + 3 * j)
  expect_equal(eta2$by_ticks(45), 60)
  # and the step's projection (40 + 60 s for the model's 60) raises the
  # rate of what follows: the page is predicted above its model's 10 s
  expect_gt(eta2$left(45) - 0.75 * 60, 0.25 * max(0, 60 - 40) + 10)
})

test_that("folds ending in pairs (two workers) give the pace of one fold", {
  # 30 folds on two workers: two end together every 8 s (4 s a fold) after
  # a 6 s start-up; after 3 pairs the pace is 4 s a fold within 10% (the
  # slope between the first and last would say 3.3 s)
  cost <- c(folds = 120)
  eta <- report_eta(cost, c(folds = "NF/workers"))
  eta$step("folds", 0)
  eta$initiate(30, 0)
  at <- 6 + rep(8 * (1:3), each = 2) + rep(c(0, 0.1), 3)
  for (t in at) eta$tick(t)
  per <- eta$by_ticks(at[6]) / 24
  expect_equal(per, 4, tolerance = 0.1)
})

test_that("a short step far over its model does not blow up the long steps after it", {
  # `make demo`'s pattern (issue 42, bench-eta.R's trace replayed): the
  # model fit, 7 s by the model, takes 35 s on the workers: 11 s before its
  # first type comes back, then the types arrive in bursts as the workers'
  # futures end (16 in 3 s, 9 in 4 s after an 8 s wait, 8 more after 4 s).
  # The held-out folds after it run at 1.5 times their model (in the trace
  # 1.5-2.8 times), the page at 1.
  cost <- c(sim = 3, fit = 7, folds = 440, page = 100)
  kind <- c(sim = "N", fit = "N/workers", folds = "NF/workers", page = "T")
  true <- c(sim = 3, fit = 35, folds = 1.5 * 440, page = 100)
  eta <- report_eta(cost, kind)
  eta$step("sim", 0)
  eta$step("fit", 3)
  eta$initiate(33, 3.2)
  at <- 3 + c(11 + seq(0, 3, length.out = 16), 22.5 + seq(0, 4, length.out = 9),
              31 + seq(0, 1.5, length.out = 8))
  said <- vapply(at, function(t) {
    eta$tick(t)
    eta$left(t)
  }, numeric(1))
  error <- said / (sum(true) - at) - 1
  # never more than 30% over the true time left (a prior of 20 s let the
  # fit's five-fold pace double the folds' rate: 79% over); below it by
  # the folds' excess over the model (a third), which no step before them
  # can show
  expect_lt(max(error), 0.3)
  expect_gt(min(error), -0.35)
})

test_that("a count of progress steps that starts after the first is done has its own pace", {
  # 10 folds of 6 s, then an in-sample fit counted in 20 types of 0.1 s:
  # after the folds, the types' pace says what is left, not the folds'
  cost <- c(folds = 60, page = 10)
  kind <- c(folds = "NF/workers", page = "T")
  eta <- report_eta(cost, kind)
  eta$step("folds", 0)
  eta$initiate(10, 0)
  for (j in 1:10) eta$tick(6 * j)
  eta$initiate(20, 60)
  for (j in 1:5) eta$tick(60 + 0.1 * j)
  # 5 of 20 done at 0.1 s each: 1.5 s left by its pace (the folds' 6 s per
  # step would say 90 s), trusted as far as it has gone (5 / 20); with the model's
  # rest (60 s at about rate 1: about spent) and the page, about 11 s
  expect_equal(eta$by_ticks(60.5), 1.5)
  expect_equal(eta$fraction(), 5 / 20)
  expect_lt(eta$left(60.5), 13)
  expect_gt(eta$left(60.5), 10)
})

test_that("a step the model does not know gets a median cost and its own kind", {
  cost <- c(a = 10, b = 20, c = 30)
  eta <- report_eta(cost, c(a = "x", b = "x", c = "x"))
  eta$step("a", 0)
  eta$step("new", 10)
  expect_equal(unname(eta$costs()[["new"]]), 20)
  # a ran at the model's pace: the rest is b, c and new's median at rate ~1
  expect_equal(eta$left(10), 20 + 20 + 30)
})

test_that("the printer feeds the estimator its clock and reports every estimate", {
  lines <- character()
  con <- textConnection("lines", "w", local = TRUE)
  t <- 0
  seen <- list()
  bar <- report_progress(TRUE, out = con, every = 0, clock = function() t,
                         trace = function(so_far, left, event) {
                           if (!is.na(left)) seen[[length(seen) + 1L]] <<- c(so_far, left)
                         }, pace = function() quiet_pace)
  settings <- list(subjects = 30, grasps = 1:33, folds = NULL)
  cost <- report_step_costs(settings, workers = future::nbrOfWorkers(), pace = quiet_pace)
  bar$begin(settings)
  bar$step(names(cost)[1])
  t <- 2 * cost[[1]]
  bar$step(names(cost)[2])
  bar$tick(list(type = "initiate", steps = 4))
  t <- t + 3
  bar$tick(list(type = "update", amount = 1))
  t <- t + 3
  bar$tick(list(type = "update", amount = 1))
  bar$done("/somewhere/reproduce-thesis.html")
  close(con)
  expect_match(lines[1], "30 subjects x 33 grasp types, leave-one-subject-out", fixed = TRUE)
  expect_match(lines[grep("\\[ 1/", lines)], "simulate the data (0 s so far)", fixed = TRUE)
  expect_match(lines[grep("fit the grasp models: 50%", lines, fixed = TRUE)], "about .* left")
  expect_match(lines[length(lines) - 1L], "report written in .*: /somewhere/reproduce-thesis.html")
  # the printed estimates are the estimator's, at the printer's clock
  eta <- report_eta(cost, report_step_kinds(names(cost)))
  eta$step(names(cost)[1], 0)
  eta$step(names(cost)[2], 2 * cost[[1]])
  eta$initiate(4)
  eta$tick(2 * cost[[1]] + 3)
  eta$tick(2 * cost[[1]] + 6)
  last <- seen[[length(seen) - 1L]]
  expect_equal(last, c(2 * cost[[1]] + 6, eta$left(2 * cost[[1]] + 6)))
  expect_equal(seen[[length(seen)]], c(2 * cost[[1]] + 6, 0))
  quiet <- report_progress(FALSE, out = con)
  expect_silent({quiet$begin(settings); quiet$step("x"); quiet$done("y")})
})


test_that("the first estimate is the cost model at the machine's measured pace", {
  settings <- list(subjects = 30, grasps = 1:33, folds = NULL)
  ref <- report_step_costs(settings, workers = 2L)
  # the reference machine, quiet: the model's own seconds
  expect_equal(report_step_costs(settings, workers = 2L, pace = quiet_pace), ref)
  # a core half as fast: everything twice as long
  slow_core <- pace_summary(cpu = 2 * pace_reference_cpu, elapsed = 2 * pace_reference_cpu, load = 0, cores = 2L)
  expect_equal(report_step_costs(settings, workers = 2L, pace = slow_core), 2 * ref)
  # busy: a process in the main thread gets a third of a core (3x): the
  # others want five cores' worth (the load average of 6 says more, but
  # counts what does not compete), so two workers get 2 / 7 of a core each
  busy <- report_step_costs(settings, workers = 2L, pace = busy_pace)
  par <- report_step_model$parallel
  expect_equal(unname(busy[!par] / ref[!par]), rep(3, sum(!par)))
  expect_equal(unname(busy[par] / ref[par]), rep(3.5, sum(par)))
  # on one worker the parallel steps run in the main process
  one <- report_step_costs(settings, workers = 1L, pace = busy_pace)
  expect_equal(unname(one / report_step_costs(settings, workers = 1L)), rep(3, length(one)))
})

test_that("a small design pays each step's fixed part, a larger one grows beyond it", {
  tiny <- report_step_costs(list(subjects = 2, grasps = c(17, 25), folds = 2), workers = 1L)
  expect_true(all(tiny >= report_step_model$fixed - 1e-12))
  full <- report_step_costs(list(subjects = 30, grasps = 1:33, folds = NULL), workers = 1L)
  expect_equal(unname(full), report_step_model$cpu)
  half <- report_step_costs(list(subjects = 15, grasps = 1:33, folds = NULL), workers = 1L)
  expect_true(all(half >= tiny - 1e-12 & half <= full + 1e-12))
})

test_that("the first line says when the machine is busy, and the estimate allows for it", {
  settings <- list(subjects = 30, grasps = 1:33, folds = NULL)
  first_lines <- function(pace) {
    lines <- character()
    con <- textConnection("lines", "w", local = TRUE)
    bar <- report_progress(TRUE, out = con, clock = function() 0, pace = function() pace)
    bar$begin(settings)
    close(con)
    lines
  }
  workers <- future::nbrOfWorkers()
  clock_min <- function(s) sprintf("about %.1f min", s / 60)
  quiet <- first_lines(quiet_pace)
  expect_match(quiet[2], clock_min(sum(report_step_costs(settings, workers, quiet_pace))), fixed = TRUE)
  expect_false(grepl("busy", quiet[2]))
  busy <- first_lines(busy_pace)
  expect_match(busy[2], clock_min(sum(report_step_costs(settings, workers, busy_pace))), fixed = TRUE)
  expect_match(busy[2], "the machine is busy (load 6.0 on 2 cores, a test fit got 33% of a core)", fixed = TRUE)
  expect_true(pace_busy(busy_pace))
  expect_false(pace_busy(quiet_pace))
  # no load average known: the measured share alone says it
  expect_true(pace_busy(pace_summary(1, 2, load = NA, cores = 2L)))
})
