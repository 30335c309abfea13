"""The bad-input table through the Python front end: each row a call and the exception family it
must raise (R's handmotion_error_* families arrive as BadInputError, BadFileError, FitFailedError).
A row that raises RError (a generic R error) or returns a result means the R function needs fixing."""

import warnings

import numpy as np
import pytest

from handmotion import _bridge
from handmotion.errors import (BadFileError, BadInputError, DegenerateDataWarning, FitFailedError,
                               HandmotionWarning)


@pytest.fixture(scope="module")
def files(tmp_path_factory, hm, small):
    d = tmp_path_factory.mktemp("bad_input")
    (d / "binary.xmlskel").write_bytes(bytes(range(256)))
    (d / "01_ex01-rad-002-grasp-su09.txt").write_bytes(bytes(range(256)))
    allbad = d / "allbad"
    allbad.mkdir()
    (allbad / "01_ex01-rad-002-grasp-su09.txt").write_bytes(bytes(range(256)))
    (allbad / "b.txt").write_text("x\n")
    hust = d / "hust"
    hm.write_hust(small[0:2], str(hust))
    (hust / "manifest.csv").write_bytes(b"\x80\xff\x00\x41")
    return d


@pytest.fixture(scope="module")
def models(hm, small):
    return hm.fit_grasp_models(small, seed=1)


@pytest.fixture(scope="module")
def handover(hm, small):
    return hm.fit_handover(small, n_markers=3, neighbours=40)


ANG = np.full((3, 16), 10.0)

CASES = [
    # readers
    ("read_graspdb14: missing path", lambda hm, s, m, h, d: hm.read_graspdb14(str(d / "nope.txt")), BadFileError),
    ("read_graspdb14: binary file",
     lambda hm, s, m, h, d: hm.read_graspdb14(str(d / "01_ex01-rad-002-grasp-su09.txt")), BadFileError),
    ("read_graspdb14: every file bad", lambda hm, s, m, h, d: hm.read_graspdb14(str(d / "allbad")), BadFileError),
    ("read_graspdb14: misspelt truncated",
     lambda hm, s, m, h, d: hm.read_graspdb14(str(d / "allbad"), truncated="dorp"), BadInputError),
    ("read_hust: binary manifest", lambda hm, s, m, h, d: hm.read_hust(str(d / "hust")), BadFileError),
    ("read_hust: missing path", lambda hm, s, m, h, d: hm.read_hust(str(d / "nope")), BadFileError),
    ("read_skeleton: binary file", lambda hm, s, m, h, d: hm.read_skeleton(str(d / "binary.xmlskel")), BadFileError),
    # writers
    ("write_hust: negative digits", lambda hm, s, m, h, d: hm.write_hust(s, str(d / "out"), digits=-1), BadInputError),
    ("write_bvh: zero scale", lambda hm, s, m, h, d: hm.write_bvh(s, str(d / "a.bvh"), scale=0), BadInputError),
    ("write_bvh: recording out of range",
     lambda hm, s, m, h, d: hm.write_bvh(s, str(d / "a.bvh"), recording=999), BadInputError),
    # constructors and simulation
    ("simulate_grasps: unknown type", lambda hm, s, m, h, d: hm.simulate_grasps(grasps=["No Such Grasp"]), BadInputError),
    ("simulate_grasps: NaN rate", lambda hm, s, m, h, d: hm.simulate_grasps(subjects=1, rate=float("nan")), BadInputError),
    ("Grasps: NaN value", lambda hm, s, m, h, d: _bridge.call("grasps", [np.array([[1.0, np.nan], [2.0, 3.0]])]),
     BadInputError),
    # fits
    ("fit_grasp_models: unknown argument", lambda hm, s, m, h, d: hm.fit_grasp_models(s, ncmop=3), BadInputError),
    ("fit_grasp_models: ncomp = 0", lambda hm, s, m, h, d: hm.fit_grasp_models(s, ncomp=0), BadInputError),
    ("fit_grasp_models: negative max_stall", lambda hm, s, m, h, d: hm.fit_grasp_models(s, max_stall=-1),
     BadInputError),
    ("fit_grasp_model: too few recordings",
     lambda hm, s, m, h, d: _bridge.call("fit_grasp_model", s[0:2], warping="linear"), FitFailedError),
    ("fit_grasp_classifier: fraction above 1", lambda hm, s, m, h, d: hm.fit_grasp_classifier(s, at=[2]),
     BadInputError),
    ("fit_grasp_classifier: misspelt time", lambda hm, s, m, h, d: hm.fit_grasp_classifier(s, method="weighted_fpca", time="middle"), BadInputError),
    ("fit_grasp_classifier: misspelt method", lambda hm, s, m, h, d: hm.fit_grasp_classifier(s, method="lda"), BadInputError),
    # generate and classify
    ("generate: unknown argument", lambda hm, s, m, h, d: hm.generate(m, n=2, sead=1), BadInputError),
    ("generate: unknown type", lambda hm, s, m, h, d: hm.generate(m, grasps="No Such Grasp"), BadInputError),
    ("generate: negative chunk", lambda hm, s, m, h, d: hm.generate(m, n=2, chunk=-1), BadInputError),
    ("classify: unknown argument", lambda hm, s, m, h, d: hm.classify(m, s, foo=1), BadInputError),
    # kinematics
    ("forward_kinematics: NaN angles", lambda hm, s, m, h, d: hm.forward_kinematics(ANG * np.nan), BadInputError),
    ("forward_kinematics: misspelt mode", lambda hm, s, m, h, d: hm.forward_kinematics(ANG, mode="ful"), BadInputError),
    # hand-over
    ("select_markers: misspelt weighting", lambda hm, s, m, h, d: hm.select_markers(s, weighting="eigen"), BadInputError),
    ("fit_handover: unknown marker", lambda hm, s, m, h, d: hm.fit_handover(s, markers=["index_tip", "foo"]),
     BadInputError),
    ("fit_handover: zero ridge", lambda hm, s, m, h, d: hm.fit_handover(s, n_markers=3, ridge=0), BadInputError),
    ("fit_handover: unknown argument", lambda hm, s, m, h, d: hm.fit_handover(s, n_markers=3, foo=1), BadInputError),
    ("HandoverModel.predict: other DoFs", lambda hm, s, m, h, d: h.predict(hm.Grasps([ANG[:, :15]])), BadInputError),
    # 3D
    ("hand_3d: negative speed", lambda hm, s, m, h, d: hm.hand_3d(s[0:1], speed=-1), BadInputError),
]


@pytest.mark.parametrize("label, fn, expected", CASES, ids=[c[0] for c in CASES])
def test_bad_input_raises_its_family(hm, small, models, handover, files, label, fn, expected):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", HandmotionWarning)
        with pytest.raises(expected) as info:
            fn(hm, small, models, handover, files)
    # the R class vector came along, and it is a handmotion class
    if info.value.r_class:
        assert "handmotion_error" in info.value.r_class, info.value.r_class


def test_the_table_is_large():
    assert len(CASES) >= 15


def test_degenerate_data_arrives_as_a_classed_warning(hm, small):
    g = small[0:4]
    same = hm.Grasps([g.recordings[0]] * 4, meta=g.meta.assign(grasp=g.meta["grasp"].iloc[0]), dofs=g.dofs)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        hm.fit_grasp_models(same, seed=1, warping="linear", mixture_components=1)
    got = [w.message for w in seen if isinstance(w.message, DegenerateDataWarning)]
    assert got, [str(w.message) for w in seen]
    assert "handmotion_warning_identical_recordings" in got[0].r_class
    assert "handmotion_warning_degenerate" in got[0].r_class
