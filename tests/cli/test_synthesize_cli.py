"""``epicyclic synthesize``: the Simpson three-speed is rediscovered, and every printed candidate
passes ``epicyclic gears`` (same ratios), ``fit``, ``analyze`` and ``rate`` on its own train file.

Targets: Ford C4 ratios 2.46, 1.46, 1.00, R −2.18 ('Ford C4 transmission', Wikipedia;
reverse from ford-torino.de), 2 simple sets, 2 brakes, 2 clutches, ±1 % — the published
train is ``examples/simpson_c4_3speed.toml``.  The search is a full one over that space
(every tie pattern, input on a member or a separate shaft, every brake and clutch placement,
1, 2 or 3 elements engaged per gear); nothing in it names the Simpson arrangement.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.synthesis.candidate import Candidate
from epicyclic.transmission import Transmission
from epicyclic.transmission.library import build

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SPEC = EXAMPLES / "synthesis" / "simpson_3speed.toml"
runner = CliRunner()


@pytest.fixture(scope="module")
def simpson_run(tmp_path_factory):
    # the command runs in its own process, as a user runs it: its Dask cluster (threads) ends with it
    import subprocess
    import sys

    out = tmp_path_factory.mktemp("simpson")
    process = subprocess.run([sys.executable, "-c", "from epicyclic.cli.main import main; main()", "synthesize",
                              str(SPEC), "--format", "json", "--threads", "--workers", "2", "--top", "50",
                              "--out-dir", str(out / "files"), "--csv", str(out / "table.csv"),
                              "--out", str(out / "result.json")], capture_output=True, text=True, timeout=600)
    assert process.returncode == 0, process.stderr
    assert "synthesize: 41/41 tasks (100 %)" in process.stderr  # progress is shown
    return out, json.loads((out / "result.json").read_text())


def test_simpson_arrangement_is_found(simpson_run):
    out, report = simpson_run
    simpson = Candidate.from_transmission(build("simpson_c4")).architecture_key
    files = sorted((out / "files").glob("candidate_*.toml"))
    assert len(files) == len(report["candidates"]) > 0
    keys = [Candidate.from_transmission(Transmission.from_file(f)).architecture_key for f in files]
    assert keys[0] == simpson  # ranked first (issue 22: it came tenth, behind layouts circulating 0.87 × P_in)
    assert report["candidates"][0]["circulating_power_max"] == pytest.approx(0.0, abs=1e-9)
    assert report["stats"]["mechanisms"] == 41  # every tie pattern of 2 sets with 2, 3 or 4 DOF


def test_every_candidate_passes_gears_fit_analyze_and_rate(simpson_run):
    """Every written candidate: same ratios in ``gears``, its geometry passes ``fit``, ``analyze`` solves it
    and ``rate --gear all`` finds every mesh of every gear at or above S_Hmin and S_Fmin (ISO 6336, with the
    [rating] inputs the synthesis sized it with: epicyclic.synthesis.sizing)."""
    out, report = simpson_run
    for cand, path in zip(report["candidates"], sorted((out / "files").glob("candidate_*.toml"))):
        result = runner.invoke(app, ["gears", str(path), "--format", "json"])
        assert result.exit_code == 0, result.output
        gears = {g["gear"]: g["ratio"] for g in json.loads(result.stdout)["gears"]}
        assert gears == pytest.approx(cand["ratios"], rel=1e-9)
        for gear, target in cand["targets"].items():
            assert abs(gears[gear] / target - 1) <= 0.01
        analysed = runner.invoke(app, ["analyze", str(path), "--format", "json"])
        assert analysed.exit_code == 0, analysed.output
        # real geometry: module and face width from the torque, and every set passes the fitting checks
        fitted = runner.invoke(app, ["fit", str(path), "--format", "json"])
        assert fitted.exit_code == 0, fitted.output
        sets = json.loads(fitted.stdout)["fitting"]
        assert len(sets) == 2 and all(s["fitting"]["passed"] for s in sets.values()), path
        rated = runner.invoke(app, ["rate", str(path), "--gear", "all", "--format", "json"])
        assert rated.exit_code == 0, rated.output
        ratings = json.loads(rated.stdout)["ratings"]
        assert {r["gear"] for r in ratings} == set(cand["ratios"]) and all(r["ok"] for r in ratings), path
        efficiency = json.loads(analysed.stdout)["solution"]["efficiency"]
        first = next(g for g in json.loads(result.stdout)["gears"] if g["gear"] == "1")
        assert efficiency == pytest.approx(first["efficiency_drive"], rel=1e-9)


def test_csv_has_one_row_per_candidate(simpson_run):
    out, report = simpson_run
    lines = (out / "table.csv").read_text().splitlines()
    assert lines[0].startswith("rank,efficiency_mean") and len(lines) == len(report["candidates"]) + 1


@pytest.mark.parametrize("text, match", [
    ("[targets]\nforward = [2.0, 0.0]\n", "ratio of 0"),
    ("[targets\n", "not valid TOML"),
    ("[targets]\nforward = [2.0]\n[sets]\nsimple = 9\n", "1 to 4 planetary sets"),
])
def test_bad_spec_exits_2_with_one_line(tmp_path, text, match):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    result = runner.invoke(app, ["synthesize", str(path), "--threads"])
    assert result.exit_code == 2
    assert match in result.stderr and "bad.toml" in result.stderr and "Traceback" not in result.output


def test_missing_spec_exits_2(tmp_path):
    result = runner.invoke(app, ["synthesize", str(tmp_path / "nope.toml")])
    assert result.exit_code == 2 and "no such file" in result.stderr
