# Build inst/extdata/flexglove from the project's copy of the flexglove
# recordings (/work/shared/data/flexglove, itself taken from
# Oooorca/AML_LAB_Project at commit 53e60c3e57c25c669102d7a50427c31e727baf02,
# the 97 synthetic Participant2 copies left out).
#
# One CSV per recording, in one folder per grasp label, named
# <P1|P2>_<object>_<trial>.csv as in the source copy. The time column is put
# back first (`time_ms,flex1,...,flex6`, as the source repository kept it)
# from the separate timestamps files; values are copied unchanged. The MIT
# LICENSE is copied unchanged beside the files.
#
# Run from the package root: Rscript data-raw/flexglove-extdata.R [source-dir]

args <- commandArgs(trailingOnly = TRUE)
src <- if (length(args)) args[1] else file.path(Sys.getenv("HANDMOTION_SHARED", "/work/shared"),
                                                "data", "flexglove")
out <- file.path("inst", "extdata", "flexglove")
stopifnot(dir.exists(src), file.exists("DESCRIPTION"))

man <- utils::read.csv(file.path(src, "manifest.csv"), stringsAsFactors = FALSE)
unlink(out, recursive = TRUE)
dir.create(out, recursive = TRUE)
for (f in man$file) {
  flex <- readLines(file.path(src, f))
  time <- readLines(file.path(src, "timestamps", f))
  # same frames in both files, one header line each
  stopifnot(length(flex) == length(time), time[1] == "time_ms",
            flex[1] == "flex1,flex2,flex3,flex4,flex5,flex6")
  dir.create(file.path(out, dirname(f)), showWarnings = FALSE)
  writeLines(paste(time, flex, sep = ","), file.path(out, f))
}
stopifnot(file.copy(file.path(src, "LICENSE"), file.path(out, "LICENSE")))
cat(sprintf("%d recordings written to %s\n", nrow(man), out))
