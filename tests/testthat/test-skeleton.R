# A tiny skeleton file: root with one finger, written so single fields can be
# broken for the bad-input tests.
skel_xml <- function(units = c("deg", "mm"), j2 = "<name>f-mcp</name><id>2</id><position>0 -50 0</position>",
                     j3 = "<name>f-tip</name><id>3</id><position>0 -90 0</position>", extra = "") {
  c("<skeleton>", sprintf("<units><angle>%s</angle><length>%s</length></units>", units[1], units[2]),
    "<joint>", "<name>root</name>", "<id>1</id>", "<position>0 0 0</position>",
    "<limits><rotx>-10 10</rotx><roty>0 0</roty><rotz>-5 5</rotz></limits>",
    "<joint>", j2, "<limits><rotx>0 90</rotx></limits>",
    "<joint>", j3, "</joint>", "</joint>", extra, "</joint>", "</skeleton>")
}
write_tmp <- function(lines) {
  f <- withr::local_tempfile(fileext = ".xmlskel", .local_envir = parent.frame())
  writeLines(lines, f)
  f
}

test_that("GraspDB14's default.xmlskel reads as 25 joints with offsets from the parent", {
  s <- read_skeleton(shared_file("data", "graspdb14", "default.xmlskel"))
  expect_s3_class(s, "hand_skeleton")
  expect_equal(nrow(s$joints), 25L)
  expect_equal(s$joints$name[1:5], c("root", "th-tmc", "th-mcp", "th-ip", "th-tip"))
  expect_true(is.na(s$joints$parent[1]))
  expect_equal(s$joints$parent[s$joints$name == "if-mcp"], 6L)
  # file positions are relative to the root: th-mcp (51,-71) minus th-tmc (27,-31)
  expect_equal(unlist(s$joints[s$joints$name == "th-mcp", c("x", "y", "z")]), c(x = 24, y = -40, z = 0))
  pos <- skeleton_rest_positions(s)
  expect_equal(unname(pos["mf-tip", ]), c(0, -200, 0))
  expect_equal(unlist(s$joints[s$joints$name == "if-mcp", c("rotz_min", "rotz_max")]),
               c(rotz_min = -15, rotz_max = 42))
  expect_equal(s$units, list(angle = "deg", length = "mm"))
})

test_that("the default hand has GraspDB14's joints and anthropometric lengths", {
  s <- hand_skeleton()
  expect_equal(nrow(s$joints), 25L)
  fingers <- c("if", "mf", "rf", "lf")
  expect_setequal(s$joints$name, c("root", paste0("th-", c("tmc", "mcp", "ip", "tip")),
                                   as.vector(outer(fingers, c("cmc", "mcp", "pip", "dip", "tip"), paste, sep = "-"))))
  pos <- skeleton_rest_positions(s)
  # middle fingertip one hand length (189 mm) from the wrist crease
  expect_equal(sqrt(sum(pos["mf-tip", ]^2)), 189, tolerance = 0.01)
  # Buchholz et al.: middle proximal phalanx 0.266 hand lengths (not An et
  # al.'s ratio-derived 0.277); index metacarpal with its hand-breadth term
  seg <- function(a, b) sqrt(sum((pos[b, ] - pos[a, ])^2))
  expect_equal(seg("mf-mcp", "mf-pip"), 0.266 * 189, tolerance = 0.01)
  expect_equal(seg("if-mcp", "if-pip"), 0.245 * 189, tolerance = 0.01)
  expect_equal(seg("if-cmc", "if-mcp"), sqrt((0.374 * 189)^2 + (0.126 * 84)^2), tolerance = 0.01)
  expect_equal(seg("mf-cmc", "mf-mcp"), 0.373 * 189, tolerance = 0.01)
  # finger lengths ordered as in a real hand: middle > index, ring > little
  reach <- sqrt(rowSums(pos^2))
  expect_gt(reach["mf-tip"], reach["if-tip"])
  expect_gt(reach["rf-tip"], reach["lf-tip"])
  expect_true(all(s$joints$rotx_min <= s$joints$rotx_max))
})

test_that("write_skeleton() and read_skeleton() round-trip", {
  s <- hand_skeleton()
  f <- withr::local_tempfile(fileext = ".xmlskel")
  write_skeleton(s, f, comment = "test")
  s2 <- read_skeleton(f)
  expect_equal(s2$joints, s$joints, tolerance = 1e-6)
})

test_that("units are converted to mm and degrees; relative positions are supported", {
  s <- read_skeleton(write_tmp(skel_xml(units = c("rad", "cm"))))
  expect_equal(s$joints$y, c(0, -500, -400))
  expect_equal(s$joints$rotx_max[2], 90 * 180 / pi)
  expect_equal(s$units, list(angle = "rad", length = "cm"))
  r <- read_skeleton(write_tmp(skel_xml()), positions = "relative")
  expect_equal(skeleton_rest_positions(r)["f-tip", "y"], -140)
})

test_that("a flat file with <parent> elements is ordered parents first", {
  f <- write_tmp(c("<skeleton><units><angle>deg</angle><length>mm</length></units>",
                   "<joint><name>tip</name><id>3</id><parent>2</parent><position>0 -90 0</position></joint>",
                   "<joint><name>root</name><id>1</id><position>0 0 0</position></joint>",
                   "<joint><name>mcp</name><id>2</id><parent>1</parent><position>0 -50 0</position></joint>",
                   "</skeleton>"))
  s <- read_skeleton(f)
  expect_equal(s$joints$name, c("root", "mcp", "tip"))
  expect_equal(s$joints$y, c(0, -50, -40))
})

test_that("bad skeleton files raise bad_skeleton errors naming file and joint", {
  expect_bad <- function(lines, pattern, joint = NULL) {
    f <- write_tmp(lines)
    err <- expect_error(read_skeleton(f), class = "handmotion_error_bad_skeleton")
    expect_match(conditionMessage(err), pattern)
    expect_match(cli::ansi_strip(conditionMessage(err)), basename(f), fixed = TRUE)
    # the joints the error names: exactly those given (none when NULL)
    expect_identical(as.character(stats::na.omit(err$joint)), joint %||% character(0))
    invisible(err)
  }
  expect_bad(c("<skeleton><joint><name>root</name>", "</skeleton>"), "not well-formed")
  expect_bad(skel_xml(units = c("grad", "mm")), "Unknown angle unit")
  expect_bad(skel_xml(units = c("deg", "furlong")), "Unknown length unit")
  err <- expect_bad(skel_xml(j3 = "<name>f-tip</name><id>2</id><position>0 -90 0</position>"),
                    "cycle", joint = "f-tip")
  expect_equal(err$line, 12L)
  expect_bad(skel_xml(extra = "<joint><name>g-mcp</name><id>2</id><position>5 -50 0</position></joint>"),
             "used twice", joint = "g-mcp")
  expect_bad(skel_xml(extra = "<joint><name>f-mcp</name><id>9</id><position>5 -50 0</position></joint>"),
             "used twice", joint = "f-mcp")
  expect_bad(skel_xml(j3 = "<name>f-tip</name><id>3</id>"), "position", joint = "f-tip")
  expect_bad(skel_xml(j3 = "<name>f-tip</name><id>3</id><position>0 x 0</position>"), "position", joint = "f-tip")
  expect_bad(skel_xml(j3 = "<id>3</id><position>0 -90 0</position>"), "has no")
  expect_bad(skel_xml(j3 = "<name>f-tip</name><id>three</id><position>0 -90 0</position>"), "id",
             joint = "f-tip")
  expect_bad(skel_xml(j3 = "<name>f-tip</name><id>3</id><parent>7</parent><position>0 -90 0</position>"),
             "missing joint", joint = "f-tip")
  # cycles and extra roots in flat files
  flat <- function(...) c("<skeleton><units><angle>deg</angle><length>mm</length></units>", ..., "</skeleton>")
  expect_bad(flat("<joint><name>root</name><id>1</id><position>0 0 0</position></joint>",
                  "<joint><name>a</name><id>2</id><parent>3</parent><position>0 0 0</position></joint>",
                  "<joint><name>b</name><id>3</id><parent>2</parent><position>0 0 0</position></joint>"),
             "Cycle", joint = "a")
  expect_bad(flat("<joint><name>root</name><id>1</id><position>0 0 0</position></joint>",
                  "<joint><name>other</name><id>2</id><position>0 0 0</position></joint>"),
             "2 root joints", joint = c("root", "other"))
  expect_bad(c("<hand/>"), "root element")
  expect_bad(skel_xml(j2 = "<name>f-mcp</name><id>2</id><position>0 -50 0</position><limits><rotx>90 0</rotx></limits>"),
             "limits", joint = "f-mcp")
  expect_error(read_skeleton(tempfile()), class = "handmotion_error_bad_file")
})

test_that("missing units fall back to deg and mm with a warning", {
  lines <- skel_xml()[-2]
  expect_warning(s <- read_skeleton(write_tmp(lines)), class = "handmotion_warning_skeleton_default_unit")
  expect_equal(s$units, list(angle = "deg", length = "mm"))
})

test_that("print and autoplot of a skeleton", {
  expect_snapshot(print(hand_skeleton()))
  p <- ggplot2::autoplot(hand_skeleton(), labels = FALSE)
  b <- ggplot2::ggplot_build(p)
  geoms <- vapply(p$layers, function(l) class(l$geom)[1], character(1))
  solid <- p$layers[[which(geoms == "GeomPolygon")[1]]]$data
  # a solid segment per bone the hand's geometry draws (the others lie inside the palm)
  expect_equal(length(unique(solid$piece[solid$kind == "bone"])), sum(hand_geometry()$segments$draw))
  expect_equal(nrow(b$data[[which(geoms == "GeomPoint")[1]]]), 25L)     # joints
})

test_that("the default skeleton is the installed file's, read once per session", {
  path <- system.file("extdata", "handmotion-hand.xmlskel", package = "handmotion")
  expect_identical(hand_skeleton(), read_skeleton(path))
  expect_identical(default_skeleton$path, path)
  # a later call returns what was read, without reading the file again
  kept <- default_skeleton$skeleton
  on.exit(default_skeleton$skeleton <- kept, add = TRUE)
  default_skeleton$skeleton <- "what was read"
  expect_identical(hand_skeleton(), "what was read")
  # another installation's file is read afresh
  default_skeleton$path <- "elsewhere"
  expect_identical(hand_skeleton(), kept)
  expect_identical(default_skeleton$path, path)
})
