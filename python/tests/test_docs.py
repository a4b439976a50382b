"""The `python` blocks of docs/book/src/python.md and of the README run as written: each
document's blocks in order, in one namespace, in an empty folder."""

from __future__ import annotations

import re

import pytest

from conftest import ROOT

DOCUMENTS = [ROOT / "docs" / "book" / "src" / "python.md", ROOT / "README.md"]


def python_blocks(path):
    text = path.read_text(encoding="utf-8")
    return [
        (text[: m.start()].count("\n") + 1, m.group(1))
        for m in re.finditer(r"^```python\n(.*?)^```$", text, flags=re.S | re.M)
    ]


@pytest.mark.parametrize("path", DOCUMENTS, ids=lambda p: p.name)
def test_python_blocks_run_as_written(path, tmp_path, monkeypatch):
    blocks = python_blocks(path)
    assert blocks, f"{path} has no python block"
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "__doc_block__"}
    for line, code in blocks:
        exec(compile(code, f"{path.name}:{line}", "exec"), namespace)
