# A three-channel raw glove for the fixtures.
tiny_glove <- function() {
  glove_profile(data.frame(channel = c("a", "b", "c"), unit = "raw", min = 0, max = 1023),
                name = "tiny")
}

# Write a recording (time in ms first, then channels a, b, c) to dir/rel.
write_timed <- function(dir, rel, t_ms, values, header = c("time_ms", "a", "b", "c")) {
  lines <- c(paste(header, collapse = ","),
             apply(cbind(format(t_ms, digits = 15, trim = TRUE),
                         matrix(format(values, digits = 15, trim = TRUE), nrow(values))), 1,
                   paste, collapse = ","))
  write_fixture(dirname(file.path(dir, rel)), basename(rel), lines)
}
