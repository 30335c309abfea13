"""The "Real recordings" article's path from Python: the shipped flexglove files to segmentation,
models, held-out accuracy and generated grasps, each step giving the numbers R gives."""

import numpy as np
import pytest

import handmotion as hm

FLEXGLOVE_PATTERN = r"^(?<grasp>[^/]+)/(?<subject>P\d)_(?<object>[a-z]+)_(?<trial>\d+)$"


@pytest.fixture(scope="module")
def flex():
    return hm.read_glove(hm.extdata("flexglove"), glove="flexglove", time="time_ms",
                         pattern=FLEXGLOVE_PATTERN)


@pytest.fixture(scope="module")
def flex_r(ro):
    # the same one-liner in R, for comparison
    return ro.r(
        'handmotion::read_glove(system.file("extdata", "flexglove", package = "handmotion"), '
        'glove = "flexglove", time = "time_ms", '
        r'pattern = "^(?<grasp>[^/]+)/(?<subject>P\\d)_(?<object>[a-z]+)_(?<trial>\\d+)$")'
    )


def test_segmentation_matches_r(flex, flex_r, ro):
    m = hm.find_motion(flex)
    m_r = ro.r["as.data.frame"](ro.r["find_motion"](flex_r))
    assert len(m) == 626
    np.testing.assert_array_equal(np.asarray(m["start"]), np.asarray(m_r.rx2("start")))
    np.testing.assert_array_equal(np.asarray(m["end"]), np.asarray(m_r.rx2("end")))
    # people rest before they grasp: the motion does not start at the first frame
    assert np.median(np.asarray(m["rest"])) / flex.rate > 0.1


def test_models_keep_the_recordings(flex):
    ms = hm.fit_grasp_models(flex, seed=1)
    s = ms.summary()
    assert s["n_used"].sum() / s["n_input"].sum() >= 0.95


def test_held_out_accuracy_matches_r(flex, flex_r, ro):
    ev = hm.evaluate_loso(flex, method="discriminant", in_sample=False)
    ev_r = ro.r["evaluate_loso"](flex_r, method="discriminant", in_sample=False)
    held_out_r = float(ev_r.rx2("accuracy").rx2("held_out")[0])
    assert ev["accuracy"]["held_out"] == pytest.approx(held_out_r, abs=1e-12)
    # one participant predicts the other well above chance (8 types: 12.5%)
    assert ev["accuracy"]["held_out"] > 0.5


def test_generated_against_real_by_participant(flex):
    res = hm.evaluate_generation(recordings=flex, split="subject", folds=2, reps=1,
                                 fit={"thesis": {}})
    overall = res["overall"]
    mmd = overall[overall["metric"] == "mmd"]
    assert list(mmd["model"]) == ["thesis"]
    assert np.isfinite(mmd["ratio"]).all()
    outside = overall[overall["metric"] == "outside_limits"]
    assert (outside["generated"] == 0).all()
