"""Every command that reads a train file reads REXS (by content): analyze, explain, fit, forces, map,
gears, plot, animate, and serve's upload; ``convert`` on the command line.

The FVA planetary stage (tests/exchange/fixtures, fva-net/rexs-api-java, Apache-2.0): sun 17, ring 61
held, ratio 1 + 61/17 = 4.58824 (Willis); the ZF 8HP70 example converted to REXS for the gears command.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

FIXTURES = Path(__file__).parent / "fixtures"
ROOT = Path(__file__).resolve().parents[2]
STAGE = ROOT / "examples" / "rexs" / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs"


def run(*argv: str):
    result = CliRunner().invoke(app, [str(a) for a in argv])
    assert result.exit_code == 0, (argv, result.stdout, result.stderr)
    return result


def test_analyze_a_rexs_file():
    result = run("analyze", STAGE, "--format", "json")
    data = json.loads(result.stdout)
    assert data["solution"]["ratio"] == pytest.approx(1 + 61 / 17)
    # the one summary line, on stderr, after the work
    assert result.stderr.count("\n") == 1 and "ignored: 11 shaft sections, 10 concept bearings" in result.stderr


def test_rate_reads_a_rexs_file_with_materials_and_roughness():
    result = run("rate", FIXTURES / "FVA_Planetary_stage_-_Minus_gearing_1.1_vers2.rexsj")
    assert "Planetary stage [9]" in result.stdout and "ISO 6336" in result.stdout


def test_duty_reads_a_rexs_load_spectrum():
    result = run("duty", ROOT / "examples" / "rexs" / "FVA-Industriegetriebe_2stufig_1-4.rexs")
    assert "REXS load spectrum 1, 4 cases" in result.stdout


@pytest.mark.parametrize("command", [["explain"], ["fit"], ["forces"], ["map", "--speed", "500..1500:3", "--torque", "100..1000:3", "--out", "{tmp}/m.csv"],
                                     ["plot", "--out", "{tmp}/p.png"]])
def test_every_file_command_reads_rexs(command, tmp_path):
    argv = [a.format(tmp=tmp_path) for a in command]
    result = run(argv[0], STAGE, *argv[1:])
    assert result.stdout


def test_gears_and_animate_read_rexs(tmp_path):
    rexs = tmp_path / "zf.rexsz"
    run("convert", ROOT / "examples" / "zf_8hp70_8speed.toml", "-o", rexs)
    result = run("gears", rexs, "--format", "json")
    assert "8" in result.stdout
    assert "REXS 1.7 (zip/xml, epicyclic" in result.stderr and result.stderr.count("\n") == 1
    assert "ignored" not in result.stderr  # a file epicyclic wrote holds nothing it does not use
    assert run("explore", rexs).stdout
    run("animate", STAGE, "--out", tmp_path / "a.gif", "--frames", "2")
    assert (tmp_path / "a.gif").stat().st_size > 0


def test_convert_on_the_command_line(tmp_path):
    out = tmp_path / "stage.toml"
    result = run("convert", STAGE, "-o", out)
    assert result.stdout.startswith(f"wrote {out}")
    assert "# REXS planetary_stage 9" in out.read_text()
    back = tmp_path / "stage.rexsj"
    run("convert", out, "-o", back)
    data = json.loads(run("analyze", back, "--format", "json").stdout)
    assert data["solution"]["ratio"] == pytest.approx(1 + 61 / 17)


def test_serve_upload_opens_rexs_as_toml():
    from starlette.testclient import TestClient

    from epicyclic.web.app import create_app

    with TestClient(create_app()) as client:
        answer = client.post("/upload", files={"file": ("stage.rexs", STAGE.read_bytes(), "application/xml")})
    assert answer.status_code == 200
    assert "planetary_stage 9" in answer.text and "Sonnenwelle [34]" in answer.text
