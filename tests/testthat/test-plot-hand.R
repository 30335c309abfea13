hust <- function(n = 1, value = 0) matrix(value, n, 16, dimnames = list(NULL, hust_dofs$name))
# built data of the first layer drawn with `geom` (e.g. "GeomSegment")
geom_data <- function(p, geom, built = ggplot2::ggplot_build(p)) {
  i <- which(vapply(p$layers, function(l) inherits(l$geom, geom), logical(1)))[1]
  built$data[[i]]
}

test_that("hand_pose() collects joints from matrices, arrays, grasps and skeletons", {
  x <- hust(3)
  x[, "PIP3"] <- c(0, 45, 90)
  p <- hand_pose(x)
  expect_s3_class(p, "hand_pose")
  expect_equal(nrow(p), 25L)
  expect_equal(unique(p$frame), 3L)
  expect_named(p, c("id", "frame", "joint", "parent", "finger", "x", "y", "z"))
  expect_equal(sum(is.na(p$parent)), 1L)
  fk <- forward_kinematics(x)
  expect_equal(hand_pose(fk, frame = 1:3)$z, as.vector(fk[, , 3]))
  g <- grasps(list(x, x), meta = data.frame(grasp = c("Tripod", "Lateral")))
  pg <- hand_pose(g, frame = "first")
  expect_equal(nrow(pg), 50L)
  expect_equal(as.character(unique(pg$grasp)), c("Tripod", "Lateral"))
  expect_equal(nrow(hand_pose(hand_skeleton())), 25L)
  expect_error(hand_pose("a"), class = "handmotion_error_bad_input")
})

test_that("autoplot(type = \"hand\") of a grasps set draws its hand_pose", {
  x <- hust(3)
  x[, "PIP3"] <- c(0, 45, 90)
  g <- grasps(list(x), meta = data.frame(grasp = "Tripod"))
  p <- ggplot2::autoplot(g, type = "hand", frame = 1:3, view = "radial")
  q <- ggplot2::autoplot(hand_pose(g, frame = 1:3), view = "radial")
  expect_equal(ggplot2::ggplot_build(p)$data, ggplot2::ggplot_build(q)$data)
})

test_that("autoplot draws the geometry's segments and palm in every panel, back to front", {
  x <- hust(3)
  x[, "PIP3"] <- c(0, 45, 90)
  p <- ggplot2::autoplot(hand_pose(x, frame = 1:3), view = "radial")
  solid <- p$layers[[1]]$data
  geo <- hand_geometry()
  pieces <- unique(solid[c("frame", "piece", "kind")])
  # a body per drawn segment (the fingers, the thumb, the palm's two edges, the forearm)
  expect_equal(sum(pieces$kind == "bone"), 3L * sum(geo$segments$draw))
  expect_equal(sum(pieces$kind == "palm"), 3L)                # the palm's face, once a hand
  expect_equal(length(unique(geom_data(p, "GeomPolygon")$PANEL)), 3L)
  # drawn back to front within each hand, the palm's parts together
  first <- solid[!duplicated(solid$draw), ]
  for (f in 1:3) expect_false(is.unsorted(first$order_depth[first$frame == f]))
  # skin tone by default: no finger legend; finger colours on request, with one
  expect_equal(p$scales$get_scales("colour")$guide, "none")
  q <- ggplot2::autoplot(hand_pose(x, frame = 1), hand_colour = "fingers")
  legend <- q$scales$get_scales("colour")
  expect_s3_class(legend$guide, "legend")
  expect_error(ggplot2::autoplot(hand_pose(x), hand_colour = "rainbow"), class = "handmotion_error_bad_input")
})

test_that("views project as documented", {
  x <- hust(1, 0)
  x[, c("MCP3", "PIP3", "DIP3")] <- 80
  p <- hand_pose(x)
  tip <- function(view) {
    pr <- project_pose(as.data.frame(unclass(p)), view)
    pr[pr$joint == "mf-tip", c("sx", "sy")]
  }
  # seen from the thumb side the palm (-z) is on the left: a curled finger ends left of the wrist
  expect_lt(tip("radial")$sx, 0)
  expect_gt(tip("ulnar")$sx, 0)
  # in the back view fingers point up and the thumb is on the left
  pr <- project_pose(as.data.frame(unclass(hand_pose(hand_skeleton()))), "back")
  expect_lt(pr$sx[pr$joint == "th-tip"], 0)
  expect_gt(pr$sy[pr$joint == "if-tip"], 100)
  expect_equal(view_matrix(c(0, 0)), view_matrix("back"))
  expect_error(view_matrix("sideways"), class = "handmotion_error_bad_input")
})

test_that("autoplot(type = \"poses\") draws one panel per group and set", {
  flat <- hust(5)
  bent <- hust(5, 60)
  g <- grasps(list(flat, bent, bent), meta = data.frame(grasp = c(1, 2, 2)))
  p <- ggplot2::autoplot(g, type = "poses")
  expect_equal(length(unique(geom_data(p, "GeomPolygon")$PANEL)), 2L)
  bones <- unique(p$layers[[1]]$data[p$layers[[1]]$data$kind == "bone", c("id", "piece")])
  expect_equal(nrow(bones), 2L * sum(hand_geometry()$segments$draw))      # one recording per type
  gg <- ggplot2::autoplot(g, type = "poses", label = "recorded", compare = list(generated = g[2:3]),
                          view = "radial")
  b <- ggplot2::ggplot_build(gg)
  expect_equal(nrow(b$layout$layout), 2L)        # one panel per type, sets side by side
  # in each panel the generated hand stands right of the recorded one, without overlap
  pts <- geom_data(gg, "GeomPoint", b)
  pts$set <- gg$layers[[2]]$data$set
  type2 <- pts[pts$PANEL == 2, ]
  expect_gt(min(type2$x[type2$set == "generated"]), max(type2$x[type2$set == "recorded"]))
  # each hand is named underneath
  txt <- geom_data(gg, "GeomText", b)
  expect_equal(sort(as.character(txt$label)), c("generated", "recorded", "recorded"))
  expect_true(all(txt$y < min(pts$y)))
  expect_setequal(as.character(unique(gg$layers[[2]]$data$set)), c("recorded", "generated"))
  expect_error(ggplot2::autoplot(g, type = "poses", by = "colour"), class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(g, type = "poses", compare = list(1)), class = "handmotion_error_bad_input")
  expect_error(ggplot2::autoplot(g, type = "poses", compare = g), class = "handmotion_error_bad_input")
})

test_that("autoplot(type = 'poses') takes a number of columns and keeps long type names whole", {
  g <- simulate_grasps(subjects = 1, grasps = c(1, 2, 21, 27), objects = 1, trials = 1, seed = 1)
  p <- autoplot(g, type = "poses", ncol = 2)
  expect_equal(p$facet$params$ncol, 2L)
  # "Large Diameter" and "Tripod Variation" are wrapped onto two lines, not clipped
  strips <- ggplot2::ggplot_build(p)$layout$layout$group
  expect_true(all(c("Large Diameter", "Tripod Variation") %in% as.character(strips)))
  expect_equal(p$theme$strip.clip, "off")
  lab <- p$facet$params$labeller(data.frame(group = "Tripod Variation"))[[1]]
  expect_equal(lab, "Tripod\nVariation")
  expect_error(autoplot(g, type = "poses", ncol = 0), class = "handmotion_error_bad_input")
})
