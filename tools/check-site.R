# Opens the built site in headless chromium and fails on what a reader
# would meet:
# 1. every page exists and every image a page refers to exists;
# 2. no page loads a script, style, font, image or frame from outside the
#    site (the site must work offline; links to elsewhere are fine);
# 3. the main pages run without a script error, both served over HTTP and
#    opened from file://, with every outside host unreachable (as offline);
# 4. the articles' "On this page" contents are filled, code stays inside
#    its boxes (long lines scroll, none wraps), and the search box finds pages and its first result opens
#    its page, over HTTP (driven from a harness page holding the site in a
#    frame) and from file:// (a copy of the page that searches by itself);
# 5. the pages with the 3D viewer draw every widget, each with a hand's
#    coloured pixels on its canvas (read on the page), and the 2D animation
#    plays.
# Five browser runs do it, started together and judged after: one over HTTP
# whose harness page opens the pages one after another in a frame (3, 4 and
# the animation of 5), two from file:// (3 and 4) and one per page of 3D
# widgets. (Fifteen runs, one per check, spent most of their 75 s starting
# chromium.) Uses the browser helpers of the test suite (one copy).
args <- commandArgs(trailingOnly = TRUE)
site <- normalizePath(if (length(args)) args[1] else "site")
source("tests/testthat/helper-browser.R")
fail <- function(...) stop("site: ", ..., call. = FALSE)
`%||%` <- function(a, b) if (is.null(a)) b else a   # (base R has it from 4.4 on)
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
offline <- "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1"

# Every browser run of the checks below is started at once (at most
# `parallel` at a time) and judged when all have ended: each run mostly
# waits for its own start-up and virtual time, so one after another they
# took minutes. Each is a fresh headless chromium (browser_args(): its own
# profile, no background networking) under coreutils' timeout.
browser_batch <- function(runs, seconds = 150, parallel = 4L) {
  files <- lapply(runs, function(r) c(tempfile("stdout-"), tempfile("stderr-")))
  running <- list()
  began <- took <- numeric(length(runs))
  todo <- seq_along(runs)
  while (length(todo) || length(running)) {
    while (length(running) < parallel && length(todo)) {
      i <- todo[1]
      todo <- todo[-1]
      running[[as.character(i)]] <- processx::process$new(
        "timeout", c(as.character(seconds), chromium_path(), runs[[i]]),
        stdout = files[[i]][1], stderr = files[[i]][2])
      began[i] <- proc.time()[["elapsed"]]
    }
    Sys.sleep(0.1)
    for (k in names(running)) if (!running[[k]]$is_alive()) {
      took[as.integer(k)] <- proc.time()[["elapsed"]] - began[as.integer(k)]
      running[[k]] <- NULL
    }
  }
  out <- lapply(files, function(f) {
    list(stdout = readLines(f[1], warn = FALSE), stderr = readLines(f[2], warn = FALSE))
  })
  names(out) <- names(runs)
  attr(out, "seconds") <- stats::setNames(took, names(runs))
  out
}
runs <- list()

# -- 3, 4 over HTTP: one harness run -------------------------------------------
# The harness lies beside the site, shares its origin and drives the pages
# in its frame one after another: the main pages (one of each kind: every
# page runs the same template scripts) until they have run a moment, the
# pages searched from (their contents, code boxes, search box), and the 2D
# animation. It writes its findings as JSON into #result. Script errors of
# every page it opens land in chromium's log (--enable-logging), each with
# its source; the pages with widgets are checked for script errors below.
error_pages <- c("index.html", "reference/index.html", "articles/index.html", "news/index.html",
                 "articles/getting-started.html")
console_errors <- function(out) {
  lines <- grep(":CONSOLE|ERROR:.*(net::|Failed to load)", out$stderr, value = TRUE)
  lines <- sub("^.*:CONSOLE[^]]*\\] ", "", lines)
  # errors and uncaught exceptions; console.log/info chatter is not an error
  grep("Uncaught|Error|error|Failed|net::ERR", lines, value = TRUE)
}
# the search must find pages by a word of the site's titles; a function's
# name finds its help page first (not a changelog entry)
query <- "hands"
search_pages <- c("index.html", "articles/reproduce-thesis.html")
ranked <- c(query = "calibrate", page = "reference/calibrate.html")
animation_page <- "articles/graspdb14.html"
tasks <- c(lapply(error_pages, function(pg) list(kind = "errors", page = pg)),
           lapply(search_pages, function(pg) list(kind = "search", page = pg, query = query)),
           list(list(kind = "search", page = "index.html", query = ranked[["query"]], key = "rank")),
           # (on a phone's width the navbar is collapsed: the box is in its opened menu)
           list(list(kind = "search", page = "index.html", query = ranked[["query"]], key = "rank narrow",
                     width = 390L)),
           list(list(kind = "animation", page = animation_page)))
tasks <- lapply(tasks, function(t) {
  t$url <- paste0(http_base, t$page)
  t$key <- t$key %||% paste(t$kind, t$page)
  t
})
harness <- sprintf('<!doctype html><html><body><pre id="result">pending</pre>
<iframe id="f" width="1200" height="900"></iframe>
<script>
var tasks = %s, f = document.getElementById("f"), all = {}, k = -1;
function finish() { f.onload = null; f.src = "about:blank"; document.getElementById("result").textContent = JSON.stringify(all); }
function next() { k++; if (k >= tasks.length) return finish(); run(tasks[k], all[tasks[k].key] = {}); }
function run(t, out) {
  var phase = 0, moved = null;
  f.width = t.width || 1200;
  f.onload = function() {
    try {
      var w = f.contentWindow, d = w.document;
      if (t.kind === "errors") { out.title = d.title; return setTimeout(next, 500); }
      if (t.kind === "animation") {
        return setTimeout(function() {
          out.animation = !!d.querySelector(".handmotion-animation");
          out.line_style = !!d.querySelector("svg[fill=\\"none\\"]");
          var m = /frame ([0-9]+) \\(/.exec(d.body.textContent);
          out.frame = m ? +m[1] : null;
          next();
        }, 1500);
      }
      if (phase === 1) {
        clearTimeout(moved);
        out.opened = w.location.pathname + w.location.search; out.title = d.title;
        out.opened_main = !!d.querySelector("main"); return next();
      }
      phase = 1;
      var $ = w.jQuery, input = $("#search-input");
      var toggler = d.querySelector(".navbar-toggler");
      if (toggler && w.getComputedStyle(toggler).display !== "none") toggler.click();
      input.trigger("focus");
      setTimeout(function() {
        out.toc = d.querySelectorAll("#toc a.nav-link").length;
        /* code boxes whose text runs past them (a long line scrolls inside
           its box: white-space pre, overflow-x auto), code that wraps (in
           the middle of a comment), a page wider than the window */
        out.overflow = Array.prototype.filter.call(d.querySelectorAll("pre"), function(p) {
          var scrolls = ["auto", "scroll"].indexOf(w.getComputedStyle(p).overflowX) >= 0;
          return p.scrollWidth > p.clientWidth + 1 && !scrolls;
        }).length;
        out.wrapping = Array.prototype.filter.call(d.querySelectorAll("pre code"), function(c) {
          return w.getComputedStyle(c).whiteSpace !== "pre";
        }).length;
        out.page_wider = d.documentElement.scrollWidth > w.innerWidth;
        out.headings = d.querySelectorAll("main h2:not([data-toc-skip])").length;
        input.val(t.query).trigger("input");
        setTimeout(function() {
          var s = d.querySelectorAll(".aa-suggestion");
          out.suggestions = s.length;
          out.first = s.length ? s[0].textContent.replace(/\\s+/g, " ").trim() : "";
          /* the list of suggestions lies within the window */
          var menu = d.querySelector(".aa-dropdown-menu");
          if (menu) {
            var r = menu.getBoundingClientRect();
            out.menu_fits = r.left >= 0 && r.right <= w.innerWidth && r.bottom <= w.innerHeight;
          }
          if (!s.length) return next();
          moved = setTimeout(next, 3000);  /* the frame did not move on */
          $(s[0]).trigger("click");
        }, 2000);
      }, 1000);
    } catch (e) { out.error = String(e); next(); }
  };
  f.src = t.url;
}
next();
</script></body></html>', jsonlite::toJSON(lapply(tasks, function(t) t[intersect(c("kind", "url", "key", "query", "width"), names(t))]), auto_unbox = TRUE))
writeLines(harness, file.path(root, "harness.html"))
# (virtual time: the harness's waits add up to about 25 s, which cost
# little real time; the budget only bounds a page that never settles)
runs[["harness"]] <- c(browser_args(60000), offline, "--enable-logging=stderr", "--v=0", "--dump-dom",
                       sprintf("http://127.0.0.1:%d/harness.html", port))
harness_result <- function(out) {
  dom <- paste(out$stdout, collapse = "\n")
  json <- sub('(?s).*<pre id="result">(.*?)</pre>.*', "\\1", dom, perl = TRUE)
  json <- gsub("&quot;", '"', gsub("&amp;", "&", gsub("&lt;", "<", gsub("&gt;", ">", json))))
  if (identical(json, "pending") || !jsonlite::validate(json)) fail("the harness got no answer from ", http_base)
  r <- jsonlite::fromJSON(json)
  lost <- setdiff(vapply(tasks, `[[`, "", "key"), names(r))
  if (length(lost)) fail("the harness did not get to ", paste(lost, collapse = ", "), " (its budget ran out)")
  r
}
# From file:// a page may not reach into a frame (each file is its own
# origin), and chromium's flag that would allow it would also allow the
# fetch() that a reader's browser refuses there. So a copy of the page, in
# its own folder, searches by itself: it types the query, records how many
# results it got, and picks the first; a page that opens with the query's
# words marked (mark.js, <mark data-markjs>) is the result page.
# Their runs check the page for script errors from file:// as well (the
# copy and the result page it opens: the home page's and a page's scripts).
# (copies of pages lie beside them until the runs end)
copies <- character()
copy_guard <- new.env()
invisible(reg.finalizer(copy_guard, function(e) unlink(copies), onexit = TRUE))
page_copy <- function(pg, tag, script) {
  copy <- file.path(site, dirname(pg), sprintf("zz-check-%s-%s", tag, basename(pg)))
  copies <<- c(copies, copy)
  writeLines(sub("</body>", paste0(script, "</body>"), read_text(file.path(site, pg)), fixed = TRUE), copy)
  sub(paste0(site, "/"), "", copy, fixed = TRUE)
}
for (pg in search_pages) {
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
});</script>', jsonlite::toJSON(query, auto_unbox = TRUE))
  runs[[paste("file search", pg)]] <- c(browser_args(8000), offline, "--enable-logging=stderr", "--v=0", "--dump-dom",
                                         paste0(file_base, page_copy(pg, "search", script)))
}
file_search_result <- function(out, pg) {
  dom <- paste(out$stdout, collapse = "\n")
  if (grepl("data-check-results=", dom, fixed = TRUE)) {
    n <- sub('.*data-check-results="([0-9]+)".*', "\\1", dom)
    fail(sprintf("from file://, %s: search for '%s' found %s results and opened none", pg, query, n))
  }
  if (!grepl("data-markjs", dom, fixed = TRUE)) fail(sprintf("from file://, %s: the search result page shows no marked words", pg))
  title <- sub("(?s).*<title>([^<]*)</title>.*", "\\1", dom, perl = TRUE)
  # the result is an article: its contents, built from file:// too
  # (scrollspy may have marked the link of the section in view "active")
  toc <- lengths(regmatches(dom, gregexpr('class="nav-link( active)?" href="#', dom)))
  main <- sub("(?s).*<main(.*)</main>.*", "\\1", dom, perl = TRUE)
  h2 <- lengths(regmatches(main, gregexpr("<h2(?![^>]*data-toc-skip)", main, perl = TRUE)))
  if (h2 == 0 || toc < h2) fail(sprintf("from file://, %s: the contents list %d links for %d sections", title, toc, h2))
  message(sprintf("site: from file://, %s: search '%s' opened \"%s\" with the words marked and %d contents links for %d sections",
                  pg, query, title, toc, h2))
}

# -- 5: 3D widgets and the 2D animation ----------------------------------------
# The widgets' pixels are read on the page itself: a copy of the page draws
# each widget's WebGL canvas (preserveDrawingBuffer, as the widget makes it)
# onto a 2D canvas once the widgets have been drawn and counts its coloured
# pixels. The hands are drawn in colour, the widget's background in grey: a
# widget that draws nothing has (almost) none. (A screenshot of the screen
# did the same at up to 100 s a try, and hung now and then.)
widget_script <- '<script>window.addEventListener("load", function() {
  setTimeout(function() {
    var counts = [];
    document.querySelectorAll(".hand3d.html-widget").forEach(function(el) {
      var c = el.querySelector("canvas"), n = -1;
      if (c) {
        var box = c.getBoundingClientRect();
        var vis = box.width > 0 && box.height > 0 && getComputedStyle(c).visibility !== "hidden";
        var t = document.createElement("canvas");
        t.width = c.width; t.height = c.height;
        var ctx = t.getContext("2d");
        ctx.drawImage(c, 0, 0);
        var px = ctx.getImageData(0, 0, t.width, t.height).data;
        n = 0;
        for (var i = 0; i < px.length; i += 4) {
          var hi = Math.max(px[i], px[i + 1], px[i + 2]), lo = Math.min(px[i], px[i + 1], px[i + 2]);
          if (hi - lo > 80) n++;
        }
        if (!vis) n = -2;
      }
      counts.push(n);
    });
    document.body.setAttribute("data-check-coloured", counts.join(","));
    document.body.setAttribute("data-check-ready", document.querySelectorAll(".hand3d.html-widget[data-ready]").length);
    /* counted: the widgets leave the page, which stops their drawing (each
       redraw costs software WebGL time until the run ends) */
    document.querySelectorAll(".hand3d.html-widget").forEach(function(el) { el.remove(); });
  }, 200);
});</script>'
widget_pages <- c("articles/looking-at-hands.html", "reference/hand_3d.html")
for (pg in widget_pages) {
  runs[[paste("widgets", pg)]] <- c(browser_args(600), "--window-size=1000,1400", "--dump-dom",
                                     paste0(http_base, page_copy(pg, "widgets", widget_script)))
}
check_widgets <- function(out, page, expected) {
  dom <- paste(out$stdout, collapse = "\n")
  ready <- as.integer(sub('.*data-check-ready="([0-9]+)".*', "\\1", dom))
  if (!grepl("data-check-ready=", dom, fixed = TRUE)) ready <- 0L
  errs <- if (grepl("data-js-error", dom, fixed = TRUE)) {
    strsplit(sub('.*data-js-error="([^"]*)".*', "\\1", dom), " | ", fixed = TRUE)[[1]]
  } else character()
  if (length(errs)) fail("script error in ", page, ": ", paste(errs, collapse = "; "))
  if (ready < expected) fail(sprintf("%s drew %d of %d 3D widgets", page, ready, expected))
  if (!grepl("data-check-coloured=", dom, fixed = TRUE)) fail(page, ": the widgets' pixels could not be read")
  coloured <- as.integer(strsplit(sub('.*data-check-coloured="([^"]*)".*', "\\1", dom), ",")[[1]])
  # every widget shows a hand (a blank canvas has none: the background,
  # text and controls are grey): 1,000-15,000 coloured pixels per widget
  # at these sizes (the grey palm and the pale skin of an overlay count
  # little), over 5,000 per page (a screenshot used to count those)
  if (length(coloured) < expected || any(coloured < 500) || sum(coloured) < 5000) {
    fail(sprintf("%s: a widget shows no hand (coloured pixels per widget: %s; -2: not visible)", page,
                 paste(coloured, collapse = ", ")))
  }
  message(sprintf("site: %s: %d 3D widget(s) drawn, no script errors, coloured pixels per widget %s",
                  page, ready, paste(coloured, collapse = ", ")))
}
# the 2D animation embedded in the GraspDB14 article (opened by the
# harness) draws lines (its <svg> carries `fill="none"`) and plays: its
# frame label has moved on
check_animation <- function(r, page) {
  if (!isTRUE(r$animation)) fail("no 2D animation in ", page)
  if (!isTRUE(r$line_style)) fail("the 2D animation in ", page, " lost its line style")
  if (is.null(r$frame) || r$frame <= 1L) fail("the 2D animation in ", page, " does not play")
  message(sprintf("site: %s: 2D animation plays (frame %d after 1.5 s)", page, r$frame))
}

# -- all runs at once, then the verdicts in order ------------------------------
started <- proc.time()[["elapsed"]]
res <- browser_batch(runs)
slowest <- sort(attr(res, "seconds"), decreasing = TRUE)[1:3]
message(sprintf("site: %d browser runs in %.0f s (slowest: %s)", length(runs), proc.time()[["elapsed"]] - started,
                paste(sprintf("%s %.0f s", names(slowest), slowest), collapse = ", ")))
h <- harness_result(res[["harness"]])
errs <- c(console_errors(res[["harness"]]), unlist(lapply(search_pages, function(pg) {
  console_errors(res[[paste("file search", pg)]])
})))
if (length(errs)) fail("script errors on the pages:\n  ", paste(utils::head(errs, 5), collapse = "\n  "))
for (pg in error_pages) {
  r <- h[[paste("errors", pg)]]
  if (!is.null(r$error) || !nzchar(r$title %||% "")) fail(pg, " did not open over HTTP")
}
message(sprintf("site: no script errors on %d pages over HTTP (%s, ...) nor from file:// (%s and the result pages they opened)",
                length(tasks), paste(error_pages[1:2], collapse = ", "), paste(search_pages, collapse = ", ")))
for (pg in search_pages) {
  r <- h[[paste("search", pg)]]
  if (!is.null(r$error)) fail("harness error on ", pg, ": ", r$error)
  if (isTRUE(r$wrapping > 0)) fail(sprintf("%s: %d code boxes wrap their lines", pg, r$wrapping))
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
r <- h[["rank"]]
if (is.null(r$opened) || !grepl(ranked[["page"]], r$opened, fixed = TRUE)) {
  fail(sprintf("search '%s' opened %s first, not %s", ranked[["query"]], if (is.null(r$opened)) r$first else r$opened, ranked[["page"]]))
}
if (!isTRUE(r$menu_fits)) fail(sprintf("search '%s': the list of results runs off the window", ranked[["query"]]))
message(sprintf("site: search '%s': %d results within the window, the first opened %s", ranked[["query"]],
                r$suggestions, ranked[["page"]]))
r <- h[["rank narrow"]]
if (!isTRUE(r$menu_fits)) fail(sprintf("search '%s' 390 px wide: the list of results runs off the window", ranked[["query"]]))
if (is.null(r$opened) || !grepl(ranked[["page"]], r$opened, fixed = TRUE)) {
  fail(sprintf("search '%s' 390 px wide opened %s first, not %s", ranked[["query"]], if (is.null(r$opened)) r$first else r$opened, ranked[["page"]]))
}
message(sprintf("site: search '%s' 390 px wide: %d results within the window, the first opened %s", ranked[["query"]],
                r$suggestions, ranked[["page"]]))
for (pg in search_pages) file_search_result(res[[paste("file search", pg)]], pg)
check_animation(h[[paste("animation", animation_page)]], animation_page)
for (pg in widget_pages) check_widgets(res[[paste("widgets", pg)]], pg, 2L)
unlink(copies)
message("site: ok")
