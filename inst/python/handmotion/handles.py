"""Thin Python handles around R objects that have no natural Python form."""

from ._bridge import call, r, r_to_py


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
        ro = r()
        text = "\n".join(ro.r["capture.output"](ro.r["print"](self.robj)))
        return f"<{type(self).__name__}>\n{text}"

    def r_class(self):
        """The R class vector of the wrapped object."""
        return list(r().r["class"](self.robj))


class GraspModels(RHandle):
    """Fitted per-type grasp models (R class ``grasp_models``).

    Use :meth:`summary` for a per-type table and pass the handle to
    :func:`handmotion.generate` or :func:`handmotion.classify`.
    """

    def summary(self):
        """Per-type summary as a pandas DataFrame (frames, warping, fallbacks, variance explained)."""
        return r_to_py(call(r().r["summary"], self.robj))

    def grasp_types(self):
        """Names of the grasp types that have a model."""
        return [str(n) for n in r().r["names"](self.robj)]

    def __len__(self):
        return len(self.grasp_types())

    def dependence(self, grasp):
        """Correlation between the DoFs' first FPC scores that the model of ``grasp`` generates
        with, as a DoF x DoF DataFrame (the identity for the thesis' independent model)."""
        import numpy as np
        import pandas as pd
        if str(grasp) not in self.grasp_types():
            from .errors import BadInputError
            raise BadInputError(f"no model for grasp type {grasp!r}; have {self.grasp_types()}")
        ro = r()
        mat = ro.r("handmotion:::dependence_matrix")(self.robj.rx2(str(grasp)))
        names = [str(v) for v in ro.r["rownames"](mat)]
        return pd.DataFrame(np.asarray(mat), index=names, columns=names)


class Skeleton(RHandle):
    """A hand skeleton (R class ``hand_skeleton``)."""

    @property
    def joints(self):
        """The joint table as a pandas DataFrame (id, name, parent, offsets, limits)."""
        return r_to_py(self.robj.rx2("joints"))


class HandoverModel(RHandle):
    """A sparse-marker reconstruction model (R class ``handover_model``)."""
