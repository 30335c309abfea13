test_that("the widget carries every frame's posed joints, at the recording's rate", {
  g <- simulate_grasps(subjects = 1, grasps = c(2, 17), objects = 1, trials = 1, seed = 1)
  w <- hand_3d(g)
  expect_s3_class(w, c("hand3d", "htmlwidget"))
  x <- w$x
  expect_length(x$recordings, 2L)
  expect_equal(x$rate, g$rate)
  sk <- hand_skeleton()
  J <- nrow(sk$joints)
  r1 <- x$recordings[[1]]
  expect_equal(r1$n, g$meta$n_frames[1])
  pos <- forward_kinematics(g$recordings[[1]], sk, unit = g$unit)[, sk$joints$name, ]
  # frame-major: frame f, joint j, coordinate c at ((f - 1) J + j - 1) 3 + c
  back <- aperm(array(r1$pos, c(3, J, r1$n)), c(3, 2, 1))
  expect_equal(back, unname(pos), tolerance = 0.006, ignore_attr = TRUE)
  # the first view is the still pictures' (oblique by default); side by side,
  # the second hand is moved across it, to the right, so both stand at one depth
  V <- view_matrix("oblique")
  expect_equal(x$camera$towards, V[3, ], tolerance = 1e-6)
  expect_equal(x$camera$up, V[2, ], tolerance = 1e-6)
  expect_equal(x$recordings[[1]]$offset, c(0, 0, 0))
  off <- x$recordings[[2]]$offset
  expect_gt(sqrt(sum(off^2)), 50)
  expect_lt(abs(sum(off * V[3, ])), 0.1)
  expect_lt(abs(sum(off * V[2, ])), 0.1)
  expect_gt(sum(off * V[1, ]), 50)
  # parents point at earlier joints; the hand's shape is the description of hand_geometry()
  expect_true(all(x$parent < seq_len(J) - 1L))
  expect_identical(x$geometry, hand_geometry_json(hand_geometry(sk)))
  expect_true(all(x$geometry$r_from > 0 & x$geometry$r_to > 0))
  expect_equal(x$geometry$palm$n * J, length(x$geometry$palm$weights))
})

test_that("joints are flagged exactly in the frames where a DoF breaks its limit", {
  rec <- matrix(0, 10, 16, dimnames = list(NULL, hust_dofs$name))
  lim <- dof_limits(hust_dofs$name)
  pip <- lim[lim$dof == "PIP2", ]
  rec[4:6, "PIP2"] <- pip$hi + 20
  w <- hand_3d(rec, limits = TRUE, rate = 100)
  x <- w$x
  J <- length(x$joints)
  flags <- matrix(x$recordings[[1]]$outside, J, 10)
  j <- match(pip$joint, x$joints)
  expect_equal(which(flags[j, ] == 1L), 4:6)
  expect_equal(sum(flags), 3L)
  expect_null(hand_3d(rec, rate = 100)$x$recordings[[1]]$outside)
})

test_that("overlay, markers and named lists", {
  g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 2, seed = 1)
  w <- hand_3d(list(recorded = g[1], generated = g[2]), layout = "overlay", markers = select_markers(method = "handpicked"))
  r <- w$x$recordings
  expect_equal(vapply(r, `[[`, character(1), "label"),
               paste0(c("recorded: ", "generated: "), g$meta$id, " (Index Finger Extension)"))
  expect_null(r[[1]]$colour)
  expect_false(is.null(r[[2]]$colour))
  expect_equal(r[[2]]$opacity, 0.5)
  expect_equal(r[[2]]$offset, c(0, 0, 0))
  # six markers per frame, where forward_kinematics(markers = ) puts them
  m <- forward_kinematics(g$recordings[[1]], markers = select_markers(method = "handpicked"))
  expect_length(r[[1]]$markers, length(m))
  expect_equal(r[[1]]$markers[1:3], unname(m[1, 1:3]), tolerance = 0.006)
})

test_that("bad arguments give classed errors", {
  g <- simulate_grasps(subjects = 1, grasps = 1:3, objects = 1, trials = 3, seed = 1)
  expect_error(hand_3d(g), "too many", class = "handmotion_error_bad_input")
  expect_error(hand_3d(g, recording = 99), class = "handmotion_error_bad_input")
  expect_error(hand_3d(g, recording = 1, speed = 3), class = "handmotion_error_bad_input")
  expect_error(hand_3d(g, recording = 1, layout = "stacked"), class = "handmotion_error_bad_input")
  expect_error(hand_3d("hand"), class = "handmotion_error_bad_input")
  expect_error(hand_3d(g, recording = 1, background = "no-such-colour"), class = "handmotion_error_bad_input")
  # colours reach the page as #rrggbb (three.js does not know R's names)
  w <- hand_3d(g, recording = 1, background = "grey90", hand_colour = "fingers")
  expect_equal(w$x$background, "#E5E5E5")
  expect_true(all(grepl("^#[0-9A-F]{6}$", c(w$x$geometry$fill, w$x$geometry$skin))))
  expect_gt(length(unique(w$x$geometry$fill)), 4L)      # a colour per finger
  expect_length(unique(hand_3d(g, recording = 1)$x$geometry$fill), 1L)   # skin
  expect_error(hand_3d(g, recording = 1, hand_colour = "blue"), class = "handmotion_error_bad_input")
  empty <- matrix(0, 0, 16, dimnames = list(NULL, hust_dofs$name))
  expect_error(hand_3d(list(none = empty)), "none", class = "handmotion_error_bad_recording")
  expect_error(hand_3d(list(a = g[1], b = matrix(1, 2, 2))), class = "handmotion_error_bad_input")
  g2 <- g[1]
  g2$rate <- 100
  expect_error(hand_3d(list(a = g[1], b = g2)), "different rates", class = "handmotion_error_bad_input")
})

test_that("the widget page draws a hand that moves, without script errors, in a real browser", {
  skip_without_browser()
  skip_if_not_installed("magick")
  g <- simulate_grasps(subjects = 1, grasps = 17, objects = 1, trials = 1, seed = 1)
  page <- file.path(withr::local_tempdir(), "hand.html")
  w <- hand_3d(g, limits = TRUE, markers = select_markers(method = "handpicked"), loop = FALSE)
  htmlwidgets::saveWidget(w, page, selfcontained = FALSE)
  n <- g$meta$n_frames[1]
  dom <- browser_dom(page, 1000 * n / g$rate + 500)
  expect_match(dom, 'data-ready="1"', fixed = TRUE)
  expect_no_match(dom, "data-js-error", fixed = TRUE)
  # it built a mesh for every segment the description draws
  meshes <- as.integer(sub('.*data-meshes="([0-9]+)".*', "\\1", dom))
  expect_equal(meshes, sum(w$x$geometry$draw))
  # nothing at all on the console: no uncaught exception, no error or warning from three.js
  console <- browser_console(page, 1000)
  expect_identical(console, character(), label = paste(console, collapse = "\n"))
  # playback follows the page's clock at the recording's rate: once the
  # recording's duration has passed, it rests on its last frame
  frame <- as.integer(sub('.*data-frame="([0-9]+)".*', "\\1", dom))
  expect_equal(frame, n - 1L)
  # (the first frame from the same widget at rest: a screenshot of a playing
  # page 100 ms in may be taken later, as the page's clock runs on while
  # chromium captures it)
  first <- file.path(dirname(page), "first.html")
  htmlwidgets::saveWidget(hand_3d(g, limits = TRUE, markers = select_markers(method = "handpicked"),
                                  autoplay = FALSE), first, selfcontained = FALSE)
  early <- png_pixels(browser_screenshot(first, 100))
  late <- png_pixels(browser_screenshot(page, 1000 * n / g$rate))
  # the canvas is drawn: many pixels differ from the background (#f7f7f5)
  bg <- c(0xf7, 0xf7, 0xf5)
  drawn <- rowSums(abs(sweep(matrix(early, ncol = 3), 2, bg))) > 30
  expect_gt(mean(drawn), 0.02)
  # and the hand moves between the two moments
  moved <- rowSums(abs(matrix(early, ncol = 3) - matrix(late, ncol = 3))) > 30
  expect_gt(sum(moved), 500)
})

test_that("hands side by side are named underneath, through one camera, in a real browser", {
  skip_without_browser()
  skip_if_not_installed("magick")
  g <- simulate_grasps(subjects = 2, grasps = 11, objects = 1, trials = 1, seed = 1)
  page <- file.path(withr::local_tempdir(), "pair.html")
  w <- hand_3d(list(recorded = g[1], generated = g[2]), autoplay = FALSE)
  htmlwidgets::saveWidget(w, page, selfcontained = FALSE)
  dom <- browser_dom(page, 500)
  expect_no_match(dom, "data-js-error", fixed = TRUE)
  expect_match(dom, 'data-meshes="[0-9]+,[0-9]+"')
  labels <- regmatches(dom, gregexpr('<div class="hand3d-label"[^>]*>[^<]*</div>', dom))[[1]]
  expect_length(labels, 2L)
  expect_match(labels[1], "recorded: T11-S01", fixed = TRUE)
  expect_match(labels[2], "generated: T11-S02", fixed = TRUE)
  # left to right, in the order given
  left <- as.numeric(sub('.*left: ([0-9.]+)px.*', "\\1", labels))
  expect_lt(left[1], left[2])
  png <- png_pixels(browser_screenshot(page, 500))
  bg <- c(0xf7, 0xf7, 0xf5)
  drawn <- rowSums(abs(sweep(matrix(png, ncol = 3), 2, bg))) > 30
  expect_gt(mean(drawn), 0.04)
})

test_that("three labels side by side in a narrow widget keep apart, inside it, and cut no word, in a real browser", {
  skip_without_browser()
  g <- simulate_grasps(subjects = 3, grasps = 11, objects = 1, trials = 1, seed = 1)
  # long labels, as the report's three-hand viewer has ("held-out
  # recording: T25-S21-O1-R1 (Lateral Tripod)"), in a 400 px widget
  w <- hand_3d(list(`held-out recording` = g[1], `thesis' model` = g[2], `copula model` = g[3]),
               autoplay = FALSE, width = 400, height = 420)
  # the labels' boxes read by the page itself once the widget is drawn:
  # left, right, and how far its longest word is wider than the text's room
  # (more than 0: the word is cut, as "Latera" over "l" was)
  probe <- '(function wait() {
    var el = document.querySelector(".hand3d.html-widget");
    if (!el || !el.getAttribute("data-ready")) return setTimeout(wait, 20);
    setTimeout(function () {
      var box = el.getBoundingClientRect();
      var ctx = document.createElement("canvas").getContext("2d");
      var out = Array.from(el.querySelectorAll(".hand3d-label")).map(function (d) {
        var r = d.getBoundingClientRect(), cs = getComputedStyle(d);
        ctx.font = cs.font;
        var longest = Math.max.apply(null, d.textContent.split(/\\s+/).map(function (s) { return ctx.measureText(s).width; }));
        var room = d.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight);
        return [r.left - box.left, r.right - box.left, longest - room, box.width].join(",");
      });
      document.body.setAttribute("data-labels", out.join(";"));
    }, 200);
  })();'
  page <- file.path(withr::local_tempdir(), "three.html")
  htmlwidgets::saveWidget(htmlwidgets::appendContent(w, htmltools::tags$script(htmltools::HTML(probe))),
                          page, selfcontained = FALSE)
  dom <- browser_dom(page, 5000)
  expect_no_match(dom, "data-js-error", fixed = TRUE)
  expect_match(dom, 'data-labels="', fixed = TRUE)
  rows <- strsplit(strsplit(sub('.*data-labels="([^"]*)".*', "\\1", dom), ";")[[1]], ",")
  b <- matrix(as.numeric(unlist(rows)), ncol = 4, byrow = TRUE)
  expect_equal(nrow(b), 3L)
  b <- b[order(b[, 1]), , drop = FALSE]
  expect_true(all(b[, 1] >= 0) && all(b[, 2] <= b[, 4] + 0.5))   # inside the widget
  expect_true(all(b[-1, 1] >= b[-3, 2]))                          # no two overlap
  expect_true(all(b[, 3] <= 0.5))                                  # no word is cut
})

test_that("a widget at rest renders nothing; playing, it renders until the end, in a real browser", {
  skip_without_browser()
  g <- simulate_grasps(subjects = 2, grasps = 17, objects = 1, trials = 1, seed = 1)
  dir <- withr::local_tempdir()
  duration_ms <- 1000 * (max(g$meta$n_frames) - 1) / g$rate
  # the widget's frame count (data-renders) read by the page itself at two
  # moments after it was drawn, so that both come from one run of the
  # browser; then the widget leaves the page (its playing stops). (The
  # browser's budget of virtual time is generous: on a loaded machine,
  # opening the page took seconds of it.)
  counts <- function(name, at_ms, ...) {
    w <- hand_3d(list(a = g[1], b = g[2]), ...)
    probe <- sprintf('(function wait() {
      var el = document.querySelector(".hand3d.html-widget");
      if (!el || !el.getAttribute("data-ready")) return setTimeout(wait, 20);
      [%d, %d].forEach(function (ms, i) { setTimeout(function () {
        document.body.setAttribute("data-probe" + i, el.getAttribute("data-renders"));
        if (i === 1) el.remove();
      }, ms); });
    })();', at_ms[1], at_ms[2])
    f <- file.path(dir, paste0(name, ".html"))
    htmlwidgets::saveWidget(htmlwidgets::appendContent(w, htmltools::tags$script(htmltools::HTML(probe))),
                            f, selfcontained = FALSE)
    dom <- browser_dom(f, at_ms[2] + 10000)
    expect_no_match(dom, "data-js-error", fixed = TRUE)
    expect_match(dom, 'data-probe1="', fixed = TRUE)
    vapply(0:1, function(i) as.integer(sub(sprintf('.*data-probe%d="([0-9]+)".*', i), "\\1", dom)), integer(1))
  }
  # at rest: the first picture (and one per camera or size event), then nothing
  resting <- counts("resting", c(300, 3000), autoplay = FALSE)
  expect_lte(resting[1], 3L)
  expect_identical(resting[2], resting[1])
  # playing once: it renders while it plays, and nothing after the end
  once <- counts("once", round(duration_ms + c(500, 3000)), autoplay = TRUE, loop = FALSE)
  expect_gt(once[1], resting[1] + 5L)
  expect_identical(once[2], once[1])
  # looping: it goes on rendering
  looping <- counts("looping", round(duration_ms * c(1, 3)), autoplay = TRUE, loop = TRUE)
  expect_gt(looping[2], looping[1] + 10L)
})
