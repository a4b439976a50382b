"""The package against the command line and the Rust core: the same reports, trajectories,
commands, fields and sweeps, bit for bit; bad input raising ValueError that names the field."""

from __future__ import annotations

import csv
import json
import pickle

import numpy as np
import pytest

import dvf
from conftest import ROOT, bits, cli, cli_json, lines

# Presets small enough to run twice (here and through the command line) in a second or two.
PRESETS = ["table1-free-space", "table2-obstacles", "example3-circle-swap", "example4-obstacle-formation"]


def test_presets_match_the_command_line(dvf_bin):
    listed = [line.split()[0] for line in cli(dvf_bin, "presets").splitlines() if line.strip()]
    assert list(dvf.presets()) == listed
    assert dvf.DEFAULT_PRESET == listed[0]
    for name in listed:
        assert dvf.Scenario(name).to_json() == cli(dvf_bin, "presets", "--preset", name).rstrip("\n")


@pytest.mark.parametrize("name", PRESETS)
def test_a_preset_reports_what_dvf_simulate_prints(dvf_bin, name):
    run = dvf.simulate(name)
    printed = cli_json(dvf_bin, "simulate", "--preset", name)
    assert bits(run.report) == bits(printed)
    assert run.violations == printed["violations"]
    assert run.min_pair_distance == printed["min_pair_distance"]
    assert [r["converged_at"] for r in run.robots] == [r["converged_at"] for r in printed["robots"]]
    # Every object of the report is a dict whose keys are attributes too.
    assert run.robots[0].converged_at == run.robots[0]["converged_at"]
    assert run.smoothness.max_omega_step == printed["smoothness"]["max_omega_step"]
    assert pickle.loads(pickle.dumps(run.report)) == run.report
    with pytest.raises(AttributeError):
        run.report.no_such_key


@pytest.mark.parametrize("name", ["table2-obstacles", "example3-circle-swap"])
def test_trajectories_are_the_csv_rows(dvf_bin, tmp_path, name):
    path = tmp_path / "traj.csv"
    cli(dvf_bin, "simulate", "--preset", name, "--csv", str(path))
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["t", "robot", "x", "y", "theta", "v", "omega"]
    # Rust writes each float as its shortest round-trip decimal: float() reads back its bits.
    table = np.array([[float(v) for v in row] for row in rows[1:]])
    run = dvf.simulate(name)
    k, n, _ = run.samples.shape
    assert table.shape == (k * n, 7)
    assert np.array_equal(run.samples.reshape(k * n, 6)[:, 0], table[:, 0])
    assert np.array_equal(np.tile(np.arange(n), k), table[:, 1])
    assert np.array_equal(run.samples.reshape(k * n, 6)[:, 1:], table[:, 2:])
    assert np.array_equal(run.trajectories, table)
    assert list(dvf.Run.COLUMNS) == rows[0]
    frame = run.to_pandas()
    assert list(frame.columns) == rows[0]
    assert np.array_equal(frame.to_numpy(dtype=float), table)
    # The views are the samples' columns, no copies.
    assert np.shares_memory(run.x, run.samples) and np.shares_memory(run.omega, run.samples)
    assert np.array_equal(run.t, table[::n, 0])


def test_every_keeps_every_nth_step_and_the_last():
    full = dvf.simulate("example3-circle-swap")
    sparse = dvf.simulate("example3-circle-swap", every=7)
    steps = full.steps
    keep = [k for k in range(steps + 1) if k % 7 == 0 or k == steps]
    assert np.array_equal(sparse.samples, full.samples[keep])
    assert bits(sparse.report) == bits(full.report)


def test_scenarios_from_a_dict_a_file_json_and_back(tmp_path):
    s = dvf.Scenario("example3-circle-swap")
    assert dvf.Scenario(s.to_dict()) == s
    assert dvf.Scenario.from_dict(s.to_dict()) == s
    path = tmp_path / "s.json"
    s.to_json(path)
    assert dvf.Scenario(str(path)) == s == dvf.Scenario(path) == dvf.Scenario.from_json(path)
    assert dvf.Scenario.from_file(path) == s == dvf.Scenario.from_preset("example3-circle-swap")
    assert dvf.Scenario(s.to_json()) == s
    assert pickle.loads(pickle.dumps(s)) == s
    small = dvf.Scenario({"robots": [{"start": [0, 0, 0], "goal": [10, 0, 0]}]})
    assert small.params["k_v"] == 1.0 and small.duration == 40.0 and len(small.bounds) == 4
    changed = s.replace(duration=3, params={"k_a": 8})
    assert changed.duration == 3 and changed.params["k_a"] == 8 and changed.params["k_v"] == s.params["k_v"]
    assert np.array_equal(s.starts[:, :2], np.array([r["start"][:2] for r in s.robots]))
    # numpy values are scenario numbers too.
    assert dvf.Scenario({"robots": [{"start": np.zeros(3), "goal": np.array([5.0, 0, 0])}]}).robots[0]["goal"] == [5.0, 0, 0]


@pytest.mark.parametrize(
    "source, field",
    [
        ({"robots": [{"start": [0, 0, 0], "goal": [1, 1, 0]}], "params": {"k_v": -1}}, "params.k_v"),
        ({"robots": [{"start": [0, "a", 0], "goal": [1, 1, 0]}]}, "robots[0].start[1]"),
        ({"robots": [{"start": [0, 0, 0], "goal": [1, 1, 0]}], "duration": -5}, "duration"),
        ({"robots": [{"start": [0, 0, 0], "goal": [1, 1, 0]}], "params": {"k_x": 1}}, "params"),
        ({"robots": []}, "robots"),
        (
            {
                "robots": [{"start": [0, 0, 0], "goal": [1, 1, 0]}],
                "obstacles": [{"center": [5, 5], "radius": 2, "influence": 1}],
            },
            "obstacles[0].influence",
        ),
        ("no-such-preset", "preset"),
        ('{"robots": [', "malformed scenario"),
    ],
)
def test_bad_scenarios_raise_value_error_naming_the_field(source, field):
    with pytest.raises(ValueError) as e:
        dvf.Scenario(source)
    assert str(e.value).startswith(field), str(e.value)
    with pytest.raises(ValueError) as e:
        dvf.simulate(source)
    assert str(e.value).startswith(field)


def test_bad_arguments_raise_value_error_naming_the_field():
    cases = [
        (lambda: dvf.simulate("table2-obstacles", every=0), "every"),
        (lambda: dvf.command({"k_a": -2}, [0, 0, 0], [1, 1, 0]), "params.k_a"),
        (lambda: dvf.command({"avoidance": "sideways"}, [0, 0, 0], [1, 1, 0]), "params.avoidance"),
        (lambda: dvf.command({"v_max": float("nan")}, [0, 0, 0], [1, 1, 0]), "params.v_max"),
        (lambda: dvf.simulate({"robots": [{"start": [0, 0, float("inf")], "goal": [1, 1, 0]}]}), "robots[0].start[2]"),
        (lambda: dvf.command(None, [[0, 0, float("nan")]], [1, 1, 0]), "poses[0][2]"),
        (lambda: dvf.command(None, [[0, 0, 0]], [[1, 1]]), "goals"),
        (lambda: dvf.command(None, [0, 0, 0], [1, 1, 0], obstacles=[[5, 5, 2, 1]]), "obstacles[0].influence"),
        (lambda: dvf.command(None, [[0, 0, 0], [3, 0, 0]], [1, 1, 0], neighbours=[[[1, 1]]]), "neighbours"),
        (lambda: dvf.field("table2-obstacles", grid=1), "grid"),
        (lambda: dvf.field("table2-obstacles", robot=9), "robot"),
        (lambda: dvf.field([0, 0, 0], bounds=[1, 0, 0, 1]), "bounds"),
        (lambda: dvf.sweep(3, family="swirl"), "family"),
        (lambda: dvf.sweep(3, robots=(0, 4)), "robots"),
        (lambda: dvf.sweep(3, spacing=(3, 4)), "spacing"),
        (lambda: dvf.sweep(3, barrier_rate=-1), "barrier_rate"),
        (lambda: dvf.sweep(3, avoidance="around"), "avoidance"),
        (lambda: dvf.sweep(0), "count"),
        (lambda: dvf.sweep(3, shard=(3, 2)), "shard"),
        (lambda: dvf.merge([]), "outcomes"),
    ]
    for call, field in cases:
        with pytest.raises(ValueError) as e:
            call()
        assert str(e.value).startswith(field), (field, str(e.value))


def test_vectorised_command_is_the_rust_controller():
    # tests/data/commands.json: inputs and dvf::command's outputs, kept equal to the Rust
    # controller by tests/command_reference.rs.
    with open(ROOT / "tests" / "data" / "commands.json") as f:
        reference = json.load(f)
    for case in reference["cases"]:
        got = dvf.command(case["params"], case["poses"], case["goals"], case["obstacles"], case["neighbours"])
        want = np.array(case["commands"], dtype=float)
        assert got.shape == want.shape
        assert np.array_equal(got, want), np.argwhere(got != want)
        # The same through arrays: obstacles as rows, neighbours padded with NaN.
        obstacles = np.array([[*o["center"], o["radius"], o["influence"]] for o in case["obstacles"]]).reshape(-1, 4)
        widest = max(len(n) for n in case["neighbours"])
        padded = np.full((len(case["poses"]), widest, 2), np.nan)
        for i, n in enumerate(case["neighbours"]):
            if n:
                padded[i, : len(n)] = n
        again = dvf.command(case["params"], np.array(case["poses"]), np.array(case["goals"]), obstacles, padded)
        assert np.array_equal(again, want)


def test_one_goal_serves_every_robot():
    poses = np.array([[0.0, 0.0, 0.0], [3.0, 1.0, 1.0], [-2.0, 5.0, -1.0]])
    each = dvf.command(None, poses, np.tile([10.0, 0.0, 0.5], (3, 1)))
    assert np.array_equal(dvf.command(None, poses, [10.0, 0.0, 0.5]), each)
    assert dvf.command(None, poses[0], [10.0, 0.0, 0.5]).shape == (1, 2)


def test_field_is_what_dvf_field_samples(dvf_bin):
    printed = cli_json(dvf_bin, "field", "--preset", "table2-obstacles", "--robot", "1", "--grid", "9")
    grid = dvf.field("table2-obstacles", robot=1, grid=9)
    points = np.array(printed["points"])
    assert np.array_equal(np.stack(grid, axis=-1).reshape(-1, 4), points)
    assert grid.x.shape == (9, 9)
    s = dvf.Scenario("table2-obstacles")
    by_goal = dvf.field(s.robots[1]["goal"], theta=printed["theta"], bounds=s.bounds, grid=9)
    assert all(np.array_equal(a, b) for a, b in zip(grid, by_goal))


SWEEP = ["--count", "6", "--seed", "40", "--robots", "2..=5", "--obstacles", "0..=2"]
OPTIONS = dict(count=6, seed=40, robots=(2, 5), obstacles=(0, 2))


def test_sweep_shards_and_merge_match_the_command_line(dvf_bin, tmp_path):
    summary = dvf.sweep(**OPTIONS)
    assert bits(summary) == bits(cli_json(dvf_bin, "sweep", *SWEEP))
    assert summary.convergence_time.p50 == summary["convergence_time"]["p50"]
    shards = [dvf.sweep(**OPTIONS, shard=(k, 3)) for k in (1, 2, 3)]
    assert dvf.sweep_shard("2/3", **OPTIONS) == shards[1]
    for k, rows in enumerate(shards, start=1):
        assert bits(rows) == bits(lines(cli(dvf_bin, "sweep", *SWEEP, "--shard", f"{k}/3")))
    outcomes = [row for rows in shards for row in rows]
    # Any order: the summary sorts by seed.
    assert bits(dvf.merge(reversed(outcomes))) == bits(summary)
    files = []
    for k, rows in enumerate(shards):
        files.append(tmp_path / f"shard-{k}.jsonl")
        files[-1].write_text("".join(json.dumps(r) + "\n" for r in rows))
    assert bits(cli_json(dvf_bin, "sweep", "merge", *map(str, files))) == bits(summary)
    # The rows are what a DataFrame takes.
    import pandas as pd

    frame = pd.DataFrame(outcomes)
    assert sorted(frame["seed"]) == list(range(40, 46))
    assert bits(dvf.merge(frame.to_dict("records"))) == bits(summary)
    with pytest.raises(ValueError, match="seed 41 is missing"):
        dvf.merge(shards[0] + shards[2])
    with pytest.raises(ValueError, match="appears twice"):
        dvf.merge(outcomes + shards[0])
    with pytest.raises(ValueError, match="another recipe"):
        dvf.merge(shards[0] + dvf.sweep(**{**OPTIONS, "robots": 3}, shard=(2, 3)))


def test_a_sweep_sets_and_varies_parameters_as_the_command_line_does(dvf_bin):
    options = dict(count=3, seed=5, robots=(2, 4), set={"v_max": 3}, grid={"k_a": [1, 2.5]})
    study = dvf.sweep(**options)
    printed = cli_json(dvf_bin, "sweep", "--count", "3", "--seed", "5", "--robots", "2..=4",
                       "--set", "v_max=3", "--grid", "k_a=1,2.5")
    assert bits(study) == bits(printed)
    assert [g["values"]["k_a"] for g in study["groups"]] == [1.0, 2.5]
    rows = dvf.sweep(**options, shard=(1, 2)) + dvf.sweep(**options, shard=(2, 2))
    assert all(r["values"]["k_a"] in (1.0, 2.5) for r in rows)
    assert bits(dvf.merge(rows)) == bits(study)
    with pytest.raises(ValueError, match="k_v"):
        dvf.sweep(count=2, set={"k_v": -1})


def test_the_package_carries_its_types():
    from importlib import resources

    files = resources.files("dvf")
    assert files.joinpath("py.typed").is_file()
    assert files.joinpath("_dvf.pyi").is_file()
    assert "eq_nonholo_controller" in (dvf.command.__doc__ or "")
