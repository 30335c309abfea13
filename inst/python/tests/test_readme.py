"""The README's Python set-up and Python block run as written: the ``sh`` block that sets
PYTHONPATH is run by bash in the repository's root, then the ``python`` block by
/usr/bin/python3 with that PYTHONPATH, in a fresh process whose working directory is a
temporary directory (the block writes hand.html). Nothing is substituted."""

import os
import re
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
README = os.path.join(ROOT, "README.md")
# the interpreter the README names; the tests themselves run in it (make test's PY)
PYTHON = "/usr/bin/python3"


def _blocks(lang):
    text = open(README, encoding="utf-8").read()
    return re.findall(r"^```" + lang + r"\n(.*?)^```$", text, flags=re.S | re.M)


pytestmark = pytest.mark.skipif(not os.path.exists(README), reason="README.md is not beside the package")


def test_readme_python_setup_runs_as_written(tmp_path):
    setup = [b for b in _blocks("sh") if "PYTHONPATH" in b]
    assert len(setup) == 1
    assert PYTHON in setup[0]
    # run it, then report the PYTHONPATH it leaves
    out = subprocess.run(["bash", "-e", "-c", setup[0] + '\necho "PYTHONPATH=$PYTHONPATH"'], cwd=ROOT,
                         capture_output=True, text=True, env={**os.environ, "PYTHONPATH": ""})
    assert out.returncode == 0, out.stderr
    lines = out.stdout.strip().splitlines()
    assert lines[0] == "0.1.0"
    assert lines[-1] == "PYTHONPATH=" + os.path.join(ROOT, "inst", "python")


def test_readme_python_block_runs_as_written(tmp_path):
    assert os.path.realpath(sys.executable) == os.path.realpath(PYTHON) or os.path.exists(PYTHON)
    blocks = _blocks("python")
    assert len(blocks) == 1
    env = {**os.environ, "PYTHONPATH": os.path.join(ROOT, "inst", "python")}
    out = subprocess.run([PYTHON, "-c", blocks[0]], cwd=tmp_path, capture_output=True, text=True, env=env)
    assert out.returncode == 0, out.stderr[-3000:]
    # the file it writes went to the temporary directory, and the planted bad input was refused
    assert (tmp_path / "hand.html").stat().st_size > 10000
    assert "NaN" in out.stdout
