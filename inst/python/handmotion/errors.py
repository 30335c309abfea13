"""Exceptions raised by the handmotion front end.

Every R error becomes a :class:`HandmotionError` (or a subclass chosen from the R
condition's class), carrying the R message and the R class vector, so Python code
can catch a bad file apart from a bad argument without parsing text.
"""


class _RCondition:
    """What an R condition carries into Python: its message and its class vector."""

    def __init__(self, message, r_class=None):
        super().__init__(message)
        self.r_message = message
        self.r_class = list(r_class or [])


class HandmotionError(_RCondition, Exception):
    """Base class: an error from handmotion (R or the Python front end).

    Attributes
    ----------
    r_message : str
        The message of the R condition (empty for errors raised in Python).
    r_class : list of str
        The R condition's class vector, e.g. ``["handmotion_error_bad_file",
        "handmotion_error", "rlang_error", "error", "condition"]``.
    """


class BadInputError(HandmotionError, ValueError):
    """A bad argument or recording (R family ``handmotion_error_bad_input``), or bad Python input."""


class BadRecordingError(BadInputError):
    """A recording that is not a finite numeric frames x DoF matrix."""


class UnknownGraspError(BadInputError):
    """A grasp type name or id that is not one of the 33 Feix types."""


class BadFileError(HandmotionError, OSError):
    """A file that cannot be read in its format (R family ``handmotion_error_bad_file``)."""


class BadSkeletonError(HandmotionError, ValueError):
    """An ``.xmlskel`` skeleton that is malformed or does not fit the data.

    Raised from a file it is also a :class:`BadFileError` (see :func:`from_r_condition`).
    """


class FitFailedError(HandmotionError, RuntimeError):
    """Data that cannot be fitted (R family ``handmotion_error_fit_failed``)."""


class RError(HandmotionError):
    """Any other error raised in R."""


# Specific R classes first, then the three families (R's documented hierarchy,
# ?handmotion_errors): the first class of the R condition found here wins.
_BY_CLASS = {
    "handmotion_error_bad_recording": BadRecordingError,
    "handmotion_error_unknown_grasp": UnknownGraspError,
    "handmotion_error_bad_skeleton": BadSkeletonError,
    "handmotion_error_bad_input": BadInputError,
    "handmotion_error_bad_file": BadFileError,
    "handmotion_error_fit_failed": FitFailedError,
}


class _SkeletonFileError(BadSkeletonError, BadFileError):
    """A malformed ``.xmlskel`` file: both a skeleton and a file error."""


def from_r_condition(message, r_class):
    """Build the Python exception that matches an R condition's class vector."""
    if "handmotion_error_bad_skeleton" in r_class and "handmotion_error_bad_file" in r_class:
        return _SkeletonFileError(message, r_class)
    for cls in r_class:
        if cls in _BY_CLASS:
            return _BY_CLASS[cls](message, r_class)
    if "handmotion_error" in r_class:
        return HandmotionError(message, r_class)
    return RError(message, r_class)


class HandmotionWarning(_RCondition, UserWarning):
    """A warning raised in R by handmotion (or any other R warning), carrying its R class.

    Attributes
    ----------
    r_class : list of str
        The R condition's class vector, e.g. ``["handmotion_warning_read_failures",
        "handmotion_warning", "rlang_warning", "warning", "condition"]``.
    """


class DegenerateDataWarning(HandmotionWarning):
    """Degenerate data accepted with a fallback (R family ``handmotion_warning_degenerate``).

    One-frame or identical recordings, more components than the data's rank, a mixture with more
    components than the recordings carry, a linear-warping fallback: the result is usable and its
    ``print()`` in R lists what happened; ``r_class`` names the specific cases
    (e.g. ``"handmotion_warning_one_frame"``).
    """


def from_r_warning(message, r_class):
    """Build the Python warning for an R warning condition."""
    if "handmotion_warning_degenerate" in r_class:
        return DegenerateDataWarning(message, r_class)
    return HandmotionWarning(message, r_class)
