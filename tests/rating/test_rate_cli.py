"""``epicyclic rate`` and the rating section of ``analyze`` (exit codes 0 / 2, formats, marking)."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.io import loads_train_file
from epicyclic.io.reader import InputFileError
from epicyclic.rating import RatingError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RATED = str(EXAMPLES / "rating" / "simple_set.toml")
runner = CliRunner()


def test_rate_table_json_markdown_html():
    table = runner.invoke(app, ["rate", RATED])
    assert table.exit_code == 0, table.output
    assert "ISO 6336:2019 method B" in table.output and "sun-planet" in table.output and "Y_F" in table.output
    data = json.loads(runner.invoke(app, ["rate", RATED, "-f", "json"]).output)
    assert data["schema"] == "epicyclic-rating/1" and data["inputs"]["standard"] == "ISO 6336:2019"
    mesh = data["ratings"][0]["meshes"][0]
    assert {"K_v", "K_Hbeta", "Z_H", "sigma_H0"} <= set(mesh["factors"])
    sun = mesh["gears"]["sun"]
    assert {"S_H", "S_F", "sigma_H", "sigma_HP", "sigma_F", "sigma_FP", "Y_F", "Y_S"} <= set(sun)
    assert sun["S_H"]["unit"] == "1" and sun["sigma_H"]["unit"] == "N/mm^2" and "ISO 6336-2" in sun["S_H"]["clause"]
    assert runner.invoke(app, ["rate", RATED, "-f", "markdown"]).output.startswith("# ")
    page = runner.invoke(app, ["rate", RATED, "-f", "html"]).output
    assert page.startswith("<!DOCTYPE html>") and "ISO 6336-3:2019" in page and "class='below'" not in page


def test_a_mesh_below_its_minimum_is_marked():
    result = runner.invoke(app, ["rate", RATED, "--set", "operating_point.torques.in=\"3000 N*m\"", "-f", "html"])
    assert result.exit_code == 0
    assert "class='below'" in result.output and "BELOW its minimum safety" in result.output
    text = runner.invoke(app, ["rate", RATED, "--set", "operating_point.torques.in=\"3000 N*m\""])
    assert " !" in text.output and "below minimum safety: P sun-planet" in text.output


def test_explain_one_mesh():
    result = runner.invoke(app, ["rate", RATED, "--explain", "P:planet-ring:ring"])
    assert result.exit_code == 0, result.output
    assert "Worked rating of ring in mesh planet-ring" in result.output and "S_F = σ_FG / σ_F" in result.output
    bad = runner.invoke(app, ["rate", RATED, "--explain", "P:planet-ring:moon"])
    assert bad.exit_code == 2 and "not 'moon'" in bad.output


def test_analyze_adds_the_safeties():
    result = runner.invoke(app, ["analyze", RATED])
    assert result.exit_code == 0 and "Tooth load capacity" in result.output
    data = json.loads(runner.invoke(app, ["analyze", RATED, "-f", "json"]).output)
    assert data["rating"]["meshes"][1]["gears"]["ring"]["S_F"]["value"] > 1


def test_bad_input_exit_2():
    plain = runner.invoke(app, ["rate", str(EXAMPLES / "geometry_simple_set.toml")])
    assert plain.exit_code == 2 and "no [rating] table" in plain.output
    missing = runner.invoke(app, ["rate", RATED, "--set", "rating.standard=\"1996\""])
    assert missing.exit_code == 2 and "rating.standard" in missing.output


def test_all_gears_of_a_transmission(tmp_path):
    source = (EXAMPLES / "zf_8hp70_geometry.toml").read_text()
    path = tmp_path / "8hp.toml"
    # the file's [lubricant] gives the viscosity at the operating temperature (Schlenk's friction); the
    # rating's data-sheet ν40 goes into [rating.lubricant] (one oil description per table, docs/file-format.md)
    path.write_text(source + (
        "\n[rating]\nmaterial = \"18CrNiMo7-6\"\nflank_roughness = 3.0\nroot_roughness = 10.0\n"
        "lubricant = { viscosity_40 = 35.0 }\n"))
    result = runner.invoke(app, ["rate", str(path), "--gear", "all", "-f", "json"])
    assert result.exit_code == 0, result.output
    ratings = json.loads(result.stdout)["ratings"]
    assert [r["gear"] for r in ratings] == ["1", "2", "3", "4", "5", "6", "7", "8", "R"]


RATING_FILE = """
[[planetary]]
name = "P"
sun = "in"
ring = "r"
carrier = "out"
teeth = {{ sun = 21, planet = 39, ring = 99 }}
[planetary.geometry]
module = 3.0
face_width = 40.0
[[brake]]
name = "B"
shaft = "r"
{lubricant}
[rating]
{rating}
"""


def test_file_format_keys():
    f = loads_train_file(RATING_FILE.format(lubricant="[lubricant]\nviscosity_40 = 150.0\nviscosity_100 = 15.0",
                                            rating='material = { all = "16MnCr5", ring = "Mine" }\nquality = "ME"\n'
                                                   "[rating.materials.Mine]\ntreatment = \"V\"\n"
                                                   "sigma_Hlim = 900.0\nsigma_Flim = 320.0\n"))
    spec = f.rating
    assert spec.viscosity_40 == 150.0 and spec.viscosity_100 == 15.0
    assert spec.material_of("P", "ring").sigma_Hlim == 900.0
    assert spec.material_of("P", "sun").sigma_Hlim == 1650.0          # Eh, quality ME
    with pytest.raises(InputFileError, match=r"\[rating\]: unknown key 'materal'"):
        loads_train_file(RATING_FILE.format(lubricant="", rating='materal = "16MnCr5"'))
    with pytest.raises(RatingError, match=r"\[rating\], key .material.: material: unknown material"):
        loads_train_file(RATING_FILE.format(lubricant="", rating='material = "Unobtainium"'))
    own = loads_train_file(RATING_FILE.format(lubricant="", rating="[rating.lubricant]\nviscosity_40 = 68.0"))
    assert own.rating.viscosity_40 == 68.0


def test_rim_thickness_from_the_file():
    f = loads_train_file(RATING_FILE.format(lubricant="[lubricant]\nviscosity_40 = 150.0",
                                            rating='rim_thickness = { ring = 7.5, "P:sun" = 20.0 }'))
    assert f.rating.rim_of("P", "ring") == 7.5 and f.rating.rim_of("P", "sun") == 20.0
    assert f.rating.rim_of("Q", "sun") is None and f.rating.rim_of("P", "planet") is None


def test_roughness_per_gear_from_the_file():
    f = loads_train_file(RATING_FILE.format(lubricant="[lubricant]\nviscosity_40 = 150.0",
                                            rating="flank_roughness = { sun = 3.0, ring = 6.0, all = 4.0 }\n"
                                                   "root_roughness = 10.0"))
    spec = f.rating
    assert spec.roughness_of("flank_roughness", "P", "ring") == 6.0
    assert spec.roughness_of("flank_roughness", "P", "planet") == 4.0
    assert spec.roughness_of("root_roughness", "P", "sun") == 10.0
    with pytest.raises(RatingError, match=r"flank_roughness\.sun"):
        loads_train_file(RATING_FILE.format(lubricant="", rating="flank_roughness = { sun = -1.0 }"))


@pytest.mark.parametrize("override, says", [
    # issue 30: a unit in [rating] got the expression grammar's tooth-ratio hint ("e.g. '(24/50)*(42/30)'")
    ('rating.life="20000 kg"', "key 'life': expected a number in h (e.g. 2 or '2 h'), got '20000 kg'"),
    ('rating.S_Hmin="1 h"', "key 'S_Hmin': expected a plain number (no unit), got '1 h'"),
    ('rating.flank_roughness="3 mm"', "key 'flank_roughness': takes a plain number in µm (R_z), without a unit"),
    # issue 30: a key naming no gear was accepted and dropped
    ("rating.rim_thickness={moon=12}", "rating.rim_thickness.moon names no gear of the rated train"),
    ("rating.tool={moon={tip_radius=0.3}}", "rating.tool.moon names no gear of the rated train"),
    # issue 30: sigma_Hlim = 1e308 overflowed (internal error, exit 1)
    ('rating.materials={own={treatment="Eh", sigma_Hlim=1e308, sigma_Flim=500, hardness=60}}',
     "sigma_Hlim must be a number in (0, 5000] N/mm^2"),
])
def test_bad_rating_values_name_the_key_and_what_it_takes(override, says):
    extra = ['rating.material={sun="own", planet="18CrNiMo7-6", ring="42CrMo4"}'] if "own" in override else []
    args = ["rate", str(EXAMPLES / "rating" / "simple_set.toml"), "--set", override]
    for item in extra:
        args += ["--set", item]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2, result.output
    assert says in " ".join(result.output.split())


def test_a_number_may_carry_its_keys_unit():
    plain = CliRunner().invoke(app, ["rate", str(EXAMPLES / "rating" / "simple_set.toml"), "-f", "json"])
    units = CliRunner().invoke(app, ["rate", str(EXAMPLES / "rating" / "simple_set.toml"), "-f", "json",
                                     "--set", 'rating.life="20000 h"', "--set", 'rating.flank_roughness="3.0 um"'])
    assert plain.exit_code == 0 and units.exit_code == 0, units.output
    assert json.loads(plain.stdout) == json.loads(units.stdout)
