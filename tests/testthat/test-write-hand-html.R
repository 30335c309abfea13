test_that("write_hand_animation() writes a self-contained HTML animation for a .html file", {
  rec <- matrix(0, 40, 16, dimnames = list(NULL, hust_dofs$name))
  rec[, 5:16] <- outer(sin(seq(0, pi, length.out = 40)), rep(80, 12))
  f <- withr::local_tempfile(fileext = ".html")
  expect_invisible(out <- write_hand_animation(rec, f, max_frames = 300))
  expect_identical(out, f)      # the path, nothing more (it printed its frames and rate)
  doc <- xml2::read_html(f)
  frames <- xml2::xml_find_all(doc, "//svg/g")
  expect_length(frames, 40L)
  expect_length(xml2::xml_find_all(frames[[1]], ".//polyline"), 5L)
  # frames differ: the fingers move
  expect_false(identical(xml2::xml_attr(xml2::xml_find_all(frames[[1]], ".//polyline"), "points"),
                         xml2::xml_attr(xml2::xml_find_all(frames[[20]], ".//polyline"), "points")))
  txt <- paste(readLines(f), collapse = "\n")
  expect_false(grepl("<link|src=|https?://(?!www.w3.org)", txt, perl = TRUE))
  expect_match(txt, "setInterval", fixed = TRUE)
})

test_that("long recordings are thinned and grasps give a title", {
  rec <- matrix(0, 500, 16)
  g <- grasps(list(rec, rec), meta = data.frame(grasp = c("Tripod", "Lateral")), rate = 100)
  f <- withr::local_tempfile(fileext = ".html")
  write_hand_animation(g, f, recording = 2, max_frames = 50)
  doc <- xml2::read_html(f)
  expect_length(xml2::xml_find_all(doc, "//svg/g"), 50L)
  expect_match(xml2::xml_text(xml2::xml_find_first(doc, "//div[@class='hm-title']")), "Lateral")
  expect_error(write_hand_animation(g, f, recording = 3, overwrite = TRUE), class = "handmotion_error_bad_input")
  # one hand per page: several are a video's job
  expect_error(write_hand_animation(list(a = g[1], b = g[2]), f, overwrite = TRUE),
               class = "handmotion_error_bad_input")
})

test_that("every frame draws the palm and the hand is centred in the drawing", {
  rec <- matrix(0, 10, 16, dimnames = list(NULL, hust_dofs$name))
  rec[, 5:16] <- seq(0, 80, length.out = 10)
  f <- withr::local_tempfile(fileext = ".html")
  write_hand_animation(rec, f, width = 400)
  doc <- xml2::read_html(f)
  frames <- xml2::xml_find_all(doc, "//svg/g")
  expect_length(xml2::xml_find_all(doc, "//svg/g/polygon[@class='palm']"), 10L)
  pts <- unlist(lapply(xml2::xml_find_all(doc, "//svg/g/polyline"), function(l) {
    strsplit(strsplit(xml2::xml_attr(l, "points"), " ")[[1]], ",")
  }), recursive = FALSE)
  xy <- do.call(rbind, lapply(pts, as.numeric))
  # the bounding box of all frames is centred on the 400 x 400 canvas
  expect_equal(mean(range(xy[, 1])), 200, tolerance = 1)
  expect_equal(mean(range(xy[, 2])), 200, tolerance = 1)
})

test_that("the page carries its own look and controls, and two copied into one page play by themselves", {
  rec <- matrix(0, 40, 16, dimnames = list(NULL, hust_dofs$name))
  rec[, 5:16] <- outer(sin(seq(0, pi, length.out = 40)), rep(80, 12))
  dir <- withr::local_tempdir()
  f <- write_hand_animation(rec, file.path(dir, "a.html"), rate = 20)
  doc <- xml2::read_html(f)
  div <- xml2::xml_find_all(doc, "//div[@class='handmotion-animation']")
  expect_length(div, 1L)
  # the lines' look rides on the <svg> itself, not on the page's <head>
  svg <- xml2::xml_find_first(div[[1]], ".//svg")
  expect_equal(xml2::xml_attr(svg, "fill"), "none")
  expect_equal(xml2::xml_attr(xml2::xml_find_first(svg, ".//polygon"), "fill"), "#e5e5e5")
  expect_length(xml2::xml_find_all(doc, "//*[@id]"), 0L)
  for (cl in c("hm-play", "hm-back", "hm-next", "hm-speed", "hm-slider")) {
    expect_length(xml2::xml_find_all(div[[1]], sprintf(".//*[@class='%s']", cl)), 1L)
  }
  expect_equal(xml2::xml_attr(xml2::xml_find_all(div[[1]], ".//option"), "value"),
               as.character(c(0.1, 0.25, 0.5, 1, 2)))
  skip_without_browser()
  # two copies of the <div> in one page, the second slowed to 0.1x: after
  # one second the first is on frame ~21, the second on frame ~3
  txt <- readLines(f)
  body <- txt[grep('class="handmotion-animation"', txt):(length(txt) - 1L)]
  slow <- sub('<option value="0.1">', '<option value="0.1" selected>', sub(" selected>1x", ">1x", body, fixed = TRUE),
              fixed = TRUE)
  page <- file.path(dir, "two.html")
  writeLines(c("<!DOCTYPE html><html><body>", body, slow, "</body></html>"), page)
  dom <- browser_dom(page, 1000)
  labels <- regmatches(dom, gregexpr("frame [0-9]+ \\([0-9.]+ s\\)", dom))[[1]]
  expect_length(labels, 2L)
  at <- as.integer(sub("frame ([0-9]+).*", "\\1", labels))
  expect_gt(at[1], 12L)
  expect_lt(at[2], 6L)
})
