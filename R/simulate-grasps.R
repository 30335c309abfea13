#' Simulate HUST-like grasp recordings
#'
#' The package's embedded default data. The HUST data set used by Jeppsson
#' (2017) (30 subjects x 33 Feix grasp types x 3 objects x 3 trials = 8910
#' recordings of 16 finger joint angles at 50 Hz, in degrees) is not
#' distributable, so `simulate_grasps()` generates recordings like it from a
#' biomechanical model, seeded and documented. Every parameter is listed in
#' the section Simulator parameters and can be replaced through `params`.
#'
#' @section The model:
#' * **Final posture** per grasp type, from the Feix taxonomy (which fingers
#'   wrap, which stay extended, thumb opposition, pad vs palm contact; see
#'   the parameter `posture_notes`).
#' * **Reach-to-grasp time course**: from a relaxed rest posture the hand
#'   opens to a peak aperture (fingers extend, thumb abducts) and then closes
#'   onto the final posture, holding it for a few frames. Both phases follow
#'   minimum-jerk profiles `10 t^3 - 15 t^4 + 6 t^5`; each finger's onset and
#'   peak time are jittered.
#' * **Subjects**: each subject is one hand: a few latent factors times a
#'   loading matrix move several joints together (hand size/flexion, thumb
#'   style, finger spread, proximal vs distal flexion, pinch style), plus the
#'   subject's own offsets, a per-type style, and a personal tempo.
#' * **Objects** of increasing size per type: larger objects give less flexion
#'   of the holding fingers, a wider peak aperture and slightly slower motion.
#' * **Trials**: tempo and small posture variation.
#' * **DIP joints** follow their PIP joint at about 2/3 of its angle.
#' * **Sensor noise**: small iid noise plus a slow drift per recording.
#'
#' @section Durations:
#' Frame counts vary by subject tempo and trial (about 10-15% coefficient of
#' variation, clipped so no ordinary recording looks over-long). For each type
#' the drawn lengths of the ordinary (not over-long) recordings are then
#' rescaled and rounded by largest remainders so that their mean is *exactly*
#' the type's target (parameter `target_frames`, at 50 Hz; at other
#' rates the target is scaled by `rate / 50` and the total rounded).
#' With `plant_overlong = TRUE` about `overlong_fraction` of each type's recordings
#' (10 of 270 by default) are 2-3 times the type's median length: a long
#' hesitation before the reach or a long final hold. Far beyond the usual
#' spread, they are caught by a fence such as
#' `n > max(Q3 + 3 * IQR, 1.5 * median)`. A few recordings per type and object
#' (`stall_per_object`, at most a tenth of them) also stall mid-closing for a
#' while, within ordinary length (a hesitation mid-motion). Alignment absorbs
#' such a stall by mapping many original frames onto one template frame; it is
#' not the flat, "held still" warping path of the thesis' Figure 5.1, which a
#' recording lacking part of the motion produces, so the aligner keeps most of
#' them. Both are flagged in the metadata.
#'
#' @section Seeds:
#' The result depends only on the arguments, never on the global random
#' number generator (whose state is left untouched). Each grasp type draws
#' from its own stream derived from `seed`, and subjects from another, so
#' `simulate_grasps(grasps = 5)` is exactly the type-5 part of
#' `simulate_grasps()`.
#'
#' @param subjects Number of subjects (a positive whole number).
#' @param grasps Grasp types to simulate: Feix ids (1-33) or names (see
#'   [feix_taxonomy]), without duplicates. Named, the names become the
#'   recordings' labels, e.g. `c(bottle = "Medium Wrap", card = "Lateral")`
#'   for a study of objects (see Your own glove).
#' @param objects Number of objects per type, of increasing size.
#' @param trials Number of trials per subject and object.
#' @param rate Sampling rate in Hz (at least 10).
#' @param seed Random seed (a whole number).
#' @param plant_overlong Plant the over-long recordings (`TRUE`) or not
#'   (a flag; the rule that finds over-long recordings is the `overlong`
#'   argument of [fit_grasp_model()]).
#' @param ... Unused: an argument of an earlier version (`overlong`) is an
#'   error naming its new name.
#' @param params `NULL` for the calibrated defaults, or a named list of
#'   simulator parameters to replace (see Simulator parameters).
#' @param glove `NULL` (the HUST joint angles in degrees) or a
#'   [glove_profile()] (or a shipped profile's name) to record through (see
#'   Your own glove).
#' @param rest,hold Seconds of rest before and of holding after the motion
#'   (each drawn from 0.7 to 1.3 times the value per recording); 0 for
#'   recordings cut to the motion, as HUST's are.
#' @param stuck Channels of `glove` that are stuck at one value throughout.
#' @param session_sd Standard deviation, in counts, of each subject's
#'   (session's) offset of a raw channel.
#' @section Your own glove:
#' With `glove`, `rest` or `hold` the recordings look like those of a data
#' glove in a lab: each channel of the profile reads the angle of the joint
#' axis it drives (channels no HUST DoF drives, such as finger spread, follow
#' the hand's closing), raw channels convert degrees to counts through the
#' profile's nominal map with a per-session offset and gain, noise of about
#' one count, rounding and clipping to the sensor's range; `stuck` channels
#' read one value throughout; the motion is framed by rest and hold phases,
#' whose true ends are kept as metadata columns `motion_start` and
#' `motion_end` (frames). Named `grasps` give the labels.
#' @return A [grasps()] object in degrees. Metadata columns: `id`, `grasp`,
#'   `subject` (`"S01"`, ...), `object` (`"small"`, `"medium"`, `"large"` for
#'   three objects), `trial`, `n_frames`, `source` (`"simulated"`),
#'   `overlong` and `stalled` (logical: planted anomalies) and `object_size`
#'   (relative size, 1 = the type's typical object).
#' @seealso [grasps()]
#' @export
#' @examples
#' g <- simulate_grasps(subjects = 3, grasps = c("Medium Wrap", "Tripod"), seed = 1)
#' g
#' summary(g)
#' head(g$meta)
#' # a raw-count glove, one person, objects as labels, rest and hold phases
#' raw <- simulate_grasps(subjects = 1, grasps = c(bottle = "Medium Wrap", pen = "Tripod"),
#'                        objects = 1, trials = 5, rate = 100, glove = "resistive",
#'                        rest = 1, hold = 1, stuck = "thumb_cross", seed = 1)
#' raw
simulate_grasps <- function(subjects = 30, grasps = 1:33, objects = 3, trials = 3, rate = 50, seed = 1,
                            plant_overlong = TRUE, params = NULL, glove = NULL, rest = 0, hold = 0,
                            stuck = NULL, session_sd = 20, ...) {
  call <- rlang::caller_env()
  check_no_dots(list(...), "simulate_grasps", call = call)
  subjects <- check_whole(subjects, "subjects", max = 1e5, call = call)
  objects <- check_whole(objects, "objects", max = 1e5, call = call)
  trials <- check_whole(trials, "trials", max = 1e5, call = call)
  types <- sim_check_types(grasps, call)
  check_rate(rate, call = call)
  if (rate < 10) {
    hm_abort(c("{.arg rate} must be at least 10 Hz for the simulator, not {.val {rate}}.",
               i = "Shorter recordings cannot hold the rest, opening, closing and hold phases."),
             "bad_input", argument = "rate", call = call)
  }
  # (a simulation is always seeded: NULL is not the current stream here)
  seed <- check_whole(seed, "seed", min = -.Machine$integer.max, max = .Machine$integer.max, call = call)
  plant_overlong <- check_flag(plant_overlong, "plant_overlong", call = call)
  if (!is.null(params) && (!is.list(params) || (length(params) && is.null(names(params))))) {
    hm_abort("{.arg params} must be a named list of simulator parameters, not {.obj_type_friendly {params}}.",
             "bad_params", argument = "params", call = call)
  }
  params <- do.call(simulator_params, c(params, list(.call = call)))
  # (checked before the early return of a plain simulation: NaN reached
  # `rest == 0` as a base R error, a bad session_sd passed unseen)
  rest <- check_number(rest, "rest", min = 0, max = 60, call = call)
  hold <- check_number(hold, "hold", min = 0, max = 60, call = call)
  session_sd <- check_number(session_sd, "session_sd", min = 0, max = 1e6, call = call)

  streams <- sim_streams(as.integer(seed))
  subj <- sim_subject_draws(streams[34L], subjects, ncol(params$loadings))
  design <- sim_design(subjects, objects, trials, params)
  parts <- lapply(types, function(g) {
    with_sim_seed(streams[g], sim_one_type(g, design, subj, params, rate, plant_overlong))
  })
  recs <- unlist(lapply(parts, `[[`, "recordings"), recursive = FALSE)
  meta <- do.call(rbind, lapply(parts, `[[`, "meta"))
  if (!is.null(names(grasps)) && all(nzchar(names(grasps)))) {
    # the user's labels for the simulated types
    meta$feix_type <- as.character(meta$grasp)
    lab <- names(grasps)[match(meta$grasp, as_feix_grasp(grasps))]
    meta$grasp <- factor(lab, levels = unique(names(grasps)))
  }
  out <- new_grasps(recs, meta, handmotion::hust_dofs$name, rate, "deg")
  if (is.null(glove) && rest == 0 && hold == 0) return(out)
  glove <- tryCatch(glove_profile(glove %||% "hust"), handmotion_error_bad_glove = function(e) {
    # (glove_profile() names its own argument, x)
    hm_abort("{.arg glove} is not a usable glove profile.", "bad_glove", argument = "glove", parent = e, call = call)
  })
  if (length(stuck) && !all(stuck %in% glove$channels$channel)) {
    hm_abort("{.arg stuck} names {.val {setdiff(stuck, glove$channels$channel)}}, not channels of the glove.",
             "bad_input", argument = "stuck", call = call)
  }
  sim_glove_protocol(out, glove, rest, hold, as.character(stuck), session_sd,
                     seed = (abs(seed) * 7919L + 101L) %% .Machine$integer.max)
}

sim_check_types <- function(grasps, call) {
  if (!is.null(names(grasps)) && (any(!nzchar(names(grasps))) || anyDuplicated(names(grasps)))) {
    hm_abort("Names of {.arg grasps} are the labels: give every type a name, once.",
             "bad_input", argument = "grasps", call = call)
  }
  if (length(grasps) == 0L || anyNA(grasps) || !(is.numeric(grasps) || is.character(grasps) || is.factor(grasps))) {
    hm_abort("{.arg grasps} must be Feix grasp ids (1-33) or names, without missing values.",
             "bad_input", argument = "grasps", call = call)
  }
  # check element by element so the message lists exactly the unknown ones
  known <- vapply(as.list(as.character(grasps)), function(x) {
    key <- if (is.numeric(grasps)) as.numeric(x) else x
    tryCatch({ as_feix_grasp(key); TRUE }, handmotion_error_unknown_grasp = function(e) FALSE)
  }, logical(1))
  if (!all(known)) {
    bad <- unique(as.character(grasps)[!known])
    hm_abort(c("{.arg grasps} has unknown grasp type{?s} {.val {bad}}.",
               i = "Use Feix ids 1-33 or names from {.code feix_taxonomy$name}."),
             "unknown_grasp", argument = "grasps", grasp = bad, call = call)
  }
  f <- as_feix_grasp(if (is.factor(grasps)) as.character(grasps) else grasps)
  ids <- as.integer(f)
  if (anyDuplicated(ids)) {
    hm_abort("{.arg grasps} lists {.val {unique(as.character(f[duplicated(ids)]))}} more than once.",
             "bad_input", argument = "grasps", call = call)
  }
  ids
}
