"""The train in a gear at a point (epicyclic.transmission.train_in_gear): the state figures, `plot` and the
page show — the file's operating point, else the stated default point with the file's loss models."""

from __future__ import annotations

from pathlib import Path

import pytest

from epicyclic.io import load_train_file, loads_train_file
from epicyclic.errors import ModelError
from epicyclic.transmission import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE, train_in_gear

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _without_operating_point(name: str):
    text = (EXAMPLES / name).read_text(encoding="utf-8")
    return loads_train_file(text.split("[operating_point]")[0], source=name)


@pytest.mark.parametrize("name", ["zf_8hp70_geometry.toml", "zf_8hp70_spin_losses.toml"])
def test_default_point_with_the_files_loss_models_as_gears_analyses_it(name):
    """Without [operating_point] the gear is solved at 1000 1/min, 100 N·m with every loss model of the
    file, spin losses included: its efficiency is the drive efficiency `epicyclic gears` prints."""
    f = _without_operating_point(name)
    state = train_in_gear(f, "3")
    assert state.gear == "3" and state.notes and "default" in state.notes[0]
    assert state.solution.speed("in") == pytest.approx(DEFAULT_INPUT_SPEED)
    assert state.solution.torque("in") == pytest.approx(DEFAULT_INPUT_TORQUE)
    analysis = state.transmission.analyze("3")
    assert state.solution.efficiency == pytest.approx(analysis.efficiency_drive, rel=1e-12)
    from epicyclic import solve

    typed = solve(state.transmission.gear_train("3"), state.solution.operating_point)  # η0 as typed only
    assert state.solution.efficiency != pytest.approx(typed.efficiency, rel=1e-6)  # the loss models act


def test_the_files_operating_point_and_gear_come_first():
    f = load_train_file(EXAMPLES / "brandenberger_1952.toml")
    state = train_in_gear(f)
    assert state.transmission is None and state.notes == () and round(state.solution.efficiency, 4) == 0.8494


def test_what_cannot_be_solved_says_why():
    f = load_train_file(EXAMPLES / "brandenberger_1952.toml")
    with pytest.raises(ModelError, match="needs a \\[transmission\\] table"):
        train_in_gear(f, "2")
    plain = loads_train_file('[[planetary]]\nname = "P"\nsun = "s"\nring = "r"\ncarrier = "c"\n'
                             'stationary_ratio = -2.6\n')
    with pytest.raises(ModelError, match="nothing to solve"):
        train_in_gear(plain)
