# A set of per-type models, fitted through the future framework. The user
# picks the plan (future::plan()); the package never sets one. Each type gets
# its own parallel-safe RNG stream from `seed` (future.seed), so the models are
# identical whatever the plan or the number of workers.

#' Fit the generative model of every grasp type
#'
#' Splits `x` by grasp type and calls [fit_grasp_model()] on each type in
#' futures (four per worker, falling in size so the workers finish together; one per
#' type under a scheduler), so the types are fitted in parallel under
#' whatever [future::plan()] the user has set (sequentially by default).
#' A progress bar (one step per type, through `progressr`, so it works from
#' future workers; its look follows [progressr::handlers()]) appears when the
#' fit takes more than 2 s, where progressr's conventions say: in interactive
#' sessions, or in scripts when you set `options(progressr.enable = TRUE)` or
#' chose handlers (never in a captured log by default);
#' `options(handmotion.progress = FALSE)` turns it off. A type whose fit fails with a handmotion error (for example too few
#' usable recordings) stays in the set as a failed model (class
#' `grasp_model_failed`, with the error's message and class), like a null
#' model in a fable, instead of stopping the others: `print()` and `summary()`
#' list it, [generate()], `predict()` and [classify()] skip it (saying so), and asking for
#' it by name (`generate(ms, grasps = )`) is an error of class
#' `handmotion_error_model_failed`. A bad argument or recording
#' (`handmotion_error_bad_input`) stops the call.
#'
#' **Clusters and schedulers.** Any future plan works unchanged and gives the
#' same models for the same seed (tested under sequential, multicore,
#' multisession, PSOCK cluster and batchtools plans): several machines with
#' `future::plan(future::cluster, workers = c("host1", "host2"))`, or a
#' scheduler with future.batchtools and the shipped SLURM template,
#' `future::plan(future.batchtools::batchtools_slurm, template =
#' system.file("templates", "slurm.tmpl", package = "handmotion"))` (one job
#' per grasp type). Workers need handmotion installed.
#'
#' **Interrupt and resume.** With `cache`, each type's model is saved to that
#' folder as soon as it is fitted (by the worker that fitted it, so the folder
#' must be reachable from every worker of a cluster). A later call with the
#' same data, arguments, seed and package version loads the saved types and
#' fits only the others: a long fit interrupted with Ctrl-C (which reaches the
#' compiled loops) resumes where it stopped, and the result is identical to an
#' uninterrupted fit. The file of a type is named after the type and a hash of
#' its inputs, so changed inputs never load a stale model.
#'
#' @param x A [grasps()] object with labelled recordings.
#' @param grasps The grasp types to fit (names or ids 1-33); every type
#'   present in `x` by default.
#' @param ... Passed to [fit_grasp_model()] (`dependence`, `ncomp`, `warp_ncomp`, `mixture_components`,
#'   `warping`, `fpc_scores`, `mixture_guard`, `engine`, `overlong`, `max_stall`,
#'   `keep_data`).
#' @param seed Seed of the per-type RNG streams; the same seed gives identical
#'   models under any plan. `NULL` draws the streams from the current RNG (and
#'   cannot be combined with `cache`).
#' @param cache Optional folder for resumable fits (see Details); created if
#'   needed.
#' @param distance What [classify()] and [predict.grasp_models()] rank the
#'   set's types by:
#'   * `"likelihood"` (default): minus twice the log-likelihood of the
#'     recording under each type's model: its vector of FPC scores (all DoFs
#'     together) under a Gaussian kernel density of the type's own training
#'     score vectors (the kernel model's: the scores' shrunk covariance and a
#'     bandwidth chosen by leave-one-out likelihood on the training
#'     recordings; a type of fewer than three recordings scores each DoF
#'     under its own mixture instead), plus, DoF by DoF, its residual norm
#'     under the residual the set's types leave: the discarded eigenvalues'
#'     sums averaged over the types (weighted by their recordings less one,
#'     as linear discriminant analysis pools the within-class covariance)
#'     and matched in mean and variance by Gaussian coordinates, so a type
#'     whose own few recordings happened to vary more does not take every
#'     recording its FPCs fit badly. The projection on a type's FPCs absorbs the recording's
#'     amplitude, so the residual alone cannot tell types of one shape and
#'     different amplitude apart; the score term can, and scoring the DoFs
#'     jointly keeps the clusters a type grasped round several objects forms
#'     and how its fingers move together. Held out by participant on the real
#'     flexglove recordings it is right for 76.8% (P1 68.0%, P2 89.0%; with
#'     each type's own residual scale 73.2%, DoF by DoF 68.7%, the residual
#'     59.3%), on the default data held out by subject 61.4% (own scale
#'     50.6%). A gain or offset of a channel common
#'     to all recordings moves every type's distance alike.
#'   * `"residual"`: the thesis' eq. 4.4, the L2 distance between the
#'     warped recording and its projection on frames `1..T_i` (see
#'     [classify()]); what [reproduce_thesis()] and the thesis tables use.
#' @return An object of class `grasp_models`, a member of the classifier
#'   family (`grasp_classifier`, see [summary.grasp_classifier()]): a list
#'   with `models` (named by grasp type: one `grasp_model` per fitted type
#'   and one `grasp_model_failed`, a list with `grasp`, `grasp_id`,
#'   `message` and `class`, per type whose fit failed), the family's
#'   fields `classes` (the fitted types), `levels` (of the training
#'   labels), `n` (recordings each type was fitted on) and `temperature`
#'   (of the class probabilities, fitted on the training recordings: see
#'   [predict.grasp_models()]), and `seed` and `distance`. The set reads
#'   as the list of its models: `ms[["Tripod"]]` (or `ms$models$Tripod`),
#'   `names(ms)`, `length(ms)`, `ms[types]` (a smaller set) and
#'   `lapply(ms, f)` are by type; `ms$` reads the fields.
#' @seealso [summary.grasp_models()] (Tables 5.1 and 5.2), [generate()],
#'   [predict.grasp_models()] (classes and probabilities), [project()],
#'   [classify()].
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 1:2, objects = 2, trials = 2, seed = 1)
#' ms <- fit_grasp_models(g, seed = 1)
#' ms
#' summary(ms)
fit_grasp_models <- function(x, grasps = NULL, ..., seed = 1, cache = NULL,
                             distance = c("likelihood", "residual")) {
  # (recordings without a motion are said once for the set, not by each type)
  out <- say_no_motion_once(fit_model_set(x, grasps, ..., seed = seed, cache = cache, distance = distance,
                                          call = rlang::caller_env()), length(x))
  # types fitted from a pair of recordings, and types that could not be
  # fitted at all, are said here, not only in print() of the set
  warn_few_recordings(x, types = names(out))
  failed <- failed_types(out)
  if (nrow(failed)) {
    hm_warn(c("{nrow(failed)} of the {length(out)} grasp type models could not be fitted and {?is/are} left out: {.val {failed$grasp}}.",
              i = "First reason: {failed$message[1]}", i = "{.code print()} of the set lists every reason."),
            "model_failed", grasp = failed$grasp)
  }
  out
}

# fit_grasp_models(); evaluate_loso() and the weighted FPCA classifier skip
# the temperature (calibrate = FALSE): they never ask the set for
# probabilities, and it costs one in-sample classification.
fit_model_set <- function(x, grasps = NULL, ..., seed = 1, cache = NULL, calibrate = TRUE,
                          distance = c("likelihood", "residual"), call = rlang::caller_env()) {
  check_grasps(x, call = call)
  distance <- check_choice(distance, c("likelihood", "residual"), arg = "distance", call = call)
  present <- levels(droplevels(x$meta$grasp))
  types <- check_grasp_selection(grasps, "grasps", levels = levels(x$meta$grasp), call = call) %||% present
  absent <- setdiff(types, present)
  if (length(absent)) {
    hm_abort("No recordings of grasp type{?s} {.val {absent}} in {.arg x}.",
             "too_few_recordings", argument = "grasps", call = call)
  }
  check_some_types(types, x, call = call)
  # Ship each worker only its own type's recordings.
  parts <- lapply(types, function(g) x[!is.na(x$meta$grasp) & x$meta$grasp == g])
  names(parts) <- types
  args <- list(...)
  unknown <- setdiff(names(args) %||% rep("", length(args)), setdiff(names(formals(fit_grasp_model)), c("x", "grasp", "seed")))
  if (length(unknown)) {
    hm_abort(c("{.fn fit_grasp_models} passes {.arg ...} to {.fn fit_grasp_model}, which has no argument{?s} {.val {unknown}}.",
               renamed_argument_hints(unknown),
               i = "Arguments must be named; see {.help handmotion::fit_grasp_model}."),
             "bad_input", argument = "...", call = call)
  }
  # rest/hold trimming is decided once for the whole set, so every type's
  # model treats its recordings (and the recordings it classifies) alike
  # (and every recording's motion is found once, here: each type's fit and
  # the temperature sample read it, R/segment-found-once.R)
  motion <- resolve_motion_found(x, args$motion %||% "auto", call = call)
  args$motion <- motion$motion
  seed <- check_seed(seed, call = call)
  # future's seeding switches the session to L'Ecuyer-CMRG; give the caller back their RNG
  old_rng <- save_rng()
  on.exit(restore_rng(old_rng), add = TRUE)
  # one stream per type, fixed by the seed and the type's place in the set,
  # so a resumed fit gives every type the stream of a full fit
  streams <- if (is.null(seed)) NULL else element_streams(seed, length(types))
  paths <- cache_paths(cache, parts, args, streams, call)
  fits <- vector("list", length(types))
  names(fits) <- types
  cached <- if (is.null(paths)) rep(FALSE, length(types)) else file.exists(paths)
  fits[cached] <- lapply(paths[cached], readRDS)
  # Four rounds of futures per worker, falling in size, and packed as they
  # start (future_map_chunks(), guided_chunks(), R/future-chunks.R).
  # Measured at ten times the default data on two quiet workers (89,100
  # recordings): one future per type 36.4 s (each of 33 round trips left a
  # worker idle while the main process took its model in and sent the next
  # type), one per worker 32.5 s (every model came back at the end), two
  # equal chunks per worker 25.3-29.3 s (mean 27.3 of 14 runs), three 24.4-27.7
  # s (mean 25.9 of 9), sequential 39.0-42.0 s. With chunks falling in size
  # (and each chunk one global, polled every 0.05 s), fresh processes
  # alternating: three rounds 25.0-27.3 s (4 runs), four 23.7-27.5 s (median
  # 24.5 of 7), five 24.3-31.0 s (3), the equal three of the build before
  # 24.4-26.3 s (mean 25.3 of 6), sequential 38.4-40.3 s. Each type keeps
  # its own stream, so the models do not depend on the plan, the chunks or
  # their order.
  todo <- which(!cached)
  # the recordings the temperature is fitted on: each type's worker scores
  # them under its model as soon as it has fitted it, so the main process
  # does not score them under every model after the last type (at ten times
  # the default data, 2 s with both workers idle)
  sample <- if (calibrate) with_motion_found(motion$found, temperature_sample(x, types, args$motion))
  sample_d <- vector("list", length(types))
  names(sample_d) <- types
  if (length(todo)) {
    if (is.null(streams)) streams <- element_streams(sample.int(.Machine$integer.max, 1L), length(types))
    res <- with_progress_shown({
      p <- hm_progressor(length(todo))
      future_map_chunks(parts[todo], fit_one_type,
                        each = list(save_to = (paths %||% rep(NA_character_, length(types)))[todo],
                                    found = lapply(parts[todo], type_motion_found, found = motion$found)),
                        more = list(args = args, progress = p, sample = sample, distance = distance),
                        streams = streams[todo], work = type_work(parts[todo]))
    })
    fits[todo] <- lapply(res, `[[`, "model")
    sample_d[todo] <- lapply(res, `[[`, "sample_distance")
  }
  sample_d[cached] <- lapply(fits[cached], sample_distance, sample = sample, distance = distance)
  # a failed type stays in the set, as a record of why
  failed <- vapply(fits, inherits, logical(1), what = "error")
  # a bad argument or recording is the caller's to fix, not a type that could
  # not be fitted: raise it (with ncomp = 0 every type "failed" and an empty
  # set came back without an error)
  bad_input <- which(vapply(fits, inherits, logical(1), what = "handmotion_error_bad_input"))
  if (length(bad_input)) stop(fits[[bad_input[1]]])
  fits[failed] <- mapply(new_grasp_model_failed, types[failed], fits[failed], SIMPLIFY = FALSE)
  # the likelihood's residual scale is the set's, pooled over its types
  # (R/classifier-fpca-likelihood.R); the sample's residual terms are added
  # under it
  fits <- pool_likelihood_residuals(fits)
  sample_d <- Map(finish_sample_distance, fits, sample_d)
  temperature <- if (calibrate) models_temperature(types[!failed], sample, sample_d)
  out <- new_grasp_models(fits, seed = seed, levels = grasp_levels(x), temperature = temperature, distance = distance)
  dg <- models_degeneracies(out)
  n_dg <- length(unique(sub(": .*", "", dg$message)))
  warn_degenerate(dg, sprintf("%d of the %d grasp type models rest%s on degenerate data:", n_dg,
                              length(fitted_models(out)), if (n_dg == 1L) "s" else ""))
  out
}

# The degenerate data of every fitted model of a set, one row per model and
# class, the message prefixed by the grasp type.
models_degeneracies <- function(models) {
  rows <- lapply(unclass(fitted_models(models)), function(m) {
    d <- m$degenerate_data
    if (is.null(d) || nrow(d) == 0L) return(NULL)
    d$message <- paste0(m$grasp, ": ", d$message)
    d
  })
  do.call(rbind, c(list(empty_degenerate_notes()), rows))
}

# The rows of the set's find_motion() table (NULL: none) for one type's
# recordings, to travel with them to the type's worker.
type_motion_found <- function(part, found) {
  if (is.null(found)) return(NULL)
  out <- found[match(part$meta$id, found$id), , drop = FALSE]
  rownames(out) <- NULL
  out
}

# The work of fitting each set of recordings, for ordering: DTW and FPCA grow
# with the frames, the number of recordings times their mean length.
type_work <- function(parts) {
  vapply(parts, function(pt) sum(pt$meta$n_frames), numeric(1))
}

# One type's fit for a worker. A top-level function, so the closure shipped to
# workers does not drag the caller's frame (the whole data set) along.
fit_one_type <- function(part, save_to, args, progress, sample = NULL, distance = "likelihood", found = NULL) {
  part <- unpack_on_worker(part)
  # (degenerate data is recorded in each model and said once for the set by
  # fit_grasp_models(), not once per type; the type's motion, found by the
  # set's fit, is read, not found again)
  # (seed = NULL: the type's own stream, set by future.seed, not fit_grasp_model()'s default)
  fit <- function() with_motion_found(found, do.call(fit_grasp_model, c(list(part), args, seed = list(NULL))))
  res <- tryCatch(withCallingHandlers(fit(),
                                      handmotion_warning_degenerate = function(w) invokeRestart("muffleWarning")),
                  handmotion_error = function(e) e)
  # saved at once (not after the whole set), so an interrupted fit keeps it;
  # written to a temporary name first so a half-written file never loads
  if (!is.null(save_to) && !is.na(save_to) && inherits(res, "grasp_model")) {
    tmp <- paste0(save_to, ".part")
    saveRDS(res, tmp)
    file.rename(tmp, save_to)
  }
  progress(as.character(part$meta$grasp[1]))
  list(model = res, sample_distance = sample_distance(res, sample, distance))
}

# The cache file of each type, or NULL without a cache: <type>-<hash>.rds,
# the hash over everything the fit depends on.
cache_paths <- function(cache, parts, args, streams, call) {
  if (is.null(cache)) return(NULL)
  cache <- check_string(cache, "cache", call = call)
  if (is.null(streams)) {
    hm_abort("A {.arg cache} needs a {.arg seed}: with {.code seed = NULL} a resumed fit could not repeat the interrupted one.",
             "bad_input", argument = "cache", call = call)
  }
  if (!dir.exists(cache) && !dir.create(cache, recursive = TRUE, showWarnings = FALSE)) {
    hm_abort("Cannot create the cache folder {.file {cache}}.", "bad_input", argument = "cache", call = call)
  }
  version <- as.character(utils::packageVersion("handmotion"))
  keys <- vapply(seq_along(parts), function(i) {
    pt <- parts[[i]]
    rlang::hash(list(pt$recordings, pt$meta, pt$dofs, pt$rate, pt$unit, args, streams[[i]], version))
  }, character(1))
  file.path(cache, paste0(gsub("[^A-Za-z0-9]+", "-", names(parts)), "-", keys, ".rds"))
}

# The temperature of the set's class probabilities (see ?predict.grasp_models):
# fitted by maximum likelihood on the in-sample distances of a sample of the
# training recordings (temperature_sample()) under every fitted type's model
# (sample_distance(), one vector per type; `types`, the fitted ones). NULL
# (no probabilities) when no model could score the sample.
models_temperature <- function(types, sample, distances) {
  if (length(types) < 2L) return(1)
  lab <- as.character(sample$meta$grasp)
  rows <- lab %in% types
  d <- matrix(NA_real_, sum(rows), length(types), dimnames = list(sample$meta$id[rows], types))
  for (t in types) {
    v <- distances[[t]]
    if (is.numeric(v) && length(v) == length(lab)) d[, t] <- v[rows]
  }
  if (all(is.na(d))) return(NULL)
  fit_temperature(d, lab[rows])
}

# The recordings of `types` the temperature is fitted on: one parameter needs
# few, so at most 30 per type, evenly spread (deterministic), and a large
# set's fit does not classify all of it (8,910 recordings: 9 s; 990: about a
# second, the temperature within 3%). Trimmed as a model trims what it
# projects (`motion`, the set's).
temperature_sample <- function(x, types, motion) {
  lab <- as.character(x$meta$grasp)
  own <- which(!is.na(lab) & lab %in% types)
  pick <- unlist(lapply(split(own, lab[own]), function(i) i[evenly_spread(length(i), 30L)]), use.names = FALSE)
  s <- x[sort(pick)]
  if (identical(motion, "trim")) s <- trim_motion(s)
  s
}

# The distances of the sample's recordings under one fitted model (in the
# order of the sample; NA where one could not be projected), an error where
# the model cannot score them at all, NULL without a sample or a model: the
# model's column of fpca_distances(), by the same per-model step
# (fpca_model_distance()); for the likelihood its two terms apart
# (list(score, residual)) until the set's residual scale is pooled.
sample_distance <- function(model, sample, distance) {
  if (is.null(sample) || !inherits(model, "grasp_model") || inherits(model, "grasp_model_failed")) return(NULL)
  likelihood <- distance == "likelihood"
  # (projection_input()'s shape, not projection_input() itself: the sample is
  # trimmed already by temperature_sample(), and must not be trimmed twice)
  input <- list(x = sample, recs = double_recordings(sample))
  tryCatch(withCallingHandlers({
    project_models(list(model), input, "model", details = FALSE, call = rlang::current_env(),
                   keep = function(pr, m) fpca_model_distance(m, pr, likelihood, sample$meta$id, terms = likelihood),
                   distance_only = !likelihood)[[1]]
  }, handmotion_warning_projection_failed = function(w) invokeRestart("muffleWarning")),
  error = function(e) e)
}

# A type's sample distances once the set's models are pooled: the
# likelihood's score term plus its residual term under the pooled scale; a
# residual distance, an error or NULL as they are.
finish_sample_distance <- function(model, d) {
  if (!is.list(d) || inherits(d, "condition") || !inherits(model, "grasp_model")) return(d)
  unname(d$score + likelihood_residual_term(model, d$residual))
}

# The one constructor of class "grasp_models", a member of the classifier
# family built by its constructor (R/classifier.R): `models`, a list named
# by grasp type of fitted models and failed ones, is a field beside the
# family's (classes: the fitted types; n: the recordings each was fitted
# on; levels: of the training labels, which predictions carry, by default
# those of the first fitted model; temperature: of the class
# probabilities) and the set's own `seed` and `distance` (what classify()
# ranks: "likelihood" or "residual", see fit_grasp_models()). The set still
# reads as the list of its models (R/grasp-models-list.R): `ms[["Tripod"]]`,
# `names(ms)`, `length(ms)`, `ms[types]`, lapply().
new_grasp_models <- function(models, seed = NULL, levels = NULL, temperature = NULL, distance = "residual") {
  stopifnot(is.list(models), !is.object(models))
  fitted <- models[vapply(models, inherits, logical(1), "grasp_model")]
  levels <- levels %||% if (length(fitted)) model_levels(fitted[[1]]) else names(models)
  validate_grasp_models(new_grasp_classifier(
    models = models, seed = seed, distance = distance,
    classes = names(fitted) %||% character(0), levels = levels %||% character(0),
    n = vapply(fitted, function(m) as.integer(m$n_used), integer(1), USE.NAMES = FALSE),
    temperature = temperature, class = "grasp_models"))
}

# The set in the classifier family: its distances are the FPCA distances
# (fpca_distances(), R/classifier-classify.R); its classes, levels and temperature are
# the family's fields, read by the family's default methods.
#' @export
classifier_distances.grasp_models <- function(object, new_data, ..., call = rlang::caller_env()) {
  fpca_distances(object, new_data, call = call)
}

#' @export
classifier_method.grasp_models <- function(object) "fpca"

# (its models are checked by check_grasp_models() where they are read)
#' @export
classifier_parts.grasp_models <- function(object) character(0)

# Every element a model or a failure, named by its own type, once; the fitted
# models share their DoFs, rate and unit (one set classifies one kind of
# recording).
validate_grasp_models <- function(x) {
  m <- x$models
  ok <- vapply(m, function(e) inherits(e, "grasp_model") || inherits(e, "grasp_model_failed"), logical(1))
  fitted <- m[vapply(m, inherits, logical(1), "grasp_model")]
  same <- function(f) length(unique(lapply(fitted, f))) <= 1L
  stopifnot(all(ok), !is.null(names(m)) || !length(m), !anyDuplicated(names(m)),
            !length(m) || identical(names(m), vapply(m, function(e) as.character(e$grasp), "", USE.NAMES = FALSE)),
            same(function(e) e$dofs), same(function(e) e$rate), same(function(e) e$unit),
            identical(x$classes, names(fitted) %||% character(0)),
            is.character(x$distance), x$distance %in% c("likelihood", "residual"))
  x
}

# A type whose fit failed, from the error it raised: the set's null model.
new_grasp_model_failed <- function(grasp, error) {
  structure(list(grasp = grasp, grasp_id = feix_ids(grasp),
                 message = gsub("\\s*\n\\s*", " ", cli::ansi_strip(conditionMessage(error))),
                 class = class(error)[1]),
            class = "grasp_model_failed")
}

#' @export
print.grasp_model_failed <- function(x, ...) {
  cli::cat_line("<grasp_model_failed> ", x$grasp, ": ", x$message)
  cli::cat_line("  (", x$class, ")")
  invisible(x)
}

# The fitted models of a set (a plain named list) and its failed types (a
# data frame: grasp, message, class).
fitted_models <- function(x) {
  m <- x$models
  m[vapply(m, inherits, logical(1), "grasp_model")]
}

failed_types <- function(x) {
  f <- x$models[vapply(x$models, inherits, logical(1), "grasp_model_failed")]
  data.frame(grasp = vapply(f, `[[`, "", "grasp"), message = vapply(f, `[[`, "", "message"),
             class = vapply(f, `[[`, "", "class"), stringsAsFactors = FALSE, row.names = NULL)
}

#' @export
`[.grasp_models` <- function(x, i, ...) {
  if (missing(i)) return(x)
  keep <- if (is.character(i) || is.factor(i)) {
    resolve_labels(i, model_set_levels(x), "i")
  } else if (is.logical(i)) {
    if (length(i) != length(x)) {
      hm_abort("A logical index must have length {length(x)}, not {length(i)}.", "bad_input", argument = "i")
    }
    names(x)[i & !is.na(i)]
  } else {
    names(x)[check_positions(i, length(x), "model")]
  }
  check_types_present(x, keep, "i", rlang::caller_env())
  new_grasp_models(x$models[keep], seed = x$seed, levels = x$levels, temperature = x$temperature,
                   distance = x$distance)
}

# Grasp types asked of a model set (`arg`) that it has no model for: an
# error that lists the types it does have (the first eight, so a 33-type set
# stays one line), since the user's next call needs one of them.
check_types_present <- function(x, types, arg, call) {
  absent <- setdiff(types, names(x))
  if (!length(absent)) return(invisible(types))
  have <- cli::cli_vec(names(x), list("vec-trunc" = 8))
  hm_abort(c("No model for grasp type{?s} {.val {absent}} in this set.",
             i = "It has models for {length(have)} type{?s}: {.val {have}}."),
           "unknown_grasp", argument = arg, call = call)
}

# Fitted models chosen by grasp name or id, for generate(): every fitted one
# by default (a warning names the failed types), an error for a failed type
# asked for by name.
select_models <- function(x, grasps, call) {
  failed <- failed_types(x)
  if (is.null(grasps)) {
    if (nrow(failed)) {
      hm_warn(c("Skipping the grasp type{?s} whose model failed: {.val {failed$grasp}}.",
                i = "See {.code print()} of the model set for the reasons."), "model_failed",
              grasp = failed$grasp)
    }
    return(fitted_models(x))
  }
  keep <- check_grasp_selection(grasps, "grasps", levels = model_set_levels(x), call = call)
  check_types_present(x, keep, "grasps", call)
  bad <- failed[failed$grasp %in% keep, , drop = FALSE]
  if (nrow(bad)) {
    hm_abort(c("The model of {.val {bad$grasp}} could not be fitted, so it cannot generate.",
               x = "{bad$message}"), "model_failed", argument = "grasps", grasp = bad$grasp, call = call)
  }
  fitted_models(x)[keep]
}

#' @export
print.grasp_models <- function(x, ...) {
  s <- summary(x)
  f <- failed_types(x)
  s <- s[is.na(s$failed), , drop = FALSE]
  failed <- if (nrow(f)) sprintf(", %d failed", nrow(f)) else ""
  cli::cat_line(cli::pluralize("<grasp_models> {nrow(s)} grasp type model{?s}{failed}"))
  if (nrow(s)) {
    cli::cat_line(sprintf("  recordings used: %d of %d; target lengths %d to %d frames", sum(s$n_used),
                          sum(s$n_input), as.integer(min(s$target_length)), as.integer(max(s$target_length))))
    n_linear <- sum(s$warping == "linear")
    n_em <- sum(s$n_em_fallback)
    cli::cat_line(cli::pluralize(
      "  linear warping: {n_linear} type{?s}; EM fallbacks: {n_em} DoF{?s} in {sum(s$n_em_fallback > 0)} type{?s}"))
    # (models whose DoFs are all constant have no variance to explain)
    if (any(is.finite(s$min_var))) {
      cli::cat_line(sprintf("  variance explained by the FPCs per DoF: min %.1f%%, mean %.1f%%",
                            min(s$min_var, na.rm = TRUE), mean(s$mean_var, na.rm = TRUE)))
    }
    dep <- table(s$dependence)
    by_dependence <- paste(vapply(names(dep), function(d) cli::pluralize("{d} ({dep[[d]]} type{?s})"), ""),
                           collapse = ", ")
    cli::cat_line("  dependence: ", by_dependence, "; mixtures replaced by one Gaussian by the guard: ",
                  sum(s$n_guarded))
    # every type is fitted with the same arguments: the first model's say them
    cli::cat_line(format_settings(unclass(fitted_models(x))[[1]]$settings))
  }
  dg <- models_degeneracies(x)
  if (nrow(dg)) {
    types <- unique(sub(": .*", "", dg$message))
    cli::cat_line(cli::pluralize(
      "  degenerate data in {length(types)} type{?s}: {name_list(types, 5L)} (see each model's print())"))
  }
  if (!is.null(x$temperature) && nrow(s) > 1L) {
    cli::cat_line(sprintf("  class probabilities: softmax(-distance / %.3g), distance: %s (see ?fit_grasp_models)",
                          x$temperature, models_distance(x)))
  }
  if (nrow(f)) cli::cat_line("  failed: ", paste0(f$grasp, " (", f$message, ")", collapse = "; "))
  invisible(x)
}

#' Summarise a set of grasp models
#'
#' One row per grasp type, the material of the thesis' Tables 5.1 (warping
#' and EM fallbacks) and 5.2 (variance explained).
#'
#' @param object A `grasp_models` set from [fit_grasp_models()].
#' @param ... Unused.
#' @return A data frame with columns `grasp_id`, `grasp`, `n` (the
#'   recordings the type's model was fitted on: the first three columns of
#'   every classifier's summary, see [summary.grasp_classifier()]), `n_input`,
#'   `n_used` (the same as `n`), `n_overlong` (removed as over-long), `n_degenerate` (removed
#'   for a degenerate warp: `degenerate_warps = "drop"`, the thesis' rule),
#'   `n_warp_fallback` (recordings whose DTW warp was degenerate, kept with a
#'   slope-constrained or linear warp: `degenerate_warps = "constrain"`),
#'   `target_length`, `warping` (`"dtw"` or
#'   `"linear"`), `em_fallback` (the DoFs whose mixture fell back to a single
#'   Gaussian, e.g. `"MCP3, DIP4"`, empty when none), `n_em_fallback`,
#'   `constant_dofs`, `dependence` (`"independent"` or `"copula"`),
#'   `n_guarded` (mixtures the mixture guard replaced by one Gaussian), and `min_var`, `median_var`, `mean_var`, `max_var`: the
#'   percentage of variance explained by the FPCs of each DoF, summarised over
#'   DoFs, and `failed`: `NA` for a fitted type, the error message for a type
#'   whose fit failed (its other figures `NA`).
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 4, grasps = 1:2, objects = 2, trials = 2, seed = 1)
#' summary(fit_grasp_models(g, seed = 1))
summary.grasp_models <- function(object, ...) {
  check_grasp_models(object, "object", "be summarised")
  rows <- lapply(object$models, function(m) {
    if (inherits(m, "grasp_model_failed")) {
      return(data.frame(grasp_id = m$grasp_id, grasp = m$grasp, n = NA_integer_, n_input = NA_integer_, n_used = NA_integer_,
                        n_overlong = NA_integer_, n_degenerate = NA_integer_, n_warp_fallback = NA_integer_,
                        target_length = NA_integer_,
                        warping = NA_character_, em_fallback = NA_character_, n_em_fallback = NA_integer_,
                        constant_dofs = NA_character_, dependence = NA_character_, n_guarded = NA_integer_,
                        min_var = NA_real_, median_var = NA_real_, mean_var = NA_real_, max_var = NA_real_,
                        failed = m$message, stringsAsFactors = FALSE))
    }
    ve <- 100 * rowSums(model_var_explained(m))
    fb <- m$fallbacks
    em <- fb$dof[fb$step == "mixture"]
    const <- fb$dof[fb$step == "fpca"]
    stat <- function(f) if (all(is.na(ve))) NA_real_ else f(ve, na.rm = TRUE)
    data.frame(grasp_id = m$grasp_id, grasp = m$grasp, n = m$n_used, n_input = m$n_input, n_used = m$n_used,
               n_overlong = sum(m$removed$reason == "overlong"),
               n_degenerate = sum(m$removed$reason == "degenerate warp"),
               n_warp_fallback = NROW(m$warping$degenerate),
               target_length = m$target_length, warping = m$warping$method,
               em_fallback = paste(em, collapse = ", "), n_em_fallback = length(em),
               constant_dofs = paste(const, collapse = ", "),
               dependence = m$dependence$type %||% "independent",
               n_guarded = sum(fb$step %in% c("mixture_guard", "warp_mixture_guard")),
               min_var = stat(min), median_var = stat(stats::median), mean_var = stat(mean),
               max_var = stat(max), failed = NA_character_, stringsAsFactors = FALSE)
  })
  out <- if (length(rows)) do.call(rbind, rows) else
    data.frame(grasp_id = integer(), grasp = character(), n = integer(), n_input = integer(), n_used = integer(),
               n_overlong = integer(), n_degenerate = integer(), n_warp_fallback = integer(),
               target_length = integer(),
               warping = character(), em_fallback = character(), n_em_fallback = integer(),
               constant_dofs = character(), dependence = character(), n_guarded = integer(),
               min_var = numeric(), median_var = numeric(),
               mean_var = numeric(), max_var = numeric(), failed = character(), stringsAsFactors = FALSE)
  rownames(out) <- NULL
  structure(out, class = c("summary_grasp_models", "data.frame"))
}

#' @export
print.summary_grasp_models <- function(x, ...) {
  d <- as.data.frame(unclass(x)[names(x)], stringsAsFactors = FALSE)
  bad <- !is.na(d$failed)
  failed <- if (any(bad)) sprintf(", %d failed", sum(bad)) else ""
  cli::cat_line(cli::pluralize("Grasp models: {sum(!bad)} type{?s}{failed}"))
  print(d[!bad, setdiff(names(d), "failed"), drop = FALSE], digits = 4, row.names = FALSE)
  if (any(bad)) {
    cli::cat_line("Failed types:")
    print(d[bad, c("grasp", "failed"), drop = FALSE], row.names = FALSE)
  }
  invisible(x)
}
