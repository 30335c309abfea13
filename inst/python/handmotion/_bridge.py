"""The one place that talks to R.

R is started lazily on first use, the handmotion R package is loaded, and a few
private R helpers are defined in their own environment: a caller that turns every
R condition into a value (so the Python side can raise a classed exception), and
flat encoders/decoders for the ``grasps`` class (one numeric vector for all
recordings, which crosses the bridge far faster than a list of matrices).
"""

import warnings

import numpy as np
import pandas as pd

from .errors import BadInputError, from_r_condition, from_r_warning

_R_HELPERS = r"""
local({
  env <- new.env()
  env$call <- function(f, args) {
    fun <- if (is.function(f)) f else getExportedValue("handmotion", f)
    # R's warnings are collected (not printed) and raised in Python
    warned <- list()
    keep <- function(w) {
      warned[[length(warned) + 1L]] <<- list(message = cli::ansi_strip(conditionMessage(w)),
                                             class = class(w))
      invokeRestart("muffleWarning")
    }
    tryCatch(list(ok = TRUE, value = withCallingHandlers(do.call(fun, args), warning = keep),
                  warnings = warned),
             error = function(e) list(ok = FALSE,
                                      message = cli::ansi_strip(conditionMessage(e)),
                                      class = class(e), warnings = warned))
  }
  env$grasps_out <- function(x) {
    meta <- x$meta
    for (nm in names(meta)) if (is.factor(meta[[nm]])) meta[[nm]] <- as.character(meta[[nm]])
    list(values = as.double(unlist(lapply(x$recordings, as.vector), use.names = FALSE)),
         n_frames = as.integer(x$meta$n_frames), meta = meta, dofs = x$dofs,
         rate = x$rate, unit = x$unit, levels = levels(x$meta$grasp),
         glove_name = x$glove$name, glove = x$glove$channels)
  }
  env$grasps_in <- function(values, n_frames, meta, dofs, rate, unit, levels = NULL, glove = NULL,
                            glove_name = NULL) {
    # the labels keep the order of their levels across the bridge
    if (!is.null(levels) && "grasp" %in% names(meta)) meta$grasp <- factor(meta$grasp, levels = levels)
    if (is.data.frame(glove)) glove <- handmotion::glove_profile(glove, name = glove_name)
    p <- length(dofs)
    ends <- cumsum(n_frames * p)
    starts <- ends - n_frames * p + 1
    recs <- lapply(seq_along(n_frames), function(i)
      matrix(values[seq.int(starts[i], length.out = n_frames[i] * p)], n_frames[i], p))
    handmotion::grasps(recs, meta = meta, dofs = dofs, rate = rate, unit = unit, glove = glove)
  }
  env
})
"""

_state = {}


def r():
    """Return the rpy2 ``robjects`` module, starting R and loading handmotion once."""
    if "ro" not in _state:
        import rpy2.robjects as ro  # imported here so `import handmotion` stays cheap

        ro.r("suppressPackageStartupMessages(library(handmotion))")
        _state["ro"] = ro
        _state["helpers"] = ro.r(_R_HELPERS)
    return _state["ro"]


def helpers():
    r()
    return _state["helpers"]


# ---------------------------------------------------------------- conversion


def py_to_r(value):
    """Convert a Python value to an R object (None -> NULL)."""
    ro = r()
    from .grasps import Grasps
    from .handles import RHandle

    if value is None:
        return ro.NULL
    if isinstance(value, RHandle):
        return value.robj
    if isinstance(value, Grasps):
        return value.to_r()
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
    if "grasps" in rclass:
        from .grasps import Grasps

        return Grasps.from_r(obj)
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
    res = helpers()["call"](fname, arglist)
    for w in res.rx2("warnings"):
        warnings.warn(from_r_warning(str(w.rx2("message")[0]), list(w.rx2("class"))), stacklevel=3)
    if not bool(res.rx2("ok")[0]):
        message = str(res.rx2("message")[0])
        raise from_r_condition(message, list(res.rx2("class")))
    return res.rx2("value")
