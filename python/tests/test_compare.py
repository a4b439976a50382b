"""Planners side by side from Python: dvf.compare is dvf compare --json (every number but the
compute time, bit for bit), planner= reaches simulate and sweep as --planner does, and bad
planners raise ValueError naming the field."""

from __future__ import annotations

import pytest

import dvf
from conftest import bits, cli, cli_json, lines


def _without_times(comparison):
    out = bits(comparison)
    for p in out["planners"]:
        p["metrics"]["ms_per_step"] = None
    return out


def test_planners_are_dvf_planners(dvf_bin):
    listed = cli_json(dvf_bin, "planners", "--json")
    assert dvf.planners() == listed
    assert [p["name"] for p in listed][:2] == ["dvf", "dvf-paper"]


def test_compare_is_dvf_compare_json(dvf_bin):
    ours = dvf.compare("table2-obstacles", planners=["dvf-paper", "dvf"])
    printed = cli_json(dvf_bin, "compare", "--preset", "table2-obstacles", "--planners", "dvf-paper,dvf", "--json")
    assert _without_times(ours) == _without_times(printed)
    assert [p["planner"] for p in ours["planners"]] == ["dvf-paper", "dvf"]
    run = ours["planners"][1]
    assert run.metrics.arrived == len(run.robots) == ours["conditions"]["robots"]
    assert run.metrics.ms_per_step >= 0
    # Every planner by default.
    every = dvf.compare("table1-free-space")
    assert [p["planner"] for p in every["planners"]] == [p["name"] for p in dvf.planners()]


def test_bad_planners_name_the_field():
    with pytest.raises(ValueError, match=r'^planners\[1\]: unknown planner "rrt": one of dvf, dvf-paper'):
        dvf.compare("table1-free-space", planners=["dvf", "rrt"])
    with pytest.raises(ValueError, match=r"^planners\[0\]"):
        dvf.compare("table1-free-space", planners=[{"name": "dvf", "lambda": 2}])
    with pytest.raises(ValueError, match=r"^planners\[0\]"):
        dvf.compare("table1-free-space", planners=[3])
    with pytest.raises(ValueError, match=r"^planners: name at least one planner"):
        dvf.compare("table1-free-space", planners=[])
    with pytest.raises(ValueError, match=r"^planners: expected a list"):
        dvf.compare("table1-free-space", planners="dvf")
    with pytest.raises(ValueError, match=r"^planner: unknown planner"):
        dvf.simulate("table1-free-space", planner="rrt")
    with pytest.raises(ValueError, match=r"^planner: unknown planner"):
        dvf.sweep(2, planner="rrt")


def test_simulate_with_a_planner_is_dvf_simulate_planner(dvf_bin):
    run = dvf.simulate("table2-obstacles", planner="dvf-paper")
    printed = cli_json(dvf_bin, "simulate", "--preset", "table2-obstacles", "--planner", "dvf-paper")
    assert bits(run.report) == bits(printed)
    assert run.report["planner"] == "dvf-paper"
    assert "planner" not in dvf.simulate("table2-obstacles").report


def test_sweep_with_a_planner_is_dvf_sweep_planner(dvf_bin):
    options = ["--count", "3", "--robots", "2..=3", "--obstacles", "0..=1", "--set", "duration=8"]
    kwargs = dict(robots=(2, 3), obstacles=(0, 1), set={"duration": 8})
    summary = dvf.sweep(3, planner="dvf-paper", **kwargs)
    assert bits(summary) == bits(cli_json(dvf_bin, "sweep", *options, "--planner", "dvf-paper"))
    assert summary["planner"] == "dvf-paper"
    shard = dvf.sweep(3, planner="dvf-paper", shard=(1, 2), **kwargs)
    printed = lines(cli(dvf_bin, "sweep", *options, "--planner", "dvf-paper", "--shard", "1/2"))
    assert bits(shard) == bits(printed)
    assert all(o["recipe"]["planner"] == "dvf-paper" for o in shard)
    other = dvf.sweep(3, shard=(2, 2), **kwargs)
    with pytest.raises(ValueError, match="another recipe or belongs to another sweep"):
        dvf.merge(shard + other)
