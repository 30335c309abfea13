test_that("the sensor table follows Tables 3.1 and 4.3", {
  s <- cyberglove_sensors
  expect_equal(nrow(s), 23)
  expect_identical(s$index, 1:23)
  expect_identical(s$sensor_no, 0:22)
  expect_identical(s$key, 8:30)
  expect_identical(s$name[c(1, 4, 8, 12, 21, 23)], c("T-TMJ", "TI-AA", "I-AA", "MI-AA", "P-Arch", "W-AA"))
  expect_equal(sum(s$status == "measured"), 18)
  expect_identical(s$name[s$status == "inferred"], c("I-DIPJ", "M-DIPJ", "R-DIPJ", "L-DIPJ"))
  expect_identical(s$name[s$status == "unsupported"], "I-AA")
  expect_setequal(stats::na.omit(s$hust_dof), hust_dofs$name)
  expect_false(anyDuplicated(stats::na.omit(s$hust_dof)) > 0)
})

test_that("the object and action tables follow Tables 4.1 and 4.2", {
  expect_identical(graspdb14_objects$id, 1:16)
  expect_match(graspdb14_objects$name[1], "Tennis ball")
  expect_identical(graspdb14_objects$grasp_ids[10], "3, 15")
  expect_equal(sum(graspdb14_objects$controlled), 11)
  ids <- as.integer(unlist(strsplit(stats::na.omit(graspdb14_objects$grasp_ids), ", ")))
  # the 25 grasp types of controlled transport, each on exactly one object
  expect_length(ids, 25)
  expect_false(anyDuplicated(ids) > 0)
  expect_true(all(ids %in% 1:33))
  expect_identical(graspdb14_actions$code, c("o_r", "s_r", "f_r", "i_r", "o_l", "s_l", "f_l"))
})

test_that("graspdb14_to_hust sends each sensor to its DoF in degrees with the flexion sign flipped", {
  # plant a distinct constant per sensor: sensor k holds k / 100 radians
  n <- 4
  m <- matrix(rep((1:23) / 100, each = n), n, 23)
  attr(m, "switch") <- c(1L, 1L, 0L, 1L)
  g <- grasps(list(m), meta = data.frame(id = "p", grasp = 11), dofs = cyberglove_sensors$name,
              rate = 60, unit = "rad")
  h <- graspdb14_to_hust(g)
  expect_identical(h$dofs, hust_dofs$name)
  expect_identical(h$unit, "deg")
  expect_identical(h$rate, 60)
  deg <- function(k) k / 100 * 180 / pi
  r <- h$recordings[[1]]
  expect_equal(r[[1, "CMC1"]], -deg(1))   # T-TMJ
  expect_equal(r[[1, "ABD1"]], deg(4))    # TI-AA keeps its sign
  expect_equal(r[[1, "MCP1"]], -deg(2))
  expect_equal(r[[1, "IP1"]], -deg(3))
  expect_equal(r[[1, "MCP2"]], -deg(5))
  expect_equal(r[[1, "DIP2"]], -deg(7))   # inferred I-DIPJ
  expect_equal(r[[1, "MCP3"]], -deg(9))
  expect_equal(r[[1, "PIP4"]], -deg(14))
  expect_equal(r[[1, "DIP5"]], -deg(19))
  expect_identical(attr(r, "switch"), c(1L, 1L, 0L, 1L))
  expect_setequal(attr(h, "unmapped"), c("I-AA", "MI-AA", "RM-AA", "LR-AA", "P-Arch", "W-FE", "W-AA"))
  expect_identical(h$meta$dip_source, "inferred")
  expect_identical(as.character(h$meta$grasp), "Power Sphere")

  pip <- graspdb14_to_hust(g, dip = "pip")$recordings[[1]]
  expect_equal(pip[, "DIP3"], pip[, "PIP3"] * 2 / 3)
  expect_true(all(graspdb14_to_hust(g, dip = "zero")$recordings[[1]][, c("DIP2", "DIP3", "DIP4", "DIP5")] == 0))
})

test_that("graspdb14_to_hust refuses raw counts and non-GraspDB14 sets", {
  raw <- grasps(list(matrix(100, 3, 23)), dofs = cyberglove_sensors$name, unit = "raw")
  expect_error(graspdb14_to_hust(raw), class = "handmotion_error_bad_input")
  expect_error(graspdb14_to_hust(hust_fixture(1)), class = "handmotion_error_bad_input")
})

test_that("the real grasp sample converts to plausible HUST flexion while holding the ball", {
  g <- read_graspdb14(shared_file("data", "graspdb14", "01_11_ex03-rad-004-grasp-su04.txt"))
  h <- graspdb14_to_hust(g)
  r <- h$recordings[[1]]
  ann <- c(rest = 10, grasp = 120)  # frames inside the annotated .rest and .grasp phases
  # a power sphere flexes the finger MCP and PIP joints: positive and larger than at rest
  fingers <- c("MCP2", "PIP2", "MCP3", "PIP3", "PIP4", "PIP5")
  expect_true(all(r[ann["grasp"], fingers] > r[ann["rest"], fingers] + 10))
  expect_true(all(abs(r) < 180))
})
