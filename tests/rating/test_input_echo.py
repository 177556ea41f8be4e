"""The input echo of ``epicyclic rate``: what was rated, before the results — geometry per gear, material with its
hardness and scale, lubricant, the tool or ISO's closed form, accuracy grade, the given factors; every safety with its
minimum beside it; ISO symbols in text, Markdown and HTML while the JSON keeps its ASCII keys.

The geometry is checked against ISO 21771:2007's closed forms (d = z m_n / cos β, d_f = d − 2 m_n (h_fP* − x) for an
external gear, |d_f| = |d| + 2 m_n (h_fP* − x) for an internal one, x in the ISO 21771 sign of the file) and the file's
own numbers (examples/rating/simple_set.toml, micropitting.toml, helical_stage_scuffing.toml).
"""

import json
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.io import load_train_file
from epicyclic.rating.input_echo import echo_sections
from epicyclic.rating.report_render import render_text
from epicyclic.rating.train import mesh_inputs

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "rating"
SIMPLE = str(EXAMPLES / "simple_set.toml")
runner = CliRunner()


def _echo(path):
    f = load_train_file(path)
    sections = echo_sections(mesh_inputs(f.geometry, f.rating)[0], f.rating)
    return {s.title: s for s in sections}


def _row(section, symbol_or_name):
    return next(r for r in section.rows if symbol_or_name in (r[0], r[1]))


def test_the_echo_holds_the_geometry_of_every_gear():
    gears = _echo(SIMPLE)["Inputs: the gears of P"]
    assert gears.head[3:] == ("sun", "planet", "ring")
    assert _row(gears, "z")[3:] == ("21", "39", "99 (internal)")
    assert _row(gears, "x")[3:] == ("0.25", "0.1", "-0.45")
    assert _row(gears, "m_n")[3:] == ("3",) * 3 and _row(gears, "b")[3:] == ("40",) * 3
    assert _row(gears, "α_n")[3:] == ("20",) * 3 and _row(gears, "β")[3:] == ("0",) * 3
    m, h_fp = 3.0, 1.25
    for i, (z, x, internal) in enumerate(((21, 0.25, False), (39, 0.1, False), (99, -0.45, True))):
        d = z * m
        d_f = d + 2 * m * (h_fp - x) if internal else d - 2 * m * (h_fp - x)
        assert float(_row(gears, "d")[3 + i]) == pytest.approx(d)
        assert float(_row(gears, "d_f")[3 + i]) == pytest.approx(d_f, abs=1e-4)
        assert _row(gears, "d_a")[3 + i]


def test_the_echo_holds_material_tool_accuracy_and_lubricant():
    echo = _echo(SIMPLE)
    gears = echo["Inputs: the gears of P"]
    assert _row(gears, "material")[3:] == ("18CrNiMo7-6", "18CrNiMo7-6", "42CrMo4")
    assert _row(gears, "surface hardness")[3].endswith(("HV", "HB", "HRC"))
    assert _row(gears, "σ_Hlim")[3] == "1500.0" and _row(gears, "σ_Flim")[3] == "425"
    tool = _row(gears, "tool")[3:]
    assert tool[0].startswith("ISO's closed form") and tool[2].startswith("cutter: z0 25, x0 0")  # cutter = {...}
    assert _row(gears, "Q")[3:] == ("6",) * 3
    assert _row(gears, "R_zH")[3:] == ("3",) * 3 and _row(gears, "R_zF")[3:] == ("10",) * 3
    general = echo["Inputs of the rating"]
    assert _row(general, "ν_40")[3] == "220" and _row(general, "ν_100")[3] == "19"
    assert _row(general, "S_Hmin")[3] == "1" and _row(general, "S_Fmin")[3] == "1.4"
    assert _row(general, "L_h")[3] == "20000.0"


def test_the_echo_lists_every_given_factor():
    given = _echo(SIMPLE)["Inputs: given factors"]
    rows = {(r[1], r[2]): r for r in given.rows}
    assert rows[("sun-planet", "K_A")][3] == "1.25" and rows[("planet-ring", "K_A")][3] == "1.25"
    assert rows[("sun-planet", "K_γ")][3] == "1"  # load_sharing = 1.0
    assert all(r[4].startswith("rating.") for r in given.rows)  # the key that gave it
    scuffing = _echo(EXAMPLES / "helical_stage_scuffing.toml")
    assert any(r[2] == "K_Hβ" for r in scuffing["Inputs: given factors"].rows)


def test_the_failure_modes_inputs_are_echoed():
    general = _echo(EXAMPLES / "micropitting.toml")["Inputs of the rating"]
    assert "load_stage = 9" in _row(general, "micropitting inputs")[3]
    assert "oil_temperature = 70" in _row(general, "micropitting inputs")[3]


@pytest.mark.parametrize("fmt", ["table", "markdown", "html"])
def test_the_report_starts_with_the_echo_and_writes_symbols_right(fmt):
    out = runner.invoke(app, ["rate", str(EXAMPLES / "micropitting.toml"), "-f", fmt])
    assert out.exit_code == 0, out.output
    text = out.stdout
    assert text.index("Inputs of the rating") < text.index("Inputs: the gears of P") < text.index("Tooth load capacity")
    assert not re.search(r"\bum\b|sigma_", text)
    assert "σ_H" in text and "µm" in text and "N/mm²" in text


@pytest.mark.parametrize("path", ["simple_set.toml", "micropitting.toml", "helical_stage_scuffing.toml"])
def test_every_safety_row_has_its_minimum(path):
    text = runner.invoke(app, ["rate", str(EXAMPLES / path)]).stdout
    lines = text.splitlines()
    safeties = 0
    for i, line in enumerate(lines):
        cells = re.split(r"\s{2,}", line.strip())
        if len(cells) > 2 and re.fullmatch(r"S_(H|F|λ|intS|B)", cells[1]) and "safety" in cells[0]:
            safeties += 1
            below = re.split(r"\s{2,}", lines[i + 1].strip())
            assert below[1] == cells[1] + "min" and below[0].startswith("minimum"), line
    assert safeties >= 4


def test_the_json_keeps_its_ascii_keys_and_has_no_nan():
    out = runner.invoke(app, ["rate", str(EXAMPLES / "micropitting.toml"), "-f", "json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout, parse_constant=lambda c: pytest.fail(f"JSON holds {c}"))
    assert set(data) == {"schema", "source", "title", "inputs", "ratings", "warnings"}
    mesh = data["ratings"][0]["meshes"][0]
    assert "sigma_H" in mesh["gears"]["sun"] and "K_Hbeta" in mesh["factors"]
    assert "S_lambda" in json.dumps(data) and "σ" not in json.dumps(list(mesh["factors"]))


def test_the_html_report_prints_with_a_header_of_the_file_and_the_date():
    out = runner.invoke(app, ["rate", SIMPLE, "-f", "html"])
    page = out.stdout
    assert "@media print" in page and "break-before:page" in page
    header = re.search(r"<header class='page'>(.*?)</header>", page).group(1)
    assert "simple_set.toml" in header and re.search(r"\d{4}-\d\d-\d\d", header)
    assert page.count("<div class='mesh'>") == 2  # sun-planet and planet-ring, each on a new page


def test_every_gear_in_one_printable_document(tmp_path):
    path = Path(__file__).resolve().parents[2] / "examples" / "rating" / "zf_8hp70_rating.toml"
    out = runner.invoke(app, ["rate", str(path), "-f", "html", "--gear", "all"])
    assert out.exit_code == 0, out.output
    page = out.stdout
    assert page.count("<!DOCTYPE html>") == 1 and page.count("Inputs of the rating") == 1
    assert page.count("<section class='rating'>") == 9 and "@media print" in page
    assert "micropitting and scuffing not rated: the mesh does not turn" in page  # a set that turns as a block
