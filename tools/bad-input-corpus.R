# A corpus of bad inputs run through the exported API (issue 34, item 8).
#
#   Rscript tools/bad-input-corpus.R [results.rds]
#
# Each case is a call that must not succeed silently: it should raise a
# classed handmotion error whose message names the culprit (the argument,
# recording, grasp type, file or line), or handle the input in a documented
# way with a classed handmotion warning that names it. Every case is
# recorded as one of
#   classed_named    handmotion_error, message names the culprit
#   classed_unnamed  handmotion_error, culprit not in the message
#   warning_named    result with a handmotion_warning naming the culprit
#   warning_unnamed  result with a handmotion_warning not naming it
#   silent           a result with no handmotion warning
#   base_error       an error that is not a handmotion_error
#   crash            the R process died (each case runs in a worker that is
#                    restarted after a crash)
# and a summary table and the list of cases that are not classed_named /
# warning_named are printed. The cases use only exported functions.
#
# The worker loads the package from the source tree (pkgload) when run from
# it, else the installed copy.

args <- commandArgs(trailingOnly = TRUE)
script <- normalizePath(sub("^--file=", "", grep("^--file=", commandArgs(), value = TRUE)[1]))

load_handmotion <- function() {
  if (file.exists("DESCRIPTION") && any(grepl("^Package: handmotion", readLines("DESCRIPTION")))) {
    suppressMessages(pkgload::load_all(".", quiet = TRUE, export_all = FALSE))
  } else {
    suppressMessages(library(handmotion))
  }
  library(ggplot2)
}

# ---------------------------------------------------------------- fixtures
# Built once per worker, in a temporary folder (the working directory).
corpus_fixtures <- function() {
  e <- new.env()
  local(envir = e, {
    g <- simulate_grasps(subjects = 3, grasps = 1:3, objects = 1, trials = 2, seed = 1)
    id2 <- g$meta$id[2]
    m <- suppressWarnings(fit_grasp_model(g, grasp = 1, seed = 1))
    ms <- suppressWarnings(fit_grasp_models(g, seed = 1))
    clf <- fit_grasp_classifier(g)
    wf <- suppressWarnings(fit_grasp_classifier(g, method = "weighted_fpca"))
    lf <- suppressWarnings(fit_grasp_classifier(g, method = "last_frame"))
    rec <- suppressWarnings(fit_grasp_recognizer(g))
    ho <- suppressWarnings(fit_handover(g, n_markers = 3))
    q <- forward_kinematics(g[1], markers = ho$markers)[[1]]
    mk <- do.call(rbind, forward_kinematics(g[1:2], markers = TRUE))
    ang <- g$recordings[[1]]
    sk <- hand_skeleton()
    raw <- simulate_grasps(subjects = 1, grasps = c(bottle = 3, pen = 20), objects = 1, trials = 2,
                           glove = "resistive", rest = 1, hold = 1, seed = 1)
    # files
    dir.create("hust")
    write_hust(g[1:4], "hust")
    hust_files <- list.files("hust", "\\.csv$", full.names = TRUE)
    hust_files <- hust_files[basename(hust_files) != "manifest.csv"]
    hust_lines <- readLines(hust_files[1])
    gdb_dir <- system.file("extdata", "graspdb14", package = "handmotion")
    gdb_file <- file.path(gdb_dir, "04_ex01-rad-001-grasp-su02.txt")
    gdb_lines <- readLines(gdb_file)
    bvh <- write_bvh(g[1], "good.bvh")
    bvh_lines <- readLines(bvh)
    skel <- write_skeleton(sk, "good.xmlskel")
    skel_lines <- readLines(skel)
    dir.create("empty")
  })
  e
}

# A file of `lines` named `name` (in the working directory); returns its name.
put <- function(name, lines) {
  writeLines(lines, name)
  name
}

# ---------------------------------------------------------------- cases
# Each case: label, group (the issue's class), expression, culprit (regular
# expressions, any of which the message must match, case-insensitively).
corpus_cases <- function(e) {
  cases <- list()
  add <- function(group, label, expr, culprit) {
    cases[[length(cases) + 1L]] <<- list(group = group, label = label, expr = expr, culprit = culprit)
  }
  id2 <- e$id2

  # --- grasps objects edited after construction, through every verb -------
  edits <- list(
    "NaN in a recording" = list(quote({x <- g; x$recordings[[2]][3, 4] <- NaN; x}), id2),
    "Inf in a recording" = list(quote({x <- g; x$recordings[[2]][5, 1] <- Inf; x}), id2),
    "NA in a recording" = list(quote({x <- g; x$recordings[[2]][1, 2] <- NA; x}), id2),
    "text recording" = list(quote({x <- g; x$recordings[[2]] <- matrix("a", 3, 16, dimnames = list(NULL, g$dofs)); x}), id2),
    "recording lost a column" = list(quote({x <- g; x$recordings[[2]] <- x$recordings[[2]][, -1]; x}), id2),
    "recording with no frames" = list(quote({x <- g; x$recordings[[2]] <- x$recordings[[2]][0, ]; x}), id2),
    "recordings and meta differ in length" = list(quote({x <- g; x$recordings[[1]] <- NULL; x}), c("meta", "recordings")),
    "meta lost a row" = list(quote({x <- g; x$meta <- x$meta[-1, ]; x}), c("meta", "recordings")),
    "duplicated ids" = list(quote({x <- g; x$meta$id[2] <- x$meta$id[1]; x}), c("\\bids?\\b", e$g$meta$id[1])),
    "rate set to 0" = list(quote({x <- g; x$rate <- 0; x}), "rate"),
    "rate set to NaN" = list(quote({x <- g; x$rate <- NaN; x}), "rate"),
    "unit misspelt" = list(quote({x <- g; x$unit <- "degrees"; x}), "unit"),
    "dofs shortened" = list(quote({x <- g; x$dofs <- x$dofs[-1]; x}), c("dofs", "DoF")),
    "dofs renamed only in the field" = list(quote({x <- g; x$dofs[1] <- "XX"; x}), c("dofs", "DoF", "XX")),
    "meta without grasp column" = list(quote({x <- g; x$meta$grasp <- NULL; x}), c("grasp", "meta")),
    "n_frames wrong" = list(quote({x <- g; x$meta$n_frames[2] <- 999L; x}), c("n_frames", id2)),
    "class lost" = list(quote(unclass(g)), c("\\bx\\b", "grasps", "list"))
  )
  verbs <- list(
    "fit_grasp_model" = quote(fit_grasp_model(BAD, grasp = 1)),
    "fit_grasp_models" = quote(fit_grasp_models(BAD)),
    "fit_grasp_classifier" = quote(fit_grasp_classifier(BAD)),
    "fit_grasp_classifier weighted" = quote(fit_grasp_classifier(BAD, method = "weighted_fpca")),
    "fit_grasp_classifier last_frame" = quote(fit_grasp_classifier(BAD, method = "last_frame")),
    "fit_grasp_recognizer" = quote(fit_grasp_recognizer(BAD)),
    "classify" = quote(classify(ms, BAD)),
    "predict classifier" = quote(predict(clf, BAD)),
    "project" = quote(project(m, BAD)),
    "fit_handover" = quote(fit_handover(BAD, n_markers = 3)),
    "forward_kinematics" = quote(forward_kinematics(BAD)),
    "write_hust" = quote(write_hust(BAD, tempfile("w"))),
    "write_bvh" = quote(write_bvh(BAD, tempfile(fileext = ".bvh"))),
    "autoplot" = quote(ggplot2::ggplot_build(autoplot(BAD))),
    "summary" = quote(summary(BAD)),
    "as.data.frame" = quote(as.data.frame(BAD)),
    "find_motion" = quote(find_motion(BAD)),
    "handover_error" = quote(handover_error(g, BAD)),
    "select_markers" = quote(select_markers(BAD, 3)),
    "evaluate_loso" = quote(evaluate_loso(BAD, folds = 2))
  )
  # every edit with a selection of verbs; the cheap verbs with every edit
  for (en in names(edits)) {
    vs <- names(verbs)
    # an object whose class was stripped is a plain list to base R's and
    # ggplot2's generics: not the package's to check
    if (en == "class lost") vs <- setdiff(vs, c("autoplot", "summary", "as.data.frame"))
    for (vn in vs) {
      expr <- do.call(substitute, list(verbs[[vn]], list(BAD = edits[[en]][[1]])))
      add("edited grasps", sprintf("%s: %s", vn, en), expr, edits[[en]][[2]])
    }
  }

  # --- fitted models edited after fitting ----------------------------------
  medits <- list(
    "fpca dropped" = list(quote({x <- m; x$fpca <- NULL; x}), "fpca"),
    "one fpca dropped" = list(quote({x <- m; x$fpca[[1]] <- NULL; x}), "fpca"),
    "gmm dropped" = list(quote({x <- m; x$gmm <- NULL; x}), "gmm"),
    "gmm weights NaN" = list(quote({x <- m; x$gmm[[1]]$weights[] <- NaN; x}), c("gmm", "weight")),
    "fpca mean shortened" = list(quote({x <- m; x$fpca[[1]]$mean <- x$fpca[[1]]$mean[1:3]; x}), c("fpca", "mean")),
    "fpca mean NaN" = list(quote({x <- m; x$fpca[[1]]$mean[2] <- NaN; x}), c("fpca", "mean")),
    "dofs dropped" = list(quote({x <- m; x$dofs <- NULL; x}), "dofs"),
    "dofs shortened" = list(quote({x <- m; x$dofs <- x$dofs[-1]; x}), "dofs"),
    "target_length negative" = list(quote({x <- m; x$target_length <- -5L; x}), "target_length"),
    "warp dropped" = list(quote({x <- m; x$warp <- NULL; x}), "warp"),
    "argvals dropped" = list(quote({x <- m; x$argvals <- NULL; x}), "argvals"),
    "rate NaN" = list(quote({x <- m; x$rate <- NaN; x}), "rate"),
    "replaced by a list" = list(quote(unclass(m)), c("object", "\\bx\\b", "list")),
    # (a model without its stored sampler rebuilds it: not a bad input)
    "sampler dropped" = NULL
  )
  mverbs <- list(
    "generate" = quote(generate(BAD, n = 2)),
    "project" = quote(project(BAD, g)),
    "classify" = quote(classify({s <- ms; s[[1]] <- BAD; s}, g)),
    "summary" = quote(summary(BAD)),
    "autoplot" = quote(ggplot2::ggplot_build(autoplot(BAD)))
  )
  medits <- Filter(Negate(is.null), medits)
  for (en in names(medits)) for (vn in names(mverbs)) {
    # (a model whose class was stripped is a plain list to base R's summary() and ggplot2's autoplot())
    if (en == "replaced by a list" && vn %in% c("summary", "autoplot")) next
    expr <- do.call(substitute, list(mverbs[[vn]], list(BAD = medits[[en]][[1]])))
    # the error names the argument (field `argument`) and the part
    add("edited model", sprintf("%s: model %s", vn, en), expr, c(medits[[en]][[2]], "^(x|object|models)$"))
  }
  add("edited model", "generate: model set with a text element", quote(generate({s <- ms; s[[2]] <- "x"; s}, n = 1)), c("x\\[\\[2\\]\\]", "Small Diameter", "models?"))
  add("edited model", "classify: model set with a text element", quote(classify({s <- unclass(ms); s$models[[2]] <- "x"; class(s) <- class(ms); s}, g)), c("\\[\\[2\\]\\]", "Small Diameter", "models?"))
  add("edited model", "classify: model set with NaN temperature", quote(classify({s <- ms; s$temperature <- NaN; s}, g)), c("temperature"))
  add("edited model", "predict: model set with NaN temperature", quote(predict({s <- ms; s$temperature <- NaN; s}, g, type = "prob")), c("temperature"))
  add("edited model", "summary: model set with a text element", quote(summary({s <- unclass(ms); s$models[[2]] <- "x"; class(s) <- class(ms); s})), c("\\[\\[2\\]\\]", "Small Diameter", "object"))
  cedits <- list(
    "fit dropped" = list(quote({x <- clf; x$fit <- NULL; x}), "fit"),
    "classes shortened" = list(quote({x <- clf; x$classes <- x$classes[-1]; x}), "classes"),
    "dofs dropped" = list(quote({x <- clf; x$dofs <- NULL; x}), "dofs"),
    "at NaN" = list(quote({x <- clf; x$at[2] <- NaN; x}), "\\bat\\b"),
    "temperature negative" = list(quote({x <- clf; x$temperature <- -1; x}), "temperature")
  )
  for (en in names(cedits)) {
    add("edited model", sprintf("predict: classifier %s", en),
        do.call(substitute, list(quote(predict(BAD, g)), list(BAD = cedits[[en]][[1]]))), cedits[[en]][[2]])
  }
  add("edited model", "predict: last-frame classifier emptied", quote(predict({x <- lf; x[] <- lapply(unclass(x), function(p) NULL); x}, g)), c("object", "last"))
  add("edited model", "predict: weighted fpca lost its parts", quote(predict({x <- wf; x[[1]] <- NULL; x}, g)), c("object", names(unclass(e$wf))[1]))
  add("edited model", "predict: recognizer lost its classifier", quote(predict({x <- rec; x[[1]] <- NULL; x}, g)), c("object", names(unclass(e$rec))[1]))
  add("edited model", "start_recognition: recognizer lost its parts", quote(start_recognition({x <- rec; x[[1]] <- NULL; x})), c("recognizer", names(unclass(e$rec))[1]))
  add("edited model", "predict: handover without markers", quote(predict({x <- ho; x$markers <- NULL; x}, q)), c("markers", "object"))
  add("edited model", "predict: handover with NaN in its reference", quote(predict({x <- ho; i <- which(vapply(unclass(x), is.matrix, TRUE))[1]; x[[i]][1, 1] <- NaN; x}, q)), c("object", names(unclass(e$ho))[which(vapply(unclass(e$ho), is.matrix, TRUE))[1]]))

  # --- empty inputs ---------------------------------------------------------
  empty <- quote(g[integer(0)])
  # (summary() and as.data.frame() of an empty selection are an empty summary and table: good input)
  for (vn in setdiff(names(verbs), c("handover_error", "summary", "as.data.frame"))) {
    add("empty", paste0(vn, ": no recordings"), do.call(substitute, list(verbs[[vn]], list(BAD = empty))),
        c("no recordings", "empty", "\\bx\\b", "new_data", "reference"))
  }
  add("empty", "grasps: empty list", quote(grasps(list())), "recordings")
  add("empty", "as_grasps: empty data frame", quote(as_grasps(data.frame())), c("\\bx\\b", "empty"))
  add("empty", "as_grasps: empty list", quote(as_grasps(list())), c("\\bx\\b", "empty", "recordings"))
  add("empty", "grasp_confusion: empty vectors", quote(grasp_confusion(character(0), character(0))), c("truth", "predicted", "empty"))
  add("empty", "glove_profile: empty data frame", quote(glove_profile(data.frame())), c("\\bx\\b", "channel"))
  add("empty", "glove_profile: empty string", quote(glove_profile("")), c("\\bx\\b", "profile"))
  add("empty", "read_hust: empty folder", quote(read_hust("empty")), c("empty", "no files", "files"))
  add("empty", "read_graspdb14: empty folder", quote(read_graspdb14("empty")), c("empty", "files"))
  add("empty", "read_bvh: empty file", quote(read_bvh(put("empty.bvh", character(0)))), "empty.bvh")
  add("empty", "read_skeleton: empty file", quote(read_skeleton(put("empty.xmlskel", character(0)))), "empty.xmlskel")
  add("empty", "read_hust: empty file", quote(read_hust(put("empty.csv", character(0)))), "empty.csv")
  add("empty", "read_graspdb14: empty file", quote(read_graspdb14(put("01_ex01-rad-002-grasp-su09.txt", character(0)))), "su09")
  add("empty", "select_markers: empty matrix", quote(select_markers(mk[0, ], 3)), c("\\bx\\b", "frame"))
  add("empty", "predict handover: no frames", quote(predict(ho, q[0, ])), c("new_data", "frame"))
  add("empty", "generate: empty model set", quote(generate(ms[integer(0)], n = 1)), c("\\bx\\b", "no models", "empty"))
  add("empty", "classify: empty model set", quote(classify(ms[integer(0)], g)), c("models", "empty"))

  # --- recordings too short to model; types with too few recordings --------
  short <- quote(grasps(lapply(1:12, function(i) g$recordings[[i]][1:2, ]), meta = g$meta[1:12, c("grasp", "subject", "trial")], dofs = g$dofs))
  short1 <- quote({x <- g; x$recordings[[2]] <- x$recordings[[2]][1:2, ]; grasps(x$recordings, meta = x$meta[c("id", "grasp", "subject", "object", "trial")], dofs = x$dofs)})
  # (fit_handover() pools frames, not recordings: short recordings are good input there)
  for (vn in c("fit_grasp_model", "fit_grasp_classifier", "fit_grasp_classifier weighted", "fit_grasp_recognizer")) {
    add("too short", paste0(vn, ": every recording two frames"), do.call(substitute, list(verbs[[vn]], list(BAD = short))),
        c("T01-S01", "frames?", "Large Diameter"))
    add("too short", paste0(vn, ": one recording two frames"), do.call(substitute, list(verbs[[vn]], list(BAD = short1))),
        c(id2, "r2"))
  }
  add("too short", "project: two-frame recordings", do.call(substitute, list(quote(project(m, BAD)), list(BAD = short))), c("T01-S01", "frame"))
  add("too short", "classify: two-frame recordings", do.call(substitute, list(quote(classify(ms, BAD)), list(BAD = short))), c("T01-S01", "frame"))
  add("too short", "fit_grasp_models: one-frame recordings", quote(fit_grasp_models(grasps(lapply(1:18, function(i) g$recordings[[i]][1, , drop = FALSE]), meta = g$meta[c("grasp", "subject", "trial")], dofs = g$dofs))), c("frame", "Large Diameter"))
  few1 <- quote(g[c(1, 7:18)])
  few2 <- quote(g[c(1:2, 7:18)])
  for (nm in c("one", "two")) {
    sel <- if (nm == "one") few1 else few2
    for (vn in c("fit_grasp_models", "fit_grasp_classifier", "fit_grasp_classifier weighted", "fit_grasp_classifier last_frame",
                 "fit_grasp_recognizer", "evaluate_loso")) {
      add("too few recordings", sprintf("%s: a type with %s recording(s)", vn, nm),
          do.call(substitute, list(verbs[[vn]], list(BAD = sel))), "Large Diameter")
    }
    add("too few recordings", sprintf("fit_grasp_model: a type with %s recording(s)", nm),
        do.call(substitute, list(quote(fit_grasp_model(BAD, grasp = 1)), list(BAD = sel))), "Large Diameter")
  }

  # --- malformed HUST files --------------------------------------------------
  hl <- e$hust_lines
  hbad <- list(
    "truncated last line" = c(hl, "1.5,2"),
    "non-numeric field" = {x <- hl; x[3] <- sub("^[^,]*", "abc", x[3]); x},
    "NaN field" = {x <- hl; x[3] <- sub("^[^,]*", "NaN", x[3]); x},
    "Inf field" = {x <- hl; x[4] <- sub("^[^,]*", "Inf", x[4]); x},
    "empty field" = {x <- hl; x[4] <- sub("^[^,]*", "", x[4]); x},
    "too many fields" = {x <- hl; x[2] <- paste0(x[2], ",1,2"); x},
    "garbage header" = c("this is not a header at all", hl),
    "blank lines only" = c("", "", ""),
    "binary junk" = NULL
  )
  for (hn in names(hbad)) {
    fn <- sprintf("s09_g01_o1_t%d.csv", match(hn, names(hbad)))
    if (is.null(hbad[[hn]])) {
      add("malformed file", paste0("read_hust: ", hn), bquote({writeBin(as.raw(c(0:255)), .(fn)); read_hust(.(fn))}), fn)
    } else {
      add("malformed file", paste0("read_hust: ", hn), bquote(read_hust(put(.(fn), .(hbad[[hn]])))), fn)
    }
  }
  add("malformed file", "read_hust: manifest with unknown file", quote({dir.create("hm"); file.copy("hust", "hm", recursive = TRUE); d <- "hm/hust"; mf <- utils::read.csv(file.path(d, "manifest.csv")); mf$file[1] <- "nope.csv"; utils::write.csv(mf, file.path(d, "manifest.csv"), row.names = FALSE); read_hust(d)}), c("nope.csv", "manifest"))
  add("malformed file", "read_hust: manifest without file column", quote({dir.create("hm2"); file.copy(list.files("hust", full.names = TRUE), "hm2"); mf <- utils::read.csv("hm2/manifest.csv"); mf$file <- NULL; utils::write.csv(mf, "hm2/manifest.csv", row.names = FALSE); read_hust("hm2")}), c("manifest", "file"))
  gl <- e$gdb_lines
  gbad <- list(
    "truncated last line" = c(gl, substr(gl[length(gl)], 1, 12)),
    "non-numeric field" = {x <- gl; x[3] <- sub("^((\\S+\\s+){10})\\S+", "\\1abc", x[3]); x},
    "NaN field" = {x <- gl; x[3] <- sub("^((\\S+\\s+){10})\\S+", "\\1NaN", x[3]); x},
    "Inf field" = {x <- gl; x[3] <- sub("^((\\S+\\s+){10})\\S+", "\\1Inf", x[3]); x},
    "unknown header" = c("garbage header line", gl[-1]),
    "extra field" = {x <- gl; x[3] <- paste(x[3], "1.0"); x}
  )
  for (gn in names(gbad)) {
    fn <- sprintf("01_ex01-rad-002-grasp-su%02d.txt", 40 + match(gn, names(gbad)))
    add("malformed file", paste0("read_graspdb14: ", gn), bquote(read_graspdb14(put(.(fn), .(gbad[[gn]])))), fn)
  }
  bl <- e$bvh_lines
  ft <- grep("^Frame Time", bl)
  nf <- grep("^Frames:", bl)
  ch <- grep("CHANNELS 3", bl)[1]
  off <- grep("OFFSET", bl)[2]
  bbad <- list(
    "Frame Time 0" = {x <- bl; x[ft] <- "Frame Time: 0"; x},
    "negative Frame Time" = {x <- bl; x[ft] <- "Frame Time: -0.02"; x},
    "NaN Frame Time" = {x <- bl; x[ft] <- "Frame Time: NaN"; x},
    "Inf Frame Time" = {x <- bl; x[ft] <- "Frame Time: Inf"; x},
    "text Frame Time" = {x <- bl; x[ft] <- "Frame Time: fast"; x},
    "negative channel count" = {x <- bl; x[ch] <- sub("CHANNELS 3", "CHANNELS -3", x[ch]); x},
    "zero channel count with names" = {x <- bl; x[ch] <- sub("CHANNELS 3", "CHANNELS 0", x[ch]); x},
    "fractional channel count" = {x <- bl; x[ch] <- sub("CHANNELS 3", "CHANNELS 2.5", x[ch]); x},
    "channel count larger than names" = {x <- bl; x[ch] <- sub("CHANNELS 3", "CHANNELS 5", x[ch]); x},
    "unknown channel name" = {x <- bl; x[ch] <- sub("Zrotation", "Wrotation", x[ch]); x},
    "negative frame count" = {x <- bl; x[nf] <- "Frames: -2"; x},
    "fractional frame count" = {x <- bl; x[nf] <- "Frames: 2.5"; x},
    "frame count too large" = {x <- bl; x[nf] <- "Frames: 9999"; x},
    "NaN in motion" = {x <- bl; x[ft + 2] <- sub("^[^ ]+", "NaN", x[ft + 2]); x},
    "Inf in motion" = {x <- bl; x[ft + 2] <- sub("^[^ ]+", "Inf", x[ft + 2]); x},
    "text in motion" = {x <- bl; x[ft + 2] <- sub("^[^ ]+", "abc", x[ft + 2]); x},
    "short motion line" = {x <- bl; x[ft + 3] <- "1 2 3"; x},
    "NaN offset" = {x <- bl; x[off] <- sub("OFFSET .*", "OFFSET NaN 0 0", x[off]); x},
    "two-value offset" = {x <- bl; x[off] <- sub("OFFSET .*", "OFFSET 1 2", x[off]); x},
    "no MOTION section" = bl[seq_len(grep("^MOTION", bl) - 1L)],
    "no HIERARCHY" = bl[-1],
    "unbalanced braces" = bl[-grep("^\\s*\\}\\s*$", bl)[1]],
    "duplicate joint names" = {x <- bl; j <- grep("JOINT", x)[1:2]; x[j[2]] <- sub("JOINT .*", sub("^\\s*JOINT ", "JOINT ", x[j[1]]), x[j[2]]); x}
  )
  for (bn in names(bbad)) {
    fn <- sprintf("bad%02d.bvh", match(bn, names(bbad)))
    add("malformed file", paste0("read_bvh: ", bn), bquote(read_bvh(put(.(fn), .(bbad[[bn]])))), c(fn, "line"))
  }
  sl <- e$skel_lines
  pos <- grep("<position>", sl)[2]
  lim <- grep("<rotx>", sl)[2]
  sbad <- list(
    "NaN position" = {x <- sl; x[pos] <- sub(">.*<", ">NaN 0 0<", x[pos]); x},
    "Inf position" = {x <- sl; x[pos] <- sub(">.*<", ">Inf 0 0<", x[pos]); x},
    "NA position" = {x <- sl; x[pos] <- sub(">.*<", ">NA 0 0<", x[pos]); x},
    "two-value position" = {x <- sl; x[pos] <- sub(">.*<", ">1 2<", x[pos]); x},
    "text position" = {x <- sl; x[pos] <- sub(">.*<", ">a b c<", x[pos]); x},
    "empty position" = {x <- sl; x[pos] <- sub(">.*<", "><", x[pos]); x},
    "reversed limits" = {x <- sl; x[lim] <- sub(">.*<", ">80 -70<", x[lim]); x},
    "NaN limits" = {x <- sl; x[lim] <- sub(">.*<", ">NaN 10<", x[lim]); x},
    "unknown angle unit" = {x <- sl; x[grep("<angle>", x)] <- "    <angle>gradians</angle>"; x},
    "duplicate joint name" = {x <- sl; n <- grep("<name>", x)[3]; x[n] <- sub(">.*<", ">th-tmc<", x[n]); x},
    "duplicate joint id" = {x <- sl; n <- grep("<id>", x)[3]; x[n] <- sub(">.*<", ">2<", x[n]); x},
    "fractional joint id" = {x <- sl; n <- grep("<id>", x)[3]; x[n] <- sub(">.*<", ">2.5<", x[n]); x},
    "not closed" = sl[-length(sl)],
    "not a skeleton" = c("<hand><finger/></hand>")
  )
  for (sn in names(sbad)) {
    fn <- sprintf("bad%02d.xmlskel", match(sn, names(sbad)))
    add("malformed file", paste0("read_skeleton: ", sn), bquote(read_skeleton(put(.(fn), .(sbad[[sn]])))), c(fn, "line"))
  }
  add("malformed file", "hand_3d: skeleton with a NaN position", quote(hand_3d(g[1], skeleton = {s <- sk; s$joints[3, grep("^(x|pos)", names(s$joints))[1]] <- NaN; s})), c("skeleton", "th-mcp"))
  add("malformed file", "forward_kinematics: skeleton with an Inf position", quote(forward_kinematics(ang, skeleton = {s <- sk; s$joints[3, grep("^(x|pos)", names(s$joints))[1]] <- Inf; s})), c("skeleton", "th-mcp"))
  add("malformed file", "write_skeleton: skeleton with a NaN position", quote(write_skeleton({s <- sk; s$joints[3, grep("^(x|pos)", names(s$joints))[1]] <- NaN; s}, "nan.xmlskel")), c("skeleton", "th-mcp"))
  add("malformed file", "glove_profile: CSV without channel column", quote(glove_profile(put("glove.csv", c("name,unit", "a,deg")))), c("glove.csv", "channel"))
  add("malformed file", "read_glove: file with the wrong channels", quote(read_glove(put("s09_g01_o1_t99.csv", c("a,b", "1,2", "3,4")), glove = "resistive")), c("s09_g01_o1_t99.csv", "column", "field"))

  # --- indices ---------------------------------------------------------------
  for (v in list(2.5, -1, 0, 99, NA, "a", c(1, 2), TRUE)) {
    vd <- paste(deparse(v), collapse = "")
    add("index", sprintf("write_bvh: recording = %s", vd), bquote(write_bvh(g, tempfile(fileext = ".bvh"), recording = .(v))), "recording")
    # (hand_3d() draws several recordings side by side: c(1, 2) is good input)
    if (!identical(v, c(1, 2))) add("index", sprintf("hand_3d: recording = %s", vd), bquote(hand_3d(g, recording = .(v))), "recording")
    add("index", sprintf("write_hand_animation: recording = %s", vd), bquote(write_hand_animation(g, tempfile(fileext = ".html"), recording = .(v))), "recording")
  }
  for (v in list(2.5, -1, 0, 1e6, NA)) {
    vd <- deparse(v)
    add("index", sprintf("forward_kinematics: frames = %s", vd), bquote(forward_kinematics(ang, frames = .(v))), "frames")
    add("index", sprintf("autoplot hand: frame = %s", vd), bquote(ggplot2::ggplot_build(autoplot(g, type = "hand", frame = .(v)))), "frame")
  }
  for (v in list(2.5, 99, -99, NA, "no-such-id", c(TRUE, FALSE), 1.5)) {
    vd <- paste(deparse(v), collapse = "")
    add("index", sprintf("grasps[%s]", vd), bquote(g[.(v)]), c("\\bi\\b", "index", "recording", "no-such-id"))
    add("index", sprintf("grasp_models[%s]", vd), bquote(ms[.(v)]), c("\\bi\\b", "index", "model", "no-such-id"))
  }
  for (v in list(2.5, -1, NaN, "3")) {
    vd <- deparse(v)
    add("index", sprintf("generate: n = %s", vd), bquote(generate(m, n = .(v))), "\\bn\\b")
    add("index", sprintf("simulate_grasps: subjects = %s", vd), bquote(simulate_grasps(subjects = .(v))), "subjects")
    add("index", sprintf("fit_grasp_model: ncomp = %s", vd), bquote(fit_grasp_model(g, grasp = 1, ncomp = .(v))), "ncomp")
    add("index", sprintf("evaluate_loso: folds = %s", vd), bquote(evaluate_loso(g, folds = .(v))), "folds")
    add("index", sprintf("segment_by_switch: min_frames = %s", vd), bquote(segment_by_switch(g, min_frames = .(v))), "min_frames")
    add("index", sprintf("select_markers: n = %s", vd), bquote(select_markers(mk, .(v))), "\\bn\\b")
    add("index", sprintf("thesis_table: id = %s", vd), bquote(thesis_table(.(v))), "\\bid\\b")
  }
  add("index", "fit_grasp_model: grasp = 2.5", quote(fit_grasp_model(g, grasp = 2.5)), "grasp")
  add("index", "fit_grasp_model: grasp = 99", quote(fit_grasp_model(g, grasp = 99)), c("grasp", "99"))
  add("index", "generate: grasps = 2.5", quote(generate(ms, grasps = 2.5, n = 1)), "grasps")
  add("index", "fit_grasp_models: grasps = -1", quote(fit_grasp_models(g, grasps = -1)), "grasps")

  # --- regular expressions and separators ------------------------------------
  for (p in c("(", "[", "(?<grasp>")) {
    add("regex", sprintf("read_hust: pattern = %s", p), bquote(read_hust("hust", pattern = .(p))), "pattern")
    add("regex", sprintf("read_hust: file_pattern = %s", p), bquote(read_hust("hust", file_pattern = .(p))), "file_pattern")
    add("regex", sprintf("read_graspdb14: pattern = %s", p), bquote(read_graspdb14(.(e$gdb_dir), pattern = .(p))), "pattern")
    add("regex", sprintf("read_glove: pattern = %s", p), bquote(read_glove("hust", glove = "hust", pattern = .(p))), "pattern")
  }
  add("regex", "read_hust: pattern of two strings", quote(read_hust("hust", pattern = c("a", "b"))), "pattern")
  add("regex", "read_hust: pattern = NA", quote(read_hust("hust", pattern = NA_character_)), "pattern")
  add("regex", "read_hust: pattern a number", quote(read_hust("hust", pattern = 1)), "pattern")
  add("regex", "read_graspdb14: pattern of two strings", quote(read_graspdb14(e_gdb, pattern = c("a", "b"))), "pattern")
  for (s in list(c(",", ";"), "", 1, ",;", TRUE)) {
    sd <- paste(deparse(s), collapse = "")
    add("separator", sprintf("read_hust: sep = %s", sd), bquote(read_hust("hust", sep = .(s))), "sep")
    add("separator", sprintf("write_hust: sep = %s", sd), bquote(write_hust(g[1], tempfile("w"), sep = .(s))), "sep")
    add("separator", sprintf("read_glove: sep = %s", sd), bquote(read_glove("hust", glove = "hust", sep = .(s))), "sep")
  }

  # --- generics on the wrong class ------------------------------------------
  wrong <- list("recordings" = quote(g), "a list" = quote(list(1, 2)), "a classifier" = quote(clf),
                "text" = quote("x"), "NULL" = quote(NULL), "a data frame" = quote(data.frame(a = 1)),
                "a list of models" = quote(list(m, m)))
  for (wn in names(wrong)) {
    w <- wrong[[wn]]
    add("wrong class", sprintf("generate on %s", wn), bquote(generate(.(w), n = 1)), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("project on %s", wn), bquote(project(.(w), g)), c("object", "class", "<"))
    if (wn != "a classifier") add("wrong class", sprintf("predict on %s", wn), bquote(predict(.(w), g)), c("object", "class", "<"))
    if (wn != "a classifier") add("wrong class", sprintf("classify with %s", wn), bquote(classify(.(w), g)), c("models", "class", "<"))
    add("wrong class", sprintf("start_recognition on %s", wn), bquote(start_recognition(.(w))), c("recognizer", "class", "<"))
    if (wn != "recordings") {
    add("wrong class", sprintf("classify of %s", wn), bquote(classify(ms, .(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("project onto %s", wn), bquote(project(m, .(w))), c("new_data", "class", "<"))
    add("wrong class", sprintf("predict classifier of %s", wn), bquote(predict(clf, .(w))), c("new_?data", "class", "<"))
    add("wrong class", sprintf("write_hust of %s", wn), bquote(write_hust(.(w), tempfile("w"))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("forward_kinematics of %s", wn), bquote(forward_kinematics(.(w))), c("\\bx\\b", "class", "<", "DoFs?"))
    add("wrong class", sprintf("find_motion of %s", wn), bquote(find_motion(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("fit_grasp_model of %s", wn), bquote(fit_grasp_model(.(w))), c("\\bx\\b", "class", "<"))
    }
  }
  for (wn in c("a list", "text", "NULL", "a data frame")) {
    w <- wrong[[wn]]
    add("wrong class", sprintf("evaluate_generation with %s", wn), bquote(evaluate_generation(.(w), g, g)), c("models", "class", "<"))
    add("wrong class", sprintf("evaluate_early_recognition of %s", wn), bquote(evaluate_early_recognition(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("calibrate of %s", wn), bquote(calibrate(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("segment_by_switch of %s", wn), bquote(segment_by_switch(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("trim_motion of %s", wn), bquote(trim_motion(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("cut_motion of %s", wn), bquote(cut_motion(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("graspdb14_to_hust of %s", wn), bquote(graspdb14_to_hust(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("glove_profile of %s", wn), bquote(glove_profile(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("write_skeleton of %s", wn), bquote(write_skeleton(.(w), tempfile())), c("skeleton", "class", "<"))
    add("wrong class", sprintf("read_failures of %s", wn), bquote(read_failures(.(w))), c("\\bx\\b", "class", "<"))
    add("wrong class", sprintf("joint_map of %s", wn), bquote(joint_map(.(w))), c("source", "class", "<"))
    add("wrong class", sprintf("handover_error of %s", wn), bquote(handover_error(.(w), g)), c("truth", "class", "<"))
    add("wrong class", sprintf("read_bvh of %s", wn), bquote(read_bvh(.(w))), c("file", "class", "<"))
    add("wrong class", sprintf("read_hust of %s", wn), bquote(read_hust(.(w))), c("path", "class", "<"))
  }
  # --- numeric and choice arguments across the verbs ------------------------
  nums <- list(
    "find_motion: high" = list(quote(find_motion(g, high = BAD)), "high"),
    "find_motion: smooth" = list(quote(find_motion(g, smooth = BAD)), "smooth"),
    "cut_motion: min_motion" = list(quote(cut_motion(g, min_motion = BAD)), "min_motion"),
    "trim_motion: low" = list(quote(trim_motion(g, low = BAD)), "low"),
    "fit_grasp_recognizer: at" = list(quote(fit_grasp_recognizer(g, at = BAD)), "at"),
    "fit_grasp_recognizer: horizon" = list(quote(fit_grasp_recognizer(g, horizon = BAD)), "horizon"),
    "fit_handover: ncomp" = list(quote(fit_handover(g, n_markers = 3, ncomp = BAD)), "ncomp"),
    "fit_handover: filter_size" = list(quote(fit_handover(g, n_markers = 3, filter_size = BAD)), "filter_size"),
    "hand_3d: speed" = list(quote(hand_3d(g[1], speed = BAD)), "speed"),
    "hand_3d: width" = list(quote(hand_3d(g[1], width = BAD)), "width"),
    "write_hand_animation: max_frames" = list(quote(write_hand_animation(g[1], tempfile(fileext = ".html"), max_frames = BAD)), "max_frames"),
    "write_graspdb14: start_time" = list(quote(write_graspdb14(g, tempfile("d"), start_time = BAD)), c("start_time", "\\bx\\b")),
    "evaluate_generation: n" = list(quote(evaluate_generation(ms, g, g, n = BAD)), "\\bn\\b"),
    "simulate_grasps: rest" = list(quote(simulate_grasps(rest = BAD)), "rest"),
    "simulate_grasps: session_sd" = list(quote(simulate_grasps(session_sd = BAD)), "session_sd"),
    "generate: chunk" = list(quote(generate(m, n = 2, chunk = BAD)), "chunk"),
    "reproduce_thesis: subjects" = list(quote(reproduce_thesis(tempfile("t"), subjects = BAD)), "subjects")
  )
  for (nn in names(nums)) for (v in list(-1, NaN, "a", c(1, 2))) {
    vd <- paste(deparse(v), collapse = "")
    add("argument", sprintf("%s = %s", nn, vd), do.call(substitute, list(nums[[nn]][[1]], list(BAD = v))), nums[[nn]][[2]])
  }
  add("malformed file", "glove_profile: CSV with a text scale", quote(glove_profile(put("glove2.csv", c("channel,scale", "a,big")))), c("glove2.csv", "scale"))
  add("malformed file", "glove_profile: CSV with repeated channels", quote(glove_profile(put("glove3.csv", c("channel", "a", "a")))), c("glove3.csv", "channel", "\\ba\\b"))
  add("malformed file", "glove_profile: missing CSV", quote(glove_profile("no-such-glove.csv")), c("no-such-glove.csv", "\\bx\\b"))
  add("malformed file", "glove_profile: binary CSV", quote({writeBin(as.raw(0:255), "glove4.csv"); glove_profile("glove4.csv")}), c("glove4.csv", "\\bx\\b"))
  add("argument", "calibrate: poses of unknown names", quote(calibrate(raw, poses = list(wave = raw$recordings[[1]]))), c("poses", "wave"))
  add("argument", "calibrate: pose with NaN", quote(calibrate(raw, poses = list(flat = {r <- raw$recordings[[1]]; r[1, 1] <- NaN; r}))), c("poses", "flat"))
  add("argument", "calibrate: recordings in degrees", quote(calibrate(g)), c("\\bx\\b", "raw"))
  add("argument", "handover_error: sets of text", quote(handover_error(g, by = "markers", reference = g, sets = "a")), "sets")
  add("argument", "select_markers: unknown method", quote(select_markers(mk, 3, method = "best")), "method")
  add("argument", "joint_map: unknown source", quote(joint_map("cyberglove99")), "source")
  add("argument", "segment_by_switch: unknown keep", quote(segment_by_switch(g, keep = "both")), "keep")
  add("argument", "thesis_table: unknown id", quote(thesis_table("9.9")), "\\bid\\b")
  add("argument", "evaluate_early_recognition: fractions above 1", quote(evaluate_early_recognition(g, fractions = 2)), "fractions")
  add("argument", "grasps: meta of another length", quote(grasps(g$recordings, meta = g$meta[1:3, ])), "meta")
  add("argument", "grasps: glove of other channels", quote(grasps(g$recordings, meta = g$meta, glove = "resistive")), c("glove", "channel"))
  add("wrong class", "simulate on recordings", quote(stats::simulate(g)), c("object", "class", "<"))
  add("wrong class", "read_skeleton of two files", quote(read_skeleton(c("good.xmlskel", "good.xmlskel"))), "file")
  add("wrong class", "read_bvh of two files", quote(read_bvh(c("good.bvh", "good.bvh"))), "file")
  add("wrong class", "read_hust: NA path", quote(read_hust(NA_character_)), "path")
  add("wrong class", "calibrate: poses not a list", quote(calibrate(raw, poses = 1)), "poses")
  add("wrong class", "glove_profile: unknown name", quote(glove_profile("cyberglove99")), c("cyberglove99", "\\bx\\b"))
  add("wrong class", "simulate_grasps: glove a number", quote(simulate_grasps(glove = 42)), "glove")
  cases
}

# ---------------------------------------------------------------- running
# Evaluate one case; classify what happened.
run_case <- function(case, env) {
  warns <- list()
  t0 <- Sys.time()
  out <- tryCatch(
    withCallingHandlers({
      setTimeLimit(elapsed = 60, transient = TRUE)
      on.exit(setTimeLimit(elapsed = Inf), add = TRUE)
      r <- eval(case$expr, env)
      force(r)
      # a plot is only drawn when printed; build it to run its checks
      if (inherits(r, "ggplot")) ggplot2::ggplot_build(r)
      list(value = TRUE)
    }, warning = function(w) {
      warns[[length(warns) + 1L]] <<- w
      invokeRestart("muffleWarning")
    }, message = function(m) invokeRestart("muffleMessage")),
    error = function(err) list(error = err))
  names_it <- function(cnd) {
    # the message, and the fields that name the culprit, each on its own
    txt <- cli::ansi_strip(c(conditionMessage(cnd),
                             as.character(unlist(cnd[c("argument", "recording", "file", "line", "grasp")]))))
    any(vapply(case$culprit, function(p) any(grepl(p, txt, ignore.case = TRUE, perl = TRUE)), logical(1)))
  }
  hm_warns <- Filter(function(w) inherits(w, "handmotion_warning"), warns)
  if (!is.null(out$error)) {
    err <- out$error
    cls <- class(err)[1]
    outcome <- if (inherits(err, "handmotion_error")) if (names_it(err)) "classed_named" else "classed_unnamed" else "base_error"
    msg <- conditionMessage(err)
  } else if (length(hm_warns)) {
    cls <- class(hm_warns[[1]])[1]
    outcome <- if (any(vapply(hm_warns, names_it, logical(1)))) "warning_named" else "warning_unnamed"
    msg <- conditionMessage(hm_warns[[1]])
  } else {
    cls <- if (length(warns)) class(warns[[1]])[1] else ""
    outcome <- "silent"
    msg <- if (length(warns)) conditionMessage(warns[[1]]) else ""
  }
  msg <- gsub("\\s+", " ", cli::ansi_strip(msg))
  data.frame(group = case$group, label = case$label, outcome = outcome, class = cls,
             message = substr(msg, 1, 300), seconds = round(as.numeric(Sys.time() - t0, units = "secs"), 2),
             stringsAsFactors = FALSE)
}

worker <- function(from, out_file, src) {
  setwd(src)
  load_handmotion()
  wd <- tempfile("corpus")
  dir.create(wd)
  setwd(wd)
  env <- corpus_fixtures()
  assign("put", put, envir = env)
  env$e_gdb <- env$gdb_dir
  cases <- corpus_cases(env)
  res <- if (file.exists(out_file)) readRDS(out_file) else NULL
  for (i in seq(from, length(cases))) {
    cat(sprintf("[%d/%d] %s\n", i, length(cases), cases[[i]]$label), file = stderr())
    # mark the case as begun, so that a crash is pinned on it
    saveRDS(c(i = i), paste0(out_file, ".running"))
    r <- run_case(cases[[i]], env)
    r$i <- i
    res <- rbind(res, r)
    saveRDS(res, out_file)
  }
  unlink(paste0(out_file, ".running"))
  invisible(length(cases))
}

driver <- function(out_file) {
  src <- getwd()
  unlink(c(out_file, paste0(out_file, ".running")))
  from <- 1L
  repeat {
    status <- system2(file.path(R.home("bin"), "Rscript"),
                      c(shQuote(script), "--worker", from, shQuote(out_file), shQuote(src)),
                      stdout = "", stderr = FALSE)
    running <- paste0(out_file, ".running")
    if (!file.exists(running)) break
    i <- readRDS(running)[["i"]]
    unlink(running)
    res <- if (file.exists(out_file)) readRDS(out_file) else NULL
    res <- rbind(res, data.frame(group = NA, label = sprintf("case %d", i), outcome = "crash", class = "",
                                 message = sprintf("worker exited with status %s", status), seconds = NA, i = i))
    saveRDS(res, out_file)
    from <- i + 1L
  }
  res <- readRDS(out_file)
  res
}

report <- function(res) {
  lev <- c("classed_named", "warning_named", "classed_unnamed", "warning_unnamed", "silent", "base_error", "crash")
  res$outcome <- factor(res$outcome, lev)
  cat("\nBad-input corpus:", nrow(res), "cases\n\n")
  tab <- table(res$group, res$outcome)
  print(addmargins(tab, 1))
  ok <- res$outcome %in% c("classed_named", "warning_named")
  cat(sprintf("\nclassed naming the culprit: %d of %d (%.1f%%); classed errors naming it: %d; silent: %d; base-R errors: %d; crashes: %d\n",
              sum(ok), nrow(res), 100 * mean(ok), sum(res$outcome == "classed_named"),
              sum(res$outcome == "silent"), sum(res$outcome == "base_error"), sum(res$outcome == "crash")))
  bad <- res[!ok, c("outcome", "label", "class", "message")]
  if (nrow(bad)) {
    cat("\nCases that are not a classed error (or classed warning) naming the culprit:\n")
    bad$message <- substr(bad$message, 1, 110)
    for (k in seq_len(nrow(bad))) {
      cat(sprintf("- [%s] %s  <%s> %s\n", bad$outcome[k], bad$label[k], bad$class[k], bad$message[k]))
    }
  }
  invisible(res)
}

if (length(args) && args[1] == "--worker") {
  worker(as.integer(args[2]), args[3], args[4])
} else {
  out_file <- normalizePath(if (length(args)) args[1] else "bad-input-corpus.rds", mustWork = FALSE)
  res <- driver(out_file)
  report(res)
}
