"""Scenarios (:class:`Scenario`), and the core's JSON as Python values (:class:`Record`)."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np

from . import _dvf


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
