"""The recognition classifiers and the live stream from Python, checked against R."""

import numpy as np
import pytest


@pytest.fixture(scope="module")
def split(hm):
    g = hm.simulate_grasps(subjects=6, grasps=[1, 9, 14], objects=2, trials=2, seed=4)
    subj = g.meta["subject"].str[1:].astype(int)
    return g[np.flatnonzero(subj <= 4).tolist()], g[np.flatnonzero(subj > 4).tolist()]


def test_discriminant_classifier_matches_r(hm, ro, split):
    train, test = split
    cl = hm.fit_grasp_classifier(train)
    pred = cl.predict(test)
    r_pred = ro.r("function(c, x) as.character(predict(c, x)$.pred_class)")(cl.robj, test.to_r())
    assert list(pred[".pred_class"]) == [str(v) for v in r_pred]
    assert list(pred.index) == list(test.meta["id"])
    prob = cl.predict(test, type="prob")
    np.testing.assert_allclose(prob.sum(axis=1).values, 1.0)
    assert list(prob.index) == list(test.meta["id"])
    assert all(c.startswith(".pred_") for c in prob.columns)
    res = hm.classify(cl, test)
    assert 0.5 < res["accuracy"] <= 1
    ev = hm.evaluate_loso(train, method="discriminant", folds=2)
    assert 0 <= ev["accuracy"]["held_out"] <= 1
    with pytest.raises(hm.BadInputError):
        cl.predict(test, type="raw")
    with pytest.raises(hm.BadInputError):
        hm.fit_grasp_classifier(train, prior="flat")


def test_weighted_fpca_from_python(hm, split):
    train, test = split
    m = hm.fit_grasp_models(train, seed=1)
    w = hm.fit_grasp_classifier(train, method="weighted_fpca", models=m)
    res = hm.classify(w, test)
    assert "weighted" in repr(res["classification"])
    with pytest.raises(hm.BadInputError):
        hm.fit_grasp_classifier(train, method="weighted_fpca", time="start")
    lf = hm.fit_grasp_classifier(train, method="last_frame", ncomp=2)
    assert "last_frame_pca" in repr(lf)


def test_every_classifier_answers_predict_alike(hm, split):
    train, test = split
    fits = [hm.fit_grasp_models(train, seed=1, mixture_components=1), hm.fit_grasp_classifier(train),
            hm.fit_grasp_classifier(train, method="last_frame", ncomp=2),
            hm.fit_grasp_classifier(train, method="weighted_fpca", seed=1), hm.fit_grasp_recognizer(train)]
    for fit in fits:
        cls = fit.predict(test)
        assert list(cls.columns) == [".pred_class"] and len(cls) == len(test.meta)
        prob = fit.predict(test, type="prob")
        np.testing.assert_allclose(prob.sum(axis=1).values, 1.0)
        top = [c[len(".pred_"):] for c in prob.idxmax(axis=1)]
        assert top == list(cls[".pred_class"])
        dist = fit.predict(test, type="distance")
        assert all(c.startswith(".dist_") for c in dist.columns)
        assert len(fit.summary()) == 3


def test_stream_gives_the_batch_probabilities(hm, split):
    train, test = split
    rec = hm.fit_grasp_recognizer(train, horizon=20)
    stream = rec.stream()
    r = test.recordings[0]
    for t in range(12):
        p = stream.update(r[t])
    batch = rec.predict(test[[0]], frames=12, type="prob")
    for k, v in p.items():
        assert v == pytest.approx(batch.loc[batch.index[0], ".pred_" + k], abs=1e-10)
    assert sum(p.values()) == pytest.approx(1.0)
    with pytest.raises(hm.BadInputError):
        stream.update([1.0, 2.0])
    with pytest.raises(hm.BadInputError):
        rec.predict(test, ms=100, frames=3)
    er = hm.evaluate_early_recognition(train, ms=[200, 400], fractions=[0.5, 1.0], folds=2)
    assert list(er["scale"]) == ["ms", "ms", "fraction", "fraction"]
    assert er["accuracy"].between(0, 1).all()
