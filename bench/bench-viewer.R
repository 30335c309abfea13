# What the 3D viewer (hand_3d(), inst/htmlwidgets/hand3d.js) costs the
# browser (issue 42): a page of three widgets, as the report holds, opened in
# headless chromium, twice: every widget at rest
# (autoplay = FALSE), and as the report opens them (autoplay, so playing
# once). The figure is the browser's CPU time (all its processes) in the
# `seconds` after the page had `settle` seconds to open: at rest, about none.
# Then a screenshot of the resting page with a 5 s virtual-time budget, timed
# in real seconds (it took 80 s while the widgets redrew on a 60 Hz timer).
#
#   Rscript bench/bench-viewer.R
#   BENCH_QUICK=1 Rscript bench/bench-viewer.R
source("bench/_common.R")
source("tests/testthat/helper-browser.R")
if (!nzchar(chromium_path())) stop("bench-viewer: no chromium (tools/setup.sh installs it)")

seconds <- bq(10, 3)
settle <- bq(20, 5)  # on a loaded machine opening the page took over 10 s
g <- simulate_grasps(subjects = 3, grasps = c(11, 17), objects = 1, trials = 1, seed = 1)
dir <- tempfile("bench-viewer")
dir.create(dir)
page_of <- function(autoplay) {
  widgets <- lapply(1:3, function(i) {
    hand_3d(list(recorded = g[i], generated = g[i + 3]), autoplay = autoplay, width = "100%", height = 420)
  })
  page <- file.path(dir, sprintf("three-%s.html", if (autoplay) "playing" else "resting"))
  htmltools::save_html(htmltools::tagList(widgets), page)
  page
}

# the browser open for `seconds` of real time (no virtual time: the page's
# own clock); its CPU is the CPU time of all its processes (browser, GPU,
# renderers: the process tree under it) just before it is stopped (rusage
# of children would lose the processes it does not reap)
tree_cpu <- function(root) {
  ps <- utils::read.table(text = system2("ps", c("-e", "-o", "pid=,ppid="), stdout = TRUE), col.names = c("pid", "ppid"))
  pids <- root
  repeat {
    more <- setdiff(ps$pid[ps$ppid %in% pids], pids)
    if (!length(more)) break
    pids <- c(pids, more)
  }
  # user + system time in clock ticks (/proc/<pid>/stat fields 14, 15; ps rounds to seconds)
  sum(vapply(pids, function(pid) {
    st <- tryCatch(readLines(sprintf("/proc/%d/stat", pid), warn = FALSE), error = function(e) "")
    if (!length(st) || !nzchar(st[1])) return(0)
    as.numeric(sum(as.numeric(strsplit(sub("^.*\\) ", "", st[1]), " ")[[1]][12:13])))
  }, numeric(1))) / 100
}
browser_cpu <- function(page) {
  args <- setdiff(browser_args(0), grep("^--virtual-time-budget", browser_args(0), value = TRUE))
  p <- processx::process$new(chromium_path(), c(args, "--window-size=1000,1400", "--remote-debugging-port=0",
                                                page_url(page)), stdout = NULL, stderr = NULL)
  # opening the page (start-up, three.js, building the meshes) apart from
  # the seconds after it
  Sys.sleep(settle)
  opened <- tree_cpu(p$get_pid())
  started <- proc.time()[["elapsed"]]
  Sys.sleep(seconds)
  cpu <- tree_cpu(p$get_pid())
  elapsed <- proc.time()[["elapsed"]] - started
  p$kill_tree()
  c(open = opened, cpu = cpu - opened, elapsed = elapsed)
}

cat(sprintf("load average %.2f; a page of 3 widgets (2 hands each) in headless chromium: CPU in the %g s after the first %g s\n",
            load_avg(), seconds, settle))
rest <- browser_cpu(page_of(FALSE))
play <- browser_cpu(page_of(TRUE))
report <- function(what, r) {
  cat(sprintf("  %-18s %5.1f s CPU in %4.1f s (%3.0f%% of a core; opening the page: %.1f s CPU)\n",
              what, r[["cpu"]], r[["elapsed"]], 100 * r[["cpu"]] / r[["elapsed"]], r[["open"]]))
}
report("at rest:", rest)
report("autoplay:", play)
bench_record("idle page CPU share", rest[["cpu"]] / rest[["elapsed"]], "cores")
bench_record("autoplay page CPU share", play[["cpu"]] / play[["elapsed"]], "cores")

png <- file.path(dir, "shot.png")
shot <- system.time(browser_run(c(browser_args(5000), "--window-size=1000,1400", paste0("--screenshot=", png),
                                  page_url(page_of(FALSE))), stdout = FALSE, stderr = FALSE, seconds = 300))
if (!file.exists(png)) cat("  (no screenshot within 300 s)\n")
cat(sprintf("  screenshot, 5 s virtual time: %.1f s real (load average %.2f)\n", shot[["elapsed"]], load_avg()))
bench_record("screenshot 5 s virtual", shot[["elapsed"]], "s")
