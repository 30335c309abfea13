import numpy as np
import pandas as pd
import pytest


def make(hm, n=3, frames=(20, 25, 30)):
    rng = np.random.default_rng(1)
    recs = [rng.normal(size=(frames[i % len(frames)], 16)) for i in range(n)]
    return hm.Grasps(recs, meta=pd.DataFrame({"grasp": ["Tripod", "Ring", "Tripod"][:n],
                                              "subject": ["a", "b", "c"][:n], "trial": [1, 2, 3][:n]}))


def test_construct_len_index(hm):
    g = make(hm)
    assert len(g) == 3
    assert g.meta["n_frames"].tolist() == [20, 25, 30]
    assert g.dofs[0] == "CMC1" and len(g.dofs) == 16
    assert len(g[1:]) == 2
    assert g[0].meta["id"].tolist() == ["r1"]
    assert g[["r3", "r1"]].meta["n_frames"].tolist() == [30, 20]
    assert len(g[np.array([True, False, True])]) == 2
    with pytest.raises(IndexError):
        g[5]


def test_bad_python_input_is_caught_before_r(hm):
    with pytest.raises(hm.BadInputError, match="NaN"):
        hm.Grasps([np.full((3, 16), np.nan)])
    with pytest.raises(hm.BadInputError, match="ragged"):
        hm.Grasps([np.zeros((3, 16)), np.zeros((3, 15))])
    with pytest.raises(hm.BadInputError, match="dtype"):
        hm.Grasps([np.array([["a"] * 16] * 3)])
    with pytest.raises(hm.BadInputError, match="2-D"):
        hm.Grasps([np.zeros(16)])
    with pytest.raises(hm.BadInputError, match="rows"):
        hm.Grasps([np.zeros((3, 16))], meta=pd.DataFrame({"grasp": ["Tripod", "Ring"]}))
    with pytest.raises(hm.BadInputError):
        hm.simulate_grasps(subjects=0)
    with pytest.raises(hm.BadInputError):
        hm.simulate_grasps(seed="x")


def test_long_round_trip(hm):
    g = make(hm)
    long = g.to_long()
    assert list(long.columns) == ["id", "frame", "time", "dof", "angle", "grasp", "subject", "object", "trial"]
    assert len(long) == (20 + 25 + 30) * 16
    back = hm.Grasps.from_long(long)
    for a, b in zip(g.recordings, back.recordings):
        np.testing.assert_array_equal(a, b)
    assert back.meta["grasp"].tolist() == ["Tripod", "Ring", "Tripod"]


def test_r_round_trip_is_lossless(hm, ro):
    g = make(hm)
    r_obj = g.to_r()
    assert "grasps" in list(ro.r["class"](r_obj))
    back = hm.Grasps.from_r(r_obj)
    for a, b in zip(g.recordings, back.recordings):
        np.testing.assert_array_equal(a, b)
    assert back.meta["id"].tolist() == g.meta["id"].tolist()
    assert back.meta["grasp"].tolist() == ["Tripod", "Ring", "Tripod"]
    assert back.meta["trial"].tolist() == [1, 2, 3]
    assert back.dofs == g.dofs and back.rate == g.rate and back.unit == g.unit
    # and R sees the same numbers as Python
    total = ro.r("function(x) sum(unlist(x$recordings))")(r_obj)[0]
    assert total == pytest.approx(sum(r.sum() for r in g.recordings), rel=1e-12)


def test_r_errors_become_classed_exceptions(hm):
    # any label is a class now; asking a Feix-labelled set for a type it lacks is still an error
    g = hm.simulate_grasps(subjects=2, grasps=["Tripod", "Ring"], objects=1, trials=2, seed=1)
    m = hm.fit_grasp_models(g, seed=1, mixture_components=1)
    with pytest.raises(hm.UnknownGraspError) as info:
        hm.generate(m, grasps="Not A Grasp")
    assert "Not A Grasp" in str(info.value)
    assert "handmotion_error_unknown_grasp" in info.value.r_class
    assert isinstance(info.value, hm.HandmotionError)


def test_simulate_matches_r_for_a_seed(hm, ro, small):
    again = hm.simulate_grasps(subjects=3, grasps=["Tripod", "Ring", "Power Sphere"], objects=2,
                               trials=2, seed=7)
    for a, b in zip(small.recordings, again.recordings):
        np.testing.assert_array_equal(a, b)
    r_sim = ro.r("function() handmotion::simulate_grasps(subjects = 3, grasps = c('Tripod', 'Ring', "
                 "'Power Sphere'), objects = 2, trials = 2, seed = 7)")()
    from_r = hm.Grasps.from_r(r_sim)
    assert len(from_r) == len(small)
    for a, b in zip(small.recordings, from_r.recordings):
        np.testing.assert_array_equal(a, b)


def test_converted_arrays_own_their_memory(hm, ro):
    """Arrays from R must be copies: R reuses a collected vector's memory."""
    g = hm.Grasps.from_r(ro.r("handmotion::simulate_grasps(subjects = 1, grasps = 1, objects = 1, "
                              "trials = 2, seed = 3)"))
    before = [r.copy() for r in g.recordings]
    ro.r("invisible(lapply(1:50, function(i) rnorm(1e5))); invisible(gc())")
    for a, b in zip(before, g.recordings):
        np.testing.assert_array_equal(a, b)
        assert b.base is None or b.base.flags.owndata
