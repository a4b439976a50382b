"""Random sweeps, their shards and the merge of shards (:func:`sweep`, :func:`sweep_shard`,
:func:`merge`)."""

from __future__ import annotations

from typing import Any, Dict, Iterable, List, Mapping, Optional, Tuple, Union

import numpy as np

from . import _dvf
from ._scenario import _dumps, _records

#: The default rate ``α`` (1/s) of the safety barrier (``params.barrier_rate``).
DEFAULT_BARRIER_RATE: float = 5.0


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


def _value(value: Any) -> str:
    """A value as the command line writes it: ``none`` for None, numbers in full."""
    if value is None:
        return "none"
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    return str(value)


def _settings(set: Optional[Mapping[str, Any]], grid: Optional[Mapping[str, Any]]) -> Dict[str, List[str]]:
    """``set`` and ``grid`` as the command line's ``--set NAME=VALUE`` and ``--grid NAME=VALUES``."""
    texts: Dict[str, List[str]] = {"set": [], "grid": []}
    for name, value in (set or {}).items():
        texts["set"].append(f"{name}={_value(value)}")
    for name, values in (grid or {}).items():
        if isinstance(values, str):
            texts["grid"].append(f"{name}={values}")
        else:
            texts["grid"].append(f"{name}={','.join(_value(v) for v in values)}")
    return texts


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
    set: Optional[Mapping[str, Any]] = None,
    grid: Optional[Mapping[str, Any]] = None,
    shard: Optional[Union[Tuple[int, int], str]] = None,
    planner: Optional[Any] = None,
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

    ``set`` sets parameters in every scenario (``{"k_v": 2, "v_max": 1.5}``: any parameter of a
    scenario file, ``dt``, ``duration`` or ``side``; ``dvf sweep --set``); ``grid`` runs the
    sweep at each value of each name (``{"k_a": [1, 2, 4]}`` or ``{"k_a": "1:4:1"}``, every
    combination; ``dvf sweep --grid``), and the summary is then ``{"groups": [...]}``, one group
    per point with its ``values``.

    ``planner`` (a name, or a dict with its name and gains; see :func:`dvf.planners`) runs every
    scenario with that planner (``dvf sweep --planner``): the summary and the outcomes record
    it, and :func:`merge` refuses outcomes of different planners.
    """
    options = dict(
        family=family,
        robots=_range("robots", robots),
        obstacles=_range("obstacles", obstacles),
        spacing=_range("spacing", spacing),
        avoidance=avoidance,
        barrier_rate=barrier_rate,
        planner=None if planner is None else _dumps(planner if isinstance(planner, str) else dict(planner), "planner"),
        **_settings(set, grid),
    )
    for name, value in (("count", count), ("seed", seed)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
            raise ValueError(f"{name}: must be a whole number of at least 0, not {value!r}")
    if shard is None:
        return _records(_dvf.SweepPlan(int(count), int(seed), **options).summary())
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
    lines = _dvf.SweepPlan(int(count), int(seed), **options).shard(int(k), int(n))
    return [_records(line) for line in lines]


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
