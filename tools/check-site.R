# Opens the built site in headless chromium and fails on what a reader
# would meet:
# 1. every page exists and every image a page refers to exists;
# 2. no page loads a script, style, font, image or frame from outside the
#    site (the site must work offline; links to elsewhere are fine);
# 3. the main pages run without a script error, both served over HTTP and
#    opened from file://, with every outside host unreachable (as offline);
# 4. the articles' "On this page" contents are filled, code stays inside
#    its boxes, and the search box finds pages and its first result opens
#    its page, over HTTP (driven from a harness page holding the site in a
#    frame) and from file:// (a copy of the page that searches by itself);
# 5. the pages with the 3D viewer draw every widget, with pixels on the
#    canvas, and the 2D animation plays.
# Uses the browser helpers of the test suite (one copy).
args <- commandArgs(trailingOnly = TRUE)
site <- normalizePath(if (length(args)) args[1] else "site")
source("tests/testthat/helper-browser.R")
fail <- function(...) stop("site: ", ..., call. = FALSE)
pages <- c("index.html", "reference/index.html", "articles/index.html", "news/index.html",
           "articles/getting-started.html", "articles/looking-at-hands.html", "reference/hand_3d.html",
           "articles/reproduce-thesis.html")
missing <- pages[!file.exists(file.path(site, pages))]
if (length(missing)) fail("missing pages: ", paste(missing, collapse = ", "))
all_pages <- list.files(site, pattern = "\\.html$", recursive = TRUE)
read_text <- function(f) paste(readLines(f, warn = FALSE, encoding = "UTF-8"), collapse = "\n")

# -- 1, 2: images exist, nothing loaded from outside ---------------------------
# What a page loads: src= of any element, href= of <link> (styles, icons,
# preloads), and url(...) in inline styles. <a href> only links.
outside_url <- "^(https?:)?//|^file:"
loaded_urls <- function(html) {
  src <- regmatches(html, gregexpr("<[a-zA-Z]+[^>]*\\ssrc\\s*=\\s*[\"'][^\"']*[\"']", html))[[1]]
  link <- regmatches(html, gregexpr("<link[^>]*\\shref\\s*=\\s*[\"'][^\"']*[\"']", html))[[1]]
  css <- regmatches(html, gregexpr("url\\(\\s*[\"']?[^\"')]+", html))[[1]]
  c(sub("^.*\\ssrc\\s*=\\s*[\"']", "", sub("[\"']$", "", src)),
    sub("^.*\\shref\\s*=\\s*[\"']", "", sub("[\"']$", "", link)),
    sub("^url\\(\\s*[\"']?", "", css))
}
outside <- character()
for (pg in all_pages) {
  html <- read_text(file.path(site, pg))
  urls <- loaded_urls(html)
  bad <- unique(urls[grepl(outside_url, urls)])
  if (length(bad)) outside <- c(outside, sprintf("%s: %s", pg, paste(utils::head(bad, 3), collapse = ", ")))
  img <- sub('^<img src="([^"]+)"$', "\\1", regmatches(html, gregexpr('<img src="[^"]+"', html))[[1]])
  img <- img[!grepl("^(data:|https?:)", img)]
  lost <- img[!file.exists(file.path(dirname(file.path(site, pg)), sub("[?#].*$", "", img)))]
  if (length(lost)) fail(pg, " refers to missing images: ", paste(utils::head(lost, 3), collapse = ", "))
}
for (f in list.files(site, pattern = "\\.css$", recursive = TRUE, full.names = TRUE)) {
  urls <- sub("^url\\(\\s*[\"']?", "", regmatches(read_text(f), gregexpr("url\\(\\s*[\"']?[^\"')]+", read_text(f)))[[1]])
  bad <- unique(urls[grepl(outside_url, urls)])
  if (length(bad)) outside <- c(outside, sprintf("%s: %s", sub(paste0(site, "/"), "", f, fixed = TRUE),
                                                  paste(utils::head(bad, 3), collapse = ", ")))
}
if (length(outside)) {
  fail(length(outside), " files load resources from outside the site:\n  ",
       paste(utils::head(outside, 10), collapse = "\n  "))
}
message(sprintf("site: %d pages, every image present, nothing loaded from outside the site", length(all_pages)))

if (!nzchar(chromium_path())) {
  message("site: no chromium here; the pages were built but not opened in a browser")
  quit(status = 0)
}

# -- the site served over HTTP, beside a harness page -------------------------
# The harness lies beside the site (not in it) and shares the site's origin
# over HTTP, so that it may drive the page in its frame.
root <- tempfile("site-check-")
dir.create(root)
invisible(file.symlink(site, file.path(root, "site")))
port <- 8700L + sample.int(200L, 1L)
server <- processx::process$new("python3", c("-m", "http.server", port, "--bind", "127.0.0.1", "--directory", root),
                                stdout = NULL, stderr = NULL)
Sys.sleep(1.5)
# on.exit() does nothing at a script's top level (the server outlived the
# CI run); a finaliser run at R's exit stops this server (by its process),
# after an error too
server_guard <- new.env()
invisible(reg.finalizer(server_guard, function(e) server$kill(), onexit = TRUE))
http_base <- sprintf("http://127.0.0.1:%d/site/", port)
file_base <- paste0("file://", site, "/")
# every host but this machine unreachable: the pages must not need one
# (quoted: system2() passes the arguments through a shell)
offline <- shQuote("--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1")

# -- 3: no script error on the main pages -------------------------------------
console_errors <- function(url) {
  out <- browser_run(c(browser_args(2000), offline, "--enable-logging=stderr", "--v=0", "--dump-dom",
                       shQuote(url)), stdout = FALSE, stderr = TRUE)
  lines <- grep(":CONSOLE|ERROR:.*(net::|Failed to load)", out, value = TRUE)
  lines <- sub("^.*:CONSOLE[^]]*\\] ", "", lines)
  # errors and uncaught exceptions; console.log/info chatter is not an error
  grep("Uncaught|Error|error|Failed|net::ERR", lines, value = TRUE)
}
# (every page runs the same template scripts: one page of each kind over
# HTTP, the home page and an article from file://; the pages with widgets
# are checked for script errors below)
for (url in c(paste0(http_base, c("index.html", "reference/index.html", "articles/index.html", "news/index.html",
                                  "articles/getting-started.html")),
              paste0(file_base, c("index.html", "articles/getting-started.html")))) {
  errs <- console_errors(url)
  if (length(errs)) fail("script errors on ", url, ":\n  ", paste(utils::head(errs, 5), collapse = "\n  "))
}
message("site: no script errors on the main pages, over HTTP or from file://")

# -- 4: contents and search ----------------------------------------------------
# Over HTTP, the harness loads a site page in a frame, counts its contents links, types
# `query` into the search box, waits for suggestions, picks the first and
# reports where the frame went; it writes its findings as JSON into #result.
harness <- function(page, query) {
  sprintf('<!doctype html><html><body><pre id="result">pending</pre>
<iframe id="f" src="%s" width="1200" height="900"></iframe>
<script>
var f = document.getElementById("f"), out = {}, phase = 0;
function done() { document.getElementById("result").textContent = JSON.stringify(out); }
f.onload = function() {
  try {
    var w = f.contentWindow, d = w.document;
    if (phase === 1) {
      out.opened = w.location.pathname + w.location.search; out.title = d.title;
      out.opened_main = !!d.querySelector("main"); return done();
    }
    phase = 1;
    var $ = w.jQuery, input = $("#search-input");
    input.trigger("focus");
    setTimeout(function() {
      out.toc = d.querySelectorAll("#toc a.nav-link").length;
      /* code boxes whose text runs past them, a page wider than the window */
      out.overflow = Array.prototype.filter.call(d.querySelectorAll("pre"),
        function(p) { return p.scrollWidth > p.clientWidth + 1; }).length;
      out.page_wider = d.documentElement.scrollWidth > w.innerWidth;
      out.headings = d.querySelectorAll("main h2:not([data-toc-skip])").length;
      input.val(%s).trigger("input");
      setTimeout(function() {
        var s = d.querySelectorAll(".aa-suggestion");
        out.suggestions = s.length;
        out.first = s.length ? s[0].textContent.replace(/\\s+/g, " ").trim() : "";
        if (!s.length) return done();
        $(s[0]).trigger("click");
        setTimeout(done, 3000);  /* the frame did not move on */
      }, 2000);
    }, 1000);
  } catch (e) { out.error = String(e); done(); }
};
</script></body></html>', page, jsonlite::toJSON(query, auto_unbox = TRUE))
}
run_harness <- function(base, harness_base, page, query) {
  h <- file.path(root, sprintf("harness-%s.html", gsub("[^a-z0-9]", "-", page)))
  writeLines(harness(paste0(base, page), query), h)
  dom <- browser_run(c(browser_args(12000), offline, "--dump-dom", shQuote(paste0(harness_base, basename(h)))),
                     stdout = TRUE, stderr = FALSE)
  dom <- paste(dom, collapse = "\n")
  json <- sub('(?s).*<pre id="result">(.*?)</pre>.*', "\\1", dom, perl = TRUE)
  json <- gsub("&quot;", '"', gsub("&amp;", "&", gsub("&lt;", "<", gsub("&gt;", ">", json))))
  if (identical(json, "pending") || !jsonlite::validate(json)) fail("the harness got no answer from ", base, page)
  jsonlite::fromJSON(json)
}
# the search must find pages by a word of the site's titles
query <- "hands"
for (pg in c("index.html", "articles/reproduce-thesis.html")) {
  r <- run_harness(http_base, sprintf("http://127.0.0.1:%d/", port), pg, query)
  if (!is.null(r$error)) fail("harness error on ", pg, ": ", r$error)
  if (r$overflow > 0 || isTRUE(r$page_wider)) {
    fail(sprintf("%s: %d code boxes run past their edge%s", pg, r$overflow,
                 if (isTRUE(r$page_wider)) ", and the page is wider than the window" else ""))
  }
  if (grepl("^articles/", pg) && r$headings > 0 && r$toc < r$headings) {
    fail(sprintf("%s: the contents list %d links for %d sections", pg, r$toc, r$headings))
  }
  if (!isTRUE(r$suggestions > 0)) fail(sprintf("%s: search for '%s' found nothing", pg, query))
  # the frame moved on to the result, with the search words (?q=) to mark
  if (is.null(r$opened) || !isTRUE(r$opened_main) || !grepl("q=", r$opened, fixed = TRUE)) {
    fail(sprintf("%s: the first search result (%s) did not open a page", pg, r$first))
  }
  message(sprintf("site: over HTTP, %s: %d contents links for %d sections, code inside its boxes; search '%s': %d results, the first opened %s",
                  pg, r$toc, r$headings, query, r$suggestions, sub("^.*/site/", "", r$opened)))
}
# From file:// a page may not reach into a frame (each file is its own
# origin), and chromium's flag that would allow it would also allow the
# fetch() that a reader's browser refuses there. So a copy of the page, in
# its own folder, searches by itself: it types the query, records how many
# results it got, and picks the first; a page that opens with the query's
# words marked (mark.js, <mark data-markjs>) is the result page.
file_search <- function(pg, query) {
  copy <- file.path(site, dirname(pg), "zz-check-search.html")
  on.exit(unlink(copy))
  html <- read_text(file.path(site, pg))
  script <- sprintf('<script>window.addEventListener("load", function() {
  var $ = window.jQuery, input = $("#search-input");
  input.trigger("focus");
  setTimeout(function() {
    input.val(%s).trigger("input");
    setTimeout(function() {
      var s = document.querySelectorAll(".aa-suggestion");
      document.body.setAttribute("data-check-results", s.length);
      if (s.length) $(s[0]).trigger("click");
    }, 2000);
  }, 1000);
});</script></body>', jsonlite::toJSON(query, auto_unbox = TRUE))
  writeLines(sub("</body>", script, html, fixed = TRUE), copy)
  dom <- paste(browser_run(c(browser_args(8000), offline, "--dump-dom", shQuote(paste0("file://", copy))),
                           stdout = TRUE, stderr = FALSE), collapse = "\n")
  if (grepl("data-check-results=", dom, fixed = TRUE)) {
    n <- sub('.*data-check-results="([0-9]+)".*', "\\1", dom)
    fail(sprintf("from file://, %s: search for '%s' found %s results and opened none", pg, query, n))
  }
  if (!grepl("data-markjs", dom, fixed = TRUE)) fail(sprintf("from file://, %s: the search result page shows no marked words", pg))
  title <- sub("(?s).*<title>([^<]*)</title>.*", "\\1", dom, perl = TRUE)
  # the result is an article: its contents, built from file:// too
  toc <- lengths(regmatches(dom, gregexpr('class="nav-link" href="#', dom, fixed = TRUE)))
  main <- sub("(?s).*<main(.*)</main>.*", "\\1", dom, perl = TRUE)
  h2 <- lengths(regmatches(main, gregexpr("<h2(?![^>]*data-toc-skip)", main, perl = TRUE)))
  if (h2 == 0 || toc < h2) fail(sprintf("from file://, %s: the contents list %d links for %d sections", title, toc, h2))
  message(sprintf("site: from file://, %s: search '%s' opened \"%s\" with the words marked and %d contents links for %d sections",
                  pg, query, title, toc, h2))
}
for (pg in c("index.html", "articles/reproduce-thesis.html")) file_search(pg, query)

# -- 5: 3D widgets and the 2D animation ----------------------------------------
# `height`: a window tall enough to hold the page's widgets, so the
# screenshot shows them (the reference page's examples are 2,500 px down)
# `pixels`: also look at the screen (one page suffices: the widget's code is
# the same on every page, and a WebGL screenshot is the slowest check here)
check_widgets <- function(page, expected, height = 1400L, pixels = TRUE) {
  dom <- browser_dom(paste0(http_base, page), 2500)
  ready <- lengths(regmatches(dom, gregexpr('data-ready="1"', dom, fixed = TRUE)))
  errs <- if (grepl("data-js-error", dom, fixed = TRUE)) {
    strsplit(sub('.*data-js-error="([^"]*)".*', "\\1", dom), " | ", fixed = TRUE)[[1]]
  } else character()
  if (length(errs)) fail("script error in ", page, ": ", paste(errs, collapse = "; "))
  if (ready < expected) fail(sprintf("%s drew %d of %d 3D widgets", page, ready, expected))
  if (!pixels) {
    return(message(sprintf("site: %s: %d 3D widget(s) drawn, no script errors", page, ready)))
  }
  # the hands are drawn in colour, the page around them in greys: a widget
  # that draws nothing leaves (almost) no saturated pixel (hand_3d.html has
  # about 70,000 with its two widgets, looking-at-hands.html 21,000 in its
  # first 1,400 px, the text of either page none)
  px <- matrix(png_pixels(browser_screenshot(paste0(http_base, page), 1000, c(1000, height))), ncol = 3)
  coloured <- sum(pmax(px[, 1], px[, 2], px[, 3]) - pmin(px[, 1], px[, 2], px[, 3]) > 80)
  if (coloured < 5000) fail(sprintf("%s shows no hand in the browser (%d coloured pixels)", page, coloured))
  message(sprintf("site: %s: %d 3D widget(s) drawn, no script errors, %d coloured pixels on screen",
                  page, ready, coloured))
}
# the 2D animation embedded in the GraspDB14 article draws lines (its <svg>
# carries `fill="none"`) and plays: its frame label has moved on
check_animation <- function(page) {
  dom <- browser_dom(paste0(http_base, page), 1500)
  if (!grepl('class="handmotion-animation"', dom, fixed = TRUE)) fail("no 2D animation in ", page)
  if (!grepl('<svg[^>]*fill="none"', dom)) fail("the 2D animation in ", page, " lost its line style")
  at <- as.integer(sub(".*>frame ([0-9]+) \\(.*", "\\1", dom))
  if (is.na(at) || at <= 1L) fail("the 2D animation in ", page, " does not play")
  message(sprintf("site: %s: 2D animation plays (frame %d after 1.5 s)", page, at))
}
check_animation("articles/graspdb14.html")
check_widgets("articles/looking-at-hands.html", 2L)
check_widgets("reference/hand_3d.html", 2L, pixels = FALSE)
message("site: ok")
