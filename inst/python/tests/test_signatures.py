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


def python_params(fun):
    return [p.name for p in inspect.signature(fun).parameters.values()
            if p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL)]


def signature_problems(params, r_lists, forwarded=()):
    """What is wrong with Python's ``params`` against R's argument lists: a name R has
    nowhere, or two of R's arguments in another order than R's (a positional call would
    mean something else)."""
    known = {a for fs in r_lists for a in fs} | set(forwarded)
    problems = [f"{p!r} is not an argument of the R function" for p in params if p not in known]
    for fs in r_lists:
        ours = [p for p in params if p in fs]
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
        found = signature_problems(python_params(fun), r_formals(ro, name), forwarded)
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
