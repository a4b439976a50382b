"""Planners side by side: :func:`compare` runs one scenario with each of several planners on the
same robots, limits and safety barrier (``dvf compare``); :func:`planners` lists them."""

from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

from . import _dvf
from ._scenario import ScenarioLike, _dumps, _records, _scenario

#: A planner: its name (``"dvf-paper"``), or a dict with its name and gains
#: (``{"name": "avf", "lambda": 2}``).
PlannerLike = Union[str, Mapping[str, Any]]


def planners() -> List[Dict[str, str]]:
    """Every planner the simulator knows, in the menus' order: ``[{name, title, source,
    avoids}]`` (``dvf planners``); ``avoids`` says what it avoids on its own, before the shared
    safety barrier."""
    return [
        {"name": name, "title": title, "source": source, "avoids": avoids}
        for name, title, source, avoids in _dvf.planners()
    ]


def _planner_text(field: str, planner: PlannerLike) -> str:
    if isinstance(planner, str):
        return _dumps(planner)
    if isinstance(planner, Mapping):
        return _dumps(dict(planner), field)
    raise ValueError(f"{field}: expected a planner's name or a dict with its name and gains, not {planner!r}")


def compare(scenario: ScenarioLike, planners: Optional[Sequence[PlannerLike]] = None) -> Dict[str, Any]:
    """Runs ``scenario`` with each of ``planners`` (names or dicts with gains; every planner of
    :func:`planners` when None) and returns the comparison as ``dvf compare --json`` prints it:
    ``{"scenario", "conditions": {dt, duration, v_max, omega_max, barrier, robots, obstacles},
    "planners": [{"planner", "title", "avoids", "metrics": {...}, "robots": [{...}, ...]}]}``.

    ``metrics`` holds the run's: ``arrived``, ``arrival_rate``, ``time_to_last_arrival`` (None if
    a robot did not arrive), ``path_length``, ``control_effort``, ``peak_curvature``,
    ``reversals``, ``chattering_robots``, ``min_pair_distance``, ``min_obstacle_clearance``,
    ``violations``, ``steps`` and ``ms_per_step``; ``robots`` the same per robot. Every number but
    ``ms_per_step`` is the command line's, to the bit. The runs go without the GIL.
    """
    s = _scenario(scenario)
    if isinstance(planners, (str, Mapping)):
        raise ValueError("planners: expected a list of planners, not one planner")
    texts = None if planners is None else [_planner_text(f"planners[{k}]", p) for k, p in enumerate(planners)]
    result: Dict[str, Any] = _records(_dvf.compare(s._text, texts))
    return result
