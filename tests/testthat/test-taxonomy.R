# The data sets R/taxonomy.R documents have the shape its @format says.

test_that("feix_taxonomy and hust_dofs have the documented rows and columns", {
  expect_identical(dim(feix_taxonomy), c(33L, 8L))
  expect_identical(names(feix_taxonomy),
                   c("id", "name", "class", "opposition", "vf1", "vf2", "vf3", "thumb"))
  expect_identical(sort(feix_taxonomy$id), 1:33)
  expect_identical(nrow(hust_dofs), 16L)
  expect_identical(names(hust_dofs), c("index", "name", "finger", "joint", "motion"))
  expect_identical(hust_dofs$index, 1:16)
  expect_true("ABD1" %in% hust_dofs$name)
})

test_that("thesis_results holds every documented table", {
  expect_true(all(c("table_5_1", "table_5_2", "table_5_6_diagonal", "table_5_7", "table_5_8_diagonal",
                    "table_5_6_cells", "table_5_8_cells", "table_5_3_claims", "accuracy", "source")
                  %in% names(thesis_results)))
})
