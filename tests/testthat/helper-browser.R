# A real browser for the pages the package writes: Debian's chromium,
# headless, with software WebGL (SwiftShader). Virtual time makes the
# page's clock run as fast as the page can compute, so "after 1.5 s of
# playback" costs no wall-clock wait. Tests skip, saying why, where no
# chromium is installed (tools/setup.sh installs it where it can).
chromium_path <- function() {
  for (p in c(Sys.getenv("HANDMOTION_CHROMIUM"), "chromium", "chromium-browser", "google-chrome")) {
    if (nzchar(p) && nzchar(found <- Sys.which(p))) return(unname(found))
  }
  ""
}

skip_without_browser <- function() {
  skip_on_cran()
  if (!nzchar(chromium_path())) skip("no chromium: install it (tools/setup.sh does) to run the browser tests")
}

# A fresh profile per call and no background networking: with the shared
# default profile and chromium's own update/sync connections (refused on a
# closed network) a screenshot of a page with two WebGL widgets once hung for
# minutes; with these it takes seconds.
browser_args <- function(budget_ms) {
  c("--headless=new", "--no-sandbox", "--disable-gpu-sandbox", "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader", "--hide-scrollbars", "--no-first-run", "--disable-extensions",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    paste0("--user-data-dir=", tempfile("chromium-profile")),
    sprintf("--virtual-time-budget=%d", as.integer(budget_ms)))
}

# chromium run under coreutils' timeout, so a page that never settles fails
# its check instead of stalling the run
browser_run <- function(args, ..., seconds = 300) {
  suppressWarnings(system2("timeout", c(as.character(seconds), chromium_path(), args), ...))
}

# A page to open: a URL as it is, a file as a file:// URL.
page_url <- function(page) if (grepl("^https?://", page)) page else paste0("file://", normalizePath(page))

# The page's DOM after `budget_ms` of virtual time.
browser_dom <- function(page, budget_ms = 1000) {
  out <- browser_run(c(browser_args(budget_ms), "--dump-dom", shQuote(page_url(page))),
                     stdout = TRUE, stderr = FALSE)
  paste(out, collapse = "\n")
}

# The page's console after `budget_ms` of virtual time: one line per message
# (console.log/warn/error and uncaught exceptions), as chromium logs them.
browser_console <- function(page, budget_ms = 1000) {
  out <- browser_run(c(browser_args(budget_ms), "--enable-logging=stderr", "--v=0",
                       "--dump-dom", shQuote(page_url(page))),
                     stdout = FALSE, stderr = TRUE)
  sub('^.*:CONSOLE[^]]*\\] ', "", grep(":CONSOLE", out, value = TRUE, fixed = TRUE))
}

# A screenshot (PNG path) of the page after `budget_ms` of virtual time.
# Headless chromium's screenshot of a page with running WebGL widgets now and
# then never returns (seen on a quiet machine: one run in three hung past
# 300 s, the next took seconds), so each try gets 100 s and a hung try is
# made again, up to three times; then the page's check fails by name.
browser_screenshot <- function(page, budget_ms = 1000, size = c(800, 500), tries = 3L) {
  png <- tempfile(fileext = ".png")
  for (i in seq_len(tries)) {
    browser_run(c(browser_args(budget_ms), sprintf("--window-size=%d,%d", size[1], size[2]),
                  paste0("--screenshot=", png), shQuote(page_url(page))),
                stdout = FALSE, stderr = FALSE, seconds = 100)
    if (file.exists(png) && file.size(png) > 0) return(png)
  }
  stop(sprintf("headless chromium took no screenshot of %s in %d tries of 100 s", page, tries), call. = FALSE)
}

# Pixels of a PNG as an integer array (height x width x channels).
png_pixels <- function(png) {
  as.integer(magick::image_data(magick::image_read(png), channels = "rgb"))
}
