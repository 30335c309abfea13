"""pytest set-up: import the in-tree package (inst/python) without installing it."""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))

import pytest  # noqa: E402


@pytest.fixture(scope="session")
def hm():
    import handmotion

    return handmotion


@pytest.fixture(scope="session")
def ro(hm):
    from handmotion._bridge import r

    return r()


@pytest.fixture(scope="session")
def small(hm):
    """A small simulated set shared by several tests (3 subjects, 3 types)."""
    return hm.simulate_grasps(subjects=3, grasps=["Tripod", "Ring", "Power Sphere"], objects=2,
                              trials=2, seed=7)
