"""A notebook with two widgets, executed and exported to HTML by nbconvert, draws both figures
when the page is opened from a file in Chromium. The exported page loads require.js, Jupyter's
HTML widget manager and anywidget from a CDN; the test serves those three from their npm
packages (.ci/install puts them in target/widget-cdn/) and refuses every other request, so the
figures draw with no server hosting the element or its wasm module. Screenshot in
test-results/python/."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT

sync_api = pytest.importorskip("playwright.sync_api")

CHROMIUM = os.environ.get("DVF_CHROMIUM", "/usr/bin/chromium")
CDN = ROOT / "target" / "widget-cdn"
RESULTS = ROOT / "test-results" / "python"
WAIT_MS = 120_000

CELLS = [
    "from dvf.widget import Playground\nPlayground('example3-circle-swap', time=3.0)",
    "Playground('table2-obstacles', controls=False)",
]


def cdn_file(url: str):
    """The local copy of a CDN file the exported page asks for, or None."""
    if url.endswith("/require.min.js"):
        return CDN / "requirejs" / "require.js"
    m = re.search(r"/@jupyter-widgets/html-manager@[^/]*/dist/([\w.-]+)$", url)
    if m:
        return CDN / "@jupyter-widgets" / "html-manager" / "dist" / m.group(1)
    if re.search(r"/anywidget@[^/]*/dist/index\.js$", url):
        return CDN / "anywidget" / "dist" / "index.js"
    return None


def test_an_exported_notebook_draws_its_widgets(tmp_path):
    if not (CDN / "done").exists():
        pytest.fail(f"{CDN} is missing: run .ci/install")
    nb = {
        "cells": [
            {"cell_type": "code", "execution_count": None, "id": f"c{k}", "metadata": {}, "outputs": [], "source": src}
            for k, src in enumerate(CELLS)
        ],
        "metadata": {"kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"}},
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    (tmp_path / "figures.ipynb").write_text(json.dumps(nb))
    env = dict(os.environ, JUPYTER_PLATFORM_DIRS="1", IPYTHONDIR=str(tmp_path / ".ipython"))
    subprocess.run(
        [sys.executable, "-m", "nbconvert", "--to", "html", "--execute", "figures.ipynb"],
        cwd=tmp_path, env=env, check=True, capture_output=True,
    )
    html = (tmp_path / "figures.html").read_text()
    assert html.count('<script type="application/vnd.jupyter.widget-view+json">') == 2

    refused = []

    def serve(route):
        url = route.request.url
        local = cdn_file(url)
        if local is not None:
            return route.fulfill(path=str(local), content_type="text/javascript")
        if url.startswith(("file:", "data:", "blob:")):
            return route.continue_()
        refused.append(url)
        return route.abort()

    RESULTS.mkdir(parents=True, exist_ok=True)
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(
            executable_path=CHROMIUM,
            args=["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking"],
        )
        try:
            page = browser.new_page(viewport={"width": 1200, "height": 1600})
            errors = []
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.route("**/*", serve)
            page.goto((tmp_path / "figures.html").as_uri())
            try:
                page.wait_for_function(
                    """() => {
                      const figs = [...document.querySelectorAll('dvf-playground')];
                      return figs.length === 2 && figs.every((f) => f.stats && f.stats.frames > 0);
                    }""",
                    timeout=WAIT_MS,
                )
            finally:
                page.screenshot(path=str(RESULTS / "exported-notebook.png"))
            shown = page.evaluate(
                "() => [...document.querySelectorAll('dvf-playground')].map((f) => [f.robotCount, f.time, f.hasAttribute('controls')])"
            )
            # The state each widget had in Python: its scenario, its time, its controls.
            assert shown == [[6, 3.0, True], [3, 0.0, False]]
            assert not errors, errors
            # Only what the template takes from elsewhere (MathJax, Mermaid) was refused.
            assert all("mathjax" in u or "mermaid" in u for u in refused), refused
        finally:
            browser.close()
