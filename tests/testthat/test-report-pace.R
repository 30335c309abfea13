test_that("the slowdown on the workers follows the other jobs' demand, not the load average", {
  # A planted machine: 2 cores shared evenly by `demand` other processes
  # that each want a whole core, plus ours. One process gets
  # min(1, 2 / (demand + 1)) of a core (what the calibration measures), two
  # workers min(1, 2 / (demand + 2)) each; the load average also counts
  # three processes waiting on the disk, which want no core.
  for (demand in c(0, 0.5, 1, 2, 3, 5)) {
    got <- min(1, 2 / (demand + 1))
    pace <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu / got, load = demand + 3, cores = 2L)
    f <- pace_factors(pace, workers = 2L)
    if (got < 1) {
      expect_equal(f[["main"]], 1 / got)
      expect_equal(f[["workers"]], 1 / min(1, 2 / (demand + 2)))
    } else {
      # a whole core: the share cannot tell 0 from 1 other process, the
      # (inflated) load average is capped at cores - 1: at worst 1.5x
      expect_equal(f[["main"]], 1)
      expect_true(f[["workers"]] >= 1 / min(1, 2 / (demand + 2)) && f[["workers"]] <= 1.5)
    }
  }
  # at load 5-6, a calibration getting half a core: the workers run 2.5x as
  # slow (three others), where (load + workers) / cores said 4x
  half <- pace_summary(cpu = pace_reference_cpu, elapsed = 2 * pace_reference_cpu, load = 6, cores = 2L)
  expect_equal(pace_factors(half, workers = 2L)[["workers"]], 2.5)
  # quiet, with a little background: within 30% of the model's own seconds
  calm <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu, load = 0.4, cores = 2L)
  expect_equal(unname(pace_factors(calm, workers = 2L)), c(1, 1.2))
  # a slower core scales both
  slow <- pace_summary(cpu = 2 * pace_reference_cpu, elapsed = 4 * pace_reference_cpu, load = 6, cores = 2L)
  expect_equal(unname(pace_factors(slow, workers = 2L)), c(4, 5))
})

test_that("the other jobs' measured use of the cores, not a lagging load average, plans the workers", {
  # A quiet machine just after a job ended: the 1-minute load average still
  # says 1.4, /proc/stat says nobody else used the cores during the
  # calibration. The workers run at the core's pace, and nothing is busy.
  after_job <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu, load = 1.4, cores = 2L, others = 0.02)
  expect_equal(unname(pace_factors(after_job, workers = 2L)), c(1, 1.01))
  expect_false(pace_busy(after_job))
  expect_match(pace_text(after_job), "other jobs using 0.0 of 2 cores")
  # one other job on a whole core while the load average has not caught up
  # (0.3): two workers share one core and a half each way, 1.5x as slow
  one_job <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu, load = 0.3, cores = 2L, others = 1)
  expect_equal(unname(pace_factors(one_job, workers = 2L)), c(1, 1.5))
  expect_true(pace_busy(one_job))
  expect_match(pace_text(one_job), "machine is busy")
  # without /proc/stat the load average stands in, as before
  no_stat <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu, load = 1.4, cores = 2L)
  expect_equal(unname(pace_factors(no_stat, workers = 2L)), c(1, 1.5))
})

test_that("the machine's pace is measured on this machine", {
  skip_on_cran()
  p <- machine_pace()
  expect_true(p$cpu > 0 && p$elapsed >= p$cpu && p$share <= 1)
  # (what other jobs use is between nothing and every core, give or take a
  # tick of /proc/stat's clock; NA where there is none)
  expect_true(is.na(p$others) || (p$others > -0.2 && p$others < p$cores + 0.2))
})
