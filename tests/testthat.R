library(testthat)
library(handmotion)

test_check("handmotion")
