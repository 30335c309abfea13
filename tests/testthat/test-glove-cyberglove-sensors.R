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
