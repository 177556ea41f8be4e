"""Spin losses in the solver and the train file: invariants (hypothesis), bit-for-bit, thermal balance, errors."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from epicyclic import OperatingPoint
from epicyclic.io import loads_train_file, load_train_file
from epicyclic.io.source import InputFileError
from epicyclic.losses import (ClutchDrag, Housing, LossModelError, Oil, OilPump, ShaftSeal, SpinLosses,
                              solve_batch_with_losses, solve_with_losses)
from epicyclic.losses.breakdown import gear_loss_breakdown, loss_breakdown
from epicyclic.transmission import Transmission
from epicyclic.transmission.batch import solve_gears
from epicyclic.transmission.library import build

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "zf_8hp70_spin_losses.toml"
GEOMETRY = ROOT / "examples" / "zf_8hp70_geometry.toml"
OIL = Oil(29.5, 6.0, 850.0)
T8 = build("zf_8hp70", 0.98)


def _spin(temperature=80.0, supply=1.5, **kw):
    drags = tuple(ClutchDrag(e.name, 8, 70.0, 88.0, 0.15, supply) for e in T8.train.shift_elements)
    return SpinLosses(OIL, temperature, clutch_drag=drags, pump=OilPump(14.0, 7.0),
                      seals=(ShaftSeal("in", 40.0), ShaftSeal("out", 55.0)), **kw)


def _batch(gear, speeds, torques, spin, models=None):
    return solve_batch_with_losses(T8.gear_train(gear), models or {}, speeds={"in": speeds}, torques={"in": torques},
                                   drives=["in"], loads=["out"], spin=spin, gear=gear, input="in")


settings_small = settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@settings_small
@given(gear=st.sampled_from(T8.gears[:-1]), speed=st.floats(300.0, 6000.0), torque=st.floats(5.0, 400.0),
       temperature=st.floats(20.0, 120.0))
def test_every_loss_is_non_negative_and_the_total_is_their_sum(gear, speed, torque, temperature):
    sol = _batch(gear, np.array([speed]), np.array([torque]), _spin(temperature))
    for parts in sol.loss_sources.values():
        for value in parts.values():
            assert np.all(value >= -1e-9 * sol.input_power)
    summed = sum(v for parts in sol.loss_sources.values() for v in parts.values())
    assert summed == pytest.approx(sol.loss, rel=1e-12)
    assert sol.input_power - sol.output_power == pytest.approx(sol.loss, rel=1e-9)  # energy balance


def test_point_and_batch_agree_and_report_by_source():
    spin = _spin()
    op = OperatingPoint(speeds={"in": 2500.0}, torques={"in": 60.0}, drives=["in"], loads=["out"])
    point = solve_with_losses(T8.gear_train("4"), op, {}, spin=spin, gear="4", input="in")
    batch = _batch("4", np.array([2500.0]), np.array([60.0]), spin)
    assert point.efficiency == pytest.approx(float(batch.efficiency[0]), rel=1e-12)
    assert set(point.housing_loss_sources) == {"pump", "seals"}
    assert point.loss == pytest.approx(sum(point.loss_sources.values()), rel=1e-12)
    assert point.oil_temperature == 80.0
    table = loss_breakdown(point).table()
    assert "housing (pump, seals)" in table and "clutch_drag" in table


def test_all_new_models_absent_or_zero_change_nothing_bit_for_bit():
    n, t = np.linspace(500.0, 5000.0, 7), np.linspace(10.0, 300.0, 7)
    plain = _batch("3", n, t, None)
    for spin in (SpinLosses(), SpinLosses(seals=(ShaftSeal("in", 40.0, factor=0.0),)),
                 SpinLosses(pump=OilPump(14.0, 0.0))):
        again = _batch("3", n, t, spin)
        assert np.array_equal(again.efficiency, plain.efficiency)
        assert np.array_equal(again.loss, plain.loss)
    models = dict(load_train_file(GEOMETRY).losses)
    base = _batch("5", n, t, None, models)
    assert np.array_equal(_batch("5", n, t, SpinLosses(), models).efficiency, base.efficiency)


def test_efficiency_falls_with_viscosity_at_low_load():
    # colder oil = more viscous: more clutch drag at part load (Yuan et al. 2007: T ∝ η below the peak)
    n, t = np.array([1200.0]), np.array([20.0])
    eta = [float(_batch("1", n, t, _spin(temperature, supply=None)).efficiency[0]) for temperature in (30, 60, 90)]
    assert eta[0] < eta[1] < eta[2]


def test_efficiency_rises_with_torque_where_spin_losses_dominate():
    eta = _batch("2", np.full(4, 2000.0), np.array([5.0, 20.0, 80.0, 300.0]), _spin()).efficiency
    assert np.all(np.diff(eta) > 0)


def test_thermal_balance_is_a_fixed_point():
    spin = _spin(None, housing=Housing(0.9, heat_transfer=15.0, cooler=60.0))
    sol = _batch("3", np.array([1500.0, 3000.0]), np.array([80.0, 150.0]), spin)
    t = sol.oil_temperature
    assert np.all((t > 20.0) & (t < 200.0))
    shed = spin.housing.dissipated(t)
    assert shed == pytest.approx(sol.loss, rel=1e-6)  # P_Q(ϑ) = P_V(ϑ) (ISO/TR 14179-1)
    op = OperatingPoint(speeds={"in": 3000.0}, torques={"in": 150.0}, drives=["in"], loads=["out"])
    point = solve_with_losses(T8.gear_train("3"), op, {}, spin=spin, gear="3", input="in")
    assert point.oil_temperature == pytest.approx(float(t[1]), abs=1e-4)


def test_thermal_balance_without_enough_cooling_is_refused():
    spin = _spin(None, housing=Housing(0.05))
    with pytest.raises(LossModelError, match="exceed what the housing sheds"):
        _batch("1", np.array([5000.0]), np.array([400.0]), spin)


def test_spin_models_naming_what_the_train_lacks():
    with pytest.raises(LossModelError, match="not a clutch or brake"):
        _batch("1", np.array([1000.0]), np.array([10.0]), SpinLosses(OIL, 80.0, clutch_drag=(
            ClutchDrag("P1", 8, 70.0, 88.0, 0.15),)))
    with pytest.raises(LossModelError, match="no moving shaft 'shaft9'"):
        _batch("1", np.array([1000.0]), np.array([10.0]), SpinLosses(seals=(ShaftSeal("shaft9", 40.0),)))
    with pytest.raises(LossModelError, match="needs a temperature"):
        SpinLosses(OIL)


def test_example_file_gears_and_map_carry_the_spin_losses():
    t = Transmission.from_file(EXAMPLE)
    assert t.spin is not None and len(t.spin.clutch_drag) == 5
    analysis = t.analyze_all(input_speed=2000.0, input_torque=50.0)
    bars = gear_loss_breakdown(analysis)
    assert {"pump", "seals", "clutch_drag", "mesh"} <= set(bars.sources)
    assert bars.rows["gear 1"]["pump"] == pytest.approx(14e-6 * 2000 / 60 * 9e5 / 0.85)  # 9 bar in gear 1
    batch = solve_gears(t, input_speed=[2000.0], input_torque=[50.0], gears=["3"])
    assert float(batch.efficiency("3")[0]) == pytest.approx(analysis["3"].efficiency_drive, rel=1e-9)
    from epicyclic.losses import efficiency_map

    emap = efficiency_map(load_train_file(EXAMPLE), [1000.0, 3000.0], [20.0, 200.0], gear="4")
    assert {"pump", "seals"} <= set(emap.losses) and emap.oil_temperature is not None
    assert np.all(np.diff(emap.efficiency, axis=0) > 0)  # spin losses: η rises with torque


HEAD = """
[[planetary]]
name = "P"
sun = "in"
ring = "r"
carrier = "out"
stationary_ratio = -2.0
[[brake]]
name = "B"
shaft = "r"
engaged = false
{drag}
[[brake]]
name = "H"
shaft = "r"
[transmission]
input = "in"
output = "out"
schedule = {{ "1" = ["H"] }}
"""


@pytest.mark.parametrize("extra, drag, match", [
    ("[lubricant]\nviscosity_40 = 30.0\ntemperature = 80.0", "", "give both 'viscosity_40' and 'viscosity_100'"),
    ("[lubricant]\nviscosity_40 = 30.0\nviscosity_100 = 6.0", "", "missing key 'temperature'"),
    ("[lubricant]\nviscosity_40 = 30.0\nviscosity_100 = 6.0\ntemperature = \"hot\"", "", "key 'temperature'"),
    ("[lubricant]\nviscosity_40 = 30.0\nviscosity_100 = 6.0\ntemperature = \"thermal\"", "",
     "needs a \\[housing\\] table"),
    ("", "[brake.drag]\ngaps = 8\ninner_radius = 70.0\nouter_radius = 88.0\nclearance = 0.15",
     "clutch drag and churning need the oil"),
    ("[lubricant]\nviscosity_40 = 30.0\nviscosity_100 = 6.0\ntemperature = 80.0",
     "[brake.drag]\ngaps = 8\ninner_radius = 70.0\nouter_radius = 88.0", "missing key 'clearance'"),
    ("[lubricant]\nviscosity_40 = 30.0\nviscosity_100 = 6.0\ntemperature = 80.0",
     "[brake.drag]\ngaps = 8\ninner_radius = 70.0\nouter_radius = 88.0\nclearance = -0.1",
     "key 'clearance': expected a positive number"),
    ("[pump]\ndisplacement = 14.0", "", "\\[pump\\].*pressure"),
    ("[pump]\ndisplacement = 14.0\npressure = 8.0\nefficiency = 1.3", "", "key 'efficiency'"),
    ("[[seal]]\nshaft = \"nowhere\"\ndiameter = 40.0", "", "no moving shaft 'nowhere'"),
    ("[housing]\narea = 1.0", "", "used with \\[lubricant\\] temperature"),
])
def test_bad_spin_tables_name_the_key(extra, drag, match):
    with pytest.raises((InputFileError, LossModelError), match=match):
        loads_train_file(extra + "\n" + HEAD.format(drag=drag))


def test_a_file_with_spin_tables_solves_with_them():
    text = ("[lubricant]\nviscosity_40 = 30.0\nviscosity_100 = 6.0\ntemperature = 60.0\n" + HEAD.format(
        drag="[brake.drag]\ngaps = 8\ninner_radius = 70.0\nouter_radius = 88.0\nclearance = 0.15\nsupply = 2.0")
        + "[pump]\ndisplacement = 10.0\npressure = 5.0\n")
    t = Transmission.from_file(_write(text))
    result = t.analyze("1", input_speed=1500.0, input_torque=20.0)
    assert result.drive.housing_loss_sources["pump"] == pytest.approx(10e-6 * 1500 / 60 * 5e5 / 0.85)
    assert result.drive.elements["B"].loss_sources == {}  # B and H hold the same shaft: no slip, no drag


def _write(text: str) -> Path:
    import tempfile

    path = Path(tempfile.mkdtemp()) / "spin.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_explain_writes_out_the_loss_models_in_english_and_german():
    from epicyclic.explain import explain

    f = load_train_file(EXAMPLE)
    solution = f.solve()
    spec = f.transmission
    en = explain(solution, f.units, losses=f.losses, spin=f.spin, gear=f.gear, input=spec.input).text()
    assert "lossless element" not in en.split("4. Torque balance")[0].split("P2 (")[1]  # η0 from the models
    for part in ("6. Losses by source", "H_V =", "μ =", "η0 at the point", "Walther (ASTM D341)",
                 "T = V·Δp/(2π·η_hm)", "7.69e-6", "(Yuan et al. 2007)"):
        assert part in en
    de = explain(solution, f.units, lang="de", losses=f.losses, spin=f.spin, gear=f.gear, input=spec.input).text()
    assert "Verluste nach Quellen" in de and "Pumpe an" in de and "Eingriff" in de
    total = solution.loss
    assert f"(solver: {total:.6g}" in en or "solver:" in en


def test_gears_and_breakdown_report_the_losses_by_source():
    import json

    t = Transmission.from_file(EXAMPLE)
    analysis = t.analyze_all(input_speed=2000.0, input_torque=50.0)
    text = analysis.table()
    assert "drive losses by source" in text and "pump" in text and "oil at 80.0 degC" in text
    first = analysis.gears[0].to_dict()
    shares = first["loss_sources_per_input_power"]
    assert sum(shares.values()) == pytest.approx(1.0 - analysis.gears[0].efficiency_drive, rel=1e-9)
    bars = gear_loss_breakdown(analysis)
    data = json.loads(bars.to_json())
    assert data["total"] == pytest.approx(sum(g.drive.loss for g in analysis.gears), rel=1e-12)
    assert "<table>" in bars._repr_html_()
    plain = Transmission.from_file(ROOT / "examples" / "zf_8hp70_8speed.toml").analyze_all()
    assert "losses by source" not in plain.table()  # typed-in η0: every loss is mesh loss, nothing to split


def test_viscosity_table_in_the_file():
    text = "[lubricant]\nviscosity_table = [[0.0, 580.0], [40.0, 46.0], [100.0, 6.8]]\ntemperature = 70.0\n" \
        + HEAD.format(drag="")
    f = loads_train_file(text)
    assert f.spin.oil.kinematic_viscosity(40.0) == pytest.approx(46.0, rel=0.005)
    with pytest.raises((InputFileError, LossModelError), match="viscosity_table"):
        loads_train_file("[lubricant]\nviscosity_table = [40.0, 46.0]\ntemperature = 70.0\n" + HEAD.format(drag=""))


def test_defaults_are_stated_and_can_be_refused():
    spin_tables = ("[lubricant]\nviscosity_40 = 30.0\nviscosity_100 = 6.0\ntemperature = 60.0\n"
                   "[pump]\ndisplacement = 10.0\npressure = 5.0\n")
    f = loads_train_file(spin_tables + HEAD.format(drag=""))
    stated = " ".join(f.spin.defaults)
    assert "[pump] efficiency = 0.85" in stated and "[lubricant] density = 860 kg/m^3" in stated
    assert "shaft = the transmission's input" in stated
    with pytest.raises(InputFileError, match="missing key 'lubricant_factor': the file refuses defaults"):
        loads_train_file('defaults = "refuse"\n' + spin_tables + HEAD.format(drag=""))
    with pytest.raises(InputFileError, match="key 'defaults'"):
        loads_train_file('defaults = "maybe"\n' + spin_tables + HEAD.format(drag=""))


def test_explain_states_the_heat_balance_of_a_thermal_file():
    from epicyclic.explain import explain

    text = EXAMPLE.read_text(encoding="utf-8").replace("temperature = 80.0", 'temperature = "thermal"')
    text += "\n[housing]\narea = 1.0\ncooler = 150.0\n"
    f = loads_train_file(text)
    solution = f.solve()
    assert 20.0 < solution.oil_temperature < 200.0
    lines = explain(solution, f.units, losses=f.losses, spin=f.spin, gear=f.gear, input="in").text()
    assert "heat balance (ISO/TR 14179-1)" in lines
    shed = float(f.spin.housing.dissipated(solution.oil_temperature))
    assert shed == pytest.approx(solution.loss, rel=1e-6)
