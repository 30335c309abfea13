hust <- function(n = 1, value = 0) matrix(value, n, 16, dimnames = list(NULL, hust_dofs$name))
gdb <- function(n = 1, value = 0) matrix(value, n, 23, dimnames = list(NULL, joint_map("graspdb14")$dof))
dist <- function(a, b) sqrt(sum((a - b)^2))

test_that("the flat pose puts the middle fingertip 150-220 mm from the wrist", {
  p <- forward_kinematics(hust(), hand_skeleton())
  expect_equal(dim(p), c(1L, 25L, 3L))
  expect_equal(dimnames(p)[[3]], c("x", "y", "z"))
  d <- dist(p[1, "mf-tip", ], p[1, "root", ])
  expect_gte(d, 150)
  expect_lte(d, 220)
  # all angles zero = the skeleton's rest pose
  expect_equal(unname(p[1, , ]), unname(skeleton_rest_positions(hand_skeleton())))
})

test_that("GraspDB14's skeleton and sensors: flat pose and real recording", {
  s <- read_skeleton(shared_file("data", "graspdb14", "default.xmlskel"))
  p <- forward_kinematics(gdb(), s)
  d <- dist(p[1, "mf-tip", ], p[1, "root", ])
  expect_gte(d, 150)
  expect_lte(d, 220)
  raw <- utils::read.table(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  a <- as.matrix(raw[, 8:30])
  colnames(a) <- joint_map("graspdb14")$dof
  p <- forward_kinematics(a, s, unit = "rad", mode = "full")
  expect_equal(dim(p), c(282L, 25L, 3L))
  expect_true(all(is.finite(p)))
  expect_setequal(attr(p, "fk")$ignored, c("I-AA", "P-Arch"))
  # during the power-sphere hold the fingers curl towards the palm (-z)
  expect_lt(p[120, "mf-tip", "z"], -50)
})

test_that("a 90 degree PIP flexion turns the distal segments towards the palm", {
  s <- hand_skeleton()
  rest <- skeleton_rest_positions(s)
  x <- hust()
  x[, "PIP3"] <- 90
  p <- forward_kinematics(x, s)
  distal <- dist(rest["mf-tip", ], rest["mf-pip", ])
  expect_equal(unname(p[1, "mf-tip", ]), unname(rest["mf-pip", ] + c(0, 0, -distal)), tolerance = 1e-8)
  # joints proximal to the PIP do not move, nor do other fingers
  expect_equal(unname(p[1, c("mf-mcp", "mf-pip", "if-tip"), ]), unname(rest[c("mf-mcp", "mf-pip", "if-tip"), ]))
})

test_that("abduction turns a finger within the palm plane towards the thumb", {
  s <- hand_skeleton()
  x <- gdb()
  x[, "MI-AA"] <- -20            # GraspDB14 angles are applied negated
  p <- forward_kinematics(x, s)
  rest <- skeleton_rest_positions(s)
  expect_equal(unname(p[1, "if-tip", "z"]), 0, tolerance = 1e-10)
  expect_gt(p[1, "if-tip", "x"], rest["if-tip", "x"] + 20)
  expect_equal(dist(p[1, "if-tip", ], p[1, "if-mcp", ]), dist(rest["if-tip", ], rest["if-mcp", ]))
})

test_that("poses are rigid: every bone keeps its length in every frame", {
  set.seed(3)
  x <- hust(50)
  x[] <- runif(length(x), -30, 100)
  s <- hand_skeleton()
  p <- forward_kinematics(x, s)
  rest <- skeleton_rest_positions(s)
  j <- s$joints
  for (k in which(!is.na(j$parent))) {
    parent <- j$name[j$id == j$parent[k]]
    len <- sqrt(rowSums((p[, j$name[k], ] - p[, parent, ])^2))
    expect_equal(len, rep(dist(rest[j$name[k], ], rest[parent, ]), 50), tolerance = 1e-9)
  }
})

test_that("vectorised frames equal frame-by-frame results; frames and units", {
  set.seed(4)
  x <- hust(7)
  x[] <- runif(length(x), -20, 90)
  all <- forward_kinematics(x)
  one <- forward_kinematics(x[5, , drop = FALSE])
  expect_equal(all[5, , , drop = FALSE], one, ignore_attr = TRUE)
  expect_equal(forward_kinematics(x, frames = "last"), all[7, , , drop = FALSE], ignore_attr = TRUE)
  expect_equal(forward_kinematics(x * pi / 180, unit = "rad"), all, ignore_attr = TRUE)
  expect_error(forward_kinematics(x, frames = 9), class = "handmotion_error_bad_input")
  expect_error(forward_kinematics(x, unit = "raw"), class = "handmotion_error_bad_input")
})

test_that("modes: full rotates the hand at the wrist, fixed-root and plain do not", {
  x <- gdb(2)
  x[, "M-PIPJ"] <- -40 * pi / 180
  x[2, "W-FE"] <- -90 * pi / 180   # wrist flexion of 90 degrees
  s <- hand_skeleton()
  full <- forward_kinematics(x, s, mode = "full", unit = "rad")
  plain <- forward_kinematics(x, s, mode = "plain", unit = "rad")
  fixed <- forward_kinematics(x, s, mode = "fixed-root", unit = "rad")
  expect_equal(plain, fixed, ignore_attr = TRUE)
  expect_equal(full[1, , ], plain[1, , ])
  expect_equal(attr(fixed, "fk")$deactivated, c("W-FE", "W-AA"))
  # 90 degree flexion at the root: y -> -z, so the hand now points to -z
  expect_equal(unname(full[2, "mf-mcp", ]), unname(c(plain[2, "mf-mcp", 1], 0, plain[2, "mf-mcp", 2])),
               tolerance = 1e-8)
  expect_equal(sqrt(rowSums(full[2, , ]^2)), sqrt(rowSums(plain[2, , ]^2)))
})

test_that("deactivating a sensor or a joint sets its angles to zero", {
  x <- gdb(1)
  x[, c("M-MCPJ", "M-PIPJ", "I-MCPJ")] <- -50
  zeroed <- x
  zeroed[, "M-MCPJ"] <- 0
  ref <- forward_kinematics(zeroed)
  expect_equal(forward_kinematics(x, deactivate = "M-MCPJ"), ref, ignore_attr = TRUE)
  expect_equal(forward_kinematics(x, deactivate = "mf-mcp"), ref, ignore_attr = TRUE)
  expect_equal(forward_kinematics(x, deactivate = 9), ref, ignore_attr = TRUE)
  expect_equal(attr(forward_kinematics(x, deactivate = "mf-mcp"), "fk")$deactivated, "M-MCPJ")
  expect_error(forward_kinematics(x, deactivate = "elbow"), class = "handmotion_error_bad_input")
})

test_that("grasps in, arrays or a list of arrays out", {
  set.seed(5)
  recs <- replicate(3, matrix(runif(8 * 16, 0, 60), 8, 16), simplify = FALSE)
  g <- grasps(recs, meta = data.frame(grasp = c(1, 2, 2)))
  out <- forward_kinematics(g)
  expect_type(out, "list")
  expect_named(out, g$meta$id)
  expect_equal(out[[2]], forward_kinematics(recs[[2]]), ignore_attr = TRUE)
  # a set of one is still a list: the return type does not depend on the length
  one <- forward_kinematics(g[1])
  expect_type(one, "list")
  expect_named(one, g$meta$id[1])
  expect_equal(one[[1]], out[[1]])
  g_rad <- g
  g_rad$unit <- "rad"
  g_rad$recordings <- lapply(g$recordings, function(r) r * pi / 180)
  expect_equal(forward_kinematics(g_rad), out)
  g_raw <- g
  g_raw$unit <- "raw"
  expect_error(forward_kinematics(g_raw), class = "handmotion_error_bad_input")
})

test_that("mappings: defaults, custom, unknown DoFs and missing joints", {
  expect_equal(joint_map(dofs = c("PIP2", "MCP2"))$joint, c("if-pip", "if-mcp"))
  expect_equal(joint_map(dofs = c("t_tmj", "w-fe"))$joint, c("th-tmc", "root"))
  expect_error(joint_map(dofs = c("a", "b")), class = "handmotion_error_bad_mapping")
  expect_identical(joint_map("hust"), hust_joint_map())
  expect_equal(nrow(joint_map("graspdb14")), 23L)
  expect_equal(joint_map("graspdb14", dofs = c("w_fe", "T-TMJ"))$dof, c("w_fe", "T-TMJ"))
  expect_equal(joint_map("graspdb14", dofs = c("w_fe", "T-TMJ"))$joint, c("root", "th-tmc"))
  expect_error(joint_map("hust", dofs = "W-FE"), class = "handmotion_error_bad_mapping")
  expect_error(joint_map(), class = "handmotion_error_bad_input")
  expect_error(joint_map("hust2"), class = "handmotion_error_bad_input")
  x <- matrix(c(0, 90), 1, dimnames = list(NULL, c("a", "b")))
  m <- data.frame(dof = "b", joint = "mf-pip", axis = "x", sign = 1, scale = 1)
  p <- forward_kinematics(x, mapping = m)
  expect_equal(attr(p, "fk")$ignored, "a")
  expect_lt(p[1, "mf-tip", "z"], -40)
  m$joint <- "mf-knuckle"
  err <- expect_error(forward_kinematics(x, mapping = m), class = "handmotion_error_bad_skeleton")
  expect_equal(err$joint, "mf-knuckle")
  m$joint <- "mf-pip"
  m$axis <- "w"
  expect_error(forward_kinematics(x, mapping = m), class = "handmotion_error_bad_mapping")
})

test_that("a turn about the parent's axis: GraspDB14's thumb rotation about the hand's long axis", {
  s <- hand_skeleton()
  rest <- skeleton_rest_positions(s)
  x <- gdb()
  x[, "T-TMCJ"] <- -90                # applied negated: +90 degrees about the root's y
  p <- forward_kinematics(x, s)
  # th-tmc keeps its place; the thumb's first bone turns about y through it:
  # (dx, dy, 0) -> (0, dy, -dx), i.e. in front of the palm (-z)
  d <- rest["th-mcp", ] - rest["th-tmc", ]
  expect_equal(unname(p[1, "th-tmc", ]), unname(rest["th-tmc", ]))
  expect_equal(unname(p[1, "th-mcp", ] - rest["th-tmc", ]), unname(c(0, d[2], -d[1])), tolerance = 1e-8)
  expect_equal(attr(p, "fk")$mapping$frame[attr(p, "fk")$mapping$dof == "T-TMCJ"], "parent")
  # the fingers do not move
  expect_equal(unname(p[1, "if-tip", ]), unname(rest["if-tip", ]))
  m <- joint_map("graspdb14")
  m$frame[1] <- "grandparent"
  expect_error(forward_kinematics(x, s, mapping = m), class = "handmotion_error_bad_mapping")
  # a mapping without a frame column means the joint's own axes
  m$frame <- NULL
  m$axis[1] <- "z"
  q <- forward_kinematics(x, s, mapping = m)
  expect_equal(unname(q[1, "th-mcp", "z"]), 0, tolerance = 1e-10)
})

test_that("the real power-sphere hold puts the thumb in front of the palm, opposite the fingers", {
  s <- read_skeleton(shared_file("data", "graspdb14", "default.xmlskel"))
  g <- read_graspdb14(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  p <- forward_kinematics(g, s, frames = 120)[[1]][1, , ]   # annotated hold: frames 82-164
  # thumb tip distal of its base (Table 5.1's z axis points it back past the wrist: y > 0)
  expect_lt(p["th-tip", "y"], p["th-mcp", "y"] - 30)
  expect_lt(p["th-tip", "z"], -30)                     # on the palm side
  expect_lt(sqrt(sum((p["th-tip", ] - p["if-tip", ])^2)), 40)
  m <- joint_map("graspdb14")
  m[1, c("axis", "frame")] <- c("z", "joint")
  literal <- forward_kinematics(g, s, frames = 120, mapping = m)[[1]][1, , ]
  expect_gt(literal["th-tip", "y"], 0)
})

test_that("a GraspDB14 recording and its HUST conversion pose the same hand", {
  s <- hand_skeleton()
  g <- read_graspdb14(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  h <- graspdb14_to_hust(g)
  # HUST has no finger-spread sensors
  a <- forward_kinematics(g, s, deactivate = c("MI-AA", "RM-AA", "LR-AA"))
  b <- forward_kinematics(h, s)
  expect_equal(a, b, ignore_attr = TRUE, tolerance = 1e-8)
})

test_that("simulated pad-opposition grasps bring the thumb tip to the fingers", {
  pad <- feix_taxonomy$id[feix_taxonomy$opposition == "pad"]
  g <- simulate_grasps(subjects = 1, grasps = pad, objects = 1, trials = 1, seed = 2)
  gap <- vapply(g$recordings, function(r) {
    p <- forward_kinematics(r, frames = "last")[1, , ]
    near <- c("if-tip", "if-dip", "if-pip", "mf-tip", "mf-dip")
    min(sqrt(rowSums(sweep(p[near, ], 2, p["th-tip", ])^2)))
  }, numeric(1))
  # the old map (CMC1 a flexion, ABD1 an abduction at th-tmc) left a median gap of ~12 cm
  expect_lt(stats::median(gap), 50)
  tip_z <- vapply(g$recordings, function(r) forward_kinematics(r, frames = "last")[1, "th-tip", "z"], numeric(1))
  expect_true(all(tip_z < 0))
})
