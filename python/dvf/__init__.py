"""dvf: the Dynamic Vector Field method for nonholonomic multi-robot planning, in Python.

dvf drives unicycle robots (``ṗ = v·(cos θ, sin θ)``, ``θ̇ = ω``) to goal poses in SE(2) with
the method of "Simultaneous Position and Orientation Planning of Nonholonomic Multi-Robot
Systems: A Dynamic Vector Field Approach" (X. He and Z. Li): a vector field towards each goal
built from the logarithm map of SE(2) (Section III, eq. ``eq_DVF``), circular fields around
obstacles blended into it (Section IV, eq. ``eq_VF_all_V3``), a virtual obstacle between robots
that come close (Section V), and a controller that turns the field into ``(v, ω)``
(eq. ``eq_nonholo_controller``). A safety barrier, not in the paper, bounds every robot's
forward speed so that no two robots and no robot and obstacle ever overlap.

The same Rust core runs the ``dvf`` command line, the browser playground and this package: a
run here gives the very numbers ``dvf simulate`` prints.

>>> import dvf
>>> run = dvf.simulate("table1-free-space")
>>> run.violations
0
>>> run.x.shape == (run.steps + 1, len(run.robots))
True

The manual is the book's chapter "Python and Jupyter" (docs/book/src/python.md).
"""

from __future__ import annotations

from typing import Dict

from . import _dvf
from ._arrays import FieldGrid, command, field
from ._compare import compare, planners
from ._run import Run, simulate
from ._scenario import Record, Scenario, ScenarioLike
from ._sweep import DEFAULT_BARRIER_RATE, merge, sweep, sweep_shard

__version__: str = _dvf.__version__

__all__ = [
    "Scenario",
    "Run",
    "Record",
    "FieldGrid",
    "simulate",
    "command",
    "field",
    "sweep",
    "sweep_shard",
    "merge",
    "compare",
    "planners",
    "presets",
    "DEFAULT_PRESET",
    "DEFAULT_BARRIER_RATE",
    "__version__",
]

#: The preset shown when nothing else is asked for.
DEFAULT_PRESET: str = _dvf.default_preset()


def presets() -> Dict[str, str]:
    """Every built-in scenario, ``{name: summary}``, the default first; ``crowd-N`` (any N up
    to 10,000) is a preset too."""
    return dict(_dvf.presets())
