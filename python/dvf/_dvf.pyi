# Types of the extension module `dvf._dvf` (src/python/): the core, which the package
# (dvf/) wraps. Scenarios, reports and sweep outcomes cross as JSON text; arrays
# are float64 numpy arrays the core filled and numpy owns. Every function raises ValueError
# with the core's message, which names the offending field.
from typing import List, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

__version__: str

def presets() -> List[Tuple[str, str]]:
    """Every preset as (name, summary), the default first."""

def default_preset() -> str:
    """The preset shown when nothing else is asked for."""

def preset(name: str) -> str:
    """The preset `name` (`crowd-N` included) as scenario JSON, bounds resolved."""

def check(text: str) -> str:
    """Scenario JSON checked, with the defaults filled in and the bounds resolved."""

def simulate(text: str, every: int = 1) -> Tuple[str, npt.NDArray[np.float64]]:
    """The report JSON of a whole run and its samples, shape (samples, robots, 6):
    [t, x, y, θ, v, ω] every `every` steps and at the end."""

def field(
    goal: Sequence[float], theta: float, bounds: Sequence[float], n: int
) -> npt.NDArray[np.float64]:
    """The goal field Γ̃_d (eqs. eq_DVF, eq_DVF_in_Fb) at attitude `theta` on an n × n grid
    over `bounds`: shape (n, n, 4), each [x, y, Γx, Γy], rows from ymin."""

def command(
    params: str,
    poses: npt.NDArray[np.float64],
    goals: npt.NDArray[np.float64],
    obstacles: npt.NDArray[np.float64],
    neighbours: npt.NDArray[np.float64],
    counts: Sequence[int],
) -> npt.NDArray[np.float64]:
    """(v, ω) of each robot (eq. eq_nonholo_controller and its avoidance forms): shape
    (robots, 2). `params` is a JSON object; obstacles are rows [x, y, r_o, R_o]; robot i
    senses the next counts[i] rows [x, y] of `neighbours`."""

class SweepPlan:
    """A sweep's options, checked (ValueError naming the field): `dvf sweep`'s."""

    def __init__(
        self,
        count: int,
        seed: int = 0,
        family: str = "random",
        robots: Optional[Tuple[int, int]] = None,
        obstacles: Optional[Tuple[int, int]] = None,
        spacing: Optional[Tuple[float, float]] = None,
        avoidance: str = "exit",
        barrier_rate: Optional[float] = 5.0,
        set: List[str] = ...,
        grid: List[str] = ...,
        planner: Optional[str] = None,
    ) -> None: ...
    def summary(self) -> str:
        """The summary JSON of the sweep (what `dvf sweep` prints)."""
    def shard(self, shard: int, shards: int) -> List[str]:
        """One shard's outcomes as JSON lines (what `dvf sweep --shard K/N` prints)."""

def merge(lines: List[str]) -> str:
    """The summary JSON of shards' outcome lines (what `dvf sweep merge` prints)."""

def planners() -> List[Tuple[str, str, str, str]]:
    """Every planner as (name, title, source, avoids), in the menus' order."""

def compare(text: str, planners: Optional[List[str]] = None) -> str:
    """The comparison JSON of scenario JSON run with each planner (JSON texts of names or
    objects with gains; all of them when None): what `dvf compare --json` prints."""
