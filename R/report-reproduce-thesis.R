# The package's main job: the thesis' chapter 5 redone on the simulated twin,
# rendered as one self-contained HTML report with every table beside the
# published value. The report body lives in inst/report/reproduce-thesis.Rmd
# so that the vignette (vignettes/reproduce-thesis.Rmd) includes the very same
# text as a child document; the settings below are shared by both routes.

#' Reproduce the thesis' chapter 5 on the simulated data
#'
#' Renders the report `inst/report/reproduce-thesis.Rmd`: it simulates the
#' HUST-like default data ([simulate_grasps()]), fits the 33 grasp models
#' ([fit_grasp_models()]), generates grasps, classifies with both schemes, and
#' shows every table (5.1-5.3, 5.6-5.8, with the thesis' published values
#' beside ours, see [thesis_table()]) and figure (5.1-5.6, the temporal
#' comparisons of Tables 5.4 and 5.5, Appendix A) with a short note on each
#' difference. Beyond the thesis, every classifier (the thesis' two, its
#' proposed weighted FPCA distance and the shrinkage LDA) is also evaluated on
#' held-out subjects ([evaluate_loso()]).
#'
#' Two sections are the thesis' research rather than the pipeline, and only
#' this report computes them: Figure 5.3, the frame-wise PCA model the thesis
#' tried and abandoned (a PCA of the posture in every frame, then an FPCA of
#' each PC's weights, whose sign flips between frames show why it failed), and
#' the split of Table 5.3's log distances into a model effect, a type effect
#' and a pairwise residual (which part of the table sets each of its counts).
#'
#' Besides the HTML report, every table is written as a CSV file to
#' `<output_dir>/tables/` and every figure as a PNG file to
#' `<output_dir>/figures/`; the time of each step is shown in the report and
#' written to `tables/timings.csv`. The confusion matrices are written in full
#' (`tables/table_5_6_confusion.csv` and so on), every verdict of the report to
#' `tables/verdicts.csv` and the R and package versions to
#' `tables/software.csv`.
#'
#' The held-out evaluations refit every model once per fold. By default that
#' is the full leave-one-subject-out (30 refits of the 33 models per
#' classifier); `folds = k` splits the subjects at random into `k`
#' groups instead, for a quicker look.
#'
#' **Time.** On one R process the full design needs about five minutes of
#' one core (measured: 4.7 min of CPU), most of it in the held-out
#' evaluations. Their folds run through
#' \pkg{future.apply}, so a parallel plan set before the call makes them
#' faster, e.g. `future::plan("multisession", workers = 2)`; the report's
#' *Timings* section and `tables/timings.csv` give the time of every step
#' and the plan it ran on.
#'
#' **Progress.** While it works, `reproduce_thesis()` prints a line as each
#' step starts (to standard error): the step, the time so far and an
#' estimate of the time left, and at the end where the report was written;
#' within a long step (the held-out folds, the horizons of early
#' recognition, the chunks of the page after the last step) a line at most
#' every 15 s. The estimate starts from a cost model of the design
#' (recordings, types, folds, workers) in CPU seconds of a reference
#' machine, scaled by this machine's pace, measured before the first step by
#' a short test fit (about a second): how fast a core is, how much of a core
#' one process gets and, for the steps on the workers, the load average
#' (the other jobs that want the cores). When the machine is busy the first
#' line says so. It then follows the measured pace: the
#' time the finished steps of each kind (held-out folds on the workers,
#' fits, tables) took against the model, and within a step the rate of its
#' own folds or horizons, which also informs the steps after it.
#' `progress = FALSE` or
#' `options(handmotion.progress = FALSE)` keeps it silent.
#'
#' The vignette `vignette("reproduce-thesis", package = "handmotion")`
#' includes the same report; there the design can be made smaller through
#' environment variables (`HANDMOTION_REPORT_SUBJECTS`,
#' `HANDMOTION_REPORT_GRASPS` (comma-separated ids), `HANDMOTION_REPORT_FOLDS`
#' (`"loso"` for the full leave-one-subject-out) and `HANDMOTION_REPORT_SEED`).
#'
#' @param output_dir Directory for the report (`reproduce-thesis.html`) and
#'   its `tables/` and `figures/`; created if needed.
#' @param subjects Number of simulated subjects (30 as in HUST).
#' @param seed Seed of the simulation, the fits and the folds.
#' @param folds `NULL` (default) for leave-one-subject-out, or a number
#'   of groups of subjects for a quicker held-out evaluation (as `folds` of
#'   [evaluate_loso()]).
#' @param grasps Grasp types to include (Feix ids or names), all 33 by default.
#'   At least two are needed for classification.
#' @param overwrite Replace an existing report? As every writer of the
#'   package, by default an existing `reproduce-thesis.html` (or tables and
#'   figures of an earlier report) in `output_dir` is an error of class
#'   `handmotion_error_file_exists`, raised before anything is computed.
#' @param ... Unused: an argument of an earlier version (`loso_folds`) is an
#'   error naming its new name.
#' @param quiet Render without knitr's progress output.
#' @param progress Print a line per step with the time left (see
#'   **Progress**).
#' @return The path of the HTML report.
#' @seealso [thesis_table()], [thesis_results]
#' @export
#' @examples
#' \donttest{
#' # the README's quick design (the article "Reproducing the thesis' chapter 5"
#' # shows the report of a larger one)
#' if (rmarkdown::pandoc_available()) {
#'   out <- reproduce_thesis(tempfile("report"), subjects = 2, grasps = c(17, 25),
#'                           folds = 2)
#'   list.files(dirname(out), recursive = TRUE)
#' }
#' }
reproduce_thesis <- function(output_dir = "output", subjects = 30, seed = 1, folds = NULL,
                             grasps = 1:33, quiet = TRUE, progress = TRUE, overwrite = FALSE, ...) {
  call <- rlang::caller_env()
  check_no_dots(list(...), "reproduce_thesis", call = call)
  settings <- check_report_settings(list(subjects = subjects, seed = seed, folds = folds,
                                         grasps = grasps), call)
  check_flag(progress, "progress", call = call)
  if (!is.character(output_dir) || length(output_dir) != 1L || is.na(output_dir) || !nzchar(output_dir)) {
    hm_abort("{.arg output_dir} must be one directory path.", "bad_input", argument = "output_dir",
             call = call)
  }
  # the writers' rule (check_overwrite()): an earlier report is replaced
  # only when asked, and that is known before minutes of work
  check_overwrite(c(file.path(output_dir, "reproduce-thesis.html"),
                    list.files(file.path(output_dir, c("tables", "figures")), full.names = TRUE)),
                  overwrite, call = call)
  if (!requireNamespace("rmarkdown", quietly = TRUE) || !requireNamespace("knitr", quietly = TRUE)) {
    hm_abort("{.fn reproduce_thesis} needs the {.pkg rmarkdown} and {.pkg knitr} packages.",
             "missing_dependency", call = call)
  }
  if (!rmarkdown::pandoc_available("1.12.3")) {
    hm_abort(c("{.fn reproduce_thesis} needs pandoc to render the report.",
               i = "Install pandoc or set {.envvar RSTUDIO_PANDOC}."),
             "missing_dependency", call = call)
  }
  template <- system.file("report", "reproduce-thesis.Rmd", package = "handmotion")
  if (!nzchar(template)) {
    hm_abort("The report template {.file report/reproduce-thesis.Rmd} is missing from the installed package.",
             "missing_file", file = "report/reproduce-thesis.Rmd", call = call)
  }
  dir.create(output_dir, recursive = TRUE, showWarnings = FALSE)
  output_dir <- normalizePath(output_dir, mustWork = TRUE)
  # Knit in a scratch copy, so knitr's figure files and intermediates never
  # land in the installed package or the user's directory.
  work <- tempfile("handmotion-report-")
  dir.create(work)
  on.exit(unlink(work, recursive = TRUE), add = TRUE)
  input <- file.path(work, "reproduce-thesis.Rmd")
  file.copy(template, input)
  params <- list(subjects = settings$subjects, seed = settings$seed,
                 folds = if (is.null(settings$folds)) 0L else settings$folds,
                 grasps = settings$grasps, output_dir = output_dir)
  show <- progress && progress_wanted()
  bar <- report_progress(show, trace = report_estimate_signal)
  bar$begin(settings)
  # the long calls inside count their steps (progressr) for this printer
  # instead of drawing bars of their own; every chunk says it starts
  # (progressr.enable: with the lines off, the progressors count nothing)
  local_progress_listener()
  old_opts <- options(progressr.enable = show)
  on.exit(options(old_opts), add = TRUE)
  old_hook <- knitr::knit_hooks$get("handmotion_chunk")
  knitr::knit_hooks$set(handmotion_chunk = function(before, options, envir) {
    if (before) report_chunk_signal(options$label)
    NULL
  })
  on.exit(knitr::knit_hooks$set(handmotion_chunk = old_hook), add = TRUE)
  old_chunk <- knitr::opts_chunk$get("handmotion_chunk")
  knitr::opts_chunk$set(handmotion_chunk = TRUE)
  on.exit(knitr::opts_chunk$set(handmotion_chunk = old_chunk), add = TRUE)
  html <- withCallingHandlers(
    rmarkdown::render(input, output_file = "reproduce-thesis.html", output_dir = output_dir,
                      intermediates_dir = work, knit_root_dir = work, params = params,
                      envir = report_env(), quiet = quiet),
    handmotion_report_step = function(cnd) bar$step(cnd$label),
    handmotion_report_chunk = function(cnd) bar$chunk(cnd$index, cnd$total),
    progression = function(p) bar$tick(p))
  bar$done(html)
  html
}

# Where the report is knitted: a fresh environment whose parent is the
# package's namespace, so that the report calls its helpers
# (R/report-helpers.R) and the package's internal functions by name, with
# the user's attached packages still in reach further up.
report_env <- function() new.env(parent = asNamespace("handmotion"))

# The report's settings: from render() params (reproduce_thesis()) or, when
# knitted without params (the vignette), from environment variables, else the
# full default design. `folds` 0 / "loso" means leave-one-subject-out.
report_settings <- function(params = NULL) {
  env <- function(name) {
    v <- Sys.getenv(name)
    if (nzchar(v)) v else NULL
  }
  s <- list(subjects = 30L, seed = 1L, folds = NULL, grasps = 1:33, output_dir = NULL)
  if (is.null(params)) {
    if (!is.null(v <- env("HANDMOTION_REPORT_SUBJECTS"))) s$subjects <- as.numeric(v)
    if (!is.null(v <- env("HANDMOTION_REPORT_SEED"))) s$seed <- as.numeric(v)
    if (!is.null(v <- env("HANDMOTION_REPORT_GRASPS"))) s$grasps <- as.numeric(strsplit(v, "[, ]+")[[1]])
    if (!is.null(v <- env("HANDMOTION_REPORT_FOLDS"))) {
      s$folds <- if (tolower(v) %in% c("loso", "0", "null")) 0L else as.numeric(v)
    }
  } else {
    params <- as.list(params)
    for (nm in intersect(names(params), names(s))) {
      if (!is.null(params[[nm]])) s[[nm]] <- params[[nm]]
    }
  }
  if (identical(s$folds, 0L) || identical(s$folds, 0) || isTRUE(is.na(s$folds))) {
    s$folds <- NULL
  }
  out_dir <- s$output_dir
  s <- check_report_settings(s[c("subjects", "seed", "folds", "grasps")], rlang::caller_env())
  s$output_dir <- if (is.character(out_dir) && length(out_dir) == 1L && nzchar(out_dir)) out_dir else NULL
  s
}

check_report_settings <- function(s, call) {
  # (the held-out evaluation needs two subjects)
  s$subjects <- check_whole(s$subjects, "subjects", min = 2, call = call)
  s$seed <- check_whole(s$seed, "seed", min = -.Machine$integer.max, max = .Machine$integer.max, call = call)
  # NULL: leave-one-subject-out, as `folds` of evaluate_loso()
  s$folds <- check_whole(s$folds, "folds", min = 2, max = s$subjects, allow_null = TRUE, call = call)
  ids <- as.integer(as_feix_grasp(s$grasps, call = call))
  if (length(unique(ids)) < 2L) {
    hm_abort("{.arg grasps} must name at least two grasp types: classification needs two.",
             "bad_input", argument = "grasps", call = call)
  }
  list(subjects = as.integer(s$subjects), seed = as.integer(s$seed), folds = s$folds,
       grasps = sort(unique(ids)))
}
