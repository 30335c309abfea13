"""A small end-to-end fit -> generate -> classify run, checked against R."""

import numpy as np
import pytest


@pytest.fixture(scope="module")
def models(hm, small):
    return hm.fit_grasp_models(small, seed=1)


def test_fit_and_summary(hm, models):
    s = models.summary()
    assert len(s) == 3
    assert len(models) == 3
    assert set(models.grasp_types()) == {"Tripod", "Ring", "Power Sphere"}
    assert models.failed() == {}


def test_generate_returns_grasps_and_array(hm, models):
    x = hm.generate(models, grasps="Power Sphere", n=10, seed=2)
    assert len(x) == 10 and len(x.dofs) == 16
    assert set(x.meta["grasp"]) == {"Power Sphere"}
    arr = x.as_array()
    longest = int(x.meta["n_frames"].max())
    assert arr.shape == (10, longest, 16)
    first = x.recordings[0]
    np.testing.assert_array_equal(arr[0, :first.shape[0]], first)
    assert np.isnan(arr[0, first.shape[0]:]).all()
    # the old argument names are errors naming the new ones (R's generate(x, grasps =))
    for old, new in [({"as_array": True}, "as_array"), ({"grasp": "Power Sphere"}, "grasps"),
                     ({"models": models}, "'x'")]:
        with pytest.raises(hm.BadInputError, match=new):
            hm.generate(models, n=1, **old) if "models" not in old else hm.generate(x=models, n=1, **old)
    # same seed, same numbers; and the same as R's generate() for that seed
    again = hm.generate(models, grasps="Power Sphere", n=10, seed=2)
    for a, b in zip(x.recordings, again.recordings):
        np.testing.assert_array_equal(a, b)


def test_generate_identical_to_r(hm, ro, models):
    x = hm.generate(models, grasps="Tripod", n=3, seed=11)
    r_gen = ro.r("function(m) handmotion::generate(m, grasps = 'Tripod', n = 3, seed = 11)")(models.robj)
    y = hm.Grasps.from_r(r_gen)
    for a, b in zip(x.recordings, y.recordings):
        np.testing.assert_array_equal(a, b)


def test_classify(hm, models, small):
    lf = hm.fit_grasp_classifier(small, method="last_frame", ncomp=2)
    res = hm.classify(lf, small, method="last_frame")
    assert 0 <= res["accuracy"] <= 1
    conf = res["confusion"]
    assert conf.shape == (3, 3)
    assert int(conf.to_numpy().sum()) == len(small)
    res2 = hm.classify(models, small, method="fpca")
    assert 0 <= res2["accuracy"] <= 1
    with pytest.raises(hm.BadInputError):
        hm.classify(models, small, method="nope")
    # fitting is never implicit: a Grasps is refused, and a model of the other kind too
    with pytest.raises(hm.BadInputError):
        hm.classify(small, small, method="last_frame")
    with pytest.raises(hm.BadInputError):
        hm.classify(models, small, method="last_frame")


def test_classify_methods_are_read_from_r(hm):
    # the one list is R's (the default of classify()'s method): the FPCA set's and every
    # method of fit_grasp_classifier(), which evaluate_loso() takes too
    from handmotion import api
    from handmotion._bridge import r
    ro = r()
    fit_methods = [str(m) for m in ro.r("eval(formals(handmotion::fit_grasp_classifier)$method)")]
    loso_methods = [str(m) for m in ro.r("eval(formals(handmotion::evaluate_loso)$method)")]
    assert set(api._classify_methods()) == {"fpca", *fit_methods}
    assert list(api._classify_methods()) == loso_methods


def test_generate_needs_models(hm):
    with pytest.raises(hm.BadInputError):
        hm.generate("not a model", n=1)


def test_tables_and_held_out(hm, models, small):
    t1 = hm.thesis_table("5.1", models=models)
    assert {"grasp", "target_frames", "thesis_target_frames"}.issubset(t1.columns)
    assert len(t1) == 3
    t2 = hm.thesis_table("5.2", models=models)
    assert {"mean", "thesis_mean"}.issubset(t2.columns)
    res = hm.classify(models, small, method="fpca")
    t3 = hm.thesis_table("5.3", classification=res["classification"])
    assert t3.shape[0] == 3
    t6 = hm.thesis_table("5.6", confusion=res["classification"])
    assert {"correct", "thesis_correct", "recall"}.issubset(t6.columns)
    lf = hm.fit_grasp_classifier(small, method="last_frame", ncomp=2)
    t7 = hm.thesis_table("5.7", fit=lf, pcs=[1, 2])
    assert list(t7.columns)[:4] == ["grasp_id", "grasp", "pc1", "thesis_pc1"]
    ev = hm.evaluate_loso(small, method="last_frame", fit_args={"ncomp": 2})
    assert 0 <= ev["accuracy"]["held_out"] <= 1
    assert int(ev["confusion"].to_numpy().sum()) == len(small)


def test_handover_round_trip(hm, small):
    ref = small[small.meta["subject"] != "S03"]
    query = small[small.meta["subject"] == "S03"][:1]
    markers = hm.select_markers(ref, n=6)
    assert len(markers) == 6
    assert set(hm.select_markers(ref, n=3)).issubset(markers)
    handpicked = hm.select_markers(method="handpicked")
    assert len(handpicked) == 6 and not any(m.startswith(("middle", "ring")) for m in handpicked)
    model = hm.fit_handover(ref, n_markers=6)
    out = model.predict(query)
    assert len(out) == 1
    assert out.recordings[0].shape == query.recordings[0].shape
    err = np.mean(np.abs(out.recordings[0] - query.recordings[0]))
    # planted baseline: always answering the reference's mean pose
    mean_pose = np.vstack(ref.recordings).mean(axis=0)
    baseline = np.mean(np.abs(query.recordings[0] - mean_pose))
    assert err < 0.5 * baseline
