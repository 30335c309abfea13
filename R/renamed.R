# Where the functions of earlier development versions went. 0.1.0 has not
# been released, so renamed and folded functions are gone rather than kept as
# aliases; this page (found under each old name by `?old_name`) says what to
# call instead.

#' Renamed and folded functions
#'
#' Before the first release the user API was cut to the verbs a user calls;
#' these functions of earlier development versions are gone. `?old_name`
#' opens this table.
#'
#' | was | now |
#' |---|---|
#' | `table_5_1(models)` ... `table_5_8(confusion)`, `table_5_3_claims()` | [thesis_table()]`("5.1", models = )` ... |
#' | `plot_pose_grid(list(recorded = a, generated = b))` | `autoplot(a, type = "poses", label = "recorded", compare = list(generated = b))` ([autoplot.grasps()]) |
#' | `plot_frame_strip(...)` | `autoplot(x, type = "strip", ...)` |
#' | `plot_frame_counts(x, rule = )` | `autoplot(x, type = "frame_counts", overlong = )` |
#' | `plot_marker_sets(sets)` | `autoplot(hand_skeleton(), markers = sets)` ([autoplot.hand_skeleton()]) |
#' | `plot_handover_components(model, truth, recs)` | `autoplot(model, truth, recs)` ([autoplot.handover_model()]) |
#' | `animate_hand(x, "f.html")` | [write_hand_animation()]`(x, "f.html")` |
#' | `predict(model, x)`, `predict(models, x)` (FPC projections) | [project()]`(model, x)`, `project(models, x)` |
#' | `predict(classifier, newdata = )` (a factor or a probability matrix) | `predict(classifier, new_data = )$.pred_class`; `type = "prob"` gives a data frame with columns `.pred_<class>` ([predict.grasp_models()]) |
#' | `predict(recognizer, x, frames = )` (one of `frames`, `ms`, `fraction` required) | `predict(recognizer, x)` sees the whole recording by default |
#' | `read_bvh(f)$joints`, `$offsets`, `$channels`, `$frame_time`, `$motion` (a list) | `read_bvh(f)` is a [grasps()] object: `attr(x, "bvh")$joints` (and `$offsets`, `$channels`, `$frame_time`, `$position`), the rotation channels in `x$recordings[[1]]` |
#' | `as_grasp_confusion(x)` | [grasp_confusion()]`(x)` |
#' | `distance_table(cl)` | `thesis_table("5.3", classification = cl)` |
#' | `default_joint_map(dofs)`, `graspdb14_joint_map()`, `hust_joint_map()` | [joint_map()]`(dofs = )`, `joint_map("graspdb14")`, `joint_map("hust")` |
#' | `clamp_to_limits()` | `generate(limits = TRUE)` for generated grasps |
#' | `markers_from_angles(x, markers = )`, `hand_marker_set()` | [forward_kinematics()]`(x, markers = )`; the markers are listed in [select_markers()] |
#' | `handpicked_markers()`, `search_markers(x, n)` | [select_markers()]`(method = "handpicked")`, `select_markers(x, n, method = "search")` |
#' | `handover_pca_error(ref, data)` | [handover_error()]`(data, by = "ncomp", reference = ref)` |
#' | `align_recordings(recs)` | a fitted model's `alignment` ([fit_grasp_model()]), `autoplot(model, type = "alignment")` |
#' | `overlong_rule()`, `find_overlong()` | the `overlong` argument of [fit_grasp_model()] |
#' | `simulator_params(...)` | `simulate_grasps(params = list(...))` |
#' | `calibration_report()` | `data-raw/calibration-report.R` in the source repository (the simulator's calibration; not installed) |
#' | `fit_frame_pca_model()` | internal: Figure 5.3 of the thesis report, [reproduce_thesis()] |
#' | `fit_last_frame_pca(x, k = 5)` | [fit_grasp_classifier()]`(x, method = "last_frame", ncomp = 5)` |
#' | argument `k` of `fit_grasp_model()`, `fit_grasp_models()`, `evaluate_loso(fit_args = )` (mixture components) | `mixture_components` |
#' | argument `k` of `fit_grasp_classifier(method = "last_frame")` (principal components) | `ncomp` |
#' | argument `newdata` of `predict()` of a hand-over model, `autoplot()` of a grasp model | `new_data`, as in every `predict()` method |
#' | argument `k` of `fit_handover()`, `select_markers(method = "search")`, `handover_error(by = "markers")` (neighbours) | `neighbours` |
#' | `$k`, `$k_used` of a last-frame classifier / a hand-over model | `$ncomp`, `$ncomp_used` / `$neighbours`, `$neighbours_used` |
#' | `fit_weighted_fpca(x, models = , time = )` | `fit_grasp_classifier(x, method = "weighted_fpca", models = , time = )` |
#' | `fit_grasp_classifier(x, at = , prior = )` | unchanged: `method = "discriminant"` is the default |
#' | class `grasp_classifier` of the discriminant (`fit_grasp_classifier(method = "discriminant")`) | `grasp_discriminant`; `grasp_classifier` is now the parent class of every fitted classifier ([summary.grasp_classifier()]); a discriminant saved by an earlier version is refused with a classed error saying to refit it |
#' | columns `metric`, `estimate` of `summary()` of a confusion matrix; `metric` of an evaluation's | `.metric`, `.estimate` (yardstick's names) |
#' | column `class` of `summary()` of a `fit_grasp_classifier()` or `fit_grasp_recognizer()` result | `grasp`, after `grasp_id`, as in every classifier's summary |
#' | argument `grasp` of `generate()` of a model set and of `autoplot(x, type = "frame_counts")` (types to select) | `grasps`, as in [fit_grasp_models()], [simulate_grasps()], [reproduce_thesis()] (`fit_grasp_model(grasp = )`, the one type's label, stays) |
#' | argument `overlong` of `simulate_grasps()` (a flag) | `plant_overlong`; `overlong` is the over-long rule of [fit_grasp_model()] and [evaluate_generation()] |
#' | `fit_handover(x, markers = n)` (a count) | `fit_handover(x, n_markers = n)`; `markers` is a marker set, as in [forward_kinematics()] and [hand_3d()] |
#' | argument `loso_folds` of `reproduce_thesis()` | `folds`; `folds = NULL` is one fold per subject in every verb that has it |
#' | `evaluate_generation(recordings_set, folds = )` (the first argument switching to folds) | `evaluate_generation(recordings = , folds = )`; `models` takes model sets only |
#' | `rank_markers(x, weighting = )` | `attr(`[select_markers()]`(x, n, weighting = ), "ranking")`; `select_markers(x, n)` takes the top `n` |
#' | `compare_marker_sets(reference, test, sets = )` | [handover_error()]`(test, by = "markers", reference = reference, sets = )` |
#' | `reconstruct(model, query)` | `predict(model, query)` ([predict.handover_model()]) |
#' | `hand_pose(x, frame = )` + `autoplot()` | `autoplot(x, type = "hand", frame = )` ([autoplot.grasps()]); a skeleton's rest pose: `autoplot(hand_skeleton())` |
#'
#' @name handmotion-renamed
#' @aliases table_5_1 table_5_2 table_5_3 table_5_3_claims table_5_6 table_5_7 table_5_8
#'   plot_pose_grid plot_frame_strip plot_frame_counts plot_marker_sets plot_handover_components
#'   animate_hand as_grasp_confusion distance_table default_joint_map graspdb14_joint_map
#'   hust_joint_map clamp_to_limits markers_from_angles hand_marker_set handpicked_markers
#'   search_markers handover_pca_error align_recordings overlong_rule find_overlong simulator_params
#'   calibration_report fit_frame_pca_model fit_last_frame_pca fit_weighted_fpca rank_markers
#'   compare_marker_sets hand_pose reconstruct
#' @keywords internal
NULL
