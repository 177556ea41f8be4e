"""``epicyclic plot`` and ``epicyclic animate``: files written, exit code 2 on bad input."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

matplotlib.use("Agg")

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BRANDENBERGER = str(EXAMPLES / "brandenberger_1952.toml")
runner = CliRunner()


def run(*args: str):
    return runner.invoke(app, list(args))


@pytest.mark.parametrize("kind", ["speed", "torque", "power", "lever", "flow"])
def test_plot_writes_svg(kind, tmp_path):
    out = tmp_path / f"{kind}.svg"
    result = run("plot", BRANDENBERGER, "--kind", kind, "--out", str(out))
    assert result.exit_code == 0, result.output
    assert out.read_text().lstrip().startswith("<?xml") and "<svg" in out.read_text()


@pytest.mark.parametrize("suffix, magic", [(".png", b"\x89PNG"), (".pdf", b"%PDF")])
def test_plot_png_and_pdf(suffix, magic, tmp_path):
    out = tmp_path / f"power{suffix}"
    result = run("plot", BRANDENBERGER, "-k", "power", "-o", str(out), "--dpi", "40")
    assert result.exit_code == 0, result.output
    assert out.read_bytes().startswith(magic)


def test_lever_of_a_transmission_without_operating_point(tmp_path):
    # A transmission file plots as it is: the default operating point, said on the figure.
    out = tmp_path / "lever.svg"
    result = run("plot", str(EXAMPLES / "simpson_c4_3speed.toml"), "-k", "lever", "--gear", "1", "-o", str(out))
    assert result.exit_code == 0, result.output
    text = out.read_text()
    assert "compound lever" in text and "gear 1: forward + low_reverse engaged" in text
    assert "the default n_in = 1000 1/min, T_in = 100 N·m" in text


@pytest.mark.parametrize("kind", ["speed", "torque", "power", "lever", "flow", "chart"])
def test_every_kind_of_a_transmission_in_a_gear(kind, tmp_path):
    out = tmp_path / f"{kind}.svg"
    result = run("plot", str(EXAMPLES / "zf_8hp70_8speed.toml"), "-k", kind, "--gear", "3", "-o", str(out))
    assert result.exit_code == 0, result.output
    assert "gear 3" in out.read_text()


def test_a_file_with_nothing_to_solve_is_bad_input(tmp_path):
    train = tmp_path / "t.toml"
    train.write_text('[[planetary]]\nname = "P"\nsun = "s"\nring = "r"\ncarrier = "c"\nstationary_ratio = -2\n')
    result = run("plot", str(train), "-o", str(tmp_path / "x.svg"))
    assert result.exit_code == 2
    assert "no [operating_point] table and no [transmission] table" in " ".join(result.output.split())


def test_animation_size(tmp_path):
    out = tmp_path / "a.svg"
    result = run("animate", str(EXAMPLES / "zf_8hp70_8speed.toml"), "--gear", "2", "--element", "P4", "--size", "300",
                 "-o", str(out))
    assert result.exit_code == 0, result.output
    text = out.read_text()
    assert 'width="300"' in text and "schematic simple set" in text and "gear 2" in text


def test_animate_html_and_gif(tmp_path):
    html = tmp_path / "a.html"
    result = run("animate", BRANDENBERGER, "--willis", "--out", str(html))
    assert result.exit_code == 0, result.output
    text = html.read_text()
    assert text.startswith("<!DOCTYPE html>") and "animateTransform" in text and "Willis" in text
    gif = tmp_path / "a.gif"
    result = run("animate", BRANDENBERGER, "--out", str(gif), "--frames", "3")
    assert result.exit_code == 0, result.output
    assert gif.read_bytes()[:6] == b"GIF89a"


@pytest.mark.parametrize("args, message", [
    (["plot", BRANDENBERGER, "--out", "x.txt"], "suffix '.txt'; expected one of .svg, .png, .pdf"),
    (["animate", BRANDENBERGER, "--out", "x.mp4"], "suffix '.mp4'; expected one of .svg, .html, .gif"),
    (["animate", BRANDENBERGER, "--element", "nope"], "no planetary set named 'nope'"),
    (["plot", str(EXAMPLES / "zf_8hp70_8speed.toml"), "--gear", "9"], "no gear '9' in the \\[transmission\\] schedule; gears are '1', '2'"),
    (["plot", str(EXAMPLES / "brandenberger_1952.toml"), "-k", "chart"], "speed chart shows every gear"),
    (["animate", BRANDENBERGER, "--size", "50"], "--size"),
    (["plot", "missing.toml"], "no such file"),
    (["plot", BRANDENBERGER, "--gear", "2"], "needs a \\[transmission\\] table"),
])
def test_bad_input_exits_2_with_one_paragraph(args, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = run(*args)
    assert result.exit_code == 2
    assert "Traceback" not in result.output
    import re

    assert re.search(message, result.output.replace("\n", " "))
    assert list(tmp_path.iterdir()) == []  # nothing written
