"""``epicyclic fit``, ``forces``, ``search`` and ``analyze`` with geometry tables."""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.geometry import search_teeth

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


def test_fit_table_and_json():
    result = runner.invoke(app, ["fit", str(EXAMPLES / "geometry_simple_set.toml")])
    assert result.exit_code == 0, result.output
    # lecad test run: both meshes at a = 56.8 mm, sun tip 41.7008 mm (printed), 3 planets fit
    assert "a_w = 56.7999 mm" in result.output and "41.7007" in result.output and "passes" in result.output
    result = runner.invoke(app, ["fit", str(EXAMPLES / "wolfrom_drive.toml"), "-f", "json"])
    data = json.loads(result.output)["fitting"]
    assert data["W"]["fitting"]["passed"] and data["W"]["kind"] == "planetary set"
    assembly = next(c for c in data["W"]["fitting"]["checks"] if c["condition"] == "assembly")
    assert assembly["ticks"] == 54  # |81·24 − 78·27| / gcd(27, 24)


def test_fit_reports_a_failing_condition_with_its_fix():
    result = runner.invoke(app, ["fit", str(EXAMPLES / "geometry_simple_set.toml"), "--planets", "5"])
    assert result.exit_code == 0
    assert "FAILS" in result.output and "cannot be equally spaced" in result.output
    assert "do not fit" in result.output or "neighbour" in result.output.lower()


def test_forces_table_json_and_equilibrium():
    result = runner.invoke(app, ["forces", str(EXAMPLES / "geometry_simple_set.toml"), "-f", "json"])
    assert result.exit_code == 0, result.output
    forces = json.loads(result.output)["forces"]["P"]["forces"]
    # the three pins take the carrier torque: Σ pin forces × radii + friction moments = solver carrier torque
    assert forces["carrier_torque_from_forces"] == pytest.approx(forces["torques"]["carrier"], rel=1e-9)
    assert forces["planets"] == 3 and forces["load_sharing_factor"] == 1.0
    result = runner.invoke(app, ["forces", str(EXAMPLES / "zf_8hp70_geometry.toml"), "--gear", "3"])
    assert result.exit_code == 0, result.output
    assert "forces of 'P4'" in result.output


def test_forces_needs_geometry_and_fit_checks_tooth_counts_without_it():
    example = str(EXAMPLES / "simple_set_ring_held_sun_drives.toml")
    result = runner.invoke(app, ["forces", example])
    assert result.exit_code == 2
    assert "no element has a geometry table" in result.output and "module" in result.output
    # fit: what the tooth counts decide (coaxiality of standard gears, assembly), said to be counts only
    result = runner.invoke(app, ["fit", example])
    assert result.exit_code == 0, result.output
    assert "from tooth counts only" in result.output and "assembly" in result.output


def test_fit_without_geometry_says_how_far_counts_are_off(tmp_path):
    # z_ring - z_sun - 2 z_planet = +3: accepted, profile shift must close it (issue 19)
    path = tmp_path / "p.toml"
    path.write_text("[[planetary]]\nname = 'P'\nsun = 'a'\nring = 'housing'\ncarrier = 'c'\n"
                    "teeth = { sun = 20, planet = 37, ring = 97 }\nplanets = 3\n", encoding="utf-8")
    data = json.loads(runner.invoke(app, ["fit", str(path), "-f", "json"]).output)
    checks = {c["condition"]: c for c in data["fitting"]["P"]["fitting"]["checks"]}
    assert checks["coaxiality"]["severity"] == "warning" and not checks["coaxiality"]["passed"]
    assert "= +3" in checks["coaxiality"]["message"] and "profile shift must close it" in checks["coaxiality"]["message"]
    assert checks["assembly"]["passed"] and checks["assembly"]["ticks"] == 117


def test_search_matches_the_library_in_every_format(tmp_path):
    args = ["search", "--ratio", "5.2", "--tolerance", "3%", "--planets", "3..6", "--module", "2"]
    direct = search_teeth(5.2, tolerance=0.03, planets=(3, 4, 5, 6), module=2.0)
    table = runner.invoke(app, args)
    assert table.exit_code == 0, table.output
    assert f"{len(direct)} tooth-count sets" in table.output
    data = json.loads(runner.invoke(app, [*args, "-f", "json"]).output)
    assert [c["z_sun"] for c in data["candidates"]] == [c.z_sun for c in direct.candidates]
    out = tmp_path / "s.csv"
    assert runner.invoke(app, [*args, "-f", "csv", "-o", str(out)]).exit_code == 0
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert len(rows) == len(direct) and int(rows[0]["z_ring"]) == direct.best.z_ring


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (["--tolerance", "3x"], "expected a relative deviation such as 3% or 0.03"),
        (["--tolerance", "150%"], "0 <= tolerance < 100 %"),
        (["--planets", "6..3"], "expected a range LOW..HIGH"),
        (["--sun", "a..b"], "--sun: expected a whole number or a range"),
        (["--held", "sun", "--driver", "sun"], "--held sun, --driver sun, --driven carrier: give three different members"),
    ],
)
def test_search_bad_input_exit_2(args, match):
    result = runner.invoke(app, ["search", "--ratio", "4", *args])
    assert result.exit_code == 2 and match in result.output


def test_analyze_reports_geometry_in_every_format(tmp_path):
    path = str(EXAMPLES / "geometry_simple_set.toml")
    text = runner.invoke(app, ["analyze", path]).output
    assert "fitting of 'P': passes" in text and "forces of 'P'" in text
    report = json.loads(runner.invoke(app, ["analyze", path, "-f", "json"]).output)
    assert report["schema"] == "epicyclic-report/3"
    assert report["geometry"]["P"]["fitting"]["passed"] is True
    assert report["geometry"]["P"]["geometry"]["meshes"][0]["center_distance"] == pytest.approx(56.8, abs=1e-3)
    markdown = runner.invoke(app, ["analyze", path, "-f", "markdown"]).output
    assert "## Geometry, fitting and forces" in markdown
    page = tmp_path / "r.html"
    assert runner.invoke(app, ["analyze", path, "-f", "html", "-o", str(page)]).exit_code == 0
    assert "<h2>Geometry, fitting and forces</h2>" in page.read_text()
    # files without geometry keep the schema-1 keys
    plain = json.loads(runner.invoke(app, ["analyze", str(EXAMPLES / "brandenberger_1952.toml"), "-f", "json"]).output)
    assert "geometry" not in plain


@pytest.mark.parametrize("args, says", [
    # a minus set with the carrier held turns backwards: +3 is out of reach (the table was just empty)
    (["--ratio", "3", "--held", "carrier", "--driver", "sun", "--driven", "ring"],
     "no tooth counts of these ranges come within ± 1 % of 3; with the carrier held, sun -> ring ranges over "
     "-14.33 … -1.3"),
    # 20/32/84 gives 5.2 exactly (1 + 84/20), but (20 + 84)/7 is not whole: seven planets cannot be equally spaced
    (["--ratio", "5.2", "--tolerance", "0", "--planets", "7", "--sun", "20", "--planet", "32"],
     "1 tooth-count set meets the ratio, but none passes assembly"),
])
def test_search_says_why_it_found_nothing(args, says):
    result = runner.invoke(app, ["search", *args])
    assert result.exit_code == 0, result.output
    assert result.output.startswith("0 tooth-count sets") and says in result.output
    found = runner.invoke(app, ["search", "--ratio", "5.2"])
    assert "none found" not in found.output


def test_forces_reads_as_a_report():
    # A user's reading of `forces` on a transmission: which gear (it did not say), units on every column (they
    # were in the title only, `angle` had none), planets counted from 1 (were 0, 1, 2), angles to 0.01° (were
    # 120.0000), small torques with their digits (a drag-loaded set showed "sun -0.01 N*m"), and the forces
    # only: the gear tables and the fitting report are `fit`'s.
    result = runner.invoke(app, ["forces", str(EXAMPLES / "zf_8hp70_geometry.toml")])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0] == "forces of ZF 8HP 70 with illustrative gear geometry and losses, gear 1"
    assert set(lines[1]) == {"="}
    assert "planet  gear    angle [deg]  mesh         F_t [N]    F_r [N]   F_a [N]  bearing [N]" in lines
    # 4 planets of set P1 at 0, 90, 180, 270°; K_γ = 1.2; F_t = 1.2 · 243.03 N·m / (4 · 36 mm) (FVA K_γ table)
    rows = [line.split() for line in lines if line.startswith(("1 ", "2 ", "3 ", "4 "))][:8]
    assert [r[0] for r in rows] == ["1", "1", "2", "2", "3", "3", "4", "4"]
    assert [r[2] for r in rows[::2]] == ["0.00", "90.00", "180.00", "270.00"]
    assert float(rows[0][4]) == pytest.approx(1.2 * 243.03e3 / (4 * 36.0), rel=1e-4)
    assert "sun (s12) -0.0067796 N*m" in result.output  # P2 carries only drag in gear 1
    assert "fitting of" not in result.output and "d_b" not in result.output
    fit = runner.invoke(app, ["fit", str(EXAMPLES / "zf_8hp70_geometry.toml")]).output
    assert fit.startswith("fitting of ZF 8HP 70") and "d_b [mm]" in fit and "a_w [mm]" in fit
    assert "alpha_wt [deg]" in fit and "forces of" not in fit


def test_forces_of_a_simple_set_by_hand():
    # geometry_simple_set: sun 60 N·m, 3 planets (K_γ = 1), sun operating pitch diameter d_w1 = 37.2750 mm:
    # F_t = 60 000 N·mm / (3 · 18.6375 mm) = 1073.11 N; F_r = F_t tan α_wt (22.1106°) = 435.98 N.
    result = runner.invoke(app, ["forces", str(EXAMPLES / "geometry_simple_set.toml"), "-f", "json"])
    body = json.loads(result.output)["forces"]["P"]
    assert body["fitting"] is None
    mesh = body["forces"]["bodies"][0]["meshes"][0]
    assert mesh["tangential"] == pytest.approx(60e3 / (3 * 37.2750 / 2), rel=1e-5)
    assert mesh["radial"] == pytest.approx(mesh["tangential"] * math.tan(math.radians(22.1106)), rel=1e-5)


GEOMETRY_EXAMPLES = sorted(p.name for p in EXAMPLES.glob("*.toml") if ".geometry]" in p.read_text(encoding="utf-8"))


@pytest.mark.parametrize("example", GEOMETRY_EXAMPLES)
def test_every_bundled_design_fits(example):
    # A bundled example is a design to copy: it must pass its own fit, warnings included. The stepped-set
    # example said "coaxial with the sun mesh" but failed coaxiality (sun shift 0.2 moved a_w to 50.389 mm)
    # and equal spacing ((20·18 + 86·30)/6 = 490 is not a multiple of 3), with an interference warning.
    result = runner.invoke(app, ["fit", str(EXAMPLES / example), "-f", "json"])
    assert result.exit_code == 0, result.output
    for name, body in json.loads(result.output)["fitting"].items():
        failed = [c["message"] for c in body["fitting"]["checks"] if not c["passed"]]
        assert not failed, (example, name, failed)


def test_geometry_examples_are_found():
    assert {"geometry_simple_set.toml", "geometry_stepped_set.toml", "wolfrom_drive.toml",
            "zf_8hp70_geometry.toml"} <= set(GEOMETRY_EXAMPLES)


ONE_PLANET = """
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
planets = 1
[planetary.geometry]
module = 2
face_width = 20
[[brake]]
name = "B"
shaft = "ring"
[operating_point]
speeds = { in = 3000 }
torques = { in = 10 }
drives = ["in"]
loads = ["out"]
"""


def test_one_planet_set_is_valid_in_fit_and_forces(tmp_path):
    # issue 19: forces refused one planet and fit -f json exited 1 on the unbounded clearance
    path = tmp_path / "one.toml"
    path.write_text(ONE_PLANET, encoding="utf-8")
    result = runner.invoke(app, ["fit", str(path), "-f", "json"])
    assert result.exit_code == 0, result.output
    (neighbours,) = [c for c in json.loads(result.output)["fitting"]["P"]["fitting"]["checks"]
                     if c["condition"] == "neighbours"]
    assert neighbours["passed"] and neighbours["clearance"] is None
    assert neighbours["null_reasons"]["clearance"].startswith("one planet")
    result = runner.invoke(app, ["forces", str(path), "-f", "json"])
    assert result.exit_code == 0, result.output
    forces = json.loads(result.output)["forces"]["P"]["forces"]
    # all of the sun torque goes through the one planet: F_t = 2000 T / d_w = 2000 * 10 / 60 N
    (body,) = forces["bodies"]
    sun_mesh = next(m for m in body["meshes"] if m["mesh"] == "sun-planet")
    assert sun_mesh["tangential"] == pytest.approx(2000 * 10 / 60)


def test_search_with_one_planet_writes_no_infinity():
    # issue 19: one planet has no neighbour; JSON must not carry Infinity
    result = runner.invoke(app, ["search", "--ratio", "4", "--planets", "1", "-f", "json"])
    assert result.exit_code == 0, result.output
    first = json.loads(result.output)["candidates"][0]
    assert first["planets"] == 1 and first["clearance"] is None and first["clearance_note"].startswith("one planet")
    assert "Infinity" not in result.output
    csv_text = runner.invoke(app, ["search", "--ratio", "4", "--planets", "1", "-f", "csv"]).output
    assert "inf" not in csv_text.splitlines()[1]


def test_analyze_says_how_far_counts_are_off_without_geometry():
    # issue 19: the Prius power-split set 30/23/78 misses z_ring = z_sun + 2 z_planet by two teeth; without a
    # geometry table the report says so and that profile shift must close it (the set is not refused)
    result = runner.invoke(app, ["analyze", str(EXAMPLES / "toyota_prius_power_split.toml"), "-f", "json"])
    assert result.exit_code == 0, result.output
    warnings = json.loads(result.output)["solution"]["warnings"]
    assert any("'PSD': z_ring - z_sun - 2 z_planet = 78 - 30 - 2*23 = +2" in w and "profile shift must close it" in w
               for w in warnings)
