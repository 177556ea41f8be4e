"""Bad input to ``epicyclic duty``: every class gives exit 2, one line on stderr naming the file and key.

The rows follow :mod:`tests.cli.test_bad_input_corpus` (its checks, its runner) for the tables the duty
command reads: ``[duty_cycle]``, ``[[duty_cycle.case]]`` and ``[planetary.bearings.*]``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from .test_bad_input_corpus import Bad
from .test_bad_input_corpus import (
    test_bad_input_gives_one_clear_line_and_exit_2 as check_bad_input,
)

EXAMPLE = (Path(__file__).resolve().parents[2] / "examples" / "zf_8hp70_geometry.toml").read_text(encoding="utf-8")


def _swap(old: str, new: str) -> str:
    assert old in EXAMPLE, old
    return EXAMPLE.replace(old, new, 1)


DUTY = [
    Bad("duty: no [duty_cycle]", "duty", EXAMPLE.split("# An illustrative duty cycle")[0], "no [duty_cycle] table"),
    Bad("duty: shares do not sum to 1", "duty", _swap("share = 0.20", "share = 0.10"), "sum to 0.9"),
    Bad("duty: negative hours", "duty", _swap("hours = 6000\n", "").replace("share = 0.03\n", "hours = -3\n", 1),
        "expected a duration >= 0"),
    Bad("duty: unknown gear", "duty", _swap('gear = "R"', 'gear = "9"'), "no gear '9'"),
    Bad("duty: unknown shaft in a case", "duty", _swap('torques = { in = "300 N*m" }', 'torques = { inn = 3 }'),
        "inn"),
    Bad("duty: bad torque unit", "duty", _swap('torques = { in = "300 N*m" }', 'torques = { in = "300 kW" }'),
        "torques.in"),
    Bad("duty: no case", "duty", EXAMPLE.split("[[duty_cycle.case]]")[0], "[[duty_cycle.case]]"),
    Bad("duty: missing C", "duty", _swap('dynamic_load_rating = "11.5 kN"        # C', 'radial_factor = 1.0  # C'),
        "dynamic_load_rating"),
    Bad("duty: C of another dimension", "duty", _swap('dynamic_load_rating = "11.5 kN"', 'dynamic_load_rating = "11 kg"'),
        "dynamic_load_rating"),
    Bad("duty: central bearing without type", "duty", _swap('type = "deep groove ball"\n', ''), "missing key 'type'"),
    Bad("duty: half the modified-life inputs", "duty", _swap('contamination = 0.5', 'reliability = 90'),
        "contamination missing"),
    Bad("duty: unknown reliability", "duty", _swap('contamination = 0.5', 'contamination = 0.5\nreliability = 93'),
        "Table 12"),
    Bad("duty: unknown bearing position", "duty", _swap("[planetary.bearings.carrier]", "[planetary.bearings.shaft]"),
        "unknown key 'shaft'"),
    Bad("duty: a case the solver refuses", "duty",
        _swap('speeds = { in = "1200 1/min" }', 'speeds = { in = "1200 1/min", out = "1 1/min" }'),
        "[[duty_cycle.case]] #12 'reverse': the given speeds contradict"),
    Bad("duty: kappa below the standard", "duty", _swap('viscosity = "8.8 mm^2/s"', 'viscosity = "0.5 mm^2/s"'),
        "at least 0.1"),
]


@pytest.mark.parametrize("case", DUTY, ids=[c.id for c in DUTY])
def test_duty_bad_input(case: Bad, tmp_path: Path):
    check_bad_input(case, tmp_path)
