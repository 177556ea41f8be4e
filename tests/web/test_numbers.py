"""The page's numbers are the command line's: the gear table against ``epicyclic gears`` for every bundled
example with a transmission, the default operating point, circulating power below the threshold."""

from __future__ import annotations

import html
import re

import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.io import loads_train_file
from epicyclic.web.examples import bundled_examples

GEARBOXES = sorted(k for k, e in bundled_examples().items() if loads_train_file(e.train_text()).transmission is not None)


def page_gear_rows(answer: str) -> list[list[str]]:
    """The gear table of a page answer, as lists of cell texts."""
    table = re.search(r'<table class="gear-table">.*?<tbody>(.*?)</tbody>', answer, re.S)
    assert table, "no gear table in the answer"
    return [[html.unescape(c.strip()) for c in re.findall(r"<td[^>]*>(.*?)</td>", row, re.S)]
            for row in re.findall(r"<tr data-gear.*?</tr>", table.group(1), re.S)]


def cli_gear_rows(path) -> list[list[str]]:
    """The rows of ``epicyclic gears FILE`` (text table: columns separated by two or more spaces)."""
    result = CliRunner().invoke(app, ["gears", str(path)])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    rule = next(k for k, line in enumerate(lines) if line.startswith("----"))
    widths = [len(part) for part in lines[rule].split("  ")]
    rows = []
    for line in lines[rule + 1:]:
        if line.startswith("spread"):
            break
        cells, start = [], 0
        for width in widths:
            cells.append(line[start:start + width].strip())
            start += width + 2
        rows.append(cells)
    return rows


def test_there_are_gearboxes_with_and_without_loss_models():
    with_losses = [k for k in GEARBOXES if loads_train_file(bundled_examples()[k].text).losses]
    assert with_losses and len(with_losses) < len(GEARBOXES)  # the comparison below covers both kinds


@pytest.mark.parametrize("key", GEARBOXES)
def test_the_gear_table_is_the_command_lines(client, examples, key, tmp_path):
    path = tmp_path / examples[key].file_name
    path.write_text(examples[key].text, encoding="utf-8")
    answer = client.post("/example", data={"example": key})
    assert answer.status_code == 200, answer.text[:400]
    assert page_gear_rows(answer.text) == cli_gear_rows(path)


def test_the_8hp_with_loss_models_has_no_lossless_gear(client):
    """The page showed η = 1.0000 in every gear of a file whose losses come from its geometry."""
    rows = page_gear_rows(client.post("/example", data={"example": "zf_8hp70_geometry"}).text)
    assert all(float(row[4]) < 0.9999 for row in rows if row[0] != "6")  # 6th is direct drive: nothing rolls


def test_a_transmission_without_operating_point_is_shown_at_the_stated_default(client):
    answer = client.post("/example", data={"example": "zf_8hp70_8speed"}).text
    assert "the default operating point" in answer and "driven at 1000 1/min with 100 N·m" in answer
    assert 'value="1000 1/min"' in answer and 'value="100 N*m"' in answer  # the form says the same
    power = re.search(r'id="input-power">([^<]*)<', answer).group(1)
    assert power.split()[0] == "10472"  # 100 N·m × 1000·2π/60 1/s = 10 472 W


def test_circulating_power_below_the_threshold_is_none(client, page_form, examples):
    """8th gear of the 8HP with loss models: 4 W of 41.9 kW went round a loop ("loads the teeth")."""
    from epicyclic.results.circulation import CIRCULATION_THRESHOLD

    text = examples["zf_8hp70_geometry"].text.replace('gear = "1"', 'gear = "8"')
    solution = loads_train_file(text).solve()
    assert solution.circulation.loops == () and CIRCULATION_THRESHOLD == 1e-3
    assert not any("power circulates" in w for w in solution.warnings)
    answer = client.post("/apply/text", data=page_form(text)).text
    assert re.search(r'id="circulating">none<', answer)
    assert "loads the teeth" not in answer


def test_a_map_with_one_speed_says_the_speed_not_one_values(client, page_form, examples):
    text = examples["geometry_simple_set"].text
    answer = client.post("/tool/map", data=page_form(text, tool_map_speed="1000..1000:1", tool_map_torque="10..50:5"))
    assert answer.status_code == 200, answer.text[:300]
    assert "(1 values)" not in answer.text and "input speed 1000 1/min, input torque 10..50 N*m (5 values)" in answer.text


def test_a_slow_set_is_shown_sped_up_not_slowed_down_below_one():
    """A set turning slower than the animation's loop is sped up: "sped up 15×", not "slowed down 0.0667×"."""
    from epicyclic import solve
    from epicyclic.demo import brandenberger_1952
    from epicyclic.plotting import planetary_animation

    from dataclasses import replace

    train, point = brandenberger_1952()
    slow = replace(point, speeds={k: v / 1e4 for k, v in point.speeds.items()})
    animation = planetary_animation(solve(train, slow), frames=48, fps=16)
    assert animation.slowdown < 1 and "sped up" in animation.pace and "slowed down" not in repr(animation)
    fast = planetary_animation(solve(train, point), frames=48, fps=16)
    assert fast.slowdown > 1 and fast.pace.startswith("slowed down")
