test_that("postures follow the roles the taxonomy gives each finger", {
  tax <- feix_taxonomy
  # finger = NA: the thumb's role; the last block are the corrections
  # checked against Feix et al. (2016), Fig. 4
  expected <- read.csv(text = "
grasp,finger,role
Index Finger Extension,2,extended
Index Finger Extension,3,wrap
Prismatic 2 Finger,2,pad
Prismatic 2 Finger,4,unused_precision
Writing Tripod,2,support
Lateral,2,side
Adducted Thumb,NA,along
Tripod,NA,pad_opposed
Medium Wrap,NA,wrap
Extension Type,4,pad
Extension Type,5,unused_power
Sphere 4 Finger,4,pad
Sphere 4 Finger,5,unused_power
Sphere 3 Finger,3,pad
Sphere 3 Finger,4,unused_power
Sphere 4 Finger,NA,pad_opposed
Sphere 3 Finger,NA,pad_opposed
Ventral,2,side
Ventral,3,unused_precision
Adduction Grip,2,side
Adduction Grip,3,side", stringsAsFactors = FALSE)
  for (i in seq_len(nrow(expected))) {
    row <- tax[tax$name == expected$grasp[i], ]
    got <- if (is.na(expected$finger[i])) sim_thumb_role(row) else sim_finger_role(row, expected$finger[i])
    expect_equal(got, expected$role[i], label = sprintf("%s, finger %s", expected$grasp[i], expected$finger[i]))
  }
  expect_equal(simulator_params()$aperture_scale[["Tripod Variation"]], 0.8)
  # a type without an adjustment is exactly its roles' angles
  built <- sim_build_postures()
  r <- sim_default_roles()
  expect_equal(built$postures["Medium Wrap", "PIP3"], r$finger["wrap", "PIP"])
  expect_equal(built$postures["Medium Wrap", "MCP5"], r$finger["wrap", "MCP"] + r$finger_mcp_offset[["5"]])
  # an adjustment adds its delta
  adj <- sim_default_adjustments()
  d <- adj$delta[adj$id == 2 & adj$joint == "PIP"]
  expect_equal(built$postures["Small Diameter", "PIP4"], r$finger["wrap", "PIP"] + d)
  # object size acts on the object-holding fingers only
  mask <- sim_build_object_mask()
  expect_equal(unname(mask["Index Finger Extension", c("MCP2", "PIP2", "MCP3")]), c(0, 0, 1))
  expect_equal(unname(mask["Palmar Pinch", c("MCP2", "MCP3")]), c(1, 0))
})
