"""docs/python.md: every ```python block is a whole program (one per section), run here in a
scratch folder, so that the page cannot drift from the module (as docs/CMakeLists.txt does for
the ```cpp blocks of the other pages)."""

import os
import re
import subprocess
import sys

import pytest

from conftest import PROJECT

PAGE = PROJECT / "docs/python.md"


def examples():
    text = PAGE.read_text()
    found = []
    heading = "top"
    for match in re.finditer(r"^(#+ [^\n]*)$|^```python\n(.*?)^```", text, re.M | re.S):
        if match.group(1):
            heading = match.group(1).lstrip("# ").strip()
        else:
            found.append(pytest.param(match.group(2), id=heading))
    return found


def test_the_page_has_an_example_per_capability():
    assert len(examples()) >= 10


@pytest.mark.parametrize("code", examples())
def test_example_runs(code, tmp_path):
    (tmp_path / "example.py").write_text(code)
    run = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, capture_output=True,
                         text=True, env=dict(os.environ), timeout=240)
    assert run.returncode == 0, run.stdout + run.stderr
