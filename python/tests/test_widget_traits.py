"""dvf.widget.Playground on the Python side, without a browser: its traits take what
dvf.Scenario takes, checked, and bad values raise ValueError naming the field."""

from __future__ import annotations

import pytest

import dvf

widget = pytest.importorskip("dvf.widget")


def test_traits_hold_checked_scenarios_and_times():
    fig = widget.Playground("table2-obstacles", time=2.5, controls=False)
    assert fig.scenario == dvf.Scenario("table2-obstacles").to_dict()
    assert (fig.time, fig.controls, fig.playing) == (2.5, False, False)
    default = widget.Playground()
    assert default.scenario["name"] == dvf.Scenario(dvf.DEFAULT_PRESET).name
    # A dict with defaults missing is filled in; a Scenario is taken as it is.
    fig.scenario = {"robots": [{"start": [0, 0, 0], "goal": [5, 0, 0]}]}
    assert fig.scenario["params"]["k_v"] == 1.0 and len(fig.scenario["bounds"]) == 4
    fig.load(dvf.Scenario("example3-line-swap"))
    assert fig.to_scenario() == dvf.Scenario("example3-line-swap")
    assert fig.run(every=100).report == dvf.simulate("example3-line-swap").report
    # The element travels with the widget: the single-file build, its wasm inlined.
    assert "customElements.define" in fig._element and "data:application/wasm;base64," in fig._element


def test_bad_traits_raise_value_error_naming_the_field():
    fig = widget.Playground("table2-obstacles")
    before = fig.scenario
    with pytest.raises(ValueError, match=r"^params\.k_v: "):
        fig.scenario = {"robots": [{"start": [0, 0, 0], "goal": [5, 0, 0]}], "params": {"k_v": 0}}
    with pytest.raises(ValueError, match=r"^preset: "):
        fig.load("no-such-preset")
    assert fig.scenario == before
    with pytest.raises(ValueError, match=r"^time: "):
        fig.time = -1.0
    with pytest.raises(ValueError, match=r"^robots\[0\]\.goal\[2\]: "):
        widget.Playground({"robots": [{"start": [0, 0, 0], "goal": [5, 0, float("nan")]}]})
