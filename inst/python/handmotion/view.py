"""Looking at hands from Python: the R package's interactive 3D hand (``hand_3d()``)
as one self-contained HTML page, shown inline in Jupyter."""

import html as _html

from ._bridge import bridge, call
from .grasps import _as_grasps
from .errors import BadInputError


class HandView:
    """An interactive 3D hand page (R's ``hand_3d()`` widget, self-contained HTML).

    In Jupyter it shows inline (in an ``<iframe>``); :meth:`save` writes the page,
    which opens in any browser without a network connection.
    """

    def __init__(self, html, height=460):
        self.html = html
        self.height = height

    def save(self, path):
        """Write the page to ``path`` and return the path."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.html)
        return str(path)

    def _repr_html_(self):
        return (f'<iframe srcdoc="{_html.escape(self.html, quote=True)}" '
                f'style="width:100%;height:{int(self.height)}px;border:0" '
                'sandbox="allow-scripts"></iframe>')

    def __repr__(self):
        return f"<HandView: 3D hand page, {len(self.html) // 1024} KB>"


def hand_3d(x, layout="side", limits=False, markers=None, speed=1, autoplay=True, loop=False,
            width=None, height=None, **kwargs):
    """An interactive 3D hand: solid hands that play at the recordings' own rate.

    ``x`` is a :class:`handmotion.Grasps` (each recording a hand; subset it first,
    at most 8), or a dict of name -> Grasps, e.g. ``{"recorded": g[0], "generated":
    new[0]}``. ``layout`` is ``"side"`` or ``"overlay"``; ``limits=True`` colours
    joints outside the skeleton's limits; ``markers`` names hand-over markers to
    draw. Returns a :class:`HandView` (inline in Jupyter; ``.save(path)``).
    """
    if isinstance(x, dict):
        if not x or not all(isinstance(k, str) and k for k in x):
            raise BadInputError("x as a dict must map non-empty names to recordings")
        data = {k: _as_grasps(v, f"x[{k!r}]") for k, v in x.items()}
    else:
        data = _as_grasps(x)
    if markers is not None and not isinstance(markers, (list, tuple)):
        markers = [markers]
    widget = call("hand_3d", data, layout=layout, limits=limits, markers=list(markers) if markers else None,
                  speed=speed, autoplay=autoplay, loop=loop, width=width, height=height, **kwargs)
    page = str(bridge("widget_html")(widget)[0])
    return HandView(page, height=height if isinstance(height, (int, float)) else 460)
