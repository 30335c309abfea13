"""Any glove, any labels: the same path as R's, from Python."""

import os

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
    new = hm.generate(models, grasps="mug", n=3, seed=2)
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


FLEXGLOVE_PATTERN = r"^(?<grasp>[^/]+)/(?<subject>P\d)_(?<object>[a-z]+)_(?<trial>\d+)$"


def test_read_the_shipped_flexglove_folder():
    # the real recordings as the lab kept them: a folder per grasp, names repeating across
    # folders, uneven Arduino time stamps; no manifest
    path = hm.extdata("flexglove")
    g = hm.read_glove(path, glove="flexglove", time="time_ms", pattern=FLEXGLOVE_PATTERN)
    assert len(g) == 626
    assert len(g.failures) == 0 and len(hm.read_failures(g)) == 0
    assert g.meta["id"].is_unique
    assert sorted(set(g.meta["subject"])) == ["P1", "P2"]
    assert g.meta["subject"].value_counts().to_dict() == {"P1": 362, "P2": 264}
    folders = sorted(next(os.walk(path))[1])
    assert len(folders) == 8
    assert {s.lower() for s in set(g.meta["grasp"])} == {f.replace("_", " ").lower() for f in folders}
    assert g.rate == pytest.approx(1000 / 30)
    assert g.glove_name == "flexglove" and g.unit == "raw"
    assert g.meta["recorded_rate"].between(30, 40).all()
    assert "resampled" in repr(g)


def test_read_glove_time_column_and_folder_labels(tmp_path):
    # a planted straight line at uneven times comes back exactly on the constant grid
    rng = np.random.default_rng(5)
    times = {}
    for label, name in [("cup", "r1"), ("pen", "r1"), ("pen", "r2")]:
        t = 100 + np.concatenate([[0], np.cumsum(rng.uniform(15, 25, 40))])
        times[f"{label}/{name}"] = t
        (tmp_path / label).mkdir(exist_ok=True)
        pd.DataFrame({"t_ms": t, "a": 2 * t, "b": 5.0, "c": 1000 - t}).to_csv(
            tmp_path / label / f"{name}.csv", index=False)
    glove = pd.DataFrame({"channel": ["a", "b", "c"], "unit": "raw", "min": 0, "max": 5000})
    g = hm.read_glove(tmp_path, glove=glove, rate=50, time="t_ms", pattern="^(?<grasp>[^/]+)/")
    assert list(g.meta["id"]) == ["cup/r1", "pen/r1", "pen/r2"]
    assert list(g.meta["grasp"]) == ["cup", "pen", "pen"]
    assert g.rate == 50
    for rid, rec in zip(g.meta["id"], g.recordings):
        t = times[rid]
        grid = t[0] + 20 * np.arange(rec.shape[0])
        assert grid[-1] <= t[-1] < grid[-1] + 20
        np.testing.assert_allclose(rec[:, 0], 2 * grid, atol=1e-9)
        np.testing.assert_allclose(rec[:, 2], 1000 - grid, atol=1e-9)
    # bad time stamps: a classed error naming the file and line
    bad = tmp_path / "pen" / "r2.csv"
    bad.write_text("t_ms,a,b,c\n0,1,2,3\n20,1,2,3\n20,1,2,3\n")
    with pytest.raises(hm.BadFileError, match="r2.csv"):
        hm.read_glove(bad, glove=glove, time="t_ms")
    with pytest.warns(hm.HandmotionWarning, match="could not be read"):
        g = hm.read_glove(tmp_path, glove=glove, time="t_ms", pattern="^(?<grasp>[^/]+)/")
    assert list(g.failures["class"]) == ["handmotion_error_bad_time"]
    assert list(g.failures["line"]) == [4]
    with pytest.raises(hm.BadInputError, match="unit"):
        hm.read_glove(tmp_path, glove=glove, time="t", recursive=True)


def test_read_glove_files_named_one_by_one(tmp_path):
    glove = pd.DataFrame({"channel": ["a", "b"], "unit": "raw", "min": 0, "max": 1023})
    for label in ["cup", "pen"]:
        (tmp_path / label).mkdir()
        (tmp_path / label / "r1.csv").write_text("a,b\n1,2\n3,4\n")
    files = [tmp_path / "cup" / "r1.csv", tmp_path / "pen" / "r1.csv"]
    g = hm.read_glove(files, glove=glove, rate=10)
    assert len(g) == 2 and g.meta["id"].is_unique
    assert list(g.meta["id"].map(os.path.basename)) == ["r1", "r1"]


def test_read_glove_timestamps_folder(tmp_path):
    # times in files of their own, as the project's copy of the flexglove source keeps them
    glove = pd.DataFrame({"channel": ["a"], "unit": "raw", "min": 0, "max": 1023})
    for label in ["cup", "pen"]:
        (tmp_path / label).mkdir()
        (tmp_path / label / "r1.csv").write_text("a\n0\n10\n20\n30\n")
        (tmp_path / "timestamps" / label).mkdir(parents=True)
    (tmp_path / "timestamps" / "cup" / "r1.csv").write_text("time_ms\n100\n110\n130\n140\n")
    (tmp_path / "timestamps" / "pen" / "r1.csv").write_text("time_ms\n0\n20\n40\n60\n")
    g = hm.read_glove(tmp_path, glove=glove, time="time_ms", timestamps="timestamps",
                      pattern="^(?<grasp>[^/]+)/")
    assert list(g.meta["id"]) == ["cup/r1", "pen/r1"] and len(g.failures) == 0
    assert g.rate == pytest.approx(50)
    np.testing.assert_allclose(g.recordings[0][:, 0], [0, 15, 30])
