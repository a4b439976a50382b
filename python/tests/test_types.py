"""The package's types as a user's type checker sees them: mypy over the installed package
(its code against its stubs, dvf/_dvf.pyi) and, in strict mode, over a program that uses it."""

from __future__ import annotations

import shutil
import subprocess
import sys
from importlib import resources

import pytest

pytest.importorskip("mypy")

USER = """
import numpy as np
import dvf
from dvf.widget import Playground

run: dvf.Run = dvf.simulate("table2-obstacles", every=2)
x: np.ndarray = run.x
scenario = dvf.Scenario.from_preset("table2-obstacles").replace(duration=3)
vw = dvf.command(scenario, [0.0, 0.0, 0.0], [1.0, 1.0, 0.0])
grid: dvf.FieldGrid = dvf.field(scenario, robot=0, grid=5)
summary = dvf.sweep(3, robots=(2, 3))
rows = dvf.sweep_shard((1, 2), 3)
merged = dvf.merge(rows)
figure = Playground(scenario, time=1.0, controls=False)
figure.time = 2.0
"""


def test_mypy_finds_no_fault_in_the_package_or_its_use(tmp_path):
    # A copy outside site-packages, where mypy checks a package as its own code.
    package = resources.files("dvf")
    shutil.copytree(str(package), tmp_path / "dvf", ignore=shutil.ignore_patterns("static", "__pycache__"))
    (tmp_path / "user.py").write_text(USER)
    for args in (["-p", "dvf"], ["--strict", "--follow-imports=silent", "user.py"]):
        done = subprocess.run(
            [sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", str(tmp_path / ".mypy"), *args],
            cwd=tmp_path, capture_output=True, text=True, check=False,
        )
        assert done.returncode == 0, done.stdout + done.stderr
