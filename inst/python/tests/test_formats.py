"""Readers, writers, skeleton, forward kinematics and BVH from Python."""

import os

import numpy as np
import pytest


def shared_graspdb14():
    env = os.environ.get("HANDMOTION_SHARED")
    candidates = [env] if env else []
    here = os.path.dirname(os.path.abspath(__file__))
    for up in range(1, 7):
        candidates.append(os.path.join(here, *[".."] * up, "shared"))
    for c in candidates:
        if c and os.path.isdir(os.path.join(c, "data", "graspdb14")):
            return os.path.join(c, "data", "graspdb14")
    return None


def extdata(ro, *parts):
    return str(ro.r["system.file"]("extdata", *parts, package="handmotion")[0])


def test_read_graspdb14_real_sample(hm):
    d = shared_graspdb14()
    if d is None:
        pytest.skip("shared GraspDB14 samples are not present")
    g = hm.read_graspdb14(os.path.join(d, "01_11_ex03-rad-004-grasp-su04.txt"))
    assert len(g) == 1
    assert g.recordings[0].shape == (282, 23)
    assert g.meta["grasp"].tolist() == ["Power Sphere"]
    assert abs(g.rate - 60) < 1
    assert g.unit == "rad"


def test_directory_read_reports_failures(hm, tmp_path, ro):
    src = extdata(ro, "graspdb14")
    files = sorted(f for f in os.listdir(src) if f.endswith(".txt") and "annot" not in f)
    good = files[0]
    (tmp_path / good).write_bytes(open(os.path.join(src, good), "rb").read())
    (tmp_path / "01_05_ex03-rad-001-grasp-su01.txt").write_text("2014 09 15 08 02 09.0 1 0.1 0.2\n")
    with pytest.warns(hm.HandmotionWarning, match="could not be read"):
        g = hm.read_graspdb14(str(tmp_path))
    assert len(g) == 1
    assert len(g.failures) == 1
    assert "01_05_ex03" in g.failures["file"].iloc[0]


def test_bad_file_raises_classed_error(hm, tmp_path):
    bad = tmp_path / "01_05_ex03-rad-001-grasp-su01.txt"
    bad.write_text("2014 09 15 08 02 09.0 1 0.1 0.2\n")
    with pytest.raises(hm.BadFileError) as info:
        hm.read_graspdb14(str(bad))
    assert "handmotion_error_bad_file" in info.value.r_class


def test_hust_round_trip(hm, small, tmp_path):
    sub = small[:4]
    hm.write_hust(sub, str(tmp_path))
    back = hm.read_hust(str(tmp_path))
    assert len(back) == 4
    by_id = {i: r for i, r in zip(back.meta["id"], back.recordings)}
    for rid, rec in zip(sub.meta["id"], sub.recordings):
        np.testing.assert_allclose(by_id[rid], rec, atol=1e-6)


def test_skeleton_fk_and_bvh(hm, small, tmp_path):
    sk = hm.hand_skeleton()
    joints = sk.joints
    assert "root" in joints["name"].tolist()
    one = hm.forward_kinematics(small[0])          # a Grasps of one: still a list
    assert isinstance(one, list) and len(one) == 1
    pos = hm.forward_kinematics(small.recordings[0])  # a 2-D array: an array
    np.testing.assert_array_equal(pos, one[0])
    assert pos.ndim == 3 and pos.shape[0] == small.recordings[0].shape[0] and pos.shape[2] == 3
    assert pos.shape[1] == len(hm.joint_names())
    many = hm.forward_kinematics(small[:2])
    assert isinstance(many, list) and len(many) == 2
    out = hm.write_bvh(small[0], str(tmp_path / "g.bvh"))
    text = open(out).read()
    assert text.startswith("HIERARCHY") and "MOTION" in text


def test_read_skeleton_real(hm):
    d = shared_graspdb14()
    if d is None:
        pytest.skip("shared GraspDB14 samples are not present")
    sk = hm.read_skeleton(os.path.join(d, "default.xmlskel"))
    assert len(sk.joints) == 25
