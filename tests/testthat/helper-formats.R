# Fixtures for the reader/writer tests: tiny synthetic GraspDB14 and HUST
# files written from scratch (never copies of the real samples).

# One GraspDB14 row per frame: date, time, switch, 23 sensor values.
graspdb14_row_text <- function(n = 5, switch = rep(1L, n), values = NULL, start_sec = 9.024) {
  if (is.null(values)) values <- matrix(round(seq_len(n * 23) / 1000 - 0.3, 5), n, 23, byrow = TRUE)
  sec <- start_sec + (seq_len(n) - 1) * 0.016
  sprintf("2014 09 15 08 02 %08.5f %d %s ", sec, as.integer(switch),
          apply(values, 1, function(v) paste(sprintf("%8.5f", v), collapse = " ")))
}

# Write lines to `name` inside `dir` with the chosen end-of-line; returns the path.
write_fixture <- function(dir, name, lines, eol = "\n", final_eol = TRUE) {
  dir.create(dir, showWarnings = FALSE, recursive = TRUE)
  path <- file.path(dir, name)
  txt <- paste(lines, collapse = eol)
  if (final_eol && length(lines)) txt <- paste0(txt, eol)
  writeBin(charToRaw(txt), path)
  path
}

# A small HUST-like grasps object (16 DoFs, degrees) with known values.
hust_fixture <- function(n_rec = 3, n_frames = 12) {
  recs <- lapply(seq_len(n_rec), function(i) {
    matrix(round(outer(seq_len(n_frames), seq_len(16), function(f, d) i * 10 + f * 0.5 + d / 7), 6),
           n_frames, 16)
  })
  grasps(recs, meta = data.frame(id = sprintf("rec%02d", seq_len(n_rec)),
                                 grasp = c(11, 2, 33, 1, 5)[seq_len(n_rec)],
                                 subject = sprintf("S%02d", seq_len(n_rec)),
                                 object = c("ball", "pen", "cup", "box", "can")[seq_len(n_rec)],
                                 trial = seq_len(n_rec)))
}

# Two short GraspDB14 recordings (23 sensors, radians, 60 Hz) that
# write_graspdb14() can name and read_graspdb14() reads back.
graspdb14_fixture_grasps <- function() {
  recs <- withr::with_seed(3, lapply(c(12, 10), function(k) matrix(stats::runif(k * 23, -1.6, 1.6), k, 23)))
  grasps(recs, meta = data.frame(id = c("a", "b"), grasp = c(11, 11), subject = c("su03", "su04"),
                                 object = c("Tennis ball (64 mm diameter)", "Tennis ball (64 mm diameter)"),
                                 trial = c(4, 7)),
         dofs = cyberglove_sensors$name, rate = 60, unit = "rad")
}
