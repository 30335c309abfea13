"""Exceptions raised by the handmotion front end.

Every R error becomes a :class:`HandmotionError` (or a subclass chosen from the R
condition's class), carrying the R message and the R class vector, so Python code
can catch a bad file apart from a bad argument without parsing text.
"""


class HandmotionError(Exception):
    """Base class: an error from handmotion (R or the Python front end).

    Attributes
    ----------
    r_message : str
        The message of the R condition (empty for errors raised in Python).
    r_class : list of str
        The R condition's class vector, e.g. ``["handmotion_error_bad_file",
        "handmotion_error", "rlang_error", "error", "condition"]``.
    """

    def __init__(self, message, r_class=None):
        super().__init__(message)
        self.r_message = message
        self.r_class = list(r_class or [])


class BadInputError(HandmotionError, ValueError):
    """A bad argument (R class ``handmotion_error_bad_input``) or bad Python input."""


class BadRecordingError(HandmotionError, ValueError):
    """A recording that is not a finite numeric frames x DoF matrix."""


class UnknownGraspError(HandmotionError, ValueError):
    """A grasp type name or id that is not one of the 33 Feix types."""


class BadFileError(HandmotionError, OSError):
    """A file that cannot be read in its format (R class ``handmotion_error_bad_file``)."""


class BadSkeletonError(HandmotionError, ValueError):
    """An ``.xmlskel`` skeleton that is malformed."""


class RError(HandmotionError):
    """Any other error raised in R."""


_BY_CLASS = {
    "handmotion_error_bad_input": BadInputError,
    "handmotion_error_bad_recording": BadRecordingError,
    "handmotion_error_unknown_grasp": UnknownGraspError,
    "handmotion_error_bad_file": BadFileError,
    "handmotion_error_bad_skeleton": BadSkeletonError,
}


def from_r_condition(message, r_class):
    """Build the Python exception that matches an R condition's class vector."""
    for cls in r_class:
        if cls in _BY_CLASS:
            return _BY_CLASS[cls](message, r_class)
    if "handmotion_error" in r_class:
        return HandmotionError(message, r_class)
    return RError(message, r_class)
