"""``convert`` round trips: every bundled example through REXS (XML and JSON) and back, unchanged.

A file written reads back to the same train: the same speeds, torques and efficiency at its operating
point, the same ratio and efficiency in every gear of its schedule, the same tooth forces; and it
validates against the official REXS schemas (``rexs-schema.xsd``, ``rexs-schema.json``, FVA GmbH,
Apache-2.0) with xmlschema and jsonschema.  Every attribute id written (but epicyclic's own
``custom_*``) exists for its component in the REXS 1.7 database with the unit written
(``fixtures/rexs_1.7_database_excerpt.json``, from ``rexs_schema_1.7.xml``, fva-net/rexs-api-java).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from hypothesis import assume, given, settings, strategies as st

from epicyclic import OperatingPoint, solve
from epicyclic.exchange.container import read_model
from epicyclic.exchange.convert import convert, rexs_text
from epicyclic.exchange.validate import validate_rexs
from epicyclic.io import load_train_file
from epicyclic.io.geometry_report import geometry_results

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = (sorted((ROOT / "examples").glob("*.toml")) + sorted((ROOT / "examples" / "rating").glob("*.toml"))
            + sorted((ROOT / "examples" / "rexs").glob("*.rexs")))
FIXTURES = Path(__file__).parent / "fixtures"
DATE = "2026-01-01T00:00:00+00:00"


def fingerprint(f) -> dict:
    """What must survive a round trip: solution numbers by shaft, per-gear ratios, tooth forces."""
    out = {}
    if f.operating_point is not None:
        s = f.solve()
        out["speeds"] = {k: s.speed(k) for k in f.train.shafts}
        out["torques"] = {k: s.torque(k) for k in f.train.shafts}
        out["efficiency"] = s.efficiency
        out["losses"] = {e: s.elements[e].loss for e in s.elements}
        if f.geometry:
            results = geometry_results(f.geometry, s)
            out["forces"] = sorted(_numbers([r.forces.to_dict() for r in results if r.forces is not None]))
    if f.transmission is not None:
        t = f.transmission
        for gear in t.gears:
            train = t.train_in_gear(f.train, gear)
            point = OperatingPoint({t.input: 1000.0}, {t.input: 100.0}, drives=[t.input], loads=[t.output])
            s = solve(train, point)
            out[f"gear {gear}"] = (s.speed(t.input) / s.speed(t.output), s.efficiency)
    return out


def _numbers(data):
    if isinstance(data, dict):
        for v in data.values():
            yield from _numbers(v)
    elif isinstance(data, (list, tuple)):
        for v in data:
            yield from _numbers(v)
    elif isinstance(data, float) and math.isfinite(data):
        yield round(data, 6)


def same(a, b) -> None:
    assert a.keys() == b.keys()
    for key in a:
        if isinstance(a[key], dict):
            assert a[key].keys() == b[key].keys(), key
            for k in a[key]:
                assert b[key][k] == pytest.approx(a[key][k], rel=1e-9, abs=1e-9), (key, k)
        elif a[key] is None or isinstance(a[key], tuple) and None in a[key]:
            assert b[key] == a[key], key  # no efficiency: self-locking, or no power flows
        else:
            # the forces are compared as sorted values rounded to 1e-6 (a stable order): a value on a rounding
            # boundary (917.8429565) may round either way after a round trip, so their unit is 1e-6 there
            step = 1.01e-6 if key == "forces" else 1e-9
            assert b[key] == pytest.approx(a[key], rel=1e-9, abs=step), key


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.name)
@pytest.mark.parametrize("suffix", [".rexs", ".rexsj"])
def test_every_example_round_trips_through_rexs(example, suffix, tmp_path):
    out = tmp_path / (example.stem + suffix)
    convert(example, out, date=DATE)
    original, back = load_train_file(example), load_train_file(out)
    assert back.exchange.container == ("xml" if suffix == ".rexs" else "json")
    assert back.title == original.title
    assert back.train.shafts == original.train.shafts
    assert [type(e).__name__ for e in back.train.elements] == [type(e).__name__ for e in original.train.elements]
    assert (back.transmission is None) == (original.transmission is None)
    if original.transmission is not None:
        assert {g: set(v) for g, v in back.transmission.schedule.items()} == {
            g: set(v) for g, v in original.transmission.schedule.items()}
        assert back.gear == original.gear
    assert set(back.geometry) == set(original.geometry)
    for part in ("rating", "duty_cycle", "bearings", "lubricant_table"):  # what only epicyclic reads travels too
        assert (getattr(back, part, None) is None) == (getattr(original, part, None) is None), part
    if original.duty_cycle is not None:
        assert [(c.name, c.gear, c.hours, c.share) for c in back.duty_cycle.cases] == [
            (c.name, c.gear, c.hours, c.share) for c in original.duty_cycle.cases]
    assert set(back.bearings) == set(original.bearings)
    same(fingerprint(original), fingerprint(back))
    # and once more through TOML: REXS -> TOML reads back to the same train
    toml = tmp_path / (example.stem + ".toml")
    convert(out, toml)
    again = load_train_file(toml)
    same(fingerprint(original), fingerprint(again))
    for part in ("rating", "duty_cycle"):
        assert (getattr(again, part) is None) == (getattr(original, part) is None), part


@pytest.mark.parametrize("example", [e for e in EXAMPLES if e.name in (
    "zf_8hp70_geometry.toml", "brandenberger_1952.toml", "wolfrom_drive.toml", "geometry_stepped_set.toml",
    "ravigneaux_ford_aod_4speed.toml")], ids=lambda p: p.name)
def test_written_rexs_validates_against_the_official_schemas(example):
    f = load_train_file(example)
    for kind in ("xml", "json"):
        assert validate_rexs(rexs_text(f, kind, DATE), kind) == []


def test_the_schema_validation_can_fail():
    assert validate_rexs('<model version="1.7"><components><component/></components></model>', "xml")
    assert validate_rexs('{"model": {"version": "1.7", "components": []}}', "json")


def test_attributes_written_are_rexs_1_7_attributes():
    database = json.loads((FIXTURES / "rexs_1.7_database_excerpt.json").read_text(encoding="utf-8"))
    units = {"none": "none", "mm": "mm", "deg": "deg", "1 / min": "1 / min", "N m": "N m", "kW": "kW",
             "%": "%", "C": "C", "mm^2 / s": "mm^2 / s", "mum": "mum", "N / mm^2": "N / mm^2", "HV": "HV",
             "HB": "HB", "kg / dm^3": "kg / dm^3", "h": "h", "kN": "kN"}
    for example in ("zf_8hp70_geometry.toml", "brandenberger_1952.toml", "geometry_simple_set.toml",
                    "wolfrom_drive.toml", "rexs/FVA-Industriegetriebe_2stufig_1-4.rexs",
                    "rating/simple_set_duty_cycle.toml"):
        model = read_model(rexs_text(load_train_file(ROOT / "examples" / example), "xml", DATE).encode(), example)
        written = [(c, c.attributes.values()) for c in model.components.values()]
        written += [(model.components[cid], attributes.values()) for case in model.load_cases
                    for cid, attributes in case.components.items()]
        assert model.load_cases or "rexs/" not in example
        for c, attributes in written:
            for a in attributes:
                if a.id.startswith("custom_"):
                    continue
                known = database["components"][c.type]
                assert a.id in known, (c.type, a.id)
                assert units[a.unit] == known[a.id][1], (c.type, a.id, a.unit)
        for r in model.relations:
            assert {ref.role for ref in r.refs} <= set(database["relations"][r.type]), r.type


def test_rexs_to_rexs_keeps_the_load_spectrum(tmp_path):
    source = ROOT / "examples" / "rexs" / "FVA-Industriegetriebe_2stufig_1-4.rexs"
    out = tmp_path / "gearbox.rexsj"
    convert(source, out, date=DATE)
    original, back = load_train_file(source), load_train_file(out)
    assert len(back.load_cases) == 4
    for a, b in zip(original.load_cases, back.load_cases):
        assert b.duration_fraction == pytest.approx(a.duration_fraction)
        assert b.lubricant_temperature == pytest.approx(a.lubricant_temperature)
        pa, pb = a.to_operating_point(), b.to_operating_point()
        assert dict(pb.speeds) == pytest.approx(dict(pa.speeds))
        assert dict(pb.torques) == pytest.approx(dict(pa.torques))
    assert validate_rexs(out.read_text(), "json") == []


def test_rexs_to_toml_is_commented(tmp_path):
    out = tmp_path / "stage.toml"
    message = convert(ROOT / "examples" / "rexs" / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs", out)
    text = out.read_text()
    assert "ignored: 11 shaft sections" in message
    assert "# REXS planetary_stage 9 'Planetenstufe [9]'" in text
    assert "# REXS switchable_coupling 65 'Koppelung [65]', switchable_coupling 66 'Koppelung [66]'" in text
    assert "'Steg 1 [4]': shaft 4 'Steg 1 [4]', shaft 6 'Steg 2 [6]'" in text
    assert "ignored: 11 shaft sections, 10 concept bearings" in text
    assert load_train_file(out).solve().speed("Steg 1 [4]") == pytest.approx(1500 / (1 + 61 / 17))


def test_gearbox_toml_lists_the_load_cases(tmp_path):
    out = tmp_path / "gearbox.toml"
    convert(ROOT / "examples" / "rexs" / "FVA-Industriegetriebe_2stufig_1-4.rexs", out)
    text = out.read_text()
    assert "# Load spectrum: 4 load cases" in text
    assert "#   load case 2: Shaft [6] 3456 1/min, Shaft [6] 345 N*m, 30 % of the time, oil 70 degC" in text


def test_convert_never_overwrites_the_input(tmp_path):
    from epicyclic.io.output import OutputError

    source = tmp_path / "a.rexs"
    source.write_bytes((ROOT / "examples" / "rexs" / "FVA-Industriegetriebe_2stufig_1-4.rexs").read_bytes())
    with pytest.raises(OutputError, match="is the input file"):
        convert(source, source)


def test_rexsz_written_reads_back(tmp_path):
    out = tmp_path / "set.rexsz"
    convert(ROOT / "examples" / "geometry_simple_set.toml", out, date=DATE)
    assert out.read_bytes()[:2] == b"PK"
    same(fingerprint(load_train_file(ROOT / "examples" / "geometry_simple_set.toml")),
         fingerprint(load_train_file(out)))


@settings(max_examples=15, deadline=None)
@given(z_sun=st.integers(12, 40), z_planet=st.integers(12, 40), planets=st.integers(1, 5),
       module=st.sampled_from([1.0, 2.5, 4.0]), x_sun=st.floats(0.0, 0.5), speed=st.floats(-3000, 3000),
       torque=st.floats(1.0, 500.0), held=st.sampled_from(["ring", "sun", "carrier"]), kind=st.sampled_from(["xml", "json"]))
def test_any_simple_set_round_trips(z_sun, z_planet, planets, module, x_sun, speed, torque, held, kind):
    """Invariant: REXS written and read back gives the same speeds, torques and tooth forces."""
    from epicyclic.exchange.reading import loads_rexs_document
    from epicyclic.io import loads_train_file
    from epicyclic.io.toml_format import read_document
    from epicyclic.io.source import parse_toml

    z_ring = z_sun + 2 * z_planet
    assume(abs(speed) > 1.0)
    drive, load = [m for m in ("sun", "ring", "carrier") if m != held]
    text = f"""
[[planetary]]
name = "P"
sun = "sun"
ring = "ring"
carrier = "carrier"
teeth = {{ sun = {z_sun}, planet = {z_planet}, ring = {z_ring} }}
planets = {planets}
stationary_efficiency = 0.97
[planetary.geometry]
module = {module}
profile_shift = {{ sun = {x_sun}, planet = {-x_sun}, ring = 0.0 }}
face_width = 20.0
[[brake]]
name = "B"
shaft = "{held}"
[operating_point]
speeds = {{ {drive} = {speed} }}
torques = {{ {drive} = {torque} }}
drives = ["{drive}"]
loads = ["{load}"]
"""
    original = loads_train_file(text)
    back = read_document(loads_rexs_document(
        rexs_text(original, kind, DATE, document=parse_toml(text)).encode(), "t.rexs"))
    same(fingerprint(original), fingerprint(back))


def test_load_cases_in_different_gears_round_trip():
    """A load spectrum whose cases run in different gears of the schedule (gear_shift_index per load case)."""
    from epicyclic.exchange.operating import RexsLoadCase
    from epicyclic.exchange.reading import loads_rexs_document
    from epicyclic.exchange.writing import build_rexs
    from epicyclic.io import loads_train_file
    from epicyclic.io.source import parse_toml

    text = """
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
[[brake]]
name = "B"
shaft = "ring"
[[clutch]]
name = "C"
first = "in"
second = "ring"
[transmission]
input = "in"
output = "out"
[transmission.schedule]
"low" = ["B"]
"direct" = ["C"]
[operating_point]
speeds = { in = 3000 }
torques = { in = 10 }
drives = ["in"]
loads = ["out"]
gear = "low"
"""
    f = loads_train_file(text)
    op = {"speeds": {"in": "3000 1/min"}, "torques": {"in": "10 N*m"}, "drives": ["in"], "loads": ["out"]}
    cases = [RexsLoadCase(1, 1, op, 0.25, 60.0, "low"), RexsLoadCase(2, 1, {**op, "speeds": {"in": "2000 1/min"}},
                                                                      0.75, 70.0, "direct")]
    for kind in ("xml", "json"):
        builder = build_rexs(f, parse_toml(text), cases, date=DATE)
        written = builder.xml() if kind == "xml" else builder.json()
        assert validate_rexs(written, kind) == []
        assert "operating_time_fraction" in written  # the REXS 1.7 attribute (gear_unit, %)
        back = loads_rexs_document(written.encode(), f"t.{kind}")
        assert [c.gear for c in back.load_cases] == ["low", "direct"]
        assert [c.duration_fraction for c in back.load_cases] == pytest.approx([0.25, 0.75])
        assert back.data["transmission"]["schedule"] == {"low": ["B"], "direct": ["C"]}
        # ratio 1 + 78/30 = 3.6 in "low", 1 in "direct"
        for case, ratio in zip(back.load_cases, (3.6, 1.0)):
            from epicyclic.io.toml_format import read_document

            train = read_document(back).transmission.train_in_gear(read_document(back).train, case.gear)
            s = solve(train, case.to_operating_point())
            assert s.speed("in") / s.speed("out") == pytest.approx(ratio)
