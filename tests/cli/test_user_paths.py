"""What a new user does first, command by command, on the bundled examples.

Regression tests for defects found by using the toolkit as the README shows it
(validation pass): each test names the command line that went wrong.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.transmission.library import build

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
ZF8 = str(EXAMPLES / "zf_8hp70_8speed.toml")
C4 = str(EXAMPLES / "simpson_c4_3speed.toml")
runner = CliRunner()


def run(*args: str):
    return runner.invoke(app, list(args))


@pytest.mark.parametrize("gear", ["1", "3", "R"])
def test_analyze_a_transmission_without_operating_point_in_a_gear(gear):
    """`epicyclic analyze examples/zf_8hp70_8speed.toml --gear 3` was an error ("no
    [operating_point]") although `plot ... --gear 3` draws that gear: both now solve at the default operating point
    (1 1/min, 1 N·m), say so, and name the gear.  The ratio is the library's (published 2.1039 in 3rd)."""
    result = run("analyze", ZF8, "--gear", gear, "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["title"].endswith(f", gear {gear}")
    solution = report["solution"]
    assert solution["ratio"] == pytest.approx(build("zf_8hp70").ratio(gear), rel=1e-12)
    assert solution["shafts"]["in"]["speed"] == 1000.0 and solution["shafts"]["in"]["torque"] == 100.0  # default_point
    assert any("the default n_in" in w for w in solution["warnings"])


def test_analyze_a_transmission_without_operating_point_takes_its_first_gear():
    result = run("analyze", C4)
    assert result.exit_code == 0, result.output
    assert "Ford C4 three-speed automatic (Simpson gearset), gear 1" in result.stdout
    assert "the default n_in = 1000 1/min, T_in = 100 N·m" in result.stdout
    assert "2.45833" in result.stdout  # n_drive/n_load in 1st: (1 + 72/33)(...) = 2.4583, published 2.46


def test_explain_takes_a_gear_like_analyze_and_plot():
    """`explain` had no --gear: a transmission could only be explained in its operating point's gear."""
    result = run("explain", C4, "-g", "2")
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("Worked solution: Ford C4 three-speed automatic (Simpson gearset), gear 2")
    assert "brake 'intermediate': 'sun' – housing, engaged" in result.stdout
    assert "the default n_in = 1000 1/min" in result.stdout
    bad = run("explain", C4, "-g", "9")
    assert bad.exit_code == 2 and "no gear '9'" in bad.output


def test_a_file_with_neither_operating_point_nor_transmission_is_still_an_error(tmp_path):
    path = tmp_path / "set.toml"
    path.write_text((EXAMPLES / "brandenberger_1952.toml").read_text().split("[operating_point]")[0])
    result = run("analyze", str(path))
    assert result.exit_code == 2
    assert "[operating_point]" in result.output


@pytest.mark.parametrize("command, fmt", [("gears", "table"), ("gears", "json"), ("gears", "markdown"),
                                          ("explore", "table"), ("explore", "json"), ("analyze", "table"),
                                          ("analyze", "json")])
def test_written_files_are_what_the_command_prints_and_end_with_a_newline(tmp_path, command, fmt):
    """`gears`/`explore` with --out wrote files without a final newline (analyze's had one)."""
    out = tmp_path / f"report.{fmt}"
    printed = run(command, C4, "-f", fmt)
    written = run(command, C4, "-f", fmt, "-o", str(out))
    assert printed.exit_code == written.exit_code == 0, printed.output + written.output
    text = out.read_text(encoding="utf-8")
    assert text.endswith("\n") and not text.endswith("\n\n")
    if command != "explore":  # explore prints the time it took
        assert text == printed.stdout
