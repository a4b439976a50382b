"""dvf.widget.Playground in a real JupyterLab, driven by Chromium: the test starts a JupyterLab
server on a free port of 127.0.0.1, opens a notebook with two widgets, runs its cells and
checks that both figures draw, that an edit in a figure and its clock (time, playing) reach
Python's traits, and that traits set in Python reach the figures. Screenshots in test-results/python/."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from conftest import ROOT

sync_api = pytest.importorskip("playwright.sync_api")

CHROMIUM = os.environ.get("DVF_CHROMIUM", "/usr/bin/chromium")
RESULTS = ROOT / "test-results" / "python"
TOKEN = "dvf-widget-test"
# Generous bounds for a loaded 2-core machine: the kernel's start and the module's first
# compile take seconds there. Waits end as soon as their condition holds.
START_S = 120
WAIT_MS = 120_000

CELLS = [
    "import json\nimport dvf\nfrom dvf.widget import Playground\nw = Playground('example3-circle-swap')\nw",
    "w2 = Playground('table2-obstacles', time=2.0, controls=False)\nw2",
    "print('START', json.dumps(w.scenario['robots'][0]['start']))",
    "w.load('example3-line-swap')\nw2.time = 4.0\nprint('SET')",
    "w2.playing = True",
    "print('STATE', w2.playing, w2.time > 4.0)",
    "print('PAUSED', w2.playing, repr(w2.time))",
]


def notebook(cells):
    return {
        "cells": [
            {"cell_type": "code", "execution_count": None, "id": f"c{k}", "metadata": {}, "outputs": [], "source": src}
            for k, src in enumerate(cells)
        ],
        "metadata": {
            "kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
            "language_info": {"name": "python"},
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    root = tmp_path_factory.mktemp("lab")
    (root / "widgets.ipynb").write_text(json.dumps(notebook(CELLS)))
    port = free_port()
    env = dict(
        os.environ,
        JUPYTER_CONFIG_DIR=str(root / ".config"),
        JUPYTER_RUNTIME_DIR=str(root / ".runtime"),
        IPYTHONDIR=str(root / ".ipython"),
        JUPYTER_PLATFORM_DIRS="1",
    )
    log = open(root / "lab.log", "w")
    server = subprocess.Popen(
        [
            sys.executable, "-m", "jupyterlab", "--no-browser",
            "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
            f"--IdentityProvider.token={TOKEN}", f"--ServerApp.root_dir={root}",
            "--LabApp.news_url=", "--LabApp.extension_manager=readonly",
            "--ServerApp.terminals_enabled=False",
            # CI runs as root.
            "--allow-root",
        ],
        stdout=log, stderr=subprocess.STDOUT, env=env, cwd=root,
    )
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + START_S
    while True:
        try:
            with urllib.request.urlopen(f"{url}/api/status?token={TOKEN}", timeout=5):
                break
        except OSError:
            if server.poll() is not None or time.monotonic() > deadline:
                server.kill()
                pytest.fail(f"JupyterLab did not start: {(root / 'lab.log').read_text()[-2000:]}")
            time.sleep(0.5)
    yield url
    server.terminate()
    try:
        server.wait(20)
    except subprocess.TimeoutExpired:
        server.kill()
    log.close()


def run_cell(page, k):
    """Runs cell k (its editor clicked, Shift+Enter) and waits until the kernel has taken it:
    its prompt shows `[*]` or a count. A key pressed while the notebook is still connecting is
    dropped; it is pressed again then."""
    cell = page.locator(".jp-Notebook .jp-Cell").nth(k)
    prompt = cell.locator(".jp-InputPrompt")
    for _ in range(5):
        cell.locator(".jp-InputArea-editor").click()
        page.keyboard.press("Shift+Enter")
        try:
            page.wait_for_function(
                "(p) => /\\[(\\*|\\d+)\\]/.test(p.textContent)", arg=prompt.element_handle(), timeout=10_000
            )
            return
        except sync_api.TimeoutError:
            continue
    raise AssertionError(f"cell {k} did not run")


def output_of(page, k, marker):
    """The text of cell k's output once it holds `marker`."""
    out = page.locator(".jp-Notebook .jp-Cell").nth(k).locator(".jp-OutputArea-output")
    out.filter(has_text=marker).first.wait_for(timeout=WAIT_MS)
    return out.filter(has_text=marker).first.inner_text()


FIGURES_DRAWN = """() => {
  const figs = [...document.querySelectorAll('dvf-playground')];
  return figs.length === 2 && figs.every((f) => f.scenario() && f.stats && f.stats.frames > 0);
}"""


def test_the_widget_draws_and_syncs_both_ways_in_jupyterlab(lab):
    RESULTS.mkdir(parents=True, exist_ok=True)
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(
            executable_path=CHROMIUM,
            args=["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking"],
        )
        page = browser.new_page(viewport={"width": 1280, "height": 2000})
        errors = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.on("console", lambda m: print("console:", m.type, m.text) if m.type in ("error", "warning") else None)
        try:
            page.goto(f"{lab}/lab/tree/widgets.ipynb?token={TOKEN}")
            page.locator(".jp-Notebook .jp-Cell").nth(len(CELLS) - 1).wait_for(timeout=WAIT_MS)
            # The kernel is up before the first cell runs.
            page.get_by_text("Python 3 (ipykernel) | Idle").wait_for(timeout=WAIT_MS)
            run_cell(page, 0)
            run_cell(page, 1)
            # Both figures draw: a scene loaded and frames painted, each in its own element.
            page.wait_for_function(FIGURES_DRAWN, timeout=WAIT_MS)
            figs = page.locator("dvf-playground")
            assert figs.nth(0).evaluate("f => f.robotCount") == 6
            assert figs.nth(1).evaluate("f => f.robotCount") == 3
            # The time given in Python is the time the second figure opened at.
            page.wait_for_function(
                "() => Math.abs(document.querySelectorAll('dvf-playground')[1].time - 2.0) < 1e-9", timeout=WAIT_MS
            )
            assert figs.nth(0).evaluate("f => f.hasAttribute('controls')")
            assert not figs.nth(1).evaluate("f => f.hasAttribute('controls')")
            page.screenshot(path=str(RESULTS / "widget-drawn.png"))

            # An edit in the figure: robot 0 of the first figure dragged by 60 px to the right.
            start = figs.nth(0).evaluate("f => f.scenario().robots[0].start")
            figs.nth(0).scroll_into_view_if_needed()
            x, y = figs.nth(0).evaluate(
                "(f, s) => { const p = f.worldToScreen(s[0], s[1]); return [p.x - window.scrollX, p.y - window.scrollY]; }",
                start,
            )
            page.mouse.move(x, y)
            page.mouse.down()
            for k in range(1, 9):
                page.mouse.move(x + 60 * k / 8, y)
            page.mouse.up()
            moved = figs.nth(0).evaluate("f => f.scenario().robots[0].start")
            assert moved[0] > start[0] + 1e-6 and moved != start, (start, moved)
            # … reaches Python's trait.
            run_cell(page, 2)
            text = output_of(page, 2, "START")
            assert json.loads(text.split("START", 1)[1]) == moved, (text, moved)

            # Traits set in Python reach the figures: a new scenario, a time.
            run_cell(page, 3)
            output_of(page, 3, "SET")
            page.wait_for_function(
                "() => document.querySelectorAll('dvf-playground')[0].robotCount === 5", timeout=WAIT_MS
            )
            page.wait_for_function(
                "() => Math.abs(document.querySelectorAll('dvf-playground')[1].time - 4.0) < 1e-9", timeout=WAIT_MS
            )
            assert figs.nth(0).evaluate("f => f.scenario().name") == json.loads(
                subprocess.run(
                    [sys.executable, "-c", "import dvf; print(dvf.Scenario('example3-line-swap').to_json())"],
                    capture_output=True, text=True, check=True,
                ).stdout
            )["name"]
            # Playing, set in Python, runs the figure's clock; its time comes back to Python.
            run_cell(page, 4)
            page.wait_for_function(
                "() => { const f = document.querySelectorAll('dvf-playground')[1]; return f.playing && f.time > 4.5; }",
                timeout=WAIT_MS,
            )
            run_cell(page, 5)
            assert "STATE True True" in output_of(page, 5, "STATE")
            # The figure's own Pause button: Python learns that it stopped, and where.
            figs.nth(1).get_by_role("button", name="Pause").click()
            page.wait_for_function(
                "() => !document.querySelectorAll('dvf-playground')[1].playing", timeout=WAIT_MS
            )
            stopped = figs.nth(1).evaluate("f => f.time")
            # The figure sends its state as it comes to rest; the kernel reads it once it has
            # arrived (the cell runs again until then, a few times at most).
            for _ in range(10):
                run_cell(page, 6)
                text = output_of(page, 6, "PAUSED")
                if text.split()[1] == "False":
                    break
                page.wait_for_timeout(500)
            assert text.split()[1] == "False" and float(text.split()[2]) == stopped, (text, stopped)
            page.screenshot(path=str(RESULTS / "widget-synced.png"))
            assert not errors, errors
        except BaseException:
            page.screenshot(path=str(RESULTS / "widget-failure.png"))
            raise
        finally:
            browser.close()
