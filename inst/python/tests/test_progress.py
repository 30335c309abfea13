"""Progress bars through Python (issue 42): none when output is not a terminal
(pytest captures it, as a log would); in a terminal one bar redrawn in place on
standard output, never a logged line per update."""

import logging


def _fit(hm, small, ro):
    ro.r("options(progressr.enable_after = 0)")
    try:
        return hm.fit_grasp_models(small, seed=1, mixture_components=1)
    finally:
        ro.r("options(progressr.enable_after = NULL)")


def test_no_bar_when_output_is_captured(hm, small, ro, capsys, caplog):
    with caplog.at_level(logging.WARNING):
        _fit(hm, small, ro)
    out = capsys.readouterr()
    logged = " ".join(r.getMessage() for r in caplog.records)
    for text in (out.out, out.err, logged):
        assert "|=" not in text and "100%" not in text


def test_terminal_bar_is_one_line_redrawn_in_place(hm, small, ro, capsys, caplog):
    bridge = ro.r("handmotion::python_bridge")

    def setup(terminal):
        return bridge("progress_setup", terminal)
    old = ro.r("options(progressr.enable = NULL, progressr.handlers = NULL)")
    try:
        setup(ro.BoolVector([True]))        # as R starts when stdout is a terminal
        with caplog.at_level(logging.WARNING):
            _fit(hm, small, ro)
        out = capsys.readouterr().out
    finally:
        ro.r["options"](old)
        setup(ro.BoolVector([False]))
    bar = out[out.index("|"):]
    assert "100%" in bar
    # every update redraws the bar with a carriage return: one line, not one per update
    assert bar.count("\r") >= 2
    assert bar.rstrip("\n").count("\n") == 0
    # nothing went through rpy2's stderr logger ("R[write to console]: ...")
    assert not any("|=" in r.getMessage() for r in caplog.records)
