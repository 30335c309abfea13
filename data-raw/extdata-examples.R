# Builds the small example files in inst/extdata/ with the package's own
# writers, from synthetic values (never from the real GraspDB14 samples, which
# carry no licence). Run from the package root after the package data exist:
#   Rscript data-raw/extdata-examples.R
pkgload::load_all(".", quiet = TRUE)
set.seed(20140915)

# A smooth reach-grasp-release profile: 0 at rest, 1 while holding.
grasp_profile <- function(n, hold = c(0.35, 0.7)) {
  t <- seq(0, 1, length.out = n)
  stats::plogis((t - hold[1]) * 25) * (1 - stats::plogis((t - hold[2]) * 25))
}

# 23 sensor angles (radians, GraspDB14 sign convention: flexion negative).
synthetic_glove <- function(n, closure = 1) {
  s <- cyberglove_sensors
  rest <- ifelse(s$motion == "flexion", -0.1, 0.05)
  reach <- ifelse(s$motion == "flexion", -1.1, 0.25) * closure
  reach[s$status == "unsupported"] <- 0
  rest[s$status == "unsupported"] <- 0
  p <- grasp_profile(n)
  m <- outer(p, reach) + matrix(rest, n, 23, byrow = TRUE)
  m <- m + matrix(stats::rnorm(n * 23, sd = 0.005), n, 23)
  m[, s$status == "unsupported"] <- 0
  # the recording software infers DIP from PIP (the glove has no DIP sensor)
  dip <- which(s$status == "inferred")
  m[, dip] <- m[, dip - 1L] * 0.6
  colnames(m) <- s$name
  round(m, 5)
}

# Frame times like the real glove: about 60 Hz, steps of 15 or 16 ms.
glove_time <- function(n) c(0, cumsum(sample(c(0.015, 0.016, 0.017), n - 1, replace = TRUE,
                                             prob = c(0.4, 0.55, 0.05))))

with_attrs <- function(m, switch = rep(1L, nrow(m))) {
  attr(m, "switch") <- switch
  attr(m, "time") <- glove_time(nrow(m))
  m
}

# Calibration stream: 21 ON/OFF runs starting ON (report section 3.5).
runs <- sample(7:10, 21, replace = TRUE)
calib_switch <- rep(rep(c(1L, 0L), length.out = 21), runs)
calib <- synthetic_glove(length(calib_switch), closure = 0.5)

recs <- list(
  with_attrs(synthetic_glove(80)),
  with_attrs(synthetic_glove(70, closure = 0.8)),
  with_attrs(synthetic_glove(75, closure = 0.6)),
  with_attrs(synthetic_glove(90, closure = 0.7)),
  with_attrs(calib, calib_switch)
)
meta <- data.frame(
  id = c("ex03", "ex03_1", "ex01", "ex02", "calib"),
  grasp = c(11, 2, NA, NA, NA), subject = c("1", "1", "2", "1", "1"),
  scenario = c("3", "3", "1", "2", "calib"), variant = c(NA, "1", NA, NA, NA),
  object_id = c(1L, 13L, 4L, 2L, 0L), trial = c(1L, 2L, 1L, 3L, NA),
  action_code = c(NA, NA, NA, "i_r", NA), stringsAsFactors = FALSE)
meta$start_time <- as.POSIXct("2014-09-15 08:02:09", tz = "UTC") + c(0, 60, 120, 180, -600)
g <- grasps(recs, meta = meta, dofs = cyberglove_sensors$name, rate = 60, unit = "rad")

out <- file.path("inst", "extdata", "graspdb14")
unlink(out, recursive = TRUE)
print(basename(write_graspdb14(g, out)))

# HUST layout: four recordings at 50 Hz in degrees, with a manifest.
hust_rec <- function(n, closure) {
  p <- grasp_profile(n, hold = c(0.5, 1.5))
  amp <- c(30, 20, 25, 20, 60, 70, 40, 65, 75, 45, 60, 70, 40, 55, 65, 40) * closure
  m <- outer(p, amp) + matrix(stats::rnorm(n * 16, sd = 0.3), n, 16)
  round(m, 3)
}
h <- grasps(list(hust_rec(60, 1), hust_rec(55, 0.9), hust_rec(65, 0.5), hust_rec(58, 0.45)),
            meta = data.frame(id = c("s01_g11_o1_t1", "s02_g11_o1_t1", "s01_g09_o2_t1", "s02_g09_o2_t1"),
                              grasp = c(11, 11, 9, 9), subject = c("s01", "s02", "s01", "s02"),
                              object = c("o1", "o1", "o2", "o2"), trial = 1L),
            rate = 50, unit = "deg")
out <- file.path("inst", "extdata", "hust")
unlink(out, recursive = TRUE)
print(basename(write_hust(h, out, digits = 6)))
