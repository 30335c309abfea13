"""The copula model and the naturalness evaluation from Python, checked against R."""

import numpy as np
import pytest


@pytest.fixture(scope="module")
def split(hm):
    g = hm.simulate_grasps(subjects=10, grasps=[1, 9], objects=2, trials=2, seed=3)
    subj = g.meta["subject"].str[1:].astype(int)
    train = g[np.flatnonzero(subj <= 7).tolist()]
    held = g[np.flatnonzero(subj > 7).tolist()]
    return train, held


@pytest.fixture(scope="module")
def copula(hm, split):
    return hm.fit_grasp_models(split[0], seed=1, dependence="copula")


def test_copula_models_carry_dependence(hm, split, copula):
    s = copula.summary()
    assert set(s["dependence"]) == {"copula"}
    dep = copula.dependence("Large Diameter")
    assert dep.shape == (16, 16)
    np.testing.assert_allclose(np.diag(dep.values), 1.0)
    off = dep.values[~np.eye(16, dtype=bool)]
    assert np.abs(off).max() > 0.2
    thesis = hm.fit_grasp_models(split[0], seed=1)
    np.testing.assert_array_equal(thesis.dependence("Large Diameter").values, np.eye(16))
    with pytest.raises(hm.BadInputError):
        copula.dependence("Tripod")
    with pytest.raises(hm.BadInputError):
        hm.fit_grasp_models(split[0], dependence="joint")


def test_generation_within_limits_and_identical_to_r(hm, ro, copula):
    x = hm.generate(copula, grasps="Large Diameter", n=20, seed=5)
    r_gen = ro.r("function(m) handmotion::generate(m, grasps = 'Large Diameter', n = 20, seed = 5)")(copula.robj)
    for a, b in zip(x.recordings, r_gen.rx2("recordings")):
        np.testing.assert_array_equal(a, np.asarray(b))
    free = hm.generate(copula, grasps="Large Diameter", n=20, seed=5, limits=False)
    assert any(not np.array_equal(a, b) for a, b in zip(x.recordings, free.recordings))
    with pytest.raises(hm.BadInputError):
        hm.generate(copula, n=2, limits="yes")


def test_evaluate_generation(hm, split, copula):
    train, held = split
    ev = hm.evaluate_generation({"copula": copula}, held, train, reps=1, seed=2)
    t = ev["table"]
    assert {"model", "grasp", "metric", "generated", "baseline", "better", "ratio"} <= set(t.columns)
    assert set(ev["overall"]["grasp"]) == {"overall"}
    assert "posture_cor_gap" in set(t["metric"])
    same = hm.evaluate_generation(copula, held, train, reps=1, seed=2)["table"]
    np.testing.assert_allclose(same["generated"].values, t["generated"].values)
    with pytest.raises(hm.BadInputError):
        hm.evaluate_generation([copula], held, train)


def test_copula_defaults_and_overrides_reach_r(hm, ro, split):
    train = split[0]
    m = hm.fit_grasp_models(train, grasps=["Large Diameter"], seed=1, dependence="copula")
    settings = ro.r("function(m) m[['Large Diameter']]$settings")(m.robj)
    assert list(settings.rx2("warping")) == ["linear"]
    assert list(settings.rx2("fpc_scores")) == ["least_squares"]
    assert list(settings.rx2("ncomp")) == [4]
    m2 = hm.fit_grasp_models(train, grasps=["Large Diameter"], seed=1, dependence="copula",
                             ncomp=2, warping="dtw")
    s2 = ro.r("function(m) m[['Large Diameter']]$settings")(m2.robj)
    assert list(s2.rx2("warping")) == ["dtw"] and list(s2.rx2("ncomp")) == [2]
