"""The method over arrays: the controller for many robots (:func:`command`) and the goal
field on a grid (:func:`field`)."""

from __future__ import annotations

import os
from typing import Any, List, Mapping, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from . import _dvf
from ._scenario import Scenario, ScenarioLike, _dumps, _scenario


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
