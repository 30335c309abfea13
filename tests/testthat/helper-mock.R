# Replace an internal function of the package for the rest of the calling
# test (testthat's local_mocked_bindings() needs testthat 3.1.7; Debian's is
# older). Used to force rare paths: an alignment that fails, the R EM.
local_mocked_internal <- function(name, value, env = parent.frame()) {
  ns <- asNamespace("handmotion")
  old <- get(name, envir = ns, inherits = FALSE)
  locked <- bindingIsLocked(name, ns)
  if (locked) unlockBinding(name, ns)
  assign(name, value, envir = ns)
  withr::defer({
    if (locked) unlockBinding(name, ns)
    assign(name, old, envir = ns)
    if (locked) lockBinding(name, ns)
  }, envir = env)
  if (locked) lockBinding(name, ns)
  invisible(old)
}

# The alignment of every recording fails (the linear fallback's path).
local_failing_alignment <- function(env = parent.frame()) {
  local_mocked_internal("dba_run", function(...) stop("alignment failure forced by the test"), env = env)
}
