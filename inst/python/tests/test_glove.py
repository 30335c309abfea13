"""Any glove, any labels: the same path as R's, from Python."""

import numpy as np
import pandas as pd
import pytest

import handmotion as hm


@pytest.fixture(scope="module")
def raw():
    return hm.simulate_grasps(subjects=1, grasps={"bottle": 1, "mug": 9, "pen": 22}, objects=1, trials=8,
                              rate=100, glove="resistive", rest=1, hold=1, stuck="thumb_cross", seed=3)


def test_labels_and_glove_cross_the_bridge(raw):
    assert sorted(set(raw.meta["grasp"])) == ["bottle", "mug", "pen"]
    assert raw.levels == ["bottle", "mug", "pen"]
    assert raw.unit == "raw"
    assert raw.glove_name == "resistive"
    assert list(raw.glove.loc[raw.glove["stuck"], "channel"]) == ["thumb_cross"]
    back = hm.Grasps.from_r(raw.to_r())
    assert back.glove_name == "resistive"
    assert back.levels == raw.levels
    np.testing.assert_array_equal(back.recordings[3], raw.recordings[3])


def test_profiles_calibration_and_motion(raw):
    prof = hm.glove_profile("cyberglove18")
    assert len(prof) == 18 and prof.attrs["name"] == "cyberglove18"
    deg = hm.calibrate(raw)
    assert deg.unit == "deg"
    assert set(deg.calibration["source"]) == {"nominal"}
    m = hm.find_motion(raw)
    planted = raw.meta["motion_start"].to_numpy()
    assert np.mean(np.abs(m["start"].to_numpy() - planted)) < 10
    t = hm.trim_motion(raw)
    assert all(t.meta["n_frames"] < raw.meta["n_frames"])


def test_models_evaluation_and_generation_on_raw_counts(raw):
    models = hm.fit_grasp_models(raw, seed=1)
    assert sorted(models.grasp_types()) == ["bottle", "mug", "pen"]
    new = hm.generate(models, grasp="mug", n=3, seed=2)
    assert set(new.meta["grasp"]) == {"mug"}
    x = np.concatenate(new.recordings)
    assert x.min() >= 0 and x.max() <= 1000
    ev = hm.evaluate_loso(raw, method="discriminant", folds=4)
    assert ev["accuracy_ci"]["lower"] <= ev["accuracy"]["held_out"] <= ev["accuracy_ci"]["upper"]
    assert ev["evaluation"] is not None


def test_read_glove_files(tmp_path, raw):
    for i in range(6):
        pd.DataFrame(raw.recordings[i], columns=raw.dofs).to_csv(
            tmp_path / f"{raw.meta['grasp'][i]}_{i}.csv", index=False)
    with pytest.warns(hm.HandmotionWarning, match="constant over every recording"):
        g = hm.read_glove(str(tmp_path), glove="resistive", rate=100,
                          pattern="^(?<grasp>[a-z]+)_(?<trial>\\d+)$")
    assert len(g) == 6
    assert g.glove_name == "resistive"
