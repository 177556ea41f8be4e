"""The ``epicyclic`` command: analyze, modes, explain; exit codes 0 / 2 / 1."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BRANDENBERGER = str(EXAMPLES / "brandenberger_1952.toml")
runner = CliRunner()

GOOD = """
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
teeth = { sun = 30, planet = 24, ring = 78 }
stationary_efficiency = 0.98

[[brake]]
name = "B"
shaft = "ring"

[operating_point]
speeds = { in = 3000 }
torques = { in = 10 }
drives = ["in"]
loads = ["out"]
"""


def run(*args: str):
    return runner.invoke(app, list(args))


def test_analyze_json_reproduces_brandenberger_in_original_units():
    # Brandenberger 1952, Beispiel zu Bild 10: n1 = 2740 U/min, η' = 0.85, N1' = 2.55 PS,
    # M_An' = 143.24 cm kg (kp·cm), n3 = 5280 U/min; compared to the printed digits.
    result = run("analyze", BRANDENBERGER, "--format", "json")
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["schema"] == "epicyclic-report/3"  # bumped for the "geometry" section (issue 14)
    assert report["units"] == {"speed": "U/min", "torque": "kp*cm", "power": "PS"}
    sol = report["solution"]
    assert round(sol["shafts"]["I"]["speed"]) == 2740
    assert round(sol["shafts"]["III"]["speed"]) == 5280
    assert round(sol["efficiency"], 2) == 0.85
    assert round(sol["output_power"], 2) == 2.55
    assert round(sol["shafts"]["II"]["torque"], 2) == 143.24
    assert round(report["ideal"]["output_power"], 2) == 3.0


@pytest.mark.parametrize("fmt, marker", [("table", "efficiency"), ("markdown", "| shaft |"),
                                         ("html", "<!DOCTYPE html>")])
def test_analyze_formats(fmt, marker):
    result = run("analyze", BRANDENBERGER, "--format", fmt)
    assert result.exit_code == 0, result.output
    assert marker in result.stdout


def test_analyze_out_writes_a_file(tmp_path):
    target = tmp_path / "deep" / "report.html"
    result = run("analyze", BRANDENBERGER, "-f", "html", "--out", str(target))
    assert result.exit_code == 0, result.output
    assert "wrote" in result.stdout and target.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")


def test_analyze_in_a_gear(tmp_path):
    path = tmp_path / "t.toml"
    path.write_text(GOOD.replace("[operating_point]", """[[clutch]]
name = "C"
first = "in"
second = "ring"
engaged = false

[transmission]
input = "in"
output = "out"
schedule = { low = ["B"], direct = ["C"] }

[operating_point]"""), encoding="utf-8")
    low = json.loads(run("analyze", str(path), "-f", "json", "--gear", "low").stdout)
    direct = json.loads(run("analyze", str(path), "-f", "json", "--gear", "direct").stdout)
    assert low["solution"]["ratio"] == pytest.approx(3.6) and direct["solution"]["ratio"] == pytest.approx(1.0)
    bad = run("analyze", str(path), "--gear", "7")
    assert bad.exit_code == 2 and "no gear '7'" in bad.stderr


def test_explain_shows_equation_7_with_numbers():
    # Brandenberger 1952, eq. (7): M1'(n1 − n3)η1η2 + M2'(n2 − n3) = 0, here with η0 = η1η2 = 0.9 and
    # n1 = 2739.84, n3 = 5280, n2 = 1500 U/min, M1' = −66.6, M2' = +40.3 kp·cm (our signs: speeds positive).
    result = run("explain", BRANDENBERGER)
    assert result.exit_code == 0, result.output
    text = result.stdout
    assert "M1'·(n1 − n3)·η0 + M2'·(n2 − n3) = 0" in text
    assert "(-66.6084)·(2739.84 − 5280)·0.9 + 40.2848·(1500 − 5280)" in text
    assert "Brandenberger eq. 7" in text
    assert "efficiency η = P_out/P_in = 2.54813 / 3 = 0.8494" in text


def test_explain_in_german():
    result = run("explain", BRANDENBERGER, "--lang", "de")
    assert result.exit_code == 0, result.output
    for term in ("Steg", "erstes Zentralrad", "zweites Zentralrad",  # two suns: first/second central gear
                 "Standübersetzung", "Wälzleistung", "Kupplungsleistung",
                 "Wirkungsgrad", "Brandenberger Gl. 7"):
        assert term in result.stdout
    markdown = run("explain", BRANDENBERGER, "--format", "markdown")
    assert markdown.stdout.startswith("# Worked solution")


def test_modes_table_and_json():
    # Queitsch Tafel 1 with s = −78/30; Brandenberger 1952, eq. 7: ring held, sun → carrier η = (1 − i0 η0)/(1 − i0).
    result = run("modes", "--sun", "30", "--ring", "78", "--eta0", "0.98", "-f", "json")
    assert result.exit_code == 0, result.output
    modes = {m["label"]: m for m in json.loads(result.stdout)["modes"]}
    assert len(modes) == 7
    assert modes["VI"]["ratio"] == pytest.approx(3.6)
    assert modes["VI"]["efficiency"] == pytest.approx((1 + 2.6 * 0.98) / 3.6, rel=1e-9)
    table = run("modes", "--sun", "30", "--ring", "78")
    assert table.exit_code == 0 and "Tafel 1" in table.stdout
    md = run("modes", "--i0", "51/50", "--eta0", "0.95", "-f", "markdown")
    assert md.exit_code == 0 and "self-locking" in md.stdout and "0.2714" in md.stdout


@pytest.mark.parametrize(
    "extra",
    [["--kind", "double", "--planet-sun", "18", "--planet-ring", "18"],
     ["--kind", "stepped", "--planet-sun", "24", "--planet-ring", "30", "--external-ring"]],
)
def test_modes_plus_sets(extra):
    result = run("modes", "--sun", "50", "--ring", "42" if "--external-ring" in extra else "90", *extra,
                 "--eta0", "0.9", "-f", "json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["stationary_ratio"] > 0


@pytest.mark.parametrize("command", [[], ["analyze"], ["modes"], ["explain"]])
def test_help_everywhere(command):
    result = run(*command, "--help")
    assert result.exit_code == 0 and "Usage" in result.stdout


def _commands():
    import typer.main

    group = typer.main.get_command(app)
    return sorted(group.commands.items())


@pytest.mark.parametrize("name, command", _commands(), ids=lambda v: v if isinstance(v, str) else "")
def test_help_prints_every_table_name_as_written(name, command):
    # Issue 30: rich markup read "[rating]" as a style tag, so `rate --help` said "with  and geometry tables".
    import re

    texts = [command.help or ""] + [getattr(p, "help", None) or "" for p in command.params]
    named = {m for text in texts for m in re.findall(r"\[[a-z_.]+\]", text)}
    result = run(name, "--help")
    assert result.exit_code == 0, result.output
    shown = " ".join(result.stdout.split())
    missing = sorted(t for t in named if t not in shown)
    assert not missing, f"{name} --help drops {missing}"
    assert "\\[" not in shown


def test_shell_completion_is_offered():
    assert "--install-completion" in run("--help").stdout


# ------------------------------------------------------------------- bad input → exit 2
def _file(tmp_path: Path, text: str) -> str:
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    return str(path)


BAD_FILES = [
    ("malformed TOML", "title = ", "not valid TOML"),
    ("unknown top-level key", "colour = 'red'\n" + GOOD, "unknown key 'colour'"),
    ("unknown element key", GOOD.replace("planets", "x").replace('name = "P"', 'name = "P"\nplanetz = 3'),
     "unknown key 'planetz'"),
    ("unknown shaft", GOOD.replace("speeds = { in = 3000 }", "speeds = { inn = 3000 }"), "unknown shaft 'inn'"),
    ("wrong unit", GOOD.replace("torques = { in = 10 }", "powers = { in = '3 m' }"), "'3 m' is not a power"),
    ("unreadable unit", GOOD.replace("torques = { in = 10 }", "powers = { in = '3 PZ' }"), "cannot read '3 PZ'"),
    ("impossible teeth", GOOD.replace("planet = 24", "planet = 10"), "cannot mesh coaxially"),
    ("ring smaller than sun", GOOD.replace("ring = 78", "ring = 20"), "more teeth than the sun"),
    ("underdetermined train", GOOD.replace('[[brake]]\nname = "B"\nshaft = "ring"\n', ""), "speed"),
    ("contradictory speeds", GOOD.replace("speeds = { in = 3000 }", "speeds = { in = 3000, ring = 5 }"),
     "ring"),
    ("efficiency above 1", GOOD.replace("0.98", "1.5"), r"efficiency in (0, 1]"),
    ("efficiency zero", GOOD.replace("0.98", "0"), r"efficiency in (0, 1]"),
    ("bad expression", GOOD.replace("teeth = { sun = 30, planet = 24, ring = 78 }", "stationary_ratio = '(24/50'"),
     "not a valid arithmetic expression"),
    ("unsafe expression", GOOD.replace("teeth = { sun = 30, planet = 24, ring = 78 }",
                                       "stationary_ratio = \"__import__('os')\""), "found a function call"),
    ("teeth and ratio", GOOD.replace("stationary_efficiency", "stationary_ratio = -2\nstationary_efficiency"),
     "not both"),
    ("no operating point", GOOD.split("[operating_point]")[0], "no [operating_point]"),
    ("drive and load", GOOD.replace('loads = ["out"]', 'loads = ["in"]'), "both as drive and as load"),
    ("power on a held shaft", GOOD.replace('loads = ["out"]', 'loads = ["out"]\npowers = { ring = 5 }')
     .replace("torques = { in = 10 }", "torques = { out = -30 }"), "ring"),
    ("brake on the housing", GOOD.replace('shaft = "ring"', 'shaft = "housing"'), "housing"),
    ("no elements", "title = 'empty'", "describes no element"),
    ("duplicate names", GOOD.replace('name = "B"', 'name = "P"'), "used twice"),
    ("array instead of table", GOOD.replace("[operating_point]", "operating_point = [1]\n[x]"), "unknown key 'x'"),
]


@pytest.mark.parametrize("label, text, needle", BAD_FILES, ids=[b[0] for b in BAD_FILES])
@pytest.mark.parametrize("command", ["analyze", "explain"])
def test_bad_input_exits_2_with_a_message(tmp_path, label, text, needle, command):
    result = run(command, _file(tmp_path, text))
    assert result.exit_code == 2, (label, result.output)
    assert needle in result.stderr, (label, result.stderr)
    assert result.stderr.startswith("error: ")
    assert "Traceback" not in result.output


def test_bad_command_line_values_exit_2(tmp_path):
    missing = run("analyze", str(tmp_path / "missing.toml"))
    assert missing.exit_code == 2 and "no such file" in missing.stderr
    assert run("analyze", BRANDENBERGER, "--format", "xml").exit_code == 2
    assert run("explain", BRANDENBERGER, "--lang", "fr").exit_code == 2
    for args, needle in [
        (["modes"], "give --sun and --ring"),
        (["modes", "--sun", "30", "--ring", "78", "--eta0", "1.5"], "(0, 1]"),
        (["modes", "--sun", "30", "--ring", "78", "--i0", "2"], "not both"),
        (["modes", "--i0", "1"], "must not be 0 or 1"),
        (["modes", "--i0", "os.system"], "found an attribute"),
        (["modes", "--sun", "30", "--ring", "77"], "odd"),
        (["modes", "--sun", "30", "--ring", "78", "--kind", "double"], "needs --planet-sun"),
        (["modes", "--sun", "30", "--ring", "78", "--planet-sun", "20"], "for --kind double or stepped"),
    ]:
        result = run(*args)
        assert result.exit_code == 2, (args, result.output)
        assert needle in result.stderr, (args, result.stderr)


def test_out_into_an_unwritable_place_exits_2(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = run("analyze", BRANDENBERGER, "--out", str(blocker / "sub" / "r.txt"))
    assert result.exit_code == 2 and result.stderr.startswith("error:")


def test_internal_error_exits_1(monkeypatch):
    import epicyclic.io.toml_format as toml_format

    def broken(self, *, lossless=False):
        raise RuntimeError("boom")

    monkeypatch.setattr(toml_format.TrainFile, "solve", broken)
    monkeypatch.delenv("EPICYCLIC_DEBUG", raising=False)
    result = run("analyze", BRANDENBERGER)
    assert result.exit_code == 1
    assert "internal error: RuntimeError: boom" in result.stderr and "Traceback" not in result.output


def test_version_option_prints_the_package_version_and_exits_0():
    from epicyclic import __version__

    result = run("--version")
    assert result.exit_code == 0, result.output
    assert result.stdout.strip() == f"epicyclic {__version__}"


def test_set_overrides_a_file_value():
    result = run("analyze", BRANDENBERGER, "--format", "json", "--set", 'operating_point.speeds.II="3000 U/min"')
    assert result.exit_code == 0, result.output
    assert round(json.loads(result.stdout)["solution"]["shafts"]["I"]["speed"]) == 5480


@pytest.mark.parametrize("command", ["analyze", "explain", "plot", "animate"])
def test_set_with_a_bad_value_exits_2_naming_file_and_key(command, tmp_path):
    out = ["--out", str(tmp_path / ("x.png" if command == "plot" else "x.html"))] if command in ("plot", "animate") \
        else []
    result = run(command, BRANDENBERGER, *out, "--set", "operating_point.speeds.II=fast")
    assert result.exit_code == 2
    assert "brandenberger_1952.toml" in result.stderr and "speeds.II" in result.stderr
    assert "Traceback" not in result.output


@pytest.mark.parametrize("command", ["gears", "explore"])
def test_set_on_transmission_commands(command):
    zf = str(EXAMPLES / "zf_8hp70_8speed.toml")
    result = run(command, zf, "--set", "brake.nope.engaged=true")
    assert result.exit_code == 2 and "no [[brake]] named 'nope'" in result.stderr
    assert run(command, zf, "--set", "planetary.P1.stationary_efficiency=0.9").exit_code == 0


def test_serve_passes_the_synthesis_limits_to_the_page(monkeypatch):
    """``serve --synthesis-architectures/--synthesis-seconds`` set the Synthesis tab's bound and time limit."""
    import uvicorn

    served = {}
    monkeypatch.setattr(uvicorn, "run", lambda app_, **kw: served.update(app=app_, **kw))
    result = runner.invoke(app, ["serve", "--port", "8765", "--synthesis-architectures", "5000000",
                                 "--synthesis-seconds", "300"])
    assert result.exit_code == 0, result.output
    limits = served["app"].state.limits
    assert (limits.synthesis_architectures, limits.synthesis_seconds) == (5_000_000, 300.0)
    assert served["port"] == 8765
