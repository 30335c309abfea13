"""Python = R: the same names as R's exports, no aliases of names R removed, no
R code in Python strings, no import loop between the package's modules."""

import ast
import os
import re

import pytest

PKG = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "handmotion")


def _not_mirrored(hm):
    """The R exports the package docstring says are deliberately not mirrored."""
    doc = hm.__doc__
    para = doc[doc.index("Deliberately not mirrored"):doc.index("Python-only helpers")]
    return set(re.findall(r"``([a-z_0-9]+)``", para))


def test_every_r_export_is_mirrored_or_listed_as_not(hm, ro):
    exports = {str(x) for x in ro.r('getNamespaceExports("handmotion")')}
    missing = sorted(e for e in exports - _not_mirrored(hm) if not callable(getattr(hm, e, None)))
    assert missing == []
    # what the docstring says is not mirrored is an R export, and is indeed absent
    assert _not_mirrored(hm) <= exports
    assert not any(hasattr(hm, e) for e in _not_mirrored(hm))
    # the docstring's list of mirrored verbs names real functions, and all of them
    doc = hm.__doc__
    listed = set(re.findall(r"``([a-z_0-9]+)``", doc[doc.index("Python = R"):doc.index("Deliberately not")]))
    assert exports - _not_mirrored(hm) <= listed
    assert all(callable(getattr(hm, n)) for n in listed)
    assert set(hm.__all__) <= set(dir(hm))


@pytest.mark.parametrize("old", ["fit_last_frame_pca", "fit_weighted_fpca", "rank_markers", "reconstruct",
                                 "table_5_1", "table_5_2", "table_5_3", "table_5_6", "table_5_7", "table_5_8"])
def test_names_r_removed_are_gone_with_a_pointer(hm, ro, old):
    # R has removed it too: it is documented on ?handmotion-renamed, not exported
    assert old not in {str(x) for x in ro.r('getNamespaceExports("handmotion")')}
    assert old not in hm.__all__ and old not in dir(hm)
    with pytest.raises(AttributeError, match="handmotion-renamed"):
        getattr(hm, old)
    assert not hasattr(hm, old)


def test_unknown_names_are_plain_attribute_errors(hm):
    with pytest.raises(AttributeError, match="no attribute 'no_such_verb'"):
        hm.no_such_verb


def _imports(path):
    """Modules of the package imported anywhere in a file (also inside functions)."""
    tree = ast.parse(open(path, encoding="utf-8").read())
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            out.add(node.module)
    return out


def test_no_import_loop():
    mods = {f[:-3]: _imports(os.path.join(PKG, f)) for f in os.listdir(PKG)
            if f.endswith(".py") and f != "__init__.py"}
    # depth-first search for a cycle
    state = {}

    def visit(m, path):
        if state.get(m) == "done":
            return
        assert state.get(m) != "open", f"import loop: {' -> '.join(path + [m])}"
        state[m] = "open"
        for dep in mods.get(m, ()):
            visit(dep, path + [m])
        state[m] = "done"

    for m in mods:
        visit(m, [])
    # the bridge knows nothing of the classes built on it
    assert mods["_bridge"] == {"errors"}


def test_no_r_code_in_python_strings():
    # R functions written in Python strings would never run under testthat; the R side of
    # the bridge is R/python-bridge.R
    for f in os.listdir(PKG):
        if f.endswith(".py"):
            text = open(os.path.join(PKG, f), encoding="utf-8").read()
            assert not re.search(r"function\s*\(", text), f


def test_version_is_the_r_packages(hm, ro):
    # written once, in DESCRIPTION: Python reads it, pyproject.toml asks Python
    assert hm.__version__ == str(ro.r('as.character(utils::packageVersion("handmotion"))')[0])
    toml = open(os.path.join(os.path.dirname(PKG), "pyproject.toml"), encoding="utf-8").read()
    assert not re.search(r'^version\s*=\s*"', toml, flags=re.M)
    assert "handmotion.__version__" in toml
    assert not re.search(r"__version__\s*=\s*[\"']", open(os.path.join(PKG, "__init__.py"), encoding="utf-8").read())


def test_no_r_internals_reached():
    # R's internals are reached through the documented python_bridge() export only
    tests = os.path.dirname(os.path.abspath(__file__))
    for folder in (PKG, tests):
        for f in os.listdir(folder):
            if f.endswith(".py"):
                text = open(os.path.join(folder, f), encoding="utf-8").read()
                assert "handmotion" + ":::" not in text, f


def test_project_mirrors_r(hm, small):
    # project() gives the thesis' residual distance (eq. 4.4): a set ranked by it
    m = hm.fit_grasp_models(small, seed=1, distance="residual")
    pr = hm.project(m, small[0:4])
    assert set(pr) == set(m.grasp_types())
    one = pr["Tripod"]
    assert one["ids"] == list(small.meta["id"][:4])
    assert one["distance"].shape == (4,) and (one["distance"] >= 0).all()
    assert one["scores"].shape[:2] == (4, 16)
    # the FPCA classifier ranks these same distances
    pred = m.predict(small[0:4], type="distance")
    nearest = [min(pr, key=lambda t: pr[t]["distance"][i]) for i in range(4)]
    assert nearest == list(pred.idxmin(axis=1).str[len(".dist_"):])
    single = hm.fit_grasp_model(small[small.meta["grasp"] == "Tripod"], seed=1)
    assert single.project(small[0:4])["ids"] == one["ids"]
