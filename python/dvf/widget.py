"""The live figure in a notebook: ``dvf.widget.Playground``, the playground's
``<dvf-playground>`` element as a Jupyter widget (anywidget).

>>> from dvf.widget import Playground
>>> fig = Playground("example3-circle-swap", time=5.0)   # doctest: +SKIP
>>> fig                                                   # doctest: +SKIP

The widget carries the element's single-file build (the wasm module and the stylesheet
inlined), so that neither Jupyter's server nor any other hosts a file for it: it draws
wherever anywidget runs, JupyterLab and a notebook exported to HTML with its widget state
among them (python/tests/test_widget.py, test_export.py). Its traits follow the figure both
ways:

- ``scenario`` (dict): the scene, every default filled in; an edit in the figure (a drag, the
  panel, undo) sets it, and a scenario set in Python loads into the figure at t = 0;
- ``time`` (float, s): the figure's clock, a few updates a second while it plays; set in
  Python, the figure shows the state at that time, paused;
- ``playing`` (bool): whether the clock runs; set in Python, the figure plays or pauses;
- ``controls`` (bool): the full toolbar and panels, or the figure alone (still editable);
- ``height`` (CSS length): the figure's height.

Several widgets in one notebook are independent figures.
"""

from __future__ import annotations

from importlib import resources
from typing import Any, Dict, Optional

import anywidget
import traitlets

from . import DEFAULT_PRESET, Run, Scenario, ScenarioLike, simulate

__all__ = ["Playground"]


def _read(name: str) -> str:
    path = resources.files(__package__).joinpath(name)
    if not path.is_file():
        raise FileNotFoundError(
            f"dvf/{name} is missing: the wheel carries the playground's single-file build "
            "(make wheel copies it from make package)"
        )
    return path.read_text(encoding="utf-8")


class Playground(anywidget.AnyWidget):
    """``<dvf-playground>`` as a notebook widget: the live, editable DVF simulation.

    ``scenario`` is anything :class:`dvf.Scenario` takes (a preset's name, a dict, a file, a
    ``Scenario``; default: the default preset), ``time`` the time shown when the figure opens
    (s), ``controls`` the full toolbar and side panels, ``playing`` whether it starts playing.
    A scenario that is not valid raises ``ValueError`` naming the field.
    """

    _esm = _read("widget.js")
    #: The element's single-file build, imported by the first view of a page.
    _element = traitlets.Unicode(_read("static/dvf-playground.inline.js")).tag(sync=True)

    scenario = traitlets.Dict().tag(sync=True)
    time = traitlets.Float(0.0).tag(sync=True)
    playing = traitlets.Bool(False).tag(sync=True)
    controls = traitlets.Bool(True).tag(sync=True)
    height = traitlets.Unicode("520px").tag(sync=True)

    def __init__(
        self,
        scenario: Optional[ScenarioLike] = None,
        time: float = 0.0,
        controls: bool = True,
        playing: bool = False,
        **kwargs: Any,
    ) -> None:
        s = Scenario(scenario if scenario is not None else DEFAULT_PRESET)
        super().__init__(scenario=s.to_dict(), time=time, controls=controls, playing=playing, **kwargs)

    @traitlets.validate("scenario")
    def _check_scenario(self, proposal: Any) -> Dict[str, Any]:
        value = proposal["value"]
        if isinstance(value, Scenario):
            return value.to_dict()
        return Scenario(value).to_dict()

    @traitlets.validate("time")
    def _check_time(self, proposal: Any) -> float:
        t = float(proposal["value"])
        if not t >= 0.0 or t == float("inf"):
            raise ValueError(f"time: must be a finite number of seconds of at least 0, not {t}")
        return t

    def load(self, scenario: ScenarioLike) -> None:
        """Shows ``scenario`` (anything :class:`dvf.Scenario` takes) from t = 0."""
        self.scenario = Scenario(scenario).to_dict()

    def to_scenario(self) -> Scenario:
        """The figure's scenario now (edits included) as a :class:`dvf.Scenario`."""
        return Scenario(self.scenario)

    def run(self, every: int = 1) -> Run:
        """The figure's scenario simulated to its end (:func:`dvf.simulate`)."""
        return simulate(self.to_scenario(), every=every)

