"""The R verbs mirrored in Python answer as R does (R/python-bridge.R carries the data)."""

import os
import shutil

import numpy as np
import pytest

EXT = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "extdata")


def test_bvh_round_trip(hm, small, tmp_path):
    f = hm.write_bvh(small[0:1], tmp_path / "a.bvh")
    with pytest.raises(hm.HandmotionError, match="exist"):
        hm.write_bvh(small[0:1], tmp_path / "a.bvh")
    b = hm.read_bvh(f)
    assert len(b) == 1 and all(":" in d for d in b.dofs)
    assert b.recordings[0].shape[0] == small.recordings[0].shape[0]


def test_skeleton_round_trip(hm, tmp_path):
    sk = hm.hand_skeleton()
    f = hm.write_skeleton(sk, tmp_path / "h.xmlskel")
    back = hm.read_skeleton(f)
    assert list(back.joints["name"]) == list(sk.joints["name"])
    num = [c for c in sk.joints.columns if c != "name" and c in back.joints.columns]
    np.testing.assert_allclose(back.joints[num].astype(float).to_numpy(na_value=np.nan),
                               sk.joints[num].astype(float).to_numpy(na_value=np.nan), atol=1e-6)
    with pytest.raises(hm.HandmotionError):
        hm.write_skeleton(sk, f)
    with pytest.raises(hm.BadInputError):
        hm.write_skeleton("not a skeleton", tmp_path / "x.xmlskel")


def test_graspdb14_verbs(hm, tmp_path):
    src = os.path.join(EXT, "graspdb14")
    if not os.path.isdir(src):
        pytest.skip("the GraspDB14 samples are not beside the package")
    d = tmp_path / "g14"
    shutil.copytree(src, d)
    (d / "junk.txt").write_text("not a motion file\n")
    with pytest.warns(hm.HandmotionWarning):
        g = hm.read_graspdb14(str(d))
    fails = hm.read_failures(g)
    assert list(fails["file"].map(os.path.basename)) == ["junk.txt"]
    h = hm.graspdb14_to_hust(g)
    assert len(h.dofs) == 16 and len(h) == len(g)
    # the switch states came through the bridge with the recordings
    assert g.switch is not None and all(len(s) == r.shape[0] for s, r in zip(g.switch, g.recordings))
    s = hm.segment_by_switch(g[0:1])
    runs = 1 + int(np.count_nonzero(np.diff(g.switch[0])))
    assert len(s) == runs
    assert sum(r.shape[0] for r in s.recordings) == g.recordings[0].shape[0]


def test_confusion_and_stream(hm, small):
    m = hm.fit_grasp_models(small, seed=1)
    res = hm.classify(m, small)
    conf = hm.grasp_confusion(res["classification"])
    assert conf.equals(res["confusion"])
    truth = list(small.meta["grasp"])
    by_labels = hm.grasp_confusion(truth, list(res["predictions"]["predicted"]))
    assert int(by_labels.to_numpy().sum()) == len(truth)
    stream = hm.start_recognition(hm.fit_grasp_recognizer(small))
    for row in small.recordings[0]:
        p = stream.update(row)
    assert abs(sum(p.values()) - 1) < 1e-9
    with pytest.raises(hm.BadInputError):
        hm.start_recognition(m)


def test_handover_error(hm, small):
    noisy = hm.Grasps([r + 2.0 for r in small.recordings[:2]], meta=small.meta.iloc[:2].drop(columns="n_frames"))
    err = hm.handover_error(small[0:2], noisy)
    # a planted constant offset of 2 degrees on every DoF
    assert err == pytest.approx(2.0, abs=1e-9)
    by = hm.handover_error(small[0:2], noisy, by="recording")
    assert len(by) == 2 and np.allclose(by["error"], 2.0)


def test_single_model_and_animation(hm, small, tmp_path):
    one = small[small.meta["grasp"] == "Tripod"]
    m = hm.fit_grasp_model(one, seed=1)
    s = m.summary()
    assert len(s) >= 1
    x = hm.generate(m, n=2, seed=2)
    assert len(x) == 2 and x.dofs == small.dofs
    f = hm.write_hand_animation(x[0], tmp_path / "a.gif", max_frames=5, width=80, height=80)
    assert (tmp_path / "a.gif").stat().st_size > 0 and f.endswith("a.gif")
    with pytest.raises(hm.HandmotionError):
        hm.write_hand_animation(x[0], tmp_path / "a.gif", max_frames=5, width=80, height=80)
    with pytest.raises(hm.BadInputError):
        hm.reproduce_thesis(tmp_path / "out", subjects=1)
