"""Every Python wrapper of an R verb has R's argument names, in R's order.

The names are read from R itself (``formals()`` of the export and of its S3
methods), so a rename on either side that the other does not follow fails here
(before this test, ``generate(models, grasp)`` against R's ``generate(x, grasps)``
and ``project(model, x)`` against ``project(object, new_data)`` had drifted apart).
"""

import inspect

import pytest

# An R verb whose ``...`` goes on to another function: Python may name that
# function's arguments (R checks them there with check_dots_for()).
DOTS_GO_TO = {"fit_grasp_models": "fit_grasp_model", "read_glove": "read_hust"}


def r_formals(ro, name):
    """Argument names of R's ``name`` and of each of its S3 methods in the package:
    a list of lists (one per function), each in R's order."""
    ns = 'asNamespace("handmotion")'
    funs = [name] + [str(m) for m in ro.r(f'ls({ns}, pattern = "^{name}\\\\.")')]
    return [[str(a) for a in ro.r(f'as.character(names(formals(get("{f}", envir = {ns}))))')] for f in funs]


def python_params(fun, positional=False):
    """The named parameters of ``fun`` (only those a call can give by position, with
    ``positional``: keyword-only ones cannot be given out of order)."""
    kinds = (inspect.Parameter.POSITIONAL_ONLY, inspect.Parameter.POSITIONAL_OR_KEYWORD)
    return [p.name for p in inspect.signature(fun).parameters.values()
            if p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL) and (not positional or p.kind in kinds)]


def signature_problems(params, r_lists, forwarded=(), positional=None):
    """What is wrong with Python's ``params`` against R's argument lists: a name R has
    nowhere, or two of R's arguments among the ``positional`` ones (all by default) in
    another order than R's (a positional call would mean something else)."""
    known = {a for fs in r_lists for a in fs} | set(forwarded)
    problems = [f"{p!r} is not an argument of the R function" for p in params if p not in known]
    ordered = params if positional is None else positional
    for fs in r_lists:
        ours = [p for p in ordered if p in fs]
        theirs = [a for a in fs if a in ours]
        if ours != theirs:
            problems.append(f"order {ours} but R has {theirs}")
    return problems


def test_the_checker_finds_a_planted_drift():
    # (the test below must be able to fail: a renamed and a swapped argument)
    r_lists = [["x", "n", "grasps", "seed", "..."]]
    assert signature_problems(["x", "n", "grasps", "seed"], r_lists) == []
    assert len(signature_problems(["models", "n", "grasps"], r_lists)) == 1
    assert len(signature_problems(["x", "grasps", "n"], r_lists)) == 1
    # keyword-only parameters are named, but cannot be out of order
    assert signature_problems(["x", "n", "seed", "grasps"], r_lists, positional=["x", "n", "seed"]) == []
    assert len(signature_problems(["x", "n", "grasp"], r_lists, positional=["x", "n"])) == 1


def test_every_wrapper_has_r_argument_names_in_r_order(hm, ro):
    ro.r("suppressMessages(requireNamespace('handmotion'))")
    exports = {str(e) for e in ro.r('getNamespaceExports("handmotion")')}
    wrappers = {n: getattr(hm, n) for n in dir(hm) if n in exports and inspect.isfunction(getattr(hm, n))}
    # (a list that silently shrank would pass: the verbs of the package docstring)
    assert len(wrappers) >= 40
    problems = {}
    for name, fun in sorted(wrappers.items()):
        forwarded = []
        if name in DOTS_GO_TO:
            forwarded = r_formals(ro, DOTS_GO_TO[name])[0]
        found = signature_problems(python_params(fun), r_formals(ro, name), forwarded,
                                   positional=python_params(fun, positional=True))
        if found:
            problems[name] = found
    assert problems == {}


@pytest.mark.parametrize("handle, method, r_name", [
    ("GraspModel", "project", "project"), ("GraspModels", "project", "project"),
    ("GraspModels", "predict", "predict.grasp_classifier"),
    ("GraspClassifier", "predict", "predict.grasp_classifier"),
    ("GraspRecognizer", "predict", "predict.grasp_recognizer"),
    ("HandoverModel", "predict", "predict.handover_model")])
def test_handle_methods_name_r_arguments(hm, ro, handle, method, r_name):
    # a handle's method is R's verb (or S3 method) with the handle as its first argument
    r_lists = [fs[1:] for fs in r_formals(ro, r_name)]
    params = python_params(getattr(getattr(hm, handle), method))[1:]
    assert signature_problems(params, r_lists) == []


def r_constant_defaults(ro, name):
    """R's defaults of ``name`` (and its S3 methods) that are constants Python can state:
    NULL (None), one number, string or logical; for a vector of choices (``match.arg()``) its
    first. {argument: value}; calls (``list()``, ``hand_skeleton()``) are left out."""
    ns = 'asNamespace("handmotion")'
    funs = [name] + [str(m) for m in ro.r(f'ls({ns}, pattern = "^{name}\\\\.")')]
    out = {}
    for f in funs:
        code = (f'local({{fm <- formals(get("{f}", envir = {ns})); '
                'fm <- fm[vapply(fm, function(v) is.null(v) || (is.atomic(v) && length(v) == 1L) || '
                '(is.call(v) && identical(v[[1]], as.name("c")) && all(vapply(as.list(v)[-1], is.character, TRUE))), TRUE)]; '
                'lapply(fm, function(v) if (is.call(v)) v[[2]] else v)})')
        vals = ro.r(code)
        if ro.r["length"](vals)[0] == 0:
            continue
        for k, v in zip(ro.r["names"](vals), vals):
            k = str(k)
            # (Python has no NA: None stands for it, as for NULL)
            out.setdefault(k, None if v == ro.NULL or ro.r["is.na"](v)[0] else v[0])
    return out


# Python defaults that say R's default in another way, with why.
SAME_DEFAULT = {"classify(method)": "None: inferred from the models, as R's missing method"}


def test_python_defaults_are_r_defaults(hm, ro):
    # an explicit keyword with a default of its own would drift from R's silently
    ro.r("suppressMessages(requireNamespace('handmotion'))")
    exports = {str(e) for e in ro.r('getNamespaceExports("handmotion")')}
    problems = {}
    for name in sorted(n for n in dir(hm) if n in exports and inspect.isfunction(getattr(hm, n))):
        r_defaults = r_constant_defaults(ro, name)
        if name in DOTS_GO_TO:
            r_defaults = {**r_constant_defaults(ro, DOTS_GO_TO[name]), **r_defaults}
        for p in inspect.signature(getattr(hm, name)).parameters.values():
            if p.default is inspect.Parameter.empty or p.name not in r_defaults:
                continue
            theirs = r_defaults[p.name]
            same = p.default == theirs if not isinstance(theirs, float) or p.default is None else (
                p.default is not None and float(p.default) == theirs)
            if not same and f"{name}({p.name})" not in SAME_DEFAULT:
                problems[f"{name}({p.name})"] = (p.default, theirs)
    # (the check must be able to fail: it reads R's defaults at all)
    assert r_constant_defaults(ro, "find_motion") == {"min_move": 12.0, "min_still": 0.1}
    assert problems == {}


def test_explicit_keywords_reach_r(hm, ro):
    # a named keyword is R's argument: the set is fitted with the distance asked for, and
    # the same arguments given through **kwargs give the same call (one path, no second)
    g = hm.simulate_grasps(subjects=3, grasps=[1, 17], objects=2, trials=2, seed=3)
    named = hm.fit_grasp_models(g, ncomp=1, mixture_components=1, distance="residual")
    assert str(ro.r("function(x) x$distance")(named.robj)[0]) == "residual"
    # (rx2 is R's [[, which reads a set's models by type or place)
    assert int(named.robj.rx2(1).rx2("settings").rx2("ncomp")[0]) == 1
    # keyword-only: a positional call cannot reach them in another meaning
    with pytest.raises(TypeError):
        hm.fit_grasp_model(g, "Large Diameter", 1, 1)
    assert list(hm.find_motion(g).columns) == list(hm.find_motion(g, min_move=12, min_still=0.1).columns)
