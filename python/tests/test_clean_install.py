"""The wheel in a clean virtual environment: pip installs it with its one dependency (numpy,
from the package index) and, with nothing else installed, a preset runs to the report
`dvf simulate` prints and bad input raises ValueError naming the field. The wheel is
$DVF_WHEEL (make test-python names the one it built)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import bits, cli_json

SCRIPT = r"""
import json, sys
import dvf
run = dvf.simulate("example3-circle-swap")
assert run.x.shape == (run.steps + 1, 6) and str(run.x.dtype) == "float64"
try:
    dvf.Scenario({"robots": [{"start": [0, 0, 0], "goal": [1, 0, 0]}], "params": {"k_omega": "fast"}})
    raise SystemExit("no error")
except ValueError as e:
    message = str(e)
try:
    import pandas
    raise SystemExit("pandas is installed")
except ImportError:
    pass
print(json.dumps({"report": run.report, "message": message}))
"""


def test_a_clean_environment_installs_the_wheel_and_runs_it(dvf_bin, tmp_path):
    wheel = os.environ.get("DVF_WHEEL")
    if not wheel:
        pytest.skip("DVF_WHEEL names no wheel (make test-python sets it)")
    env_dir = tmp_path / "venv"
    base = getattr(sys, "_base_executable", sys.executable)
    subprocess.run([base, "-m", "venv", str(env_dir)], check=True)
    python = env_dir / "bin" / "python"
    done = subprocess.run(
        [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", str(Path(wheel).resolve())],
        capture_output=True, text=True, check=False,
    )
    assert done.returncode == 0, done.stderr
    out = subprocess.run([str(python), "-c", SCRIPT], capture_output=True, text=True, check=False, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout)
    assert bits(got["report"]) == bits(cli_json(dvf_bin, "simulate", "--preset", "example3-circle-swap"))
    assert got["message"].startswith("params.k_omega: "), got["message"]
