test_that("write_hand_animation() writes a self-contained HTML animation for a .html file", {
  rec <- matrix(0, 40, 16, dimnames = list(NULL, hust_dofs$name))
  rec[, 5:16] <- outer(sin(seq(0, pi, length.out = 40)), rep(80, 12))
  f <- withr::local_tempfile(fileext = ".html")
  expect_invisible(out <- write_hand_animation(rec, f, max_frames = 300))
  expect_equal(as.vector(out), f)
  expect_equal(attr(out, "frames"), 40L)
  expect_equal(attr(out, "fps"), 50)
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
  expect_match(xml2::xml_text(xml2::xml_find_first(doc, "//h3")), "Lateral")
  expect_error(write_hand_animation(g, f, recording = 3), class = "handmotion_error_bad_input")
  # one hand per page: several are a video's job
  expect_error(write_hand_animation(list(a = g[1], b = g[2]), f), class = "handmotion_error_bad_input")
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
