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
