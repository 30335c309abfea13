"""handmotion: natural human hand motion for grasp animation, from Python.

A thin front end over the handmotion R package (through rpy2): the statistics all
run in R; this package converts data and errors. Seeds pass through unchanged, so
results are identical to R's for the same seed.

>>> import handmotion as hm
>>> g = hm.simulate_grasps(subjects=3, seed=1)
>>> m = hm.fit_grasp_models(g, seed=1)
>>> x = hm.generate(m, grasps="Power Sphere", n=10, seed=2)

Python = R
----------
Every user verb of the R package's exports has a Python function of the same name
and argument names (a test compares this list with R's NAMESPACE):

* data: ``simulate_grasps``, ``grasps`` (the :class:`Grasps` class), ``as_grasps``,
  ``segment_by_switch``
* your own glove: ``glove_profile``, ``read_glove``, ``calibrate``,
  ``calibration_pose_angles``, ``find_motion``, ``trim_motion``, ``cut_motion``
* formats: ``read_hust``, ``write_hust``, ``read_graspdb14``, ``write_graspdb14``,
  ``read_failures``, ``graspdb14_to_hust``, ``read_skeleton``, ``write_skeleton``,
  ``read_bvh``, ``write_bvh``
* hands: ``hand_skeleton``, ``forward_kinematics``
* models: ``fit_grasp_model``, ``fit_grasp_models``, ``project``
* generation: ``generate``, ``evaluate_generation``
* classification: ``fit_grasp_classifier``, ``classify``, ``fit_grasp_recognizer``,
  ``start_recognition``; R's ``predict()`` is the ``predict()`` method of every classifier
  handle, R's ``update()`` of a stream is ``RecognitionStream.update()``
* evaluation: ``evaluate_loso``, ``evaluate_early_recognition``, ``grasp_confusion``
* the thesis: ``reproduce_thesis``, ``thesis_table``
* hand-over: ``select_markers``, ``fit_handover``, ``handover_error``; R's ``predict()``
  (reconstruction) is ``HandoverModel.predict()``
* pictures: ``hand_3d``, ``write_hand_animation``

Argument names and their order are R's (``tests/test_signatures.py`` compares every
function here with R's ``formals()``): ``generate(x, n, grasps, ...)``,
``project(object, new_data)``, ``fit_handover(reference, markers, n_markers, ...)``. Each
function names the arguments users set (those added after R's positional ones are
keyword-only, so a positional call keeps its meaning) with R's defaults (the test compares
them too); R's other arguments, which each function's docstring lists, pass through
``**kwargs`` by their R names. An argument R renamed (``?handmotion-renamed``) is a
:class:`BadInputError` naming the new one.

What comes back: a fitted model is a handle (:class:`GraspModels`, :class:`GraspClassifier`,
...); recordings are a :class:`Grasps`; an R table is a pandas DataFrame. The three
evaluations whose R result has several parts, ``classify``, ``evaluate_loso`` and
``evaluate_generation``, return a dict: its tables as DataFrames, its figures as floats, and
the R result itself as a handle (``"classification"`` or ``"evaluation"``) for
``thesis_table`` and plotting in R. ``evaluate_early_recognition`` is one table, a DataFrame.

Deliberately not mirrored: ``autoplot`` (ggplot2 graphics belong to R; every result
is a DataFrame or numpy array to plot in Python), ``hand_3d_output`` and
``render_hand_3d`` (Shiny bindings, R-only), ``joint_map`` (R's mapping of DoFs to
skeleton joints, used inside forward_kinematics()) and ``python_bridge`` (the R entry this
package's bridge calls, ``?python_bridge``; it never reaches R's internals through ``:::``). Python-only helpers:
``joint_names`` (the joint order of ``forward_kinematics`` arrays) and ``extdata`` (the path
of a file or folder the R package ships, R's ``system.file("extdata", ...)``, e.g. the real
flexglove recordings for ``read_glove``).

Progress
--------
Long calls (``fit_grasp_models``, ``evaluate_loso``, ...) show R's progress bar
when they take more than 2 s: in a terminal, one bar redrawn in place on standard
output; when standard output is not a terminal (redirected to a log, a notebook,
pytest), none. R's options decide after that, e.g.
``handmotion._bridge.r().r("options(progressr.enable = FALSE)")`` for none at all.
``reproduce_thesis()`` prints one line per step with the time left (``progress=False``
for none).

Names R removed before its first release (``?handmotion-renamed``) are not kept as
aliases: asking for one raises an ``AttributeError`` that names the replacement.
"""

import os

from .api import (calibrate, calibration_pose_angles, classify, cut_motion, evaluate_early_recognition,
                  evaluate_generation, evaluate_loso, extdata, find_motion, fit_grasp_classifier, fit_grasp_model,
                  fit_grasp_models, fit_grasp_recognizer, fit_handover, forward_kinematics, generate, glove_profile,
                  grasp_confusion, graspdb14_to_hust, hand_skeleton, handover_error, joint_names, read_bvh,
                  read_failures, read_glove, read_graspdb14, read_hust, read_skeleton, reproduce_thesis,
                  segment_by_switch, select_markers, simulate_grasps, start_recognition, thesis_table, trim_motion,
                  write_bvh, write_graspdb14, write_hand_animation, write_hust, write_skeleton)
from .errors import (BadFileError, BadInputError, BadRecordingError, BadSkeletonError,
                     DegenerateDataWarning, FitFailedError, HandmotionError, HandmotionWarning, RError,
                     UnknownGraspError)
from .grasps import Grasps, as_grasps
from .handles import (GraspClassifier, GraspModel, GraspModels, GraspRecognizer, HandoverModel, RecognitionStream,
                      RHandle, Skeleton, project)
from .view import HandView, hand_3d


def _description_version():
    """The R package's version, read from its DESCRIPTION, the one place it is written: three
    folders up in the source tree (inst/python/handmotion), two in the installed R package
    (<library>/handmotion/python/handmotion). None when neither is there."""
    here = os.path.dirname(os.path.abspath(__file__))
    for up in (("..", "..", ".."), ("..", "..")):
        desc = os.path.join(here, *up, "DESCRIPTION")
        if os.path.isfile(desc):
            with open(desc, encoding="utf-8") as f:
                fields = dict(line.split(":", 1) for line in f if ":" in line and not line[0].isspace())
            if fields.get("Package", "").strip() == "handmotion" and "Version" in fields:
                return fields["Version"].strip()
    return None


_VERSION = _description_version()
if _VERSION is not None:
    __version__ = _VERSION

# R's grasps() constructor is the Grasps class
grasps = Grasps

# The names R removed (R/renamed.R, ?handmotion-renamed) that this package used to carry.
_RENAMED = {
    "fit_last_frame_pca": 'fit_grasp_classifier(x, method="last_frame", ncomp=...)',
    "fit_weighted_fpca": 'fit_grasp_classifier(x, method="weighted_fpca", models=..., time=...)',
    "rank_markers": "select_markers(x, n): the n top-ranked markers",
    "reconstruct": "model.predict(query) on the HandoverModel from fit_handover()",
    "table_5_1": 'thesis_table("5.1", models=...)',
    "table_5_2": 'thesis_table("5.2", models=...)',
    "table_5_3": 'thesis_table("5.3", classification=...)',
    "table_5_6": 'thesis_table("5.6", confusion=...)',
    "table_5_7": 'thesis_table("5.7", fit=..., pcs=...)',
    "table_5_8": 'thesis_table("5.8", confusion=..., held_out=...)',
}


def __getattr__(name):
    if name == "__version__":
        # no DESCRIPTION beside this folder: the version of the R package R loads
        from ._bridge import r

        return str(r().r('as.character(utils::packageVersion("handmotion"))')[0])
    if name in _RENAMED:
        raise AttributeError(f"handmotion.{name}() was removed (as in R, see ?handmotion-renamed); "
                             f"use {_RENAMED[name]}")
    raise AttributeError(f"module 'handmotion' has no attribute {name!r}")


__all__ = [
    "Grasps", "grasps", "as_grasps", "GraspModel", "GraspModels", "GraspClassifier", "GraspRecognizer",
    "RecognitionStream", "HandoverModel", "RHandle", "Skeleton",
    "HandmotionError", "BadInputError", "BadRecordingError", "UnknownGraspError", "BadFileError",
    "BadSkeletonError", "FitFailedError", "RError", "HandmotionWarning", "DegenerateDataWarning",
    "simulate_grasps", "segment_by_switch",
    "glove_profile", "read_glove", "calibrate", "calibration_pose_angles", "find_motion", "trim_motion",
    "cut_motion",
    "read_hust", "write_hust", "read_graspdb14", "write_graspdb14", "read_failures", "graspdb14_to_hust",
    "read_skeleton", "write_skeleton", "read_bvh", "write_bvh", "extdata",
    "hand_skeleton", "forward_kinematics", "joint_names",
    "fit_grasp_model", "fit_grasp_models", "project",
    "generate", "evaluate_generation",
    "fit_grasp_classifier", "classify", "fit_grasp_recognizer", "start_recognition",
    "evaluate_loso", "evaluate_early_recognition", "grasp_confusion",
    "reproduce_thesis", "thesis_table",
    "select_markers", "fit_handover", "handover_error",
    "hand_3d", "HandView", "write_hand_animation",
]
