"""What the tests share: the `dvf` command line they compare against, and exact comparison of
JSON values (every float by its bits)."""

from __future__ import annotations

import json
import math
import os
import subprocess
from pathlib import Path
from typing import Any, List

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def dvf_bin() -> Path:
    """The `dvf` binary of this checkout (DVF_BIN, or target/debug/dvf that make test-python builds)."""
    path = Path(os.environ.get("DVF_BIN", ROOT / "target" / "debug" / "dvf"))
    if not path.exists():
        pytest.fail(f"{path} is missing: run `cargo build --bin dvf` (make test-python does)")
    return path


def cli(binary: Path, *args: str, stdin: str | None = None) -> str:
    """Stdout of `dvf ARGS`, which must succeed."""
    done = subprocess.run(
        [str(binary), *args], input=stdin, capture_output=True, text=True, check=False
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def cli_json(binary: Path, *args: str) -> Any:
    return json.loads(cli(binary, *args))


def bits(value: Any) -> Any:
    """`value` with every float as its hex form: equal results are equal bits (0.0 and -0.0,
    NaNs by their payload's form, differ)."""
    if isinstance(value, float):
        return value.hex() if not math.isnan(value) else "nan"
    if isinstance(value, dict):
        return {k: bits(v) for k, v in value.items()}
    if isinstance(value, list):
        return [bits(v) for v in value]
    return value


def lines(text: str) -> List[Any]:
    return [json.loads(line) for line in text.splitlines() if line.strip()]
