# A machine measured as the reference one, quiet; and the same machine busy:
# the calibration's process got a third of a core, with six other jobs on
# two cores (fed, never timed).
quiet_pace <- pace_summary(cpu = pace_reference_cpu, elapsed = pace_reference_cpu, load = 0, cores = 2L)

busy_pace <- pace_summary(cpu = pace_reference_cpu, elapsed = 3 * pace_reference_cpu, load = 6, cores = 2L)
