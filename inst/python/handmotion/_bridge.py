"""The one place that talks to R.

R is started lazily on first use and the handmotion R package is loaded. The R
side of the bridge lives in the R package itself (``R/python-bridge.R``, tested
by testthat) and is reached only through its exports, never ``:::``: the user
verbs by name, and the one documented entry ``handmotion::python_bridge(part, ...)``
for the bridge's own steps (``?python_bridge``): ``"call"`` turns every R condition
into a value (so the Python side can raise a classed exception), ``"grasps_out"``
and ``"grasps_in"`` flatten the ``grasps`` class into one numeric vector for all
recordings (which crosses the bridge far faster than a list of matrices).

This module imports no other module of the package but :mod:`.errors`: objects
that know their R form have a ``to_r()`` method, and the modules that define
Python twins of R classes register their converters with :func:`register_r_class`,
so the dependencies run one way (``_bridge`` <- ``grasps`` <- ``handles`` <- ``api``).
"""

import sys
import warnings

import numpy as np
import pandas as pd

from .errors import BadInputError, from_r_condition, from_r_warning

_state = {}

# R class -> a callable that turns such an R object into its Python twin (filled by grasps.py)
_R_CLASSES = {}


def register_r_class(r_class, convert):
    """Convert R objects of class ``r_class`` with ``convert(robj)`` in :func:`r_to_py`."""
    _R_CLASSES[r_class] = convert


def r():
    """Return the rpy2 ``robjects`` module, starting R and loading handmotion once."""
    if "ro" not in _state:
        import rpy2.robjects as ro  # imported here so `import handmotion` stays cheap

        ro.r("suppressPackageStartupMessages(library(handmotion))")
        # one progress bar redrawn in place in a terminal, none in a log or a
        # notebook (R/python-bridge.R, py_progress_setup())
        ro.r("handmotion::python_bridge")("progress_setup", ro.BoolVector([_terminal()]))
        _state["ro"] = ro
    return _state["ro"]


def _terminal():
    """Is Python's standard output a terminal (where a bar can be redrawn in place)?"""
    try:
        return sys.stdout.isatty()
    except (AttributeError, ValueError):
        return False


def bridge(part):
    """A callable for one step ``part`` of the R side of the bridge: ``handmotion::python_bridge(part, ...)``."""
    if "bridge" not in _state:
        _state["bridge"] = r().r("handmotion::python_bridge")
    entry = _state["bridge"]
    return lambda *args, **kwargs: entry(part, *args, **kwargs)


# ---------------------------------------------------------------- conversion


def py_to_r(value):
    """Convert a Python value to an R object (None -> NULL)."""
    ro = r()
    if value is None:
        return ro.NULL
    to_r = getattr(value, "to_r", None)
    if callable(to_r) and not isinstance(value, pd.DataFrame):
        # a Grasps or a handle on an R object
        return to_r()
    if isinstance(value, pd.DataFrame):
        return df_to_r(value)
    if isinstance(value, bool):
        return ro.BoolVector([value])
    if isinstance(value, (int, np.integer)):
        return ro.IntVector([int(value)])
    if isinstance(value, (float, np.floating)):
        return ro.FloatVector([float(value)])
    if isinstance(value, str):
        return ro.StrVector([value])
    if isinstance(value, dict):
        return ro.ListVector({k: py_to_r(v) for k, v in value.items()})
    if isinstance(value, np.ndarray):
        return array_to_r(value)
    if isinstance(value, (list, tuple)):
        if all(isinstance(v, str) for v in value):
            return ro.StrVector(list(value))
        if all(isinstance(v, (bool, np.bool_)) for v in value):
            return ro.BoolVector(list(value))
        if all(isinstance(v, (int, np.integer)) and not isinstance(v, bool) for v in value):
            return ro.IntVector([int(v) for v in value])
        if all(isinstance(v, (int, float, np.integer, np.floating)) for v in value):
            return ro.FloatVector([float(v) for v in value])
        return ro.r["list"](*[py_to_r(v) for v in value])
    if hasattr(value, "__sexp__") or value.__class__.__module__.startswith("rpy2"):
        return value
    raise BadInputError(f"cannot pass a {type(value).__name__} to R")


def array_to_r(a):
    """A numpy vector or 2-D array as an R vector or matrix (column-major)."""
    ro = r()
    a = np.asarray(a)
    if a.ndim == 1:
        if a.dtype.kind in "iu":
            return ro.IntVector(a.tolist())
        if a.dtype.kind == "b":
            return ro.BoolVector(a.tolist())
        if a.dtype.kind in "US":
            return ro.StrVector(a.tolist())
        return ro.FloatVector(a.astype(float).tolist())
    if a.ndim == 2:
        vec = ro.FloatVector(np.asarray(a, dtype=float).ravel(order="F"))
        return ro.r["matrix"](vec, nrow=a.shape[0], ncol=a.shape[1])
    raise BadInputError(f"only 1-D and 2-D arrays can be passed to R, not {a.ndim}-D")


def df_to_r(df):
    """A pandas DataFrame as an R data.frame (categoricals become character)."""
    ro = r()
    cols = {}
    for name in df.columns:
        s = df[name]
        if isinstance(s.dtype, pd.CategoricalDtype):
            s = s.astype(object)
        if s.dtype == object:
            vals = [None if (v is None or (isinstance(v, float) and np.isnan(v))) else str(v) for v in s]
            cols[str(name)] = ro.StrVector([ro.NA_Character if v is None else v for v in vals])
        elif s.dtype.kind == "b":
            cols[str(name)] = ro.BoolVector(s.tolist())
        elif s.dtype.kind in "iu":
            # nullable Int64 columns carry pd.NA, which becomes R's NA_integer_
            cols[str(name)] = ro.IntVector([ro.NA_Integer if pd.isna(v) else int(v) for v in s])
        else:
            cols[str(name)] = ro.FloatVector([ro.NA_Real if pd.isna(v) else float(v) for v in s])
    frame = ro.r["data.frame"](**cols, **{"stringsAsFactors": False, "check.names": False})
    return frame


def r_array(obj, dtype=None):
    """A numpy COPY of an R vector. np.asarray() would share R's memory through the
    buffer protocol, and that memory is reused once R collects the vector."""
    return np.array(obj, dtype=dtype, copy=True)


def r_to_py(obj):
    """Convert an R result to plain Python: data.frame -> DataFrame, atomic -> numpy/scalar."""
    ro = r()
    from rpy2.rinterface import NULLType

    if isinstance(obj, NULLType):
        return None
    rclass = list(ro.r["class"](obj))
    for cls in rclass:
        if cls in _R_CLASSES:
            return _R_CLASSES[cls](obj)
    if "data.frame" in rclass:
        return df_to_py(obj)
    if isinstance(obj, (ro.vectors.FloatVector, ro.vectors.IntVector, ro.vectors.BoolVector,
                        ro.vectors.StrVector)):
        dims = ro.r["dim"](obj)
        if not isinstance(dims, NULLType):
            return r_array(obj).reshape(tuple(int(d) for d in dims), order="F")
        vals = r_array(obj)
        return vals[0] if vals.size == 1 else vals
    return obj


def df_to_py(frame):
    """An R data.frame as a pandas DataFrame (factors become strings, NA becomes None/NaN)."""
    ro = r()
    from rpy2.rinterface import NULLType

    names = list(ro.r["names"](frame))
    cols = {}
    for i, name in enumerate(names):
        col = frame[i]
        cls = list(ro.r["class"](col))
        if "factor" in cls:
            col = ro.r["as.character"](col)
        if isinstance(col, ro.vectors.StrVector):
            na = r_array(ro.r["is.na"](col), dtype=bool)
            cols[name] = pd.Series([None if m else str(v) for v, m in zip(col, na)], dtype=object)
        elif isinstance(col, ro.vectors.BoolVector):
            na = r_array(ro.r["is.na"](col), dtype=bool)
            vals = r_array(col)
            cols[name] = pd.Series([None if m else bool(v) for v, m in zip(vals, na)], dtype=object) \
                if na.any() else pd.Series(vals.astype(bool))
        elif isinstance(col, ro.vectors.IntVector):
            na = r_array(ro.r["is.na"](col), dtype=bool)
            arr = r_array(col)
            cols[name] = pd.Series(pd.array([None if m else int(v) for v, m in zip(arr, na)], dtype="Int64")) \
                if na.any() else pd.Series(arr.astype(np.int64))
        elif isinstance(col, ro.vectors.FloatVector):
            cols[name] = pd.Series(r_array(col, dtype=float))
        elif isinstance(col, NULLType):
            cols[name] = pd.Series([], dtype=object)
        else:
            cols[name] = pd.Series(list(col), dtype=object)
    return pd.DataFrame(cols)


# ---------------------------------------------------------------- calling


def call(fname, *args, **kwargs):
    """Call an exported handmotion R function; raise a classed HandmotionError on R errors.

    Keyword arguments keep their R names (Python's ``None`` is R's ``NULL``).
    Returns the raw R object.
    """
    ro = r()
    rargs = [py_to_r(a) for a in args]
    rkw = {k: py_to_r(v) for k, v in kwargs.items()}
    arglist = ro.r["list"](*rargs, **rkw)
    res = bridge("call")(fname, arglist)
    for w in res.rx2("warnings"):
        warnings.warn(from_r_warning(str(w.rx2("message")[0]), list(w.rx2("class"))), stacklevel=3)
    if not bool(res.rx2("ok")[0]):
        message = str(res.rx2("message")[0])
        raise from_r_condition(message, list(res.rx2("class")))
    return res.rx2("value")
