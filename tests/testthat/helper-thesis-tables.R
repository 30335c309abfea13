small_design <- local({
  cache <- NULL
  function() {
    if (is.null(cache)) {
      g <- simulate_grasps(subjects = 4, grasps = c(3, 9, 17), objects = 2, trials = 2, seed = 1)
      ms <- fit_grasp_models(g, seed = 1)
      cl <- classify(ms, g)
      lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 3)
      cl_lf <- classify(lf, g)
      ev <- evaluate_loso(g, method = "last_frame", fit_args = list(ncomp = 3), folds = 2, in_sample = FALSE)
      cache <<- list(g = g, ms = ms, cl = cl, lf = lf, cl_lf = cl_lf, ev = ev)
    }
    cache
  }
})
