"""A whole run: :func:`simulate` and its :class:`Run`, the report and the trajectories as
arrays."""

from __future__ import annotations

from typing import Any, Dict, List, Optional

import numpy as np

from . import _dvf
from ._scenario import Scenario, ScenarioLike, _records, _scenario


class Run:
    """A scenario simulated to its end: the report as attributes, the trajectories as arrays.

    The report is the JSON ``dvf simulate`` prints, number for number (:attr:`report`); its
    keys are attributes too (``run.violations``, ``run.min_pair_distance``, …). The samples,
    every ``every``-th step and the last, are one array :attr:`samples` of shape
    ``(samples, robots, 6)`` holding ``[t, x, y, θ, v, ω]``, filled by the core and handed to
    numpy without a copy; :attr:`t`, :attr:`x`, :attr:`y`, :attr:`theta`, :attr:`v` and
    :attr:`omega` are views into it (``x[k, i]``: robot ``i`` at sample ``k``).
    """

    __slots__ = ("scenario", "report", "samples", "every")

    def __init__(self, scenario: Scenario, report: Dict[str, Any], samples: np.ndarray, every: int) -> None:
        self.scenario: Scenario = scenario
        #: The report as ``dvf simulate`` prints it, as a dict.
        self.report: Dict[str, Any] = report
        #: ``(samples, robots, 6)``: ``[t, x, y, θ, v, ω]`` of each robot at each sample.
        self.samples: np.ndarray = samples
        #: The recording stride in steps.
        self.every: int = every
        samples.flags.writeable = False

    @property
    def t(self) -> np.ndarray:
        """Sample times (s), shape ``(samples,)``."""
        return self.samples[:, 0, 0]

    @property
    def x(self) -> np.ndarray:
        """Positions' x (m), shape ``(samples, robots)``."""
        return self.samples[:, :, 1]

    @property
    def y(self) -> np.ndarray:
        """Positions' y (m), shape ``(samples, robots)``."""
        return self.samples[:, :, 2]

    @property
    def theta(self) -> np.ndarray:
        """Headings θ (rad, unwrapped as the simulation integrates them), shape ``(samples, robots)``."""
        return self.samples[:, :, 3]

    @property
    def v(self) -> np.ndarray:
        """Forward speeds v (m/s) of the last step's command, shape ``(samples, robots)``."""
        return self.samples[:, :, 4]

    @property
    def omega(self) -> np.ndarray:
        """Turn rates ω (rad/s) of the last step's command, shape ``(samples, robots)``."""
        return self.samples[:, :, 5]

    @property
    def name(self) -> str:
        """The scenario's name."""
        return self.report["name"]

    @property
    def time(self) -> float:
        """Simulated time at the end (s)."""
        return self.report["time"]

    @property
    def steps(self) -> int:
        """Steps taken."""
        return self.report["steps"]

    @property
    def robots(self) -> List[Dict[str, Any]]:
        """Per robot: ``final`` pose, ``position_error``, ``heading_error``, ``converged_at``, ``smoothness``."""
        return self.report["robots"]

    @property
    def min_pair_distance(self) -> Optional[float]:
        """Smallest distance between two robots at any step (None: fewer than two interacting robots)."""
        return self.report["min_pair_distance"]

    @property
    def min_obstacle_clearance(self) -> Optional[float]:
        """Smallest distance from a robot to a sensed obstacle's surface (None: none came that close)."""
        return self.report["min_obstacle_clearance"]

    @property
    def violations(self) -> int:
        """Events of two robots closer than ``2·safe_radius`` or a robot inside an obstacle."""
        return self.report["violations"]

    @property
    def smoothness(self) -> Dict[str, Any]:
        """How smooth the robots' turn rates were, over all robots."""
        return self.report["smoothness"]

    @property
    def converged(self) -> bool:
        """Every robot reached its goal pose and stayed there to the end."""
        return all(r["converged_at"] is not None for r in self.report["robots"])

    @property
    def converged_at(self) -> np.ndarray:
        """Per robot, the time from which it stayed at its goal (NaN: not at the end)."""
        return np.array(
            [np.nan if r["converged_at"] is None else r["converged_at"] for r in self.report["robots"]],
            dtype=float,
        )

    #: The columns of :attr:`trajectories` and of :meth:`to_pandas`.
    COLUMNS = ("t", "robot", "x", "y", "theta", "v", "omega")

    @property
    def trajectories(self) -> np.ndarray:
        """The samples as one table of shape ``(samples · robots, 7)``, columns
        :attr:`COLUMNS` (``t, robot, x, y, θ, v, ω``), one row per robot and sample in time
        order: the rows of ``dvf simulate --csv``, as numbers."""
        k, n, _ = self.samples.shape
        table = np.empty((k * n, 7))
        table[:, 0] = self.samples[:, :, 0].reshape(-1)
        table[:, 1] = np.tile(np.arange(n, dtype=float), k)
        table[:, 2:] = self.samples[:, :, 1:].reshape(k * n, 5)
        return table

    def to_pandas(self) -> "Any":
        """The samples as a pandas DataFrame with columns ``t, robot, x, y, theta, v, omega``,
        one row per robot and sample in time order: the rows of ``dvf simulate --csv``.

        Needs pandas (``pip install dvf[pandas]``).
        """
        try:
            import pandas as pd  # type: ignore[import-untyped, unused-ignore]
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("Run.to_pandas() needs pandas: pip install pandas") from e
        k, n, _ = self.samples.shape
        flat = self.samples.reshape(k * n, 6)
        return pd.DataFrame(
            {
                "t": flat[:, 0],
                "robot": np.tile(np.arange(n, dtype=np.int64), k),
                "x": flat[:, 1],
                "y": flat[:, 2],
                "theta": flat[:, 3],
                "v": flat[:, 4],
                "omega": flat[:, 5],
            }
        )

    def __repr__(self) -> str:
        converged = sum(r["converged_at"] is not None for r in self.robots)
        return (
            f"Run({self.name!r}, time={self.time}, robots={len(self.robots)}, "
            f"converged={converged}, violations={self.violations}, samples={self.samples.shape[0]})"
        )


def simulate(scenario: ScenarioLike, every: int = 1, planner: Optional[Any] = None) -> Run:
    """Simulates ``scenario`` to its end (``duration / dt`` steps of the unicycle
    ``ṗ = v·(cos θ, sin θ)``, ``θ̇ = ω`` under the controller of eqs. ``eq_nonholo_controller``,
    ``eq_nonholo_controller_ob_avoid`` and ``eq_nonholo_controller_co_avoid`` with the safety
    barrier), recording every robot every ``every`` steps and at the end.

    ``scenario`` is anything :class:`Scenario` takes (a preset's name, a dict, a file).
    ``planner`` (a name such as ``"dvf-paper"``, or a dict with its name and gains; see
    :func:`dvf.planners`) replaces the scenario's own ``planner`` (``dvf simulate --planner``).
    Returns a :class:`Run` whose report is the one ``dvf simulate`` prints, the same bits.
    The computation runs without the GIL.
    """
    s = _scenario(scenario)
    if planner is not None:
        s = s.replace(planner=planner)
    if isinstance(every, bool) or not isinstance(every, (int, np.integer)):
        raise ValueError(f"every: must be a whole number of steps, not {every!r}")
    if every < 1:
        raise ValueError(f"every: must be at least 1, not {every}")
    report, samples = _dvf.simulate(s._text, int(every))
    return Run(s, _records(report), samples, int(every))
