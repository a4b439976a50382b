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

import json
import os
from typing import Any, Dict, Iterable, List, Mapping, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from . import _dvf

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
    "presets",
    "DEFAULT_PRESET",
    "DEFAULT_BARRIER_RATE",
    "__version__",
]

#: The preset shown when nothing else is asked for.
DEFAULT_PRESET: str = _dvf.default_preset()

#: The default rate ``α`` (1/s) of the safety barrier (``params.barrier_rate``).
DEFAULT_BARRIER_RATE: float = 5.0

ScenarioLike = Union["Scenario", Mapping[str, Any], str, "os.PathLike[str]"]


class Scenario:
    """A scenario: the robots' starts and goals, the obstacles, the method's parameters.

    The format is the JSON scenario format of the command line and the playground
    (docs/book/src/scenarios.md); a scenario is checked as it is built, and every default is
    filled in. ``Scenario(source)`` takes

    - a ``dict`` in the scenario format (only ``robots`` is required);
    - another ``Scenario``;
    - a path to a JSON scenario file (``os.PathLike``, or a ``str`` ending in ``.json`` or
      naming a file);
    - JSON text (a ``str`` starting with ``{``);
    - a preset's name (:func:`presets`; ``crowd-N`` included).

    Raises ``ValueError`` with the core's message, which names the offending field
    (``params.k_v: must be positive, not -1``).
    """

    __slots__ = ("_text", "_dict")

    def __init__(self, source: ScenarioLike) -> None:
        if isinstance(source, Scenario):
            text = source._text
        elif isinstance(source, Mapping):
            text = _dvf.check(_dumps(source))
        elif isinstance(source, str) and source.lstrip().startswith("{"):
            text = _dvf.check(source)
        elif isinstance(source, os.PathLike) or (
            isinstance(source, str) and (source.endswith(".json") or os.path.isfile(source))
        ):
            with open(source, encoding="utf-8") as f:
                text = _dvf.check(f.read())
        elif isinstance(source, str):
            text = _dvf.preset(source)
        else:
            raise ValueError(
                f"scenario: expected a dict, a Scenario, a JSON file, JSON text or a preset name, not {type(source).__name__}"
            )
        self._text: str = text
        self._dict: Dict[str, Any] = json.loads(text)

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> "Scenario":
        """The scenario of a dict in the scenario format."""
        if not isinstance(data, Mapping):
            raise ValueError(f"scenario: expected a dict, not {type(data).__name__}")
        return cls(data)

    @classmethod
    def from_json(cls, source: Union[str, "os.PathLike[str]"]) -> "Scenario":
        """The scenario of JSON text, or of the JSON file at a path."""
        if isinstance(source, str) and source.lstrip().startswith("{"):
            return cls(source)
        with open(source, encoding="utf-8") as f:
            return cls(f.read())

    @classmethod
    def preset(cls, name: str) -> "Scenario":
        """A built-in scenario (:func:`presets`; ``crowd-N`` for a crowd of N robots)."""
        return cls(_dvf.preset(name))

    @classmethod
    def from_preset(cls, name: str) -> "Scenario":
        """The same as :meth:`preset`."""
        return cls.preset(name)

    @classmethod
    def from_file(cls, path: Union[str, "os.PathLike[str]"]) -> "Scenario":
        """The scenario of the JSON file at ``path``."""
        with open(path, encoding="utf-8") as f:
            return cls(f.read())

    def to_dict(self) -> Dict[str, Any]:
        """The scenario as a dict: every default filled in, the bounds resolved (a fresh copy)."""
        return json.loads(self._text)

    def to_json(self, path: Optional[Union[str, "os.PathLike[str]"]] = None) -> str:
        """The scenario as JSON text, as ``dvf presets NAME`` writes it; also written to ``path``."""
        if path is not None:
            with open(path, "w", encoding="utf-8") as f:
                f.write(self._text + "\n")
        return self._text

    def replace(self, **fields: Any) -> "Scenario":
        """A copy with top-level fields replaced; ``params`` is merged key by key.

        >>> dvf.Scenario("table1-free-space").replace(duration=10, params={"k_a": 8}).params["k_a"]
        8.0
        """
        data = self.to_dict()
        for key, value in fields.items():
            if key == "params" and isinstance(value, Mapping):
                data["params"].update(value)
            else:
                data[key] = value
        return Scenario(data)

    @property
    def name(self) -> str:
        """Free text, shown to people."""
        return self._dict["name"]

    @property
    def duration(self) -> float:
        """Simulated seconds."""
        return self._dict["duration"]

    @property
    def dt(self) -> float:
        """The step (s)."""
        return self._dict["dt"]

    @property
    def bounds(self) -> Tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)``: the area drawn and sampled."""
        b = self._dict["bounds"]
        return (b[0], b[1], b[2], b[3])

    @property
    def params(self) -> Dict[str, Any]:
        """The method's parameters (a copy; see :meth:`replace`)."""
        return dict(self._dict["params"])

    @property
    def robots(self) -> List[Dict[str, List[float]]]:
        """``[{"start": [x, y, θ], "goal": [x_d, y_d, θ_d]}, …]`` (a copy)."""
        return self.to_dict()["robots"]

    @property
    def obstacles(self) -> List[Dict[str, Any]]:
        """``[{"center": [x, y], "radius": r_o, "influence": R_o}, …]`` (a copy)."""
        return self.to_dict()["obstacles"]

    @property
    def starts(self) -> np.ndarray:
        """The start poses as an array of shape ``(robots, 3)``."""
        return np.array([r["start"] for r in self._dict["robots"]], dtype=float).reshape(-1, 3)

    @property
    def goals(self) -> np.ndarray:
        """The goal poses as an array of shape ``(robots, 3)``."""
        return np.array([r["goal"] for r in self._dict["robots"]], dtype=float).reshape(-1, 3)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scenario) and self._dict == other._dict

    def __hash__(self) -> int:
        # From values that equal scenarios share (0.0 and -0.0 are equal, their texts are not).
        return hash((self.name, len(self._dict["robots"]), len(self._dict["obstacles"]), self.duration))

    def __repr__(self) -> str:
        return (
            f"Scenario({self.name!r}, robots={len(self._dict['robots'])}, "
            f"obstacles={len(self._dict['obstacles'])}, duration={self.duration})"
        )

    def __reduce__(self) -> Tuple[Any, Tuple[str]]:
        return (Scenario, (self._text,))


def _dumps(data: Any, root: str = "") -> str:
    """JSON text of plain data, numpy scalars and arrays included (floats at full precision);
    ``root`` is the path of ``data`` in the scenario, for messages."""

    def default(value: Any) -> Any:
        if isinstance(value, np.ndarray):
            return value.tolist()
        if isinstance(value, np.generic):
            return value.item()
        if isinstance(value, Scenario):
            return value.to_dict()
        raise TypeError(f"{type(value).__name__} is not JSON data")

    try:
        return json.dumps(data, default=default, allow_nan=False)
    except ValueError:
        # JSON has no NaN or infinity: name the field that holds one, as the core would.
        path, value = _non_finite(data, root)
        raise ValueError(f"{path}: must be a finite number, not {_rust_float(value)}") from None
    except TypeError as e:
        raise ValueError(f"scenario: not JSON data: {e}") from None


def _non_finite(data: Any, path: str = "") -> Tuple[str, float]:
    """The path (``robots[0].goal[2]``) and value of the first NaN or infinity in ``data``."""
    if isinstance(data, np.ndarray):
        data = data.tolist()
    if isinstance(data, (float, np.floating)) and not np.isfinite(data):
        return path, float(data)
    if isinstance(data, Mapping):
        for key, value in data.items():
            found = _non_finite(value, f"{path}.{key}" if path else str(key))
            if found[0]:
                return found
    if isinstance(data, (list, tuple)):
        for k, value in enumerate(data):
            found = _non_finite(value, f"{path}[{k}]")
            if found[0]:
                return found
    return "", 0.0


def _rust_float(value: float) -> str:
    """A non-finite float as the core writes it (NaN, inf, -inf)."""
    return "NaN" if value != value else ("inf" if value > 0 else "-inf")


class Record(Dict[str, Any]):
    """A dict from the core's JSON (a report, a robot's report, a sweep's summary or row) whose
    keys are attributes too: ``run.robots[0].converged_at`` is ``run.robots[0]["converged_at"]``."""

    __slots__ = ()

    def __getattr__(self, key: str) -> Any:
        try:
            return self[key]
        except KeyError:
            raise AttributeError(key) from None

    def __dir__(self) -> List[str]:
        return sorted(set(super().__dir__()) | set(self))


def _records(text: str) -> Any:
    """The core's JSON text as plain values with every object a :class:`Record`."""
    return json.loads(text, object_hook=Record)


def _scenario(source: ScenarioLike) -> Scenario:
    return source if isinstance(source, Scenario) else Scenario(source)


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


def simulate(scenario: ScenarioLike, every: int = 1) -> Run:
    """Simulates ``scenario`` to its end (``duration / dt`` steps of the unicycle
    ``ṗ = v·(cos θ, sin θ)``, ``θ̇ = ω`` under the controller of eqs. ``eq_nonholo_controller``,
    ``eq_nonholo_controller_ob_avoid`` and ``eq_nonholo_controller_co_avoid`` with the safety
    barrier), recording every robot every ``every`` steps and at the end.

    ``scenario`` is anything :class:`Scenario` takes (a preset's name, a dict, a file).
    Returns a :class:`Run` whose report is the one ``dvf simulate`` prints, the same bits.
    The computation runs without the GIL.
    """
    s = _scenario(scenario)
    if isinstance(every, bool) or not isinstance(every, (int, np.integer)):
        raise ValueError(f"every: must be a whole number of steps, not {every!r}")
    if every < 1:
        raise ValueError(f"every: must be at least 1, not {every}")
    report, samples = _dvf.simulate(s._text, int(every))
    return Run(s, _records(report), samples, int(every))


def _params_text(params: Any) -> str:
    if params is None:
        return "{}"
    if isinstance(params, Scenario):
        return _dumps(params.params, "params")
    if isinstance(params, Mapping):
        return _dumps(dict(params), "params")
    raise ValueError(f"params: expected a dict of parameters or a Scenario, not {type(params).__name__}")


def _rows(name: str, value: Any, columns: int) -> np.ndarray:
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{name}: expected numbers, {e}") from None
    if a.ndim == 1 and a.shape[0] == columns:
        a = a.reshape(1, columns)
    if a.ndim != 2 or a.shape[1] != columns:
        raise ValueError(f"{name}: expected an array of shape (n, {columns}), not {a.shape}")
    return np.ascontiguousarray(a)


def _obstacle_rows(obstacles: Any) -> np.ndarray:
    if obstacles is None:
        return np.zeros((0, 4))
    if isinstance(obstacles, np.ndarray):
        return _rows("obstacles", obstacles, 4)
    rows = []
    for i, o in enumerate(obstacles):
        if isinstance(o, Mapping):
            try:
                rows.append([o["center"][0], o["center"][1], o["radius"], o["influence"]])
            except (KeyError, IndexError, TypeError):
                raise ValueError(
                    f"obstacles[{i}]: expected {{'center': [x, y], 'radius': r_o, 'influence': R_o}}"
                ) from None
        else:
            rows.append(o)
    return _rows("obstacles", np.array(rows, dtype=float).reshape(-1, 4) if rows else np.zeros((0, 4)), 4)


def _neighbour_lists(neighbours: Any, n: int) -> Tuple[np.ndarray, List[int]]:
    if neighbours is None:
        return np.zeros((0, 2)), [0] * n
    if isinstance(neighbours, np.ndarray) and neighbours.ndim == 3:
        # (robots, k, 2), rows holding NaN left out: a ragged list padded to a block.
        lists = [row[~np.isnan(row).any(axis=1)] for row in np.asarray(neighbours, dtype=float)]
    else:
        lists = list(neighbours)
    if len(lists) != n:
        raise ValueError(f"neighbours: must give one list per pose ({n}), not {len(lists)}")
    blocks = []
    counts = []
    for i, lst in enumerate(lists):
        a = np.asarray(lst, dtype=float)
        if a.size == 0:
            a = np.zeros((0, 2))
        if a.ndim != 2 or a.shape[1] != 2:
            raise ValueError(f"neighbours[{i}]: expected positions of shape (k, 2), not {a.shape}")
        blocks.append(a)
        counts.append(a.shape[0])
    return np.ascontiguousarray(np.concatenate(blocks) if blocks else np.zeros((0, 2))), counts


def command(
    params: Any,
    poses: Any,
    goals: Any,
    obstacles: Any = None,
    neighbours: Any = None,
) -> np.ndarray:
    """The controller's ``(v, ω)`` for many robots at once (eq. ``eq_nonholo_controller``,
    with obstacles eq. ``eq_nonholo_controller_ob_avoid``, with neighbours
    eq. ``eq_nonholo_controller_co_avoid``): row ``i`` is the Rust ``dvf::command`` of robot
    ``i``, the same bits, before the safety barrier (which needs the whole scene).

    - ``params``: a dict of parameters (missing keys at their defaults), a :class:`Scenario`
      (its parameters) or None (the defaults);
    - ``poses``: ``(n, 3)`` array of ``[x, y, θ]`` (one pose ``(3,)`` gives one row);
    - ``goals``: ``(n, 3)``, or one goal ``(3,)`` for every robot;
    - ``obstacles``: the obstacles every robot senses: ``(m, 4)`` rows ``[x, y, r_o, R_o]`` or
      dicts of the scenario format;
    - ``neighbours``: per robot, the positions ``(k_i, 2)`` of the robots it senses (a list of
      n arrays, or one ``(n, k, 2)`` array whose rows holding NaN are left out).

    Returns an array of shape ``(n, 2)``: ``[v, ω]`` per robot.
    """
    p = _rows("poses", poses, 3)
    g = _rows("goals", goals, 3)
    if g.shape[0] == 1 and p.shape[0] != 1:
        g = np.ascontiguousarray(np.broadcast_to(g, p.shape))
    block, counts = _neighbour_lists(neighbours, p.shape[0])
    return _dvf.command(_params_text(params), p, g, _obstacle_rows(obstacles), block, counts)


class FieldGrid(NamedTuple):
    """The goal field on a grid: ``gx[j, i], gy[j, i]`` at ``(x[j, i], y[j, i])``, rows from ymin."""

    x: np.ndarray
    y: np.ndarray
    gx: np.ndarray
    gy: np.ndarray


def field(
    source: Union[ScenarioLike, Sequence[float]],
    robot: int = 0,
    *,
    theta: Optional[float] = None,
    bounds: Optional[Sequence[float]] = None,
    grid: int = 41,
) -> FieldGrid:
    """The obstacle-free dynamic vector field ``Γ̃_d = R(θ)(−φ̃)`` towards a goal pose
    (Section III, eqs. ``eq_DVF`` and ``eq_DVF_in_Fb``) on a ``grid × grid`` lattice,
    corners included.

    ``source`` is a scenario (anything :class:`Scenario` takes: the field of robot ``robot``'s
    goal at its start attitude over the scenario's bounds, what ``dvf field`` samples) or a
    goal pose ``[x_d, y_d, θ_d]``. ``theta`` is the attitude the field is drawn for (the
    field is dynamic: it depends on θ), ``bounds`` ``[xmin, ymin, xmax, ymax]``.
    Returns ``FieldGrid(x, y, gx, gy)``, arrays of shape ``(grid, grid)`` (matplotlib's
    ``quiver(*field(...))`` draws it).
    """
    if isinstance(source, (Scenario, Mapping, str, os.PathLike)):
        s = _scenario(source)
        robots = s._dict["robots"]
        if isinstance(robot, bool) or not isinstance(robot, (int, np.integer)) or not 0 <= robot < len(robots):
            raise ValueError(f"robot: index {robot} is out of range (the scenario has {len(robots)} robots)")
        goal = robots[robot]["goal"]
        theta = robots[robot]["start"][2] if theta is None else theta
        bounds = s._dict["bounds"] if bounds is None else bounds
    else:
        goal = _rows("goal", source, 3)[0].tolist()
        if bounds is None:
            bounds = [goal[0] - 10.0, goal[1] - 10.0, goal[0] + 10.0, goal[1] + 10.0]
        theta = 0.0 if theta is None else theta
    b = np.asarray(bounds, dtype=float)
    if b.shape != (4,):
        raise ValueError(f"bounds: expected [xmin, ymin, xmax, ymax], not shape {b.shape}")
    if isinstance(grid, bool) or not isinstance(grid, (int, np.integer)):
        raise ValueError(f"grid: must be a whole number, not {grid!r}")
    a = _dvf.field([float(v) for v in goal], float(theta), b.tolist(), int(grid))
    return FieldGrid(a[:, :, 0], a[:, :, 1], a[:, :, 2], a[:, :, 3])


def _range(name: str, value: Any) -> Any:
    if value is None:
        return None
    if isinstance(value, (int, float, np.number)) and not isinstance(value, bool):
        return (value, value)
    try:
        lo, hi = value
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected a number or a range (min, max), not {value!r}") from None
    return (lo, hi)


def sweep(
    count: int,
    seed: int = 0,
    *,
    family: str = "random",
    robots: Any = None,
    obstacles: Any = None,
    spacing: Any = None,
    avoidance: str = "exit",
    barrier_rate: Optional[float] = DEFAULT_BARRIER_RATE,
    shard: Optional[Union[Tuple[int, int], str]] = None,
) -> Any:
    """Random scenarios ``seed … seed + count − 1`` of a family, run (``dvf sweep``).

    Without ``shard``: their summary as a dict (success rate, convergence-time quantiles,
    smoothness, ``failures``: one row per failing seed), the same bits as ``dvf sweep``'s.
    The scenarios run on every core, without the GIL.

    With ``shard=(k, n)`` (or ``"k/n"``): the outcomes of every n-th scenario from the k-th
    (``dvf sweep --shard k/n``), one dict per scenario, rows a DataFrame takes; :func:`merge`
    turns the outcomes of all n shards into the unsharded summary.

    ``family`` is ``random``, ``dense`` or ``formation``; ``robots``, ``obstacles`` and
    ``spacing`` (formation only) are ranges ``(min, max)`` or single numbers; ``avoidance``
    is ``exit`` or ``paper``; ``barrier_rate`` is ``α`` (1/s) or None (no barrier).
    """
    options = dict(
        family=family,
        robots=_range("robots", robots),
        obstacles=_range("obstacles", obstacles),
        spacing=_range("spacing", spacing),
        avoidance=avoidance,
        barrier_rate=barrier_rate,
    )
    for name, value in (("count", count), ("seed", seed)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
            raise ValueError(f"{name}: must be a whole number of at least 0, not {value!r}")
    if shard is None:
        return _records(_dvf.sweep(int(count), int(seed), **options))
    if isinstance(shard, str):
        try:
            k, n = (int(part) for part in shard.split("/"))
        except ValueError:
            raise ValueError(f"shard: expected K/N, not {shard!r}") from None
    else:
        try:
            k, n = shard
        except (TypeError, ValueError):
            raise ValueError(f"shard: expected (k, n), not {shard!r}") from None
    if min(k, n) < 1:
        raise ValueError(f"shard: must be K/N with 1 ≤ K ≤ N, not {k}/{n}")
    return [_records(line) for line in _dvf.sweep_shard(int(k), int(n), int(count), int(seed), **options)]


def sweep_shard(
    shard: Union[Tuple[int, int], str],
    count: int,
    seed: int = 0,
    **options: Any,
) -> List[Dict[str, Any]]:
    """The outcomes of one shard, ``(k, n)`` or ``"k/n"``: :func:`sweep` with ``shard``."""
    return sweep(count, seed, shard=shard, **options)


def merge(outcomes: Iterable[Union[Mapping[str, Any], str]]) -> Dict[str, Any]:
    """The summary of shards' outcomes (dicts from ``sweep(…, shard=…)``, or JSON lines of
    ``dvf sweep --shard``), in any order: exactly the unsharded summary (``dvf sweep merge``).
    Raises ``ValueError`` when they mix recipes, or miss or repeat a seed.
    """
    lines = [o if isinstance(o, str) else _dumps(dict(o)) for o in outcomes]
    return _records(_dvf.merge(lines))


def presets() -> Dict[str, str]:
    """Every built-in scenario, ``{name: summary}``, the default first; ``crowd-N`` (any N up
    to 10,000) is a preset too."""
    return dict(_dvf.presets())
