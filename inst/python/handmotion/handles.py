"""Thin Python handles around R objects that have no natural Python form."""

import numpy as np

from ._bridge import bridge, call, r, r_to_py
from .errors import BadInputError
from .grasps import _as_grasps


class RHandle:
    """Wraps an R object; ``print()`` shows R's own print method.

    Attributes
    ----------
    robj : rpy2 object
        The wrapped R object, passed back to R unchanged by every handmotion function.
    """

    def __init__(self, robj):
        self.robj = robj

    def __repr__(self):
        # (print() runs inside capture.output(), on the R side of the bridge:
        # called from Python first, R's print wrote the object to the console too)
        text = "\n".join(bridge("print_text")(self.robj))
        return f"<{type(self).__name__}>\n{text}"

    def to_r(self):
        """The wrapped R object (what every handmotion function passes to R)."""
        return self.robj

    def r_class(self):
        """The R class vector of the wrapped object."""
        return list(r().r["class"](self.robj))


_PREDICT_TYPES = ("class", "prob", "distance")


class Classifier(RHandle):
    """A fitted classifier: every one answers :meth:`predict` alike (R's ``predict()``,
    ``?predict.grasp_models``)."""

    def predict(self, new_data, type="class", **kwargs):
        """One row per recording of ``new_data`` (index: the recording ids), as R's
        ``predict(object, new_data, type)`` returns it:
        ``type="class"`` a column ``.pred_class`` (None where a recording could not be
        classified), ``"prob"`` a column ``.pred_<class>`` per class (rows sum to 1),
        ``"distance"`` a column ``.dist_<class>`` per class (smaller is closer)."""
        if type not in _PREDICT_TYPES:
            raise BadInputError(f"type must be one of {_PREDICT_TYPES}, not {type!r}")
        out = call(r().r["predict"], self.robj, _as_grasps(new_data, "new_data"), type=type, **kwargs)
        df = r_to_py(out)
        df.index = [str(v) for v in r().r["rownames"](out)]
        return df

    def summary(self):
        """R's ``summary()`` of the classifier as a pandas DataFrame (one row per class)."""
        return r_to_py(call(r().r["summary"], self.robj))


class GraspModels(Classifier):
    """Fitted per-type grasp models (R class ``grasp_models``).

    Use :meth:`summary` for a per-type table, :meth:`predict` to classify, and pass the
    handle to :func:`handmotion.generate` or :func:`handmotion.classify`.
    """

    def summary(self):
        """Per-type summary as a pandas DataFrame (frames, warping, fallbacks, variance explained)."""
        return r_to_py(call(r().r["summary"], self.robj))

    def grasp_types(self):
        """Names of the grasp types that have a fitted model (a type whose fit failed stays
        in the set, see :meth:`failed`, but has no model)."""
        return [str(n) for n in bridge("fitted_types")(self.robj)]

    def failed(self):
        """The grasp types whose fit failed, with the reason, as a dict {type: message}."""
        s = self.summary()
        bad = s[s["failed"].notna()]
        return {str(g): str(m) for g, m in zip(bad["grasp"], bad["failed"])}

    def __len__(self):
        return len(self.grasp_types())

    def dependence(self, grasp):
        """Correlation between the DoFs' first FPC scores that the model of ``grasp`` generates
        with, as a DoF x DoF DataFrame (the identity for the thesis' independent model)."""
        if str(grasp) not in self.grasp_types():
            raise BadInputError(f"no model for grasp type {grasp!r}; have {self.grasp_types()}")
        return _labelled_matrix(bridge("dependence_matrix")(self.robj.rx2(str(grasp))))

    def project(self, new_data):
        """The recordings of ``new_data`` projected onto each type's model: :func:`handmotion.project`."""
        return project(self, new_data)


class GraspModel(RHandle):
    """One grasp type's generative model (R class ``grasp_model``, from
    :func:`handmotion.fit_grasp_model`): pass it to :func:`handmotion.generate` or
    :func:`project`. It is not a classifier (a :class:`GraspModels` set is)."""

    def summary(self):
        """R's ``summary()`` of the model as a DataFrame."""
        return r_to_py(call(r().r["as.data.frame"], call(r().r["summary"], self.robj)))

    def project(self, new_data):
        """The recordings of ``new_data`` projected onto this model: :func:`project`."""
        return project(self, new_data)


class Skeleton(RHandle):
    """A hand skeleton (R class ``hand_skeleton``)."""

    @property
    def joints(self):
        """The joint table as a pandas DataFrame (id, name, parent, offsets, limits)."""
        return r_to_py(self.robj.rx2("joints"))


class HandoverModel(RHandle):
    """A sparse-marker reconstruction model (R class ``handover_model``, from
    :func:`handmotion.fit_handover`)."""

    def predict(self, new_data, **kwargs):
        """Rebuild all joint angles from sparse markers (R's ``predict(object, new_data)`` on the
        model); a :class:`handmotion.Grasps`. ``new_data`` is a Grasps (its markers are computed by forward
        kinematics) or a numpy array frames x (3 x markers) of marker positions (NaN = occluded)."""
        q = new_data if isinstance(new_data, np.ndarray) and new_data.ndim == 2 else _as_grasps(new_data, "new_data")
        return r_to_py(call(r().r["predict"], self.robj, q, **kwargs))


def _projection(p):
    return {"ids": [str(v) for v in p.rx2("ids")],
            "distance": np.atleast_1d(r_to_py(p.rx2("distance"))),
            "scores": r_to_py(p.rx2("scores")),
            "residual": r_to_py(p.rx2("residual"))}


def project(object, new_data):
    """Project the recordings of ``new_data`` onto a model (R's ``project(object, new_data)``): for a
    :class:`GraspModel` one projection, for a :class:`GraspModels` a dict ``{grasp type:
    projection}`` (failed types have none). A projection is a dict with ``ids`` (the
    recordings), ``distance`` (numpy, one per recording: the thesis' eq. 4.4 over the whole
    hand), ``scores`` (numpy, recordings x DoF x FPC) and ``residual`` (numpy, recordings x
    DoF residual norms)."""
    if not isinstance(object, (GraspModel, GraspModels)):
        raise BadInputError("object must be a GraspModel or GraspModels from fit_grasp_model(s)()")
    res = call("project", object, _as_grasps(new_data, "new_data"), details=False)
    if isinstance(object, GraspModel):
        return _projection(res)
    return {str(name): _projection(p) for name, p in zip(r().r["names"](res), res)}


def _labelled_matrix(mat):
    """An R matrix with dimnames as a DataFrame, copied out of R's memory (r_to_py: a view
    through np.asarray() would point at memory R reuses once it collects the matrix)."""
    import pandas as pd
    ro = r()
    return pd.DataFrame(r_to_py(mat), index=[str(v) for v in ro.r["rownames"](mat)],
                        columns=[str(v) for v in ro.r["colnames"](mat)])


class GraspClassifier(Classifier):
    """A fitted grasp classifier (R classes ``grasp_discriminant``, ``last_frame_pca`` and
    ``weighted_fpca`` of the family ``grasp_classifier``, from
    :func:`handmotion.fit_grasp_classifier`)."""


class GraspRecognizer(Classifier):
    """An early grasp recogniser (R class ``grasp_recognizer``): classify from the first
    frames, or open a :class:`RecognitionStream` for a live loop."""

    def predict(self, new_data, type="class", frames=None, ms=None, fraction=None):
        """Classify every recording of ``new_data`` from its first frames: at most one of ``frames``,
        ``ms`` or ``fraction`` (none: the whole recording); the result as
        :meth:`Classifier.predict`."""
        given = {k: v for k, v in dict(frames=frames, ms=ms, fraction=fraction).items() if v is not None}
        if len(given) > 1:
            raise BadInputError("give at most one of frames, ms and fraction (none: the whole recording)")
        return super().predict(new_data, type=type, **given)

    def stream(self):
        """A new live stream (R's ``start_recognition()``)."""
        return RecognitionStream(call("start_recognition", self.robj))


class RecognitionStream(RHandle):
    """A live recognition stream: :meth:`update` with one frame at a time."""

    def update(self, frame):
        """Add the newest frame (one value per DoF) and return the class probabilities as a
        dict ``{grasp type: probability}``."""
        v = np.asarray(frame, dtype=float).ravel()
        if not np.all(np.isfinite(v)):
            raise BadInputError("frame must hold finite numbers, one per DoF")
        p = call(r().r["update"], self.robj, r().FloatVector(v))
        return {str(k): float(val) for k, val in zip(r().r["names"](p), p)}
