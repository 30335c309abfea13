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
