"""The 3D hand page from Python."""

import pytest

import handmotion as hm


@pytest.fixture(scope="module")
def g():
    return hm.simulate_grasps(subjects=1, grasps=[2, 17], objects=1, trials=1, seed=1)


def test_hand_3d_page_is_self_contained(g, tmp_path):
    view = hm.hand_3d(g, limits=True, markers=["thumb_tip", "index_tip"])
    assert isinstance(view, hm.HandView)
    assert "HTMLWidgets" in view.html and "hand3d" in view.html
    # three.js is inlined, not linked: the page works offline
    assert "three.js Authors" in view.html or "THREE" in view.html
    assert 'src="http' not in view.html
    out = view.save(tmp_path / "hand.html")
    assert (tmp_path / "hand.html").stat().st_size > 100_000
    assert out.endswith("hand.html")
    frame = view._repr_html_()
    assert frame.startswith("<iframe srcdoc=")


def test_hand_3d_named_hands_and_errors(g):
    view = hm.hand_3d({"recorded": g[0], "other": g[1]}, layout="overlay")
    assert "recorded: " in view.html
    with pytest.raises(hm.BadInputError):
        hm.hand_3d(g, speed=3)
    with pytest.raises(hm.BadInputError):
        hm.hand_3d({"": g[0]})
    with pytest.raises(hm.BadInputError):
        hm.hand_3d("hand")
