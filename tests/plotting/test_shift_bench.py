"""The test-bench picture of a shift: four panels on one time axis, the phases shaded, an unfinished shift said."""

import matplotlib

matplotlib.use("Agg")

import pytest

from epicyclic.dynamics import PressureProfile
from epicyclic.dynamics.shift import simulate_shift
from epicyclic.io import load_train_file
from epicyclic.io.dynamics_format import dynamics_spec
from epicyclic.plotting.shift_bench import shift_bench_figure
from epicyclic.transmission import Transmission

PATH = "examples/dynamics/zf_8hp70_shift.toml"


@pytest.fixture(scope="module")
def inputs():
    t = Transmission.from_train_file(load_train_file(PATH))
    return t, dynamics_spec(open(PATH, encoding="utf-8").read(), PATH, t)


def test_panels_share_time_and_phases_are_shaded(inputs):
    t, spec = inputs
    result = simulate_shift(t, spec, "2", "3")
    fig = shift_bench_figure(result)
    axes = fig.axes
    assert [a.get_ylabel() for a in axes] == ["speed [1/min]", "torque [N·m]", "pressure [bar]", "slip power [kW]"]
    assert all(a.get_shared_x_axes().joined(axes[0], a) for a in axes)
    assert len(axes[0].patches) == len(result.phases) == 2  # torque and inertia phase
    assert fig._suptitle.get_text() == "shift 2 → 3"


def test_an_unfinished_shift_says_so(inputs):
    from dataclasses import replace

    t, spec = inputs
    spec = replace(spec, pressures={"C": PressureProfile.constant(0.0, "C")}, duration=0.5)
    fig = simulate_shift(t, spec, "2", "3").plot()
    assert "NOT COMPLETED" in fig._suptitle.get_text()
