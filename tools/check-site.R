# Opens the built site in headless chromium, served over HTTP (so a script
# error names its file): the pages exist, and the pages with the 3D viewer
# draw every widget, with pixels on the canvas and no script error from the
# widget (three.js, htmlwidgets, hand3d.js). pkgdown's page template loads
# some scripts from CDNs; offline those fail and its own pkgdown.js then
# errors: such errors are listed, not counted against the widget. Uses the
# browser helpers of the test suite (one copy).
args <- commandArgs(trailingOnly = TRUE)
site <- normalizePath(if (length(args)) args[1] else "site")
source("tests/testthat/helper-browser.R")
pages <- c("index.html", "reference/index.html", "articles/index.html", "news/index.html",
           "articles/looking-at-hands.html", "reference/hand_3d.html", "articles/reproduce-thesis.html")
missing <- pages[!file.exists(file.path(site, pages))]
if (length(missing)) stop("site: missing pages: ", paste(missing, collapse = ", "))
# every image a page refers to exists
for (pg in pages) {
  html <- paste(readLines(file.path(site, pg), warn = FALSE), collapse = "\n")
  src <- regmatches(html, gregexpr('<img src="[^"]+"', html))[[1]]
  src <- sub('^<img src="([^"]+)"$', "\\1", src)
  src <- src[!grepl("^(data:|https?:)", src)]
  lost <- src[!file.exists(file.path(dirname(file.path(site, pg)), src))]
  if (length(lost)) stop("site: ", pg, " refers to missing images: ", paste(utils::head(lost, 3), collapse = ", "))
}
if (!nzchar(chromium_path())) {
  message("site: no chromium here; the pages were built but not opened in a browser")
  quit(status = 0)
}
port <- 8700L + sample.int(200L, 1L)
server <- system2("python3", c("-m", "http.server", port, "--bind", "127.0.0.1", "--directory", shQuote(site)),
                  wait = FALSE, stdout = FALSE, stderr = FALSE)
Sys.sleep(1.5)
# on.exit() does nothing at a script's top level (the server outlived the
# CI run); a finaliser run at R's exit stops it, after an error too
server_guard <- new.env()
invisible(reg.finalizer(server_guard, function(e) system(sprintf("pkill -f 'http.server %d'", port)), onexit = TRUE))
base <- sprintf("http://127.0.0.1:%d/", port)
widget_error <- function(err) {
  # errors of the widget's own scripts, or of scripts we cannot name
  !grepl("@ https?://127\\.0\\.0\\.1:[0-9]+/(pkgdown\\.js|deps/)", err)
}
# `height`: a window tall enough to hold the page's widgets, so the
# screenshot shows them (the reference page's examples are 2,500 px down)
check_widgets <- function(page, expected, height = 1400L) {
  dom <- browser_dom(paste0(base, page), 2500)
  ready <- lengths(regmatches(dom, gregexpr('data-ready="1"', dom, fixed = TRUE)))
  errs <- if (grepl("data-js-error", dom, fixed = TRUE)) {
    strsplit(sub('.*data-js-error="([^"]*)".*', "\\1", dom), " | ", fixed = TRUE)[[1]]
  } else character()
  ours <- errs[widget_error(errs)]
  if (length(errs) > length(ours)) {
    message("site: ", page, ": page-template errors (CDN scripts unreachable offline): ",
            paste(setdiff(errs, ours), collapse = "; "))
  }
  if (length(ours)) stop("site: script error in ", page, ": ", paste(ours, collapse = "; "))
  if (ready < expected) stop(sprintf("site: %s drew %d of %d 3D widgets", page, ready, expected))
  # the hands are drawn in colour, the page around them in greys: a widget
  # that draws nothing leaves (almost) no saturated pixel (hand_3d.html has
  # about 70,000 with its two widgets, looking-at-hands.html 21,000 in its
  # first 1,400 px, the text of either page none)
  px <- matrix(png_pixels(browser_screenshot(paste0(base, page), 1000, c(1000, height))), ncol = 3)
  coloured <- sum(pmax(px[, 1], px[, 2], px[, 3]) - pmin(px[, 1], px[, 2], px[, 3]) > 80)
  if (coloured < 5000) stop(sprintf("site: %s shows no hand in the browser (%d coloured pixels)", page, coloured))
  message(sprintf("site: %s: %d 3D widget(s) drawn, no widget script errors, %d coloured pixels on screen",
                  page, ready, coloured))
}
# the 2D animation embedded in the GraspDB14 article draws lines (its <svg>
# carries `fill="none"`) and plays: its frame label has moved on
check_animation <- function(page) {
  dom <- browser_dom(paste0(base, page), 1500)
  if (!grepl('class="handmotion-animation"', dom, fixed = TRUE)) stop("site: no 2D animation in ", page)
  if (!grepl('<svg[^>]*fill="none"', dom)) stop("site: the 2D animation in ", page, " lost its line style")
  at <- as.integer(sub(".*>frame ([0-9]+) \\(.*", "\\1", dom))
  if (is.na(at) || at <= 1L) stop("site: the 2D animation in ", page, " does not play")
  message(sprintf("site: %s: 2D animation plays (frame %d after 1.5 s)", page, at))
}
check_animation("articles/graspdb14.html")
check_widgets("articles/looking-at-hands.html", 2L)
check_widgets("reference/hand_3d.html", 2L, height = 4500L)
message("site: ok")
