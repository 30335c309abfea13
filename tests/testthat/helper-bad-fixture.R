bad_fixture <- local({
  cache <- NULL
  function() {
    if (is.null(cache)) {
      g <- simulate_grasps(subjects = 3, grasps = 1:3, objects = 1, trials = 2, seed = 1)
      cache <<- list(g = g, m = suppressWarnings(fit_grasp_model(g, grasp = 1, seed = 1)),
                     ms = suppressWarnings(fit_grasp_models(g, seed = 1)),
                     clf = fit_grasp_classifier(g))
    }
    cache
  }
})
