"""The Python twin of R's ``grasps`` class."""

import numpy as np
import pandas as pd

from ._bridge import bridge, call, df_to_py, df_to_r, r, r_array, register_r_class
from .errors import BadInputError

CORE_META = ["id", "grasp", "subject", "object", "trial", "n_frames", "source"]


def _check_recordings(recordings):
    """Validate before anything reaches R: 2-D, numeric, finite, same DoF count."""
    if isinstance(recordings, np.ndarray) and recordings.ndim == 2:
        recordings = [recordings]
    if isinstance(recordings, np.ndarray) and recordings.ndim == 3:
        recordings = list(recordings)
    if not isinstance(recordings, (list, tuple)) or len(recordings) == 0:
        raise BadInputError("recordings must be a non-empty list of 2-D numpy arrays (frames x DoF)")
    out = []
    ncol = None
    for i, rec in enumerate(recordings):
        a = np.asarray(rec)
        if a.dtype == object or a.dtype.kind not in "biuf":
            raise BadInputError(f"recording {i} has dtype {a.dtype}; it must be numeric (frames x DoF)")
        if a.ndim != 2:
            raise BadInputError(f"recording {i} is {a.ndim}-D; it must be a 2-D array (frames x DoF)")
        if a.shape[0] == 0 or a.shape[1] == 0:
            raise BadInputError(f"recording {i} has zero length (shape {a.shape})")
        if not np.all(np.isfinite(a)):
            bad = np.argwhere(~np.isfinite(a))[0]
            raise BadInputError(
                f"recording {i} has NaN or infinite values (first at frame {bad[0] + 1}, DoF column {bad[1] + 1})")
        if ncol is None:
            ncol = a.shape[1]
        elif a.shape[1] != ncol:
            raise BadInputError(
                f"recordings are ragged: recording {i} has {a.shape[1]} DoF columns, recording 0 has {ncol}")
        out.append(np.ascontiguousarray(a, dtype=float))
    return out


class Grasps:
    """A set of grasp recordings: numpy arrays (frames x DoF) plus a metadata DataFrame.

    Mirrors R's ``grasps`` class and converts to and from it losslessly.

    Parameters
    ----------
    recordings : list of numpy.ndarray
        One frames x DoF array per recording (a single 2-D array is a set of one).
    meta : pandas.DataFrame, optional
        One row per recording; recognised columns ``id``, ``grasp`` (Feix name or
        id), ``subject``, ``object``, ``trial``, ``source``; extra columns are kept.
    dofs : list of str, optional
        DoF names (default: the 16 HUST DoFs when there are 16 columns).
    rate : float
        Sampling rate in Hz.
    unit : str
        ``"deg"``, ``"rad"`` or ``"raw"``.

    Examples
    --------
    >>> import numpy as np, handmotion as hm
    >>> g = hm.Grasps([np.zeros((40, 16)), np.ones((42, 16))],
    ...               meta={"grasp": ["Tripod", "Ring"]})
    >>> len(g), g.meta["n_frames"].tolist()
    (2, [40, 42])
    """

    def __init__(self, recordings, meta=None, dofs=None, rate=50.0, unit="deg", glove=None):
        recs = _check_recordings(recordings)
        n = len(recs)
        if meta is None:
            meta = pd.DataFrame(index=range(n))
        elif isinstance(meta, dict):
            meta = pd.DataFrame(meta)
        if not isinstance(meta, pd.DataFrame):
            raise BadInputError("meta must be a pandas DataFrame (or a dict of columns)")
        if len(meta) != n:
            raise BadInputError(f"meta has {len(meta)} rows but there are {n} recordings")
        meta = meta.reset_index(drop=True).copy()
        if "id" not in meta:
            meta["id"] = [f"r{i + 1}" for i in range(n)]
        meta["id"] = meta["id"].astype(str)
        if meta["id"].duplicated().any():
            raise BadInputError("recording ids must be unique")
        for col in ("grasp", "subject", "object", "source"):
            if col not in meta:
                meta[col] = None
        if "trial" not in meta:
            meta["trial"] = pd.array([None] * n, dtype="Int64")
        meta["n_frames"] = [r.shape[0] for r in recs]
        if dofs is None:
            dofs = _default_dofs(recs[0].shape[1])
        dofs = [str(d) for d in dofs]
        if len(dofs) != recs[0].shape[1]:
            raise BadInputError(f"dofs has {len(dofs)} names but recordings have {recs[0].shape[1]} columns")
        if not (isinstance(rate, (int, float, np.integer, np.floating)) and np.isfinite(rate) and rate > 0):
            raise BadInputError(f"rate must be a positive number, not {rate!r}")
        if unit not in ("deg", "rad", "raw"):
            raise BadInputError(f"unit must be 'deg', 'rad' or 'raw', not {unit!r}")
        self.recordings = recs
        self.meta = meta[CORE_META + [c for c in meta.columns if c not in CORE_META]]
        self.dofs = dofs
        self.rate = float(rate)
        self.unit = unit
        # the glove profile: None (recognised from the DoF names in R), the name of a
        # shipped profile, or a DataFrame of channels (see R's glove_profile())
        if glove is not None and not isinstance(glove, (str, pd.DataFrame)):
            raise BadInputError("glove must be a shipped profile's name or a DataFrame of channels")
        self.glove = glove
        self.glove_name = glove if isinstance(glove, str) else None
        self.levels = None
        # per recording, the 0/1 switch states of a GraspDB14 file (None: no switch)
        self.switch = None

    # ------------------------------------------------------------ container protocol
    def __len__(self):
        return len(self.recordings)

    def __getitem__(self, key):
        """Index by position, slice, list of positions, boolean mask or recording id(s)."""
        n = len(self)
        if isinstance(key, str):
            key = [key]
        if isinstance(key, slice):
            idx = list(range(n))[key]
        elif isinstance(key, (int, np.integer)):
            idx = [int(key) % n] if -n <= key < n else None
            if idx is None:
                raise IndexError(f"index {key} out of range for {n} recordings")
        else:
            key = list(key.tolist() if isinstance(key, (np.ndarray, pd.Series)) else key)
            if all(isinstance(k, (bool, np.bool_)) for k in key):
                if len(key) != n:
                    raise BadInputError(f"a boolean mask must have length {n}, not {len(key)}")
                idx = [i for i, k in enumerate(key) if k]
            elif all(isinstance(k, str) for k in key):
                pos = {v: i for i, v in enumerate(self.meta["id"])}
                missing = [k for k in key if k not in pos]
                if missing:
                    raise KeyError(f"unknown recording ids: {missing}")
                idx = [pos[k] for k in key]
            else:
                idx = [int(k) for k in key]
        out = Grasps.__new__(Grasps)
        out.recordings = [self.recordings[i] for i in idx]
        out.meta = self.meta.iloc[idx].reset_index(drop=True)
        out.dofs, out.rate, out.unit = list(self.dofs), self.rate, self.unit
        out.glove = getattr(self, "glove", None)
        out.glove_name = getattr(self, "glove_name", None)
        out.levels = getattr(self, "levels", None)
        sw = getattr(self, "switch", None)
        out.switch = None if sw is None else [sw[i] for i in idx]
        return out

    def __repr__(self):
        nf = self.meta["n_frames"]
        span = f", frames {nf.min()}-{nf.max()}" if len(self) else ""
        # read from uneven time stamps (R's print() says the same)
        rec = self.meta["recorded_rate"] if "recorded_rate" in self.meta else None
        note = ", resampled from time stamps" if rec is not None and rec.notna().any() else ""
        return (f"<Grasps: {len(self)} recordings of {len(self.dofs)} DoFs at {self.rate:g} Hz "
                f"in {self.unit}{span}{note}>")

    def as_array(self, pad=np.nan):
        """All recordings as one numpy array n x frames x DoF.

        Recordings shorter than the longest are padded at the end with ``pad``
        (NaN by default; the true lengths are ``meta["n_frames"]``).
        """
        if len(self) == 0:
            return np.empty((0, 0, len(self.dofs)))
        longest = int(self.meta["n_frames"].max())
        arr = np.full((len(self), longest, len(self.dofs)), pad, dtype=float)
        for i, rec in enumerate(self.recordings):
            arr[i, :rec.shape[0], :] = rec
        return arr

    # ------------------------------------------------------------ long form
    def to_long(self):
        """Long DataFrame like R's ``as.data.frame``: id, frame, time, dof, angle, grasp, subject, object, trial."""
        p = len(self.dofs)
        nf = self.meta["n_frames"].to_numpy()
        rec = np.repeat(np.arange(len(self)), nf * p)
        frame = np.concatenate([np.tile(np.arange(1, n + 1), p) for n in nf])
        dof = np.concatenate([np.repeat(np.arange(p), n) for n in nf])
        angle = np.concatenate([r.ravel(order="F") for r in self.recordings])
        m = self.meta
        return pd.DataFrame({
            "id": m["id"].to_numpy()[rec], "frame": frame, "time": (frame - 1) / self.rate,
            "dof": pd.Categorical(np.asarray(self.dofs)[dof], categories=self.dofs),
            "angle": angle,
            "grasp": m["grasp"].to_numpy()[rec], "subject": m["subject"].to_numpy()[rec],
            "object": m["object"].to_numpy()[rec], "trial": m["trial"].to_numpy()[rec],
        })

    @classmethod
    def from_long(cls, df, rate=50.0, unit="deg"):
        """Rebuild a Grasps from the long form of :meth:`to_long` (order of ids is kept)."""
        need = {"id", "frame", "dof", "angle"}
        if not need.issubset(df.columns):
            raise BadInputError(f"a long data frame needs columns {sorted(need)}")
        dofs = list(df["dof"].cat.categories) if isinstance(df["dof"].dtype, pd.CategoricalDtype) \
            else list(pd.unique(df["dof"]))
        ids = list(pd.unique(df["id"]))
        recs, rows = [], []
        for rid in ids:
            d = df[df["id"] == rid]
            wide = d.pivot(index="frame", columns="dof", values="angle")[dofs]
            recs.append(wide.to_numpy(dtype=float))
            first = d.iloc[0]
            rows.append({"id": rid, **{c: first[c] for c in ("grasp", "subject", "object", "trial")
                                        if c in d.columns}})
        return cls(recs, meta=pd.DataFrame(rows), dofs=dofs, rate=rate, unit=unit)

    # ------------------------------------------------------------ R conversion
    def to_r(self):
        """This set as an R ``grasps`` object (validated by R's constructor)."""
        values = np.concatenate([rec.ravel(order="F") for rec in self.recordings])
        meta = self.meta.drop(columns=["n_frames"])
        glove = getattr(self, "glove", None)
        extra = {}
        if isinstance(glove, pd.DataFrame):
            extra = dict(glove=df_to_r(glove), glove_name=getattr(self, "glove_name", None) or "custom")
        elif isinstance(glove, str):
            extra = dict(glove=glove)
        if getattr(self, "levels", None):
            extra["levels"] = list(self.levels)
        sw = getattr(self, "switch", None)
        if sw is not None and any(v is not None for v in sw):
            extra["switch"] = [None if v is None else np.asarray(v, dtype=np.int64) for v in sw]
        res = call("python_bridge", "grasps_in", values=values,
                   n_frames=np.asarray(self.meta["n_frames"], dtype=np.int64),
                   meta=df_to_r(meta), dofs=list(self.dofs), rate=self.rate, unit=self.unit, **extra)
        return res

    @classmethod
    def from_r(cls, robj):
        """Convert an R ``grasps`` object."""
        flat = bridge("grasps_out")(robj)
        values = r_array(flat.rx2("values"), dtype=float)
        nf = r_array(flat.rx2("n_frames"), dtype=int)
        dofs = [str(d) for d in flat.rx2("dofs")]
        p = len(dofs)
        bounds = np.concatenate([[0], np.cumsum(nf * p)])
        recs = [values[bounds[i]:bounds[i + 1]].reshape((nf[i], p), order="F") for i in range(len(nf))]
        out = cls.__new__(cls)
        out.recordings = recs
        out.meta = df_to_py(flat.rx2("meta"))
        out.dofs = dofs
        out.rate = float(flat.rx2("rate")[0])
        out.unit = str(flat.rx2("unit")[0])
        lv = flat.rx2("levels")
        out.levels = None if lv is None or lv == r().NULL else [str(v) for v in lv]
        out.glove = df_to_py(flat.rx2("glove"))
        out.glove_name = str(flat.rx2("glove_name")[0])
        sw = [None if v == r().NULL else r_array(v, dtype=np.int64) for v in flat.rx2("switch")]
        out.switch = sw if any(v is not None for v in sw) else None
        return out


def _default_dofs(p):
    """The DoF names R's grasps() gives p unnamed columns (the 16 HUST DoFs, else dof1..dofp),
    asked from R so the list is written down once."""
    return [str(d) for d in bridge("default_dofs")(int(p))]


def as_grasps(x):
    """``x`` as a :class:`Grasps` (R's ``as_grasps()``): a Grasps as it is, a frames x DoF
    array or a list of them converted; anything else is a :class:`BadInputError`."""
    return _as_grasps(x)


def _as_grasps(x, arg="x"):
    """:func:`as_grasps` whose error names the argument ``arg``: the one conversion every
    function of the package uses."""
    if isinstance(x, Grasps):
        return x
    if isinstance(x, np.ndarray) or isinstance(x, (list, tuple)):
        return Grasps(x)
    raise BadInputError(f"{arg} must be a handmotion.Grasps (or a list of frames x DoF arrays), "
                        f"not {type(x).__name__}")


register_r_class("grasps", Grasps.from_r)
