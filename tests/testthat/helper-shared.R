# Locates ../shared (the project's shared folder with real GraspDB14 samples and
# the thesis tables). They carry no licence, so they are never copied into the
# package: tests read them in place and skip when they are absent.
# Looks at $HANDMOTION_SHARED first, then walks up from the working directory
# (tests run from tests/testthat, or from handmotion.Rcheck/tests/testthat).
shared_dir <- function() {
  env <- Sys.getenv("HANDMOTION_SHARED")
  if (nzchar(env) && dir.exists(env)) return(normalizePath(env))
  d <- normalizePath(getwd())
  for (i in 1:6) {
    cand <- file.path(d, "shared")
    if (dir.exists(file.path(cand, "data", "graspdb14"))) return(cand)
    cand <- file.path(dirname(d), "shared")
    if (dir.exists(file.path(cand, "data", "graspdb14"))) return(cand)
    d <- dirname(d)
  }
  NA_character_
}

# Path to a file under shared/; skips the calling test when shared/ is absent.
shared_file <- function(...) {
  root <- shared_dir()
  testthat::skip_if(is.na(root), "shared/ folder with the real fixtures is not present")
  p <- file.path(root, ...)
  testthat::skip_if_not(file.exists(p), paste("fixture missing:", p))
  p
}
