"""The R error-class hierarchy maps onto Python exceptions, and R warnings become Python warnings."""

import warnings

import pytest

from handmotion.errors import (BadFileError, BadInputError, BadRecordingError, BadSkeletonError,
                               FitFailedError, HandmotionError, RError, UnknownGraspError,
                               from_r_condition)


def r_classes(*specific, family):
    return [f"handmotion_error_{c}" for c in specific] + [f"handmotion_error_{family}", "handmotion_error",
                                                          "rlang_error", "error", "condition"]


@pytest.mark.parametrize("specific, family, expected", [
    (["truncated_line"], "bad_file", BadFileError),
    (["unknown_grasp"], "bad_input", UnknownGraspError),
    (["bad_recording"], "bad_input", BadRecordingError),
    (["no_labels"], "bad_input", BadInputError),
    (["too_few_recordings"], "fit_failed", FitFailedError),
])
def test_families_map_to_exception_classes(specific, family, expected):
    e = from_r_condition("msg", r_classes(*specific, family=family))
    assert type(e) is expected
    assert isinstance(e, HandmotionError) and e.r_message == "msg"


def test_specific_classes_are_caught_by_their_family():
    assert isinstance(from_r_condition("m", r_classes("unknown_grasp", family="bad_input")), BadInputError)
    assert isinstance(from_r_condition("m", r_classes("bad_recording", family="bad_input")), ValueError)
    skel = from_r_condition("m", r_classes("bad_skeleton", family="bad_file"))
    assert isinstance(skel, BadSkeletonError) and isinstance(skel, BadFileError)


def test_other_r_errors():
    assert type(from_r_condition("m", ["handmotion_error", "error"])) is HandmotionError
    assert type(from_r_condition("m", ["simpleError", "error"])) is RError


def test_r_errors_and_warnings_from_r(hm, ro):
    from handmotion import _bridge
    g = hm.simulate_grasps(subjects=1, grasps=[1], objects=1, trials=2, seed=1)
    with pytest.raises(FitFailedError):  # 2 recordings cannot carry 2 FPCs
        _bridge.call("fit_grasp_model", g[0:2], warping="linear")
    with pytest.raises(BadInputError):
        hm.simulate_grasps(subjects=0)
    # an R warning arrives as a Python HandmotionWarning carrying its R class
    warn = ro.r("function(m) { warning(m); 1 }")
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        _bridge.call(warn, "careful")
    got = [w.message for w in seen if isinstance(w.message, hm.HandmotionWarning)]
    assert got and "careful" in str(got[0]) and "warning" in got[0].r_class
