"""Safe text at the edges (epicyclic.text) and what the commands print."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.text import markdown_text, short, terminal_text

HOSTILE = "Bild 10 \x1b[2J\x1b]0;pwned\x07 \u202eevil\u202c <script>alert(1)</script> | a|b"
TITLE = json.dumps(HOSTILE)  # a TOML basic string with escapes for the control characters
TRAIN = f"""title = {TITLE}
description = {TITLE}
[[planetary]]
name = "P<b>|1"
sun = "in"
ring = "ring"
carrier = "out"
stationary_ratio = -2
stationary_efficiency = 0.98
[[brake]]
name = "B"
shaft = "ring"
[[clutch]]
name = "C|<i>"
first = "in"
second = "ring"
engaged = false
[operating_point]
speeds = {{ in = 3000 }}
torques = {{ in = 10 }}
drives = ["in"]
loads = ["out"]
[transmission]
input = "in"
output = "out"
schedule = {{ "1" = ["B"], "2<x>|" = ["C|<i>"] }}
"""


def test_terminal_text_removes_controls_and_bidi_overrides_only():
    assert terminal_text(HOSTILE) == "Bild 10 [2J]0;pwned evil <script>alert(1)</script> | a|b"
    assert terminal_text("a\tb\nc ü ½ — η") == "a\tb\nc ü ½ — η"


def test_markdown_text_escapes_html_and_pipes():
    assert markdown_text("<script>x</script> | a&b\nc") == "&lt;script&gt;x&lt;/script&gt; \\| a&amp;b c"


def test_short_bounds_what_messages_quote():
    assert short("x" * 1000, 20) == "'" + "x" * 18 + "…"
    assert len(short(list(range(100_000)))) == 60


@pytest.fixture
def train(tmp_path):
    path = tmp_path / "t.toml"
    path.write_text(TRAIN, encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("args", [["analyze"], ["analyze", "-f", "json"], ["explain"], ["gears"],
                                  ["analyze", "-f", "html"], ["gears", "-f", "json"]])
def test_no_control_character_reaches_the_terminal(train, args):
    result = CliRunner().invoke(app, [args[0], train, *args[1:]])
    assert result.exit_code == 0, result.output
    assert not any(c in result.stdout for c in "\x1b\x07\u202e\u202c")
    if "json" in args:
        json.loads(result.stdout)  # still valid JSON


@pytest.mark.parametrize("args", [["analyze", "-f", "markdown"], ["explain", "-f", "markdown"],
                                  ["gears", "-f", "markdown"]])
def test_markdown_output_escapes_html_and_pipes(train, args):
    result = CliRunner().invoke(app, [args[0], train, *args[1:]])
    assert result.exit_code == 0, result.output
    assert "&lt;script&gt;" in result.stdout or args[0] == "gears"
    for line in result.stdout.splitlines():
        if line.startswith("    "):  # an indented code block shows its text literally
            continue
        assert not any(tag in line for tag in ("<script>", "<b>", "<i>", "<x>")), line


def test_markdown_table_rows_keep_their_column_count(train):
    text = CliRunner().invoke(app, ["analyze", train, "-f", "markdown"]).stdout
    for block in text.split("###")[1:]:
        rows = [line for line in block.splitlines() if line.startswith("|")]
        counts = {line.replace("\\|", "").count("|") for line in rows}
        assert len(counts) == 1, rows


def test_html_output_escapes_the_title(train):
    text = CliRunner().invoke(app, ["analyze", train, "-f", "html"]).stdout
    assert "<script>alert" not in text and "&lt;script&gt;" in text


def test_a_tex_like_title_is_drawn_as_text(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    path = tmp_path / "t.toml"
    path.write_text(TRAIN.replace(f"title = {TITLE}", 'title = "cost $\\\\frac{ 5 $x^"'), encoding="utf-8")
    result = CliRunner().invoke(app, ["plot", str(path), "-k", "power", "-o", str(tmp_path / "p.svg")])
    assert result.exit_code == 0, result.output
