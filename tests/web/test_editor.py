"""Load errors at their key and line: the loader's real messages, located in the text."""

from __future__ import annotations

import pytest

from epicyclic.io import loads_train_file
from epicyclic.web.editor import locate, problem
from epicyclic.web.examples import bundled_examples

BASE = bundled_examples()["brandenberger_1952"].text


@pytest.mark.parametrize("old, new, expected", [
    ("title =", "titel =", 'titel = "Brandenberger 1952, Bild 10"'),
    ("sun = 50,", "sun = 0,", "teeth = { kind"),
    ("stationary_efficiency = 0.9", "stationary_efficiency = 1.9", "stationary_efficiency = 1.9"),
    ("efficiency = 0.9              #", "efficiency = 2              #", "efficiency = 2 "),
    ('loads = ["I"]', 'loads = ["IV"]', 'loads = ["IV"]'),
    ('"1500 U/min"', '"1500 kg"', "speeds = { II ="),
    ('torque = "kp*cm"', 'torque = "furlong"', 'torque = "furlong"'),
    ('first = "III"', 'frist = "III"', 'frist = "III"'),
    ('carrier = "III"    # system III: the Steg\n', "", "[[planetary]]"),
    ('name = "stage"', 'name = "stage"\nname = "again"', 'name = "again"'),  # TOML error: (at line N)
])
def test_the_loaders_messages_point_at_the_changed_line(old, new, expected):
    text = BASE.replace(old, new)
    assert text != BASE
    with pytest.raises(Exception) as info:
        loads_train_file(text, "b.toml")
    found = problem(text, str(info.value))
    assert found.line is not None, str(info.value)
    assert text.splitlines()[found.line - 1].startswith(expected), (str(info.value), found.line)
    assert [here for _, _, here in found.excerpt].count(True) == 1


def test_solver_errors_point_at_the_operating_point():
    text = BASE.replace('speeds = { II = "1500 U/min" }', "")
    with pytest.raises(Exception) as info:
        loads_train_file(text, "b.toml").solve()
    line = locate(text, str(info.value), fallback="operating_point")
    assert line is not None and line >= text.splitlines().index("[operating_point]") + 1  # in that table
    assert locate("title = 't'\n[operating_point]\n", "the speed is still free", "operating_point") == 2


def test_multi_line_arrays_are_not_headers():
    text = 'title = "t"\n[[gear]]\nname = "g"\nmeshes = [\n  [40, 44],\n]\nratio = 2\n'
    assert locate(text, "f: [[gear]] #1 'g': key 'ratio': give either") == 7


def test_line_named_by_the_message():
    assert locate("a = [[[]]]\n", "f.toml: line 1, key 'a': arrays and tables are nested too deep") == 1


def test_no_place_no_line():
    assert problem("a = 1\n", "something went wrong").line is None
