"""Duty cycles that say when a design fails: every case and every sum below its minimum, marked and named.

The cycle is ``examples/rating/simple_set_duty_cycle.toml`` (an illustrative planetary reduction).  Its
overloaded variant multiplies every case's torque by 2.2 and rates the planet bearings by their basic life
L10h only: the sun's flank damage sum D_H is far above 1 and L10h far below the cycle's 20 000 h — the
defect (a cycle with D_H = 38.6 and L10h = 3 588 h against 20 000 h printed no mark) in a reproducible file.
Closed forms: ν of the oil at 70 °C by Walther's equation (ASTM D341) from ν_40, ν_100; a case that gives no
speeds and no torques is the file's operating point.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.io import load_train_file
from epicyclic.io.duty_format import analyse_file_duty_cycle
from epicyclic.losses import Oil
from epicyclic.rating.duty_checks import CHECKS, Shortfall, register_check, shortfalls

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "rating" / "simple_set_duty_cycle.toml"


def _variant(tmp_path: Path, text: str, name: str = "cycle.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _overloaded(tmp_path: Path) -> Path:
    head, cycle = EXAMPLE.read_text(encoding="utf-8").split("[duty_cycle]")
    cycle = re.sub(r'torques = \{ in = "(\d+) N\*m" \}',
                   lambda m: f'torques = {{ in = "{round(int(m.group(1)) * 2.2)} N*m" }}', cycle)
    head = re.sub(r"^(fatigue_load_limit|pitch_diameter|viscosity|contamination) = .*$", "", head, flags=re.M)
    return _variant(tmp_path, head + "[duty_cycle]" + cycle)


def _duty(*argv):
    return CliRunner().invoke(app, ["duty", *[str(a) for a in argv]])


def test_an_overloaded_cycle_is_marked_and_named(tmp_path):
    path = _overloaded(tmp_path)
    result = _duty(path)
    assert result.exit_code == 0
    damage = result.stdout.split("Palmgren-Miner")[1]
    sun = next(line for line in damage.splitlines() if "sun-planet   sun" in line)
    assert " !" in sun
    bearings = result.stdout.split("bearing rating life")[1].split("Palmgren")[0]
    assert "required 20000 h" in bearings and "planet 1" in bearings and " !" in bearings
    assert "BELOW MINIMUM" in result.stdout
    assert "below minimum: P sun-planet sun, over the cycle: D_H = " in result.stderr
    assert "below minimum: P planet 1, over the cycle: L10h = " in result.stderr and "< 20000 h" in result.stderr
    assert "case 'peak': S_H = " in result.stderr


def test_strict_exits_non_zero_only_when_something_fails(tmp_path):
    assert _duty(_overloaded(tmp_path), "--strict").exit_code == 3
    assert _duty(EXAMPLE, "--strict").exit_code == 0


def test_the_json_lists_every_shortfall(tmp_path):
    data = json.loads(_duty(_overloaded(tmp_path), "-f", "json").stdout)
    assert data["ok"] is False and data["required_life"] == {"value": 20000.0, "unit": "h"}
    found = {(s["quantity"], s["where"], s["case"]) for s in data["shortfalls"]}
    assert ("D_H", "P sun-planet sun", None) in found and ("L10h", "P planet 1", None) in found
    sun = next(d for d in data["damage"] if d["gear"] == "sun")
    assert sun["D_H"] > 1.0
    for s in data["shortfalls"]:
        if s["quantity"] == "S_H":
            case = [c["name"] for c in data["cases"]].index(s["case"])
            gear = next(d for d in data["damage"] if f"{d['element']} {d['mesh']} {d['gear']}" == s["where"])
            assert gear["cases"][case]["S_H"] == pytest.approx(s["value"]) and s["value"] < s["limit"] == 1.0


def test_a_design_that_lasts_has_no_shortfall():
    result = analyse_file_duty_cycle(load_train_file(EXAMPLE))
    assert result.ok and result.shortfalls == () and "!" not in result.table()


def test_a_check_added_later_runs_with_the_others(tmp_path):
    def scuffing(result, required):
        yield Shortfall("S_B", "P sun-planet", result.duty.cases[0].name, 1.2, 1.5)

    register_check(scuffing)
    try:
        missed = shortfalls(analyse_file_duty_cycle(load_train_file(EXAMPLE)), 20000.0)
        assert [s.quantity for s in missed] == ["S_B"]
        assert missed[0].text() == "below minimum: P sun-planet, case 'peak': S_B = 1.2 < 1.5"
    finally:
        CHECKS.remove(scuffing)


def test_cases_inherit_the_operating_point(tmp_path):
    # the "rated" case gives the [operating_point]'s speeds and torques; without them it must be the same case
    text = EXAMPLE.read_text(encoding="utf-8")
    bare = text.replace('name = "rated"\nshare = 0.25\nspeeds = { in = "1500 rpm" }\ntorques = { in = "600 N*m" }',
                        'name = "rated"\nshare = 0.25')
    assert bare != text
    given = analyse_file_duty_cycle(load_train_file(EXAMPLE)).to_dict()
    inherited = analyse_file_duty_cycle(load_train_file(_variant(tmp_path, bare))).to_dict()
    assert inherited["cases"][1] == given["cases"][1]
    assert inherited["damage"] == given["damage"]


def test_a_case_that_gives_its_torque_keeps_it(tmp_path):
    f = load_train_file(EXAMPLE)
    peak = f.duty_cycle.cases[0].operating_point
    assert peak.torques["in"] == pytest.approx(750.0) and peak.torques != f.operating_point.torques


def test_bearing_viscosity_from_the_lubricant_at_the_oil_temperature(tmp_path):
    text = EXAMPLE.read_text(encoding="utf-8")
    text = re.sub(r'^viscosity = "55 mm\^2/s".*$', "", text, flags=re.M)
    text = text.replace("viscosity_100 = 19.0\n", "viscosity_100 = 19.0\ntemperature = 70.0\n")
    result = analyse_file_duty_cycle(load_train_file(_variant(tmp_path, text)))
    nu = float(Oil(220.0, 19.0).kinematic_viscosity(70.0))  # Walther / ASTM D341 through nu_40 and nu_100
    planet = result.bearings[0]
    assert planet.viscosity == pytest.approx([nu] * 4, rel=1e-12) and list(planet.temperature) == [70.0] * 4
    typed = text.replace('contamination = 0.5', f'contamination = 0.5\nviscosity = {nu!r}')
    by_hand = analyse_file_duty_cycle(load_train_file(_variant(tmp_path, typed, "typed.toml"))).bearings[0]
    assert planet.modified_life_hours == pytest.approx(by_hand.modified_life_hours, rel=1e-12)
    assert any("the lubricant at 70.0" in n for n in planet.notes)


def test_no_viscosity_and_no_temperature_names_the_key(tmp_path):
    text = re.sub(r'^viscosity = "55 mm\^2/s".*$', "", EXAMPLE.read_text(encoding="utf-8"), flags=re.M)
    result = _duty(_variant(tmp_path, text))
    assert result.exit_code == 2
    assert "bearings.planet.viscosity" in result.stderr and "[lubricant] viscosity_40, viscosity_100 and " \
        "temperature" in result.stderr


def test_a_typed_viscosity_far_from_the_lubricants_is_noted(tmp_path):
    text = EXAMPLE.read_text(encoding="utf-8").replace("viscosity_100 = 19.0\n", "viscosity_100 = 19.0\ntemperature = 90.0\n")
    planet = analyse_file_duty_cycle(load_train_file(_variant(tmp_path, text))).bearings[0]
    nu = float(Oil(220.0, 19.0).kinematic_viscosity(90.0))
    assert planet.rating.viscosity == 55.0 and planet.oil_viscosity == pytest.approx([nu] * 4)
    assert any(n.startswith("nu typed 55 mm^2/s; [lubricant] gives") for n in planet.notes)
    at_70 = text.replace("temperature = 90.0", "temperature = 70.0")  # 51.7 mm^2/s: 6 % from the typed 55, noted
    near = analyse_file_duty_cycle(load_train_file(_variant(tmp_path, at_70, "c70.toml"))).bearings[0]
    assert abs(55.0 / float(Oil(220.0, 19.0).kinematic_viscosity(70.0)) - 1) > 0.05
    assert any(n.startswith("nu typed") for n in near.notes)
