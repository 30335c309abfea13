"""Functions mirroring the handmotion R API (same names and argument names).

The list of which R exports are mirrored (and which deliberately are not) is in the
package docstring (``help(handmotion)``).

Every function validates its Python input before R sees it, calls the R function
of the same name through one bridge, and converts the result: ``grasps`` objects
become :class:`handmotion.Grasps`, data frames become pandas DataFrames, arrays
become numpy arrays, and model objects become handles. Seeds pass straight
through, so Python and R give identical numbers for the same seed.
"""

import os

import numpy as np

from ._bridge import call, r, r_array, r_to_py
from .errors import BadInputError
from .grasps import Grasps, _as_grasps
from .handles import (GraspClassifier, GraspModel, GraspRecognizer, GraspModels, HandoverModel, RecognitionStream,
                      RHandle, Skeleton, project)


def _check_count(value, name, minimum=1):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise BadInputError(f"{name} must be a whole number >= {minimum}, not {value!r}")
    return int(value)


def _refuse_renamed(kwargs, renamed):
    """An argument given by its old name (``{old: new}``) is a :class:`BadInputError` naming the
    new one, as R's verbs do (``?handmotion-renamed``), rather than a silent pass to R."""
    old = [k for k in renamed if k in kwargs]
    if old:
        raise BadInputError("; ".join(f"argument {k!r} is now {renamed[k]!r}" for k in old))


def _check_seed(seed):
    if seed is None:
        return None
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise BadInputError(f"seed must be a whole number or None, not {seed!r}")
    return int(seed)


def _given(**kwargs):
    """The arguments that are not None: what goes on through R's ``...`` (there R's ``NULL``
    is the default, so leaving it out is the same call and the same cache key)."""
    return {k: v for k, v in kwargs.items() if v is not None}


def _grasps_arg(grasps):
    if isinstance(grasps, dict):
        # {label: Feix type}: the labels of the simulated recordings
        from ._bridge import r
        ro = r()
        vals = list(grasps.values())
        vec = ro.IntVector([int(v) for v in vals]) if all(isinstance(v, (int, np.integer)) for v in vals) \
            else ro.StrVector([str(v) for v in vals])
        vec.names = ro.StrVector([str(k) for k in grasps])
        return vec
    """Grasp types as R expects them: names (str) or ids (int); None means all."""
    if grasps is None:
        return None
    if isinstance(grasps, (str, int, np.integer)):
        grasps = [grasps]
    grasps = list(grasps)
    if all(isinstance(g, str) for g in grasps):
        return grasps
    if all(isinstance(g, (int, np.integer)) and not isinstance(g, bool) for g in grasps):
        return [int(g) for g in grasps]
    raise BadInputError("grasp types must be all names (str) or all ids (int)")


# ---------------------------------------------------------------- data


def simulate_grasps(subjects=30, grasps=None, objects=3, trials=3, rate=50, seed=1, plant_overlong=True,
                    rest=0, hold=0, **kwargs):
    """Simulate HUST-like grasp recordings (the package's embedded default data).

    Parameters mirror R's ``simulate_grasps()``: counts of ``subjects``, ``objects``
    and ``trials``; ``grasps`` as Feix names or ids (default all 33); ``rate`` in Hz;
    ``seed`` for reproducibility (identical to R for the same seed); ``plant_overlong``
    plants the over-long recordings the thesis removed; ``rest`` and ``hold`` (seconds)
    add the still hand before and after the motion a real glove records. R's other
    arguments (``params``, ``glove``, ``stuck``, ``session_sd``) pass by keyword.

    Returns
    -------
    Grasps
    """
    args = dict(subjects=_check_count(subjects, "subjects"), objects=_check_count(objects, "objects"),
                trials=_check_count(trials, "trials"), rate=float(rate), seed=_check_seed(seed),
                plant_overlong=bool(plant_overlong), rest=float(rest), hold=float(hold))
    if grasps is not None:
        args["grasps"] = _grasps_arg(grasps)
    args.update(kwargs)
    return r_to_py(call("simulate_grasps", **args))


def read_hust(path, manifest=None, pattern=None, **kwargs):
    """Read HUST-layout CSV files (one per grasp, 16 DoF columns) into a :class:`Grasps`.

    ``manifest`` is a pandas DataFrame or CSV path mapping files to grasp, subject,
    object and trial; ``pattern`` a regular expression with named groups (matched against
    the relative path when it holds a ``/``). ``time``, ``time_unit``, ``recursive`` and the
    other arguments are R's (see :func:`read_glove`). Files that could not be read are in
    ``result.failures``.
    """
    return _with_failures(call("read_hust", _path_arg(path), manifest=manifest, pattern=pattern, **kwargs))


def _path_arg(path):
    """A path (str or os.PathLike) or a list of them, as R's character vector wants them."""
    if isinstance(path, (list, tuple)):
        return [os.fspath(p) for p in path]
    return os.fspath(path)


def _with_failures(res):
    """The Grasps of a reader's R result, its ``"failures"`` attribute as ``.failures``."""
    out = r_to_py(res)
    out.failures = r_to_py(r().r["attr"](res, "failures"))
    return out


def extdata(*parts):
    """The path of a file or folder shipped in the R package's ``inst/extdata`` (R's
    ``system.file("extdata", ..., package = "handmotion")``), e.g. ``extdata("flexglove")``."""
    path = str(r().r["system.file"]("extdata", *parts, package="handmotion")[0])
    if not path:
        raise BadInputError(f"handmotion ships no extdata {'/'.join(parts)!r}")
    return path


def read_graspdb14(path, recursive=False, pattern=r"\.txt$", datatype=None, truncated="error"):
    """Read a GraspDB14 motion file or a directory of them into a :class:`Grasps`.

    Files that fail to parse are listed in ``result.failures`` (a DataFrame of file,
    line, class and message) rather than dropped silently.
    """
    return _with_failures(call("read_graspdb14", path, recursive=bool(recursive), pattern=pattern,
                               datatype=datatype, truncated=truncated))


def write_hust(x, dir, **kwargs):
    """Write a :class:`Grasps` in the HUST layout plus its manifest; returns the manifest path."""
    return r_to_py(call("write_hust", _as_grasps(x), dir, **kwargs))


def write_graspdb14(x, dir, **kwargs):
    """Write a :class:`Grasps` of 23 CyberGlove sensors in the GraspDB14 motion-file format."""
    return r_to_py(call("write_graspdb14", _as_grasps(x), dir, **kwargs))


def read_skeleton(file):
    """Read an ``.xmlskel`` hand skeleton; returns a :class:`Skeleton` handle."""
    return Skeleton(call("read_skeleton", str(file)))


def hand_skeleton():
    """The package's default hand skeleton."""
    return Skeleton(call("hand_skeleton"))


def forward_kinematics(x, skeleton=None, mode="plain", deactivate=None, **kwargs):
    """3-D joint positions (mm) over time.

    Returns a numpy array frames x joints x 3 for a 2-D array ``x``, and a list of
    such arrays (one per recording, also for a set of one) for a :class:`Grasps`;
    the joints follow :func:`joint_names`.
    """
    single = isinstance(x, np.ndarray) and x.ndim == 2
    g = _as_grasps(x)
    kw = dict(mode=mode, deactivate=deactivate, **kwargs)
    if skeleton is not None:
        kw["skeleton"] = skeleton
    res = [r_array(a) for a in call("forward_kinematics", g, **kw)]
    return res[0] if single else res


def joint_names(skeleton=None):
    """Joint names, in the order of the second axis of :func:`forward_kinematics` arrays."""
    sk = skeleton if skeleton is not None else hand_skeleton()
    return list(sk.joints["name"])


def write_bvh(x, file, **kwargs):
    """Export a recording or generated grasp as a BVH animation (Blender can import it); refuses
    to overwrite an existing file unless ``overwrite=True``."""
    g = _as_grasps(x)
    call("write_bvh", g, str(file), **kwargs)
    return str(file)


def read_bvh(file):
    """Read a BVH file (R's ``read_bvh()``) as a :class:`Grasps` of one recording whose DoFs are
    the rotation channels (``<joint>:<channel>``, degrees); the hierarchy stays in R (``to_r()``
    keeps the object R read only for the recordings)."""
    return r_to_py(call("read_bvh", str(file)))


def write_skeleton(skeleton, file, comment=None, overwrite=False):
    """Write a :class:`Skeleton` as an ``.xmlskel`` file (refuses to overwrite unless ``overwrite``)."""
    if not isinstance(skeleton, Skeleton):
        raise BadInputError("skeleton must be a Skeleton from hand_skeleton() or read_skeleton()")
    call("write_skeleton", skeleton, str(file), comment=comment, overwrite=bool(overwrite))
    return str(file)


def read_failures(x):
    """The files or lines a reader could not read (R's ``read_failures()``): a DataFrame (file,
    line, class, message); empty when everything was read."""
    failures = getattr(x, "failures", None)
    if failures is None:
        if not isinstance(x, Grasps):
            raise BadInputError("x must be the result of a reader such as read_graspdb14()")
        return r_to_py(call("read_failures", x))
    return failures


def graspdb14_to_hust(x, dip="inferred"):
    """GraspDB14's 23 CyberGlove sensors mapped onto the 16 HUST DoFs (R's ``graspdb14_to_hust()``)."""
    return r_to_py(call("graspdb14_to_hust", _as_grasps(x), dip=dip))


def segment_by_switch(x, keep="all", min_frames=1, switch=None):
    """Cut recordings at the changes of a switch channel (R's ``segment_by_switch()``)."""
    return r_to_py(call("segment_by_switch", _as_grasps(x), keep=keep,
                        min_frames=_check_count(min_frames, "min_frames"), switch=switch))


def write_hand_animation(x, file, recording=1, overwrite=False, **kwargs):
    """Animate one recording as a GIF (or ``.mp4`` where ffmpeg is installed) with R's
    ``write_hand_animation()``; refuses to overwrite unless ``overwrite``. Returns the path."""
    call("write_hand_animation", _as_grasps(x), str(file), recording=_check_count(recording, "recording"),
         overwrite=bool(overwrite), **kwargs)
    return str(file)


# ---------------------------------------------------------------- models


def fit_grasp_model(x, grasp=None, seed=1, *, ncomp=None, warp_ncomp=None, mixture_components=None,
                    warping=None, dependence="independent", motion="auto", **kwargs):
    """Fit the generative model of one grasp type (R's ``fit_grasp_model()``, same arguments);
    a :class:`GraspModel` for :func:`generate` and :func:`project`. ``None`` is R's
    ``NULL``: the default of ``dependence`` (two FPCs per DoF and DTW for the thesis' model).
    R's other arguments (``engine``, ``overlong``, ``max_stall``, ``keep_data``,
    ``mixture_guard``, ``fpc_scores``, ``residuals``, ``degenerate_warps``) pass by keyword."""
    return GraspModel(call("fit_grasp_model", _as_grasps(x), grasp=grasp, ncomp=ncomp, warp_ncomp=warp_ncomp,
                           mixture_components=mixture_components, warping=warping, seed=_check_seed(seed),
                           dependence=dependence, motion=motion, **kwargs))


def fit_grasp_models(x, grasps=None, seed=1, dependence="independent", *, ncomp=None, mixture_components=None,
                     warping=None, motion="auto", cache=None, distance="likelihood", **kwargs):
    """Fit one generative model per grasp type (time warping + FPCA + score distributions); returns a :class:`GraspModels`.

    ``dependence="independent"`` is the thesis' model (DTW, two FPCs per DoF, a mixture per
    DoF, each DoF on its own); ``"copula"`` joins all DoFs' scores and the duration by a
    Gaussian copula so that generated fingers move together (linear time normalisation, four
    least-squares FPCs per DoF); ``"kernel"`` draws that joint score vector from a kernel
    density on the training recordings' own vectors (same basis; keeps the clusters of a type
    grasped round a few objects). ``ncomp``, ``mixture_components``, ``warping`` and ``motion``
    (and, by keyword, R's other arguments of ``fit_grasp_model()``: ``fpc_scores``,
    ``mixture_guard``, ...) go to R's ``fit_grasp_model()``, which documents both models and
    their defaults; ``None`` is R's ``NULL``, the default. ``cache`` is a folder for resumable
    fits; ``distance`` (``"likelihood"`` or ``"residual"``) what :func:`classify` ranks by.
    """
    if dependence not in ("independent", "copula", "kernel"):
        raise BadInputError(f"dependence must be 'independent', 'copula' or 'kernel', not {dependence!r}")
    g = _as_grasps(x)
    if distance not in ("likelihood", "residual"):
        raise BadInputError(f"distance must be 'likelihood' or 'residual', not {distance!r}")
    return GraspModels(call("fit_grasp_models", g, grasps=_grasps_arg(grasps), seed=_check_seed(seed),
                            dependence=dependence, motion=motion, cache=None if cache is None else str(cache),
                            distance=distance, **_given(ncomp=ncomp, mixture_components=mixture_components,
                                                        warping=warping), **kwargs))


def evaluate_generation(models=None, held_out=None, training=None, n=None, reps=5, seed=1, recordings=None, *,
                        fit=None, split="auto", folds=None, **kwargs):
    """How natural generated grasps are, against a real-vs-real baseline (R's ``evaluate_generation()``).

    Either ``models`` (a :class:`GraspModels` or a dict of them by name, e.g.
    ``{"thesis": m1, "copula": m2}``) with ``held_out``, the recordings of new subjects, and
    ``training``, those the models were fitted on; or ``recordings`` alone, evaluated by folds
    (``fit``, a dict of argument dicts for :func:`fit_grasp_models` by model name, ``None``: R's
    three models; ``split``, ``folds`` as in R; ``folds=None`` is one fold per subject; R's
    ``overlong`` passes by keyword). Returns a
    dict with ``table`` (one row per model, type and measure: ``generated``, ``baseline``,
    ``better``, ``ratio``), ``overall`` (the rows of grasp ``"overall"``) and ``evaluation`` (a
    handle on the R result, for plotting in R).
    """
    ro = r()
    n = None if n is None else _check_count(n, "n", 5)
    if isinstance(models, Grasps):
        raise BadInputError("models must be model sets; to evaluate recordings by folds give them as recordings=")
    if recordings is not None:
        if models is not None or held_out is not None or training is not None:
            raise BadInputError("give either recordings (folds) or models with held_out and training, not both")
        if fit is not None:
            kwargs["fit"] = ro.r["list"](**{str(k): ro.r["list"](**v) for k, v in fit.items()})
        if split not in ("auto", "subject", "recording"):
            raise BadInputError(f"split must be 'auto', 'subject' or 'recording', not {split!r}")
        kwargs["split"] = split
        if folds is not None:
            kwargs["folds"] = _check_count(folds, "folds")
        res = call("evaluate_generation", recordings=_as_grasps(recordings, "recordings"), n=n,
                   reps=_check_count(reps, "reps"), seed=_check_seed(seed), **kwargs)
    else:
        if isinstance(models, GraspModels):
            rmodels = models.robj
        elif isinstance(models, dict) and models and all(isinstance(v, GraspModels) for v in models.values()):
            rmodels = ro.r["list"](**{str(k): v.robj for k, v in models.items()})
        else:
            raise BadInputError("models must be a GraspModels or a dict of them by name")
        if fit is not None or folds is not None or split != "auto":
            raise BadInputError("fit, split and folds are for recordings evaluated by folds, not for models")
        res = call("evaluate_generation", rmodels, _as_grasps(held_out, "held_out"),
                   _as_grasps(training, "training"), n=n, reps=_check_count(reps, "reps"),
                   seed=_check_seed(seed), **kwargs)
    table = r_to_py(ro.r["as.data.frame"](res))
    return {"table": table, "overall": table[table["grasp"] == "overall"].reset_index(drop=True),
            "evaluation": RHandle(res)}


def generate(x, n=1, grasps=None, seed=1, limits=None, *, warp=True, phases=True, **kwargs):
    """Generate new grasps by sampling component scores (thesis eq. 2.5); R's
    ``generate(x, n, grasps, seed, warp, limits, ...)``. ``warp=False`` keeps every grasp on
    the model's template time; ``phases`` adds the rest and hold of a model fitted to
    recordings that have them. R's ``chunk`` and ``callback`` (streaming to an R function)
    pass by keyword.

    ``x`` is a :class:`GraspModels` (``grasps`` selects the types, all by default) or a
    :class:`GraspModel`. ``seed`` defaults to 1 as in every handmotion verb that draws random
    numbers (a call repeats itself); ``None`` draws from R's current random stream.

    ``limits`` keeps angles inside the hand's joint limits by a smooth map (``None``: on for
    copula models, off for the thesis' model).

    Returns a :class:`Grasps` (use its ``as_array()`` for an n x frames x DoF numpy
    array padded with NaN).
    """
    _refuse_renamed(kwargs, {"models": "x", "grasp": "grasps",
                             "as_array": "the Grasps' as_array() method (generate(x).as_array())"})
    if not isinstance(x, (GraspModels, GraspModel)):
        raise BadInputError("x must come from fit_grasp_models() or fit_grasp_model()")
    n = _check_count(n, "n")
    if limits not in (None, True, False):
        raise BadInputError(f"limits must be None, True or False, not {limits!r}")
    kw = dict(n=n, seed=_check_seed(seed), warp=bool(warp), limits=limits, phases=bool(phases), **kwargs)
    if grasps is not None:
        kw["grasps"] = _grasps_arg(grasps)
    return r_to_py(call("generate", x, **kw))


_state_methods = {}


def _classify_methods():
    """The classifiers' method names, read from R, where they are written once: the default
    of ``classify()``'s ``method`` (``?handmotion::classify``; ``evaluate_loso()`` takes the
    same), so a method added in R is one Python accepts."""
    methods = _state_methods.get("classify")
    if methods is None:
        methods = tuple(str(m) for m in r().r("eval(formals(handmotion::classify)$method)"))
        _state_methods["classify"] = methods
    return methods



def classify(models, x, method=None, **kwargs):
    """Classify recordings with fitted models; the method follows from ``models``.

    ``models`` are fitted models: a :class:`GraspModels` from :func:`fit_grasp_models`
    (``"fpca"``, the thesis' distance) or a :class:`GraspClassifier` from
    :func:`fit_grasp_classifier`. It is R's ``classify()``, a thin wrapper over
    ``predict(type="distance")`` that keeps the true types for the confusion matrix.
    Nothing is fitted here: a :class:`Grasps` is refused (fit first; for a held-out
    estimate use :func:`evaluate_loso`).

    Returns a dict with ``predictions`` (DataFrame), ``confusion`` (DataFrame, rows =
    predicted model, columns = true type), ``accuracy`` (float), ``metrics`` (DataFrame
    of R's ``summary()``) and ``classification`` (a handle on the R result, for
    :func:`thesis_table`).
    """
    if method is not None and method not in _classify_methods():
        raise BadInputError(f"method must be one of {_classify_methods()}, not {method!r}")
    if isinstance(models, Grasps):
        raise BadInputError("models must be fitted: fit_grasp_models(train) or fit_grasp_classifier(train); "
                            "evaluate_loso() fits on training subjects and classifies the held-out ones")
    g = _as_grasps(x)
    ro = r()
    if method is not None:
        kwargs["method"] = method
    res = call("classify", models, g, **kwargs)
    conf = call("grasp_confusion", res)
    table = ro.r["as.data.frame.matrix"](ro.r["unclass"](conf.rx2("table")))
    summ = r_to_py(call(ro.r["summary"], conf))
    acc = summ.loc[summ[".metric"] == "accuracy", ".estimate"]
    return {"classification": RHandle(res),
            "predictions": r_to_py(ro.r["as.data.frame"](res)),
            "confusion": r_to_py(table).set_axis(list(ro.r["rownames"](table)), axis=0),
            "accuracy": float(acc.iloc[0]) if len(acc) else float("nan"),
            "metrics": summ}


def evaluate_loso(x, method="fpca", folds=None, seed=1, split="auto", *, fit_args=None, subjects=None,
                  in_sample=True, **kwargs):
    """Held-out evaluation of a classifier: by subject (leave-one-subject-out, or ``folds``
    groups of subjects) with two or more subjects, else ``folds`` (default 5) stratified folds of
    recordings; ``split`` is ``"auto"``, ``"subject"`` or ``"recording"``. ``fit_args`` (a dict)
    go to the method's fit, ``subjects`` restricts the held-out subjects, ``in_sample=False``
    skips the in-sample accuracy.

    Returns a dict with ``accuracy`` (held-out and in-sample), ``accuracy_ci`` (95% interval of
    the held-out accuracy), ``confusion`` (held-out, DataFrame) and ``evaluation`` (a handle on
    the R result).
    """
    if split not in ("auto", "subject", "recording"):
        raise BadInputError(f"split must be 'auto', 'subject' or 'recording', not {split!r}")
    kwargs["split"] = split
    if fit_args is not None:
        kwargs["fit_args"] = r().r["list"](**{str(k): v for k, v in dict(fit_args).items()})
    if subjects is not None:
        kwargs["subjects"] = [str(v) for v in subjects]
    kwargs["in_sample"] = bool(in_sample)
    if method not in _classify_methods():
        raise BadInputError(f"method must be one of {_classify_methods()}, not {method!r}")
    ro = r()
    res = call("evaluate_loso", _as_grasps(x), method=method,
               folds=None if folds is None else _check_count(folds, "folds"), seed=_check_seed(seed),
               **kwargs)
    acc = res.rx2("accuracy")
    table = ro.r["as.data.frame.matrix"](ro.r["unclass"](res.rx2("confusion").rx2("table")))
    ci = res.rx2("accuracy_ci")
    return {"accuracy": {str(k): float(v) for k, v in zip(ro.r["names"](acc), acc)},
            "accuracy_ci": {str(k): float(v) for k, v in zip(ro.r["names"](ci), ci)},
            "confusion": r_to_py(table).set_axis(list(ro.r["rownames"](table)), axis=0),
            "evaluation": RHandle(res)}


# ----------------------------------------------------------- recognition


def fit_grasp_classifier(x, method="discriminant", **kwargs):
    """A fitted grasp classifier for :func:`classify` (R's ``fit_grasp_classifier()``; the
    method's arguments by name, validated in R):

    * ``"discriminant"``: shrinkage LDA on postures at fractions of the motion, duration,
      travel and extremes per DoF (``at``, ``prior``); a :class:`GraspClassifier`;
    * ``"last_frame"``: per-type PCA of the recordings' last frames, the thesis' baseline
      (``ncomp``, ``grasps``), also for :func:`thesis_table`;
    * ``"weighted_fpca"``: the thesis' FPCA distance with per-type DoF weights (``models``, a
      :class:`GraspModels` or None; ``time``, ``"uniform"`` or ``"end"``).

    Every method gives a :class:`GraspClassifier`, whose ``predict()`` answers as R's.
    """
    if "models" in kwargs and kwargs["models"] is not None:
        if not isinstance(kwargs["models"], GraspModels):
            raise BadInputError("models must be a GraspModels from fit_grasp_models(), or None")
        kwargs["models"] = kwargs["models"].robj
    fit = call("fit_grasp_classifier", _as_grasps(x), method=method, **kwargs)
    return GraspClassifier(fit)


def fit_grasp_recognizer(x, horizon=None, **kwargs):
    """One discriminant per number of frames seen, for recognition while the hand still moves
    (R's ``fit_grasp_recognizer()``); a :class:`GraspRecognizer`."""
    kw = dict(kwargs)
    if horizon is not None:
        kw["horizon"] = _check_count(horizon, "horizon")
    return GraspRecognizer(call("fit_grasp_recognizer", _as_grasps(x), **kw))


def start_recognition(recognizer):
    """A live recognition stream (R's ``start_recognition()``): ``update()`` it with one frame
    at a time. The same as ``recognizer.stream()``."""
    if not isinstance(recognizer, GraspRecognizer):
        raise BadInputError("recognizer must come from fit_grasp_recognizer()")
    return recognizer.stream()


def grasp_confusion(truth, predicted=None, levels=None):
    """A confusion matrix (R's ``grasp_confusion()``) as a DataFrame, rows = predicted, columns =
    true type. ``truth`` is the ``"classification"`` of :func:`classify` (or a list of true
    labels, with ``predicted`` the predicted ones)."""
    ro = r()
    if isinstance(truth, RHandle):
        conf = call("grasp_confusion", truth)
    else:
        conf = call("grasp_confusion", [str(v) for v in truth],
                    None if predicted is None else [str(v) for v in predicted], levels=levels)
    table = ro.r["as.data.frame.matrix"](ro.r["unclass"](conf.rx2("table")))
    return r_to_py(table).set_axis(list(ro.r["rownames"](table)), axis=0)


def evaluate_early_recognition(x, ms=None, fractions=None, folds=None, seed=1, split="auto", **kwargs):
    """Held-out accuracy of early recognition against time (ms) and fraction of the motion
    (R's ``evaluate_early_recognition()``); a DataFrame (scale, value, accuracy, n, frames).
    ``split`` as in :func:`evaluate_loso`; other keyword arguments go to the recogniser's fit."""
    if split not in ("auto", "subject", "recording"):
        raise BadInputError(f"split must be 'auto', 'subject' or 'recording', not {split!r}")
    kw = dict(kwargs, split=split)
    if ms is not None:
        kw["ms"] = [float(v) for v in ms]
    if fractions is not None:
        kw["fractions"] = [float(v) for v in fractions]
    res = call("evaluate_early_recognition", _as_grasps(x),
               folds=None if folds is None else _check_count(folds, "folds"), seed=_check_seed(seed), **kw)
    return r_to_py(r().r["as.data.frame"](r().r["unclass"](res)))


def thesis_table(id, **kwargs):
    """One of the thesis' chapter-5 tables as a pandas DataFrame, ours beside the published values.

    ``id`` is ``"5.1"``, ``"5.2"``, ``"5.3"``, ``"5.3 claims"``, ``"5.6"``, ``"5.7"`` or ``"5.8"``;
    the table's inputs are named as in R's ``thesis_table()``: ``models`` (from
    :func:`fit_grasp_models`), ``classification`` (``classify(...)["classification"]``),
    ``confusion`` and ``held_out``, ``fit`` (from ``fit_grasp_classifier(x, method="last_frame")``) and ``pcs``.
    """
    return r_to_py(call("thesis_table", str(id), **kwargs))


# ---------------------------------------------------------------- hand-over


def select_markers(x=None, n=6, method="ranked", **kwargs):
    """Choose ``n`` hand-over markers.

    ``method="ranked"`` (default): the ``n`` most influential markers of a reference set
    ``x``; the sets are nested (the 3-marker set lies inside the 6-marker set).
    ``"handpicked"``: the six-marker baseline after Hoyet et al. (``x`` not needed).
    ``"search"``: the set with the least held-out reconstruction error on ``x``
    (keyword arguments ``holdout``, ``max_frames``, ``seed``, ... as in R).
    """
    ref = None if x is None else x if isinstance(x, RHandle) else _as_grasps(x, "x")
    return [str(v) for v in call("select_markers", ref, n=_check_count(n, "n"), method=method, **kwargs)]


def fit_handover(reference, markers=None, n_markers=6, *, ncomp=None, neighbours=256, method="pca", **kwargs):
    """Fit the PCA + locally weighted regression reconstruction model; returns a :class:`HandoverModel`.

    ``markers`` is a list of marker names (a marker set, as in :func:`forward_kinematics`);
    ``None`` (default) takes the ``n_markers`` top-ranked markers of ``reference``. ``ncomp``
    (PCs of the reconstruction, ``None``: chosen), ``neighbours`` (of the locally weighted
    regression) and ``method`` (``"pca"`` or ``"direct"``) as in R; R's other arguments
    (``smooth``, ``filter_size``, ``ridge``, ``eps``, ``skeleton``) pass by keyword.
    """
    return HandoverModel(call("fit_handover", _as_grasps(reference, "reference"), markers=markers,
                              n_markers=_check_count(n_markers, "n_markers"), ncomp=ncomp,
                              neighbours=neighbours, method=method, **kwargs))


def handover_error(truth, recon=None, by="overall", reference=None, sets=None, **kwargs):
    """Reconstruction error in degrees (R's ``handover_error()``): a number for
    ``by="overall"``, else a DataFrame (``by`` = ``"recording"``, ``"frame"``, ``"dof"``,
    ``"ncomp"`` or ``"markers"``; ``reference``, ``sets`` as in R)."""
    res = call("handover_error", _as_grasps(truth, "truth"), None if recon is None else _as_grasps(recon, "recon"),
               by=by, reference=None if reference is None else _as_grasps(reference, "reference"), sets=sets,
               **kwargs)
    out = r_to_py(res)
    return float(out) if by == "overall" else out


def reproduce_thesis(output_dir="output", subjects=30, seed=1, folds=None, grasps=None, quiet=True,
                     progress=True, overwrite=False):
    """The whole of the thesis' chapter 5 as an HTML report in ``output_dir`` (R's
    ``reproduce_thesis()``; minutes on the default design). Returns the report's path. An existing
    report is replaced only with ``overwrite=True`` (else ``BadFileError``, as every writer)."""
    kw = dict(subjects=_check_count(subjects, "subjects", 2), seed=_check_seed(seed), quiet=bool(quiet),
              progress=bool(progress), overwrite=bool(overwrite))
    if folds is not None:
        kw["folds"] = _check_count(folds, "folds", 2)
    if grasps is not None:
        kw["grasps"] = _grasps_arg(grasps)
    return str(r_to_py(call("reproduce_thesis", os.fspath(output_dir), **kw)))


# ---------------------------------------------------------------- your own glove


def glove_profile(x="hust", name=None, unit="deg"):
    """A glove profile as a DataFrame of channels (R's ``glove_profile()``).

    ``x`` is a shipped profile's name (``"hust"``, ``"graspdb14"``, ``"cyberglove18"``,
    ``"cyberglove22"``, ``"resistive"``), a DataFrame of channels or a CSV path. The result
    (columns ``channel``, ``joint``, ``axis``, ``sign``, ``scale``, ``frame``, ``unit``,
    ``min``, ``max``, ``angle_min``, ``angle_max``, ``stuck``) can be passed as ``glove=``
    to :class:`Grasps`, :func:`read_glove` or :func:`simulate_grasps`.
    """
    import pandas as pd
    if isinstance(x, pd.DataFrame):
        from ._bridge import df_to_r
        x = df_to_r(x)
    res = call("glove_profile", x, name=name, unit=unit)
    out = r_to_py(r().r["getElement"](res, "channels"))
    out.attrs["name"] = str(r().r["getElement"](res, "name")[0])
    return out


def _glove_arg(glove):
    import pandas as pd
    if isinstance(glove, pd.DataFrame):
        from ._bridge import df_to_r
        return call("glove_profile", df_to_r(glove), name=glove.attrs.get("name", "custom"))
    return glove


def read_glove(path, glove, rate=None, time=None, time_unit=None, timestamps=None, pattern=None,
               manifest=None, recursive=None, **kwargs):
    r"""Read any glove's delimited files (one per recording) with the channels of ``glove``
    (a profile name or DataFrame), as R's ``read_glove()``.

    Labels come from ``pattern`` (a regular expression with named groups ``grasp``,
    ``subject``, ``object``, ``trial``, ``id``; one that holds a ``/`` is matched against
    the path below ``path``, so ``"^(?<grasp>[^/]+)/"`` takes the label from the folder and
    sub-folders are read) or a ``manifest``. Ids are the file names, or the relative paths
    when a name repeats across folders. ``time`` names a time column (unit from
    ``time_unit``, or the name's suffix: ``"time_ms"``); the unevenly spaced frames are then
    resampled to one constant ``rate`` (default: one over the median interval), each file's
    own rate kept in ``meta["recorded_rate"]``; ``timestamps`` names a folder (below ``path``)
    holding that column in a file per data file at the same relative path. ``recursive=None`` looks into sub-folders
    when ``pattern`` holds a ``/``. Files that could not be read are in ``result.failures``.

    The shipped real recordings (626 files, 8 grasp folders, participants P1 and P2)::

        import handmotion as hm
        g = hm.read_glove(hm.extdata("flexglove"), glove="flexglove", time="time_ms",
                          pattern=r"^(?<grasp>[^/]+)/(?<subject>P\d)_(?<object>[a-z]+)_(?<trial>\d+)$")
    """
    args = dict(rate=None if rate is None else float(rate), time=time, time_unit=time_unit,
                timestamps=None if timestamps is None else os.fspath(timestamps), pattern=pattern,
                manifest=manifest)
    if recursive is not None:
        args["recursive"] = bool(recursive)
    return _with_failures(call("read_glove", _path_arg(path), glove=_glove_arg(glove), **args, **kwargs))


def calibrate(x, poses=None, angles=None, ranges=None):
    """Raw counts to degrees per channel: from calibration ``poses`` (a dict of name -> frames x
    channels arrays or Grasps; ``"flat"`` and ``"fist"`` are built in), ``ranges`` (a DataFrame
    with channel, min, max[, angle_min, angle_max]) or the profile's nominal map. Returns a
    :class:`Grasps` in degrees whose ``calibration`` attribute is a DataFrame (channel, gain,
    offset, source)."""
    ro = r()
    args = {}
    if poses is not None:
        if not isinstance(poses, dict):
            raise BadInputError("poses must be a dict of pose name -> recordings")
        args["poses"] = ro.r["list"](**{str(k): (_as_grasps(v).to_r() if isinstance(v, Grasps)
                                                 else np.asarray(v, dtype=float)) for k, v in poses.items()})
    if angles is not None:
        args["angles"] = ro.r["list"](**{str(k): np.asarray(v, dtype=float) for k, v in angles.items()})
    if ranges is not None:
        args["ranges"] = ranges
    res = call("calibrate", _as_grasps(x), **args)
    out = r_to_py(res)
    out.calibration = r_to_py(ro.r["attr"](res, "calibration"))
    return out


def find_motion(x, min_move=12, min_still=0.1):
    """Where the grasping motion starts and ends in each recording (R's ``find_motion()``): a
    DataFrame with id, start, end, n_frames, rest, hold, found."""
    return r_to_py(call("find_motion", _as_grasps(x), min_move=float(min_move), min_still=float(min_still)))


def trim_motion(x, **kwargs):
    """Each recording cut to its motion, without the rest before and the hold after it."""
    return r_to_py(call("trim_motion", _as_grasps(x), **kwargs))


def cut_motion(x, min_motion=0.3, min_gap=0.3, min_move=12):
    """A continuous stream cut into one recording per motion (R's ``cut_motion()``)."""
    return r_to_py(call("cut_motion", _as_grasps(x), min_motion=float(min_motion), min_gap=float(min_gap),
                        min_move=float(min_move)))


def calibration_pose_angles(glove, pose="flat"):
    """The built-in angles of the ``"flat"`` and ``"fist"`` calibration poses, one per channel."""
    res = call("calibration_pose_angles", _glove_arg(glove), pose=pose)
    return r_to_py(res)
