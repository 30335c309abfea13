# The bad-input suite: one row per bad input -- the call and the specific
# class it must raise -- across every reader, writer, constructor, fit,
# generate, classify/predict, kinematics, BVH, skeleton, hand-over and 3D
# entry point. Every row must raise its handmotion_error_* class, and that
# class must sit in one family of the hierarchy (?handmotion_errors); the
# messages users read are snapshot-tested (_snaps/bad-input-table.md). A row
# that fails with a generic R error means the function needs fixing, not the
# row.

# The objects the calls work on, built once. Files are written to a fixed
# relative folder so that the messages (which name them) are reproducible.
bad_input_fixtures <- function(dir) {
  # (inside the test environment, which sees the namespace: several rows call
  # internal functions, which R CMD check does not attach as load_all() does)
  e <- new.env(parent = environment())
  local(envir = e, {
    g <- simulate_grasps(subjects = 3, grasps = 1:3, objects = 1, trials = 2, seed = 1)
    m <- suppressWarnings(fit_grasp_model(g, grasp = 1, seed = 1))
    ms <- suppressWarnings(fit_grasp_models(g, seed = 1))
    clf <- fit_grasp_classifier(g)
    ho <- fit_handover(g, n_markers = 3, neighbours = 40)
    q <- forward_kinematics(g[1], markers = ho$markers)[[1]]
    mk <- do.call(rbind, forward_kinematics(g[1:2], markers = TRUE))
    ang <- matrix(10, 3, 16, dimnames = list(NULL, hust_dofs$name))
    gnan <- g
    gnan$recordings[[2]][3, 4] <- NaN
    gdof <- g
    gdof$dofs[1] <- "XX"
    gdof$recordings <- lapply(gdof$recordings, function(r) {
      colnames(r)[1] <- "XX"
      r
    })
    unlabelled <- g
    unlabelled$meta$grasp[] <- NA
    gd <- graspdb14_fixture_grasps()
    lf <- fit_grasp_classifier(g, method = "last_frame", ncomp = 2)
  })
  files <- file.path(dir, c("gdb", "hust", "empty", "allbad", "binman", "folders"))
  for (f in files) dir.create(f)
  e$gdb_file <- write_graspdb14(e$gd[1], "gdb")
  e$hust_files <- write_hust(e$g[1:3], "hust")
  writeBin(as.raw(0:255), "binary.txt")
  writeBin(as.raw(0:255), "01_ex01-rad-002-grasp-su09.txt")
  writeBin(as.raw(0:255), "binary.bvh")
  writeBin(as.raw(0:255), "binary.xmlskel")
  writeLines("not motion", "unknown-name.txt")
  writeLines("a file, not a folder", "a-file")
  writeBin(as.raw(0:255), file.path("allbad", basename(e$gdb_file)))
  writeLines("x", file.path("allbad", "b.txt"))
  write_hust(e$g[1:2], "binman")
  writeBin(as.raw(c(0x80, 0xff, 0x00, 0x41)), file.path("binman", "manifest.csv"))
  dir.create(file.path("folders", "a.csv"))
  bvh <- write_bvh(e$g, "good.bvh")
  writeLines(utils::head(readLines(bvh), -3), "cut.bvh")
  e
}

bad_input_cases <- function() {
  rows <- list(
    # --- readers
    list("read_graspdb14: missing path", quote(read_graspdb14("no-such-file.txt")), "file_not_found"),
    list("read_graspdb14: path not a string", quote(read_graspdb14(42)), "bad_input"),
    list("read_graspdb14: misspelt datatype", quote(read_graspdb14("gdb", datatype = "radians")), "bad_input"),
    list("read_graspdb14: misspelt truncated", quote(read_graspdb14("gdb", truncated = "dorp")), "bad_input"),
    list("read_graspdb14: binary file", quote(read_graspdb14("01_ex01-rad-002-grasp-su09.txt")), "not_text"),
    list("read_graspdb14: unknown file name", quote(read_graspdb14("unknown-name.txt")), "unknown_file_name"),
    list("read_graspdb14: empty folder", quote(read_graspdb14("empty")), "no_files"),
    list("read_graspdb14: every file bad", quote(suppressWarnings(read_graspdb14("allbad"))), "no_files"),
    list("read_hust: missing path", quote(read_hust("no-such-file.csv")), "file_not_found"),
    list("read_hust: binary file", quote(read_hust("binary.txt")), "not_text"),
    list("read_hust: manifest and pattern", quote(read_hust("hust", manifest = "m.csv", pattern = "x")), "bad_input"),
    list("read_hust: binary manifest", quote(read_hust("binman")), "not_text"),
    list("read_hust: misspelt truncated", quote(read_hust("hust", truncated = "cut")), "bad_input"),
    list("read_hust: a folder in place of every file", quote(suppressWarnings(read_hust("folders"))), "no_files"),
    list("read_bvh: missing file", quote(read_bvh("no-such.bvh")), "file_not_found"),
    list("read_bvh: binary file", quote(read_bvh("binary.bvh")), "bad_file"),
    list("read_bvh: cut-off motion", quote(read_bvh("cut.bvh")), "bad_file"),
    list("read_skeleton: binary file", quote(read_skeleton("binary.xmlskel")), "bad_skeleton"),
    list("read_skeleton: not a path", quote(read_skeleton(42)), "bad_input"),
    list("read_skeleton: missing file", quote(read_skeleton("no-such.xmlskel")), "file_not_found"),
    list("read_skeleton: misspelt positions", quote(read_skeleton("binary.xmlskel", positions = "abs")), "bad_input"),
    # --- writers
    list("write_hust: negative digits", quote(write_hust(g, "out", digits = -1)), "bad_input"),
    list("write_hust: two separators", quote(write_hust(g, "out", sep = c(",", ";"))), "bad_input"),
    list("write_hust: too few file names", quote(write_hust(g, "out", file_names = "a.csv")), "bad_input"),
    list("write_hust: not grasps", quote(write_hust("a", "out")), "bad_input"),
    list("write_hust: existing files", quote(write_hust(g[1:3], "hust")), "file_exists"),
    list("write_graspdb14: zero digits", quote(write_graspdb14(gd, "out", digits = 0)), "bad_input"),
    list("write_graspdb14: not GraspDB14 sensors", quote(write_graspdb14(g, "out")), "bad_input"),
    list("write_bvh: NaN scale", quote(write_bvh(g, "a.bvh", scale = NaN)), "bad_input"),
    list("write_bvh: zero rate", quote(write_bvh(ang, "a.bvh", rate = 0)), "bad_input"),
    list("write_bvh: two files", quote(write_bvh(g, c("a.bvh", "b.bvh"))), "bad_input"),
    list("write_bvh: recording out of range", quote(write_bvh(g, "a.bvh", recording = 99)), "bad_input"),
    list("write_skeleton: not a skeleton", quote(write_skeleton("x", "s.xmlskel")), "bad_input"),
    list("write_skeleton: a folder for the file", quote(write_skeleton(hand_skeleton(), "empty")), "unwritable_file"),
    list("write_bvh: a folder for the file", quote(write_bvh(g, "empty")), "unwritable_file"),
    list("write_bvh: an existing file", quote(write_bvh(g, "good.bvh")), "file_exists"),
    list("write_bvh: a missing folder", quote(write_bvh(g, file.path("no", "such", "a.bvh"))), "unwritable_file"),
    list("write_hust: a file for the folder", quote(write_hust(g, "a-file")), "unwritable_file"),
    list("read_failures: a number", quote(read_failures(42)), "bad_input"),
    # --- constructors
    list("grasps: NaN value", quote(grasps(list(matrix(c(1, NaN, 3, 4), 2)), dofs = c("a", "b"))), "bad_recording"),
    list("grasps: infinite values", quote(grasps(list(matrix(Inf, 2, 2)), dofs = c("a", "b"))), "bad_recording"),
    list("grasps: factor DoF names", quote(grasps(list(matrix(1:4, 2)), dofs = factor(c("a", "b")))), "bad_input"),
    list("grasps: rate as text", quote(grasps(list(matrix(1, 2, 2)), rate = "50")), "bad_input"),
    list("grasps: negative rate", quote(grasps(list(matrix(1, 2, 2)), rate = -1)), "bad_input"),
    list("grasps: unknown unit", quote(grasps(list(matrix(1, 2, 2)), unit = "furlong")), "bad_input"),
    list("grasps: a list for a matrix", quote(grasps(list(list(1, 2)))), "bad_recording"),
    list("grasps: no recordings", quote(grasps(list())), "bad_input"),
    list("grasps: DoF counts differ", quote(grasps(list(matrix(1, 2, 2), matrix(1, 2, 3)))), "bad_recording"),
    list("grasps: zero frames", quote(grasps(list(matrix(1, 0, 2)))), "bad_recording"),
    list("grasps: NA id", quote(grasps(list(matrix(1, 2, 2), matrix(1, 2, 2)), meta = data.frame(id = c("a", NA)))), "bad_input"),
    list("as_grasps: a number", quote(as_grasps(42)), "bad_input"),
    list("as_grasps: a list of text", quote(as_grasps(list(a = "x"))), "bad_recording"),
    # --- fits
    list("fit_grasp_model: NaN ncomp", quote(fit_grasp_model(g, grasp = 1, ncomp = NaN)), "bad_input"),
    list("fit_grasp_model: factor k", quote(fit_grasp_model(g, grasp = 1, mixture_components = factor(2))), "bad_input"),
    list("fit_grasp_model: negative max_stall", quote(fit_grasp_model(g, grasp = 1, max_stall = -1)), "bad_input"),
    list("fit_grasp_model: keep_data as text", quote(fit_grasp_model(g, grasp = 1, keep_data = "yes")), "bad_input"),
    list("fit_grasp_model: a list for the overlong rule", quote(fit_grasp_model(g, grasp = 1, overlong = list(1))), "bad_input"),
    list("fit_grasp_model: NaN in a recording", quote(fit_grasp_model(gnan, grasp = 1)), "bad_recording"),
    list("fit_grasp_model: no labels", quote(fit_grasp_model(unlabelled)), "no_labels"),
    list("fit_grasp_model: misspelt engine", quote(fit_grasp_model(g, grasp = 1, engine = "fastest")), "bad_input"),
    list("fit_grasp_model: several types", quote(fit_grasp_model(g)), "multiple_grasps"),
    list("fit_grasp_model: too few recordings", quote(fit_grasp_model(g[1:2], ncomp = 2, warping = "linear")), "too_few_recordings"),
    list("fit_grasp_models: no types", quote(fit_grasp_models(g, grasps = integer(0))), "bad_input"),
    list("fit_grasp_models: unknown argument", quote(fit_grasp_models(g, ncmop = 3)), "bad_input"),
    list("fit_grasp_models: ncomp = 0 for every type", quote(fit_grasp_models(g, ncomp = 0)), "bad_input"),
    list("fit_grasp_models: unknown type", quote(fit_grasp_models(g, grasps = "No Such Grasp")), "unknown_grasp"),
    list("fit_grasp_classifier: NaN fraction", quote(fit_grasp_classifier(g, at = c(0.5, NaN))), "bad_input"),
    list("fit_grasp_classifier: fraction above 1", quote(fit_grasp_classifier(g, at = 2)), "bad_input"),
    list("fit_grasp_classifier: misspelt prior", quote(fit_grasp_classifier(g, prior = "uniform")), "bad_input"),
    list("fit_grasp_classifier: not grasps", quote(fit_grasp_classifier("x")), "bad_input"),
    list("fit_grasp_recognizer: no fractions", quote(fit_grasp_recognizer(g, at = numeric(0))), "bad_input"),
    list("fit_grasp_classifier, weighted_fpca: misspelt time", quote(fit_grasp_classifier(g, method = "weighted_fpca", time = "middle")), "bad_input"),
    list("fit_grasp_classifier, weighted_fpca: not grasps", quote(fit_grasp_classifier("x", method = "weighted_fpca")), "bad_input"),
    list("fit_grasp_classifier, last_frame: ncomp = 0", quote(fit_grasp_classifier(g, method = "last_frame", ncomp = 0)), "bad_input"),
    list("fit_grasp_classifier, last_frame: unknown type", quote(fit_grasp_classifier(g, method = "last_frame", grasps = "No Such Grasp")), "unknown_grasp"),
    list("fit_frame_pca_model: frame_ncomp = 0", quote(fit_frame_pca_model(g, frame_ncomp = 0)), "bad_input"),
    list("evaluate_loso: seed as text", quote(evaluate_loso(g, seed = "a")), "bad_input"),
    list("evaluate_loso: NA in_sample", quote(evaluate_loso(g, in_sample = NA)), "bad_input"),
    list("evaluate_loso: fit_args as text", quote(evaluate_loso(g, fit_args = "ncomp")), "bad_input"),
    list("evaluate_loso: unknown subject", quote(evaluate_loso(g, subjects = "S99")), "bad_input"),
    list("evaluate_generation: zero reps", quote(evaluate_generation(ms, g, g, reps = 0)), "bad_input"),
    list("select_markers, search: negative max_frames", quote(select_markers(g, n = 2, method = "search", max_frames = -5)), "bad_input"),
    list("select_markers, search: unknown holdout column", quote(select_markers(g, n = 2, method = "search", holdout = "colour")), "bad_input"),
    list("fit_handover: zero ridge", quote(fit_handover(g, n_markers = 3, ridge = 0)), "bad_input"),
    list("fit_handover: unknown marker", quote(fit_handover(g, markers = c("index_tip", "foo"))), "bad_markers"),
    list("fit_handover: more markers than there are", quote(fit_handover(g, n_markers = 14)), "bad_markers"),
    list("fit_handover: too few neighbours", quote(fit_handover(g, n_markers = 3, neighbours = 2)), "bad_input"),
    list("fit_handover: NA smooth", quote(fit_handover(g, n_markers = 3, smooth = NA)), "bad_input"),
    list("fit_handover: unknown argument", quote(fit_handover(g, n_markers = 3, foo = 2)), "bad_input"),
    list("fit_handover: three frames", quote(fit_handover(grasps(list(g$recordings[[1]][1:3, ]), dofs = g$dofs), n_markers = 3)), "reference_too_small"),
    # --- generate
    list("generate: a billion grasps", quote(generate(m, n = 1e9)), "bad_input"),
    list("generate: NaN n", quote(generate(m, n = NaN)), "bad_input"),
    list("generate: factor n", quote(generate(m, n = factor(2))), "bad_input"),
    list("generate: infinite seed", quote(generate(m, n = 2, seed = Inf)), "bad_input"),
    list("generate: two seeds", quote(generate(m, n = 2, seed = c(1, 2))), "bad_input"),
    list("generate: unknown type", quote(generate(ms, grasps = "No Such Grasp", n = 1)), "unknown_grasp"),
    list("generate: no type", quote(generate(ms, grasps = character(0), n = 1)), "bad_input"),
    list("generate: a copula model without its copula", quote(generate({x <- suppressWarnings(fit_grasp_model(g, grasp = 1, seed = 1, dependence = "copula")); x$dependence$copula <- NULL; x}, n = 2)), "bad_model"),
    list("generate: negative chunk", quote(generate(m, n = 2, chunk = -1)), "bad_input"),
    list("generate: a callback that is not a function", quote(generate(m, n = 2, callback = "f")), "bad_input"),
    list("generate: unknown argument", quote(generate(m, n = 2, sead = 1)), "bad_input"),
    # --- classify / predict
    list("classify: text for recordings", quote(classify(ms, "not grasps")), "bad_input"),
    list("classify: two methods", quote(classify(ms, g, method = c("fpca", "last_frame"))), "bad_input"),
    list("classify: other DoFs", quote(classify(ms, gdof)), "bad_input"),
    list("classify: recordings for models", quote(classify(g, g)), "bad_input"),
    list("classify: unknown argument", quote(classify(ms, g, foo = 1)), "bad_input"),
    list("classify: text for models", quote(classify("x", g)), "bad_input"),
    list("predict: a number for new_data", quote(predict(clf, 42)), "bad_input"),
    list("predict: an unnamed matrix for a last-frame model", quote(predict(lf, matrix(1, 2, 16))), "bad_input"),
    list("predict: unknown argument", quote(predict(ms, g, foo = 1)), "bad_input"),
    list("project: a model changed after fitting", quote(project({x <- m; x$fpca[[1]]$mean <- x$fpca[[1]]$mean[1:3]; x}, g)), "bad_model"),
    list("project: a model set with a changed model", quote(project({x <- ms; x[[2]]$fpca[[1]]$components <- x[[2]]$fpca[[1]]$components[, 1]; x}, g)), "bad_model"),
    list("as_grasp_confusion: text", quote(as_grasp_confusion("x")), "bad_input"),
    list("thesis_table 5.3: text", quote(thesis_table("5.3", classification = "x")), "bad_input"),
    list("project: text for recordings", quote(project(m, "x")), "bad_input"),
    list("predict: a single model (not a classifier)", quote(predict(m, g)), "bad_input"),
    list("predict: an unknown type", quote(predict(ms, g, type = "raw")), "bad_input"),
    # --- kinematics
    list("forward_kinematics: NaN angles", quote(forward_kinematics(ang * NaN)), "bad_recording"),
    list("forward_kinematics: no frames", quote(forward_kinematics(ang[0, ])), "bad_recording"),
    list("forward_kinematics: a list", quote(forward_kinematics(list(1, 2))), "bad_input"),
    list("forward_kinematics: frame out of range", quote(forward_kinematics(ang, frames = 100)), "bad_input"),
    list("forward_kinematics: a list for the skeleton", quote(forward_kinematics(ang, skeleton = list())), "bad_input"),
    list("forward_kinematics: repeated DoF", quote(forward_kinematics(ang[, c(1, 1:15)])), "bad_input"),
    list("forward_kinematics: two units", quote(forward_kinematics(ang, unit = c("deg", "rad"))), "bad_input"),
    list("forward_kinematics: misspelt mode", quote(forward_kinematics(ang, mode = "ful")), "bad_input"),
    list("autoplot hand: frame out of range", quote(ggplot2::autoplot(g, type = "hand", frame = 1e6)), "bad_input"),
    list("forward_kinematics markers: three unnamed columns", quote(forward_kinematics(matrix(1, 2, 3), markers = TRUE)), "bad_input"),
    list("markers_from_angles: NA forearm", quote(markers_from_angles(g, forearm = NA)), "bad_input"),
    list("forward_kinematics: unknown joint to deactivate", quote(forward_kinematics(g, deactivate = "NoSuchJoint")), "bad_input"),
    list("clamp_to_limits: text", quote(clamp_to_limits(matrix("a", 2, 16, dimnames = list(NULL, hust_dofs$name)))), "bad_input"),
    # --- hand-over
    list("select_markers, ranked: text", quote(select_markers("a", 3)), "bad_input"),
    list("select_markers, ranked: matrices with other columns", quote(select_markers(list(mk, mk[, 1:6]), 3)), "bad_markers"),
    list("select_markers, ranked: NaN coordinate", quote(select_markers({x <- mk; x[3, 4] <- NaN; x}, 3)), "bad_markers"),
    list("select_markers, ranked: fractional n_components", quote(select_markers(mk, 3, weighting = "equal", n_components = 2.5)), "bad_input"),
    list("select_markers, ranked: unknown marker column", quote(select_markers({x <- mk; colnames(x)[1:3] <- c("foo.x", "foo.y", "foo.z"); x}, 3)), "bad_markers"),
    list("select_markers, ranked: broken triple", quote(select_markers({x <- mk; colnames(x)[2] <- "foo"; x}, 3)), "bad_markers"),
    list("select_markers, ranked: one frame", quote(select_markers(mk[1, , drop = FALSE], 3)), "reference_too_small"),
    list("select_markers: n = 0", quote(select_markers(mk, 0)), "bad_markers"),
    list("select_markers: fractional n", quote(select_markers(mk, 2.5)), "bad_markers"),
    list("predict handover: extra argument", quote(predict(ho, q, k = 3)), "bad_input"),
    list("predict handover: unnamed columns", quote(predict(ho, unname(q))), "bad_markers"),
    list("predict handover: missing marker", quote(predict(ho, q[, 1:6])), "bad_markers"),
    list("predict handover: infinite coordinate", quote(predict(ho, {x <- q; x[2, 2] <- Inf; x})), "bad_markers"),
    list("predict handover: frame without markers", quote(predict(ho, {x <- q; x[2, ] <- NA; x})), "occluded"),
    list("predict handover: empty list", quote(predict(ho, list())), "bad_input"),
    list("handover_error: text", quote(handover_error("a", g)), "bad_input"),
    list("handover_error: other recordings", quote(handover_error(g, g[1])), "bad_input"),
    list("handover_error: misspelt by", quote(handover_error(g, g, by = "dof2")), "bad_input"),
    list("handover_error: other unit", quote(handover_error(g, {h <- g; h$unit <- "rad"; h})), "bad_input"),
    # --- 3D hands
    list("hand_3d: negative speed", quote(hand_3d(g, speed = -1)), "bad_input"),
    list("hand_3d: recording out of range", quote(hand_3d(g, recording = 999)), "bad_input"),
    list("hand_3d: misspelt layout", quote(hand_3d(g, layout = "stacked")), "bad_input"),
    list("hand_3d: text", quote(hand_3d("x")), "bad_input"),
    list("hand_3d: zero rate", quote(hand_3d(g[1], rate = 0)), "bad_input"),
    list("hand_3d: unknown argument", quote(hand_3d(g[1], foo = 1)), "bad_input"),
    list("hand_3d: a unit through ...", quote(hand_3d(g[1], unit = "rad")), "bad_input"),
    list("plot_pose_grid: no recordings per group", quote(plot_pose_grid(g, per_group = 0)), "bad_input"),
    list("plot_frame_counts: negative bins", quote(plot_frame_counts(g, binwidth = -1)), "bad_input"),
    # --- simulation, alignment and the rest
    list("simulate_grasps: factor subjects", quote(simulate_grasps(subjects = factor(3))), "bad_input"),
    list("simulate_grasps: infinite trials", quote(simulate_grasps(trials = Inf)), "bad_input"),
    list("simulate_grasps: NaN rate", quote(simulate_grasps(rate = NaN)), "bad_input"),
    list("simulate_grasps: a list of types", quote(simulate_grasps(grasps = list(1, 2))), "bad_input"),
    list("align_recordings: a billion frames", quote(align_recordings(g, target_length = 1e9)), "bad_input"),
    list("align_recordings: text recording", quote(align_recordings(list(a = matrix(1:6, 3), b = "x"))), "bad_input"),
    list("find_overlong: infinite count", quote(find_overlong(c(10, Inf, 12))), "bad_input"),
    list("find_overlong: text", quote(find_overlong(c("10", "12"))), "bad_input"),
    list("fit_grasp_model: negative over-long multiple", quote(fit_grasp_model(g, grasp = 1, overlong = c(iqr_mult = -1, median_mult = 1.5))), "bad_input"),
    list("segment_by_switch: negative min_frames", quote(segment_by_switch(g, min_frames = -1)), "bad_input"),
    list("grasp_confusion: lengths differ", quote(grasp_confusion(c("Tripod", "Ring"), "Tripod")), "bad_input"),
    list("graspdb14_to_hust: a number", quote(graspdb14_to_hust(42)), "bad_input"),
    list("fit_grasp_classifier: misspelt method", quote(fit_grasp_classifier(g, method = "lda")), "bad_input"),
    list("fit_grasp_classifier: argument of another method", quote(fit_grasp_classifier(g, ncomp = 2)), "bad_input"),
    list("handover_error, markers: no reference", quote(handover_error(g, by = "markers")), "bad_input"),
    list("handover_error, markers: unknown argument", quote(handover_error(g, by = "markers", reference = g, kk = 1)), "bad_input"),
    list("handover_error: fitting argument without markers", quote(handover_error(g, g, neighbours = 8)), "bad_input")
  )
  data.frame(label = vapply(rows, `[[`, "", 1), expr = I(lapply(rows, `[[`, 2)),
             class = vapply(rows, `[[`, "", 3), stringsAsFactors = FALSE)
}

families <- paste0("handmotion_error_", c("bad_input", "bad_file", "fit_failed"))

# Evaluate one case by its label (so the snapshot shows the label).
run_bad_input <- function(label) {
  i <- match(label, bad_cases$label)
  eval(bad_cases$expr[[i]], bad_env)
}

withr::local_dir(withr::local_tempdir())
bad_env <- bad_input_fixtures(".")
bad_cases <- bad_input_cases()

test_that("the table is large and has one row per label", {
  expect_gte(nrow(bad_cases), 80L)
  expect_false(anyDuplicated(bad_cases$label) > 0L)
})

test_that("every bad input raises its class, in one family of the hierarchy", {
  for (i in seq_len(nrow(bad_cases))) {
    cnd <- tryCatch(suppressWarnings(run_bad_input(bad_cases$label[i])), error = function(e) e)
    expected <- paste0("handmotion_error_", bad_cases$class[i])
    expect(inherits(cnd, expected),
           sprintf("%s: expected <%s>, got %s", bad_cases$label[i], expected,
                   if (inherits(cnd, "condition")) paste0("<", class(cnd)[1], "> ", conditionMessage(cnd))
                   else "a result"))
    expect(sum(families %in% class(cnd)) == 1L,
           sprintf("%s: not in exactly one family (%s)", bad_cases$label[i], paste(class(cnd), collapse = "/")))
  }
})

test_that("the messages name what is wrong", {
  for (label in bad_cases$label) {
    eval(bquote(expect_snapshot(error = TRUE, suppressWarnings(run_bad_input(.(label))))))
  }
})
