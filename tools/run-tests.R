# Runs the testthat suite against the installed package's sources (load_all),
# prints one plain closing line "testthat: N passed, N failed, N skipped" and
# exits non-zero when anything failed or errored.
options(testthat.progress.max_fails = Inf)
res <- testthat::test_local(".", reporter = testthat::ProgressReporter$new(show_praise = FALSE),
                            stop_on_failure = FALSE)
df <- as.data.frame(res)
failed <- sum(df$failed) + sum(df$error)
cat(sprintf("testthat: %d passed, %d failed, %d skipped\n",
            sum(df$passed), failed, sum(df$skipped)))
quit(status = if (failed > 0) 1 else 0)
