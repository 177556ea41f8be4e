"""Reading input files within limits (epicyclic.io.source)."""

from __future__ import annotations

import os
import threading
import time

import pytest

from epicyclic.io import InputFileError, load_train_file, loads_train_file, read_source
from epicyclic.io.source import parse_toml
from epicyclic.limits import MAX_FILE_BYTES, MAX_NESTING, MAX_TOML_VALUES

GOOD = """title = "t"
[[planetary]]
name = "P"
sun = "in"
ring = "ring"
carrier = "out"
stationary_ratio = -2
[[brake]]
name = "B"
shaft = "ring"
"""


def test_a_fifo_is_refused_without_opening_it(tmp_path):
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    outcome = []

    def read():
        try:
            read_source(fifo)
        except InputFileError as exc:
            outcome.append(str(exc))

    thread = threading.Thread(target=read, daemon=True)
    thread.start()
    thread.join(timeout=5)
    assert outcome and "FIFO" in outcome[0], "read_source blocked on a FIFO"


@pytest.mark.parametrize("device, word", [("/dev/zero", "device"), ("/dev/null", "device")])
def test_devices_are_refused(device, word):
    with pytest.raises(InputFileError, match=word):
        read_source(device)


def test_size_limit_default_environment_and_argument(tmp_path, monkeypatch):
    path = tmp_path / "t.toml"
    path.write_text(GOOD + "#" * (MAX_FILE_BYTES - len(GOOD) - 1) + "\n")
    assert read_source(path).startswith("title")  # exactly 1 MiB is read
    path.write_text(GOOD + "#" * MAX_FILE_BYTES)
    with pytest.raises(InputFileError, match=r"at most 1 MiB \(1,048,576 bytes\)"):
        read_source(path)
    monkeypatch.setenv("EPICYCLIC_MAX_FILE_BYTES", str(3 * MAX_FILE_BYTES))
    assert read_source(path).startswith("title")
    with pytest.raises(InputFileError, match="at most 100 bytes"):
        load_train_file(path, max_bytes=100)


def test_a_file_that_grows_past_its_stat_size_is_still_capped(tmp_path, monkeypatch):
    path = tmp_path / "t.toml"
    path.write_text("x" * 200)
    real_stat = os.stat

    def lying_stat(p, *args, **kwargs):  # like /proc files, which report size 0
        result = real_stat(p, *args, **kwargs)
        return os.stat_result((result.st_mode, *result[1:6], 0, *result[7:]))

    monkeypatch.setattr(os, "stat", lying_stat)
    with pytest.raises(InputFileError, match="larger than 100 bytes"):
        read_source(path, max_bytes=100)


def test_permission_denied_names_the_file(tmp_path, monkeypatch):
    path = tmp_path / "secret.toml"
    path.write_text(GOOD)

    def denied(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(os, "open", denied)
    with pytest.raises(InputFileError, match=r"secret.toml: cannot read the file \(Permission denied\)"):
        read_source(path)


def test_bom_crlf_and_utf8_are_read():
    text = "\ufeff" + GOOD.replace("\n", "\r\n").replace('"t"', '"Übersetzung ½"')
    assert loads_train_file(text).title == "Übersetzung ½"


def test_brackets_inside_strings_and_comments_do_not_count_as_nesting():
    deep = "[" * 100
    text = (f'description = "{deep}"\n# {deep}\n' f"x = '{deep}'\n" f'y = """\n{deep}\n"""\n'
            f"z = '''{deep}'''\n" 'w = "a \\" [[[[[[[[[[[[[[[[[[[[[[ b"\n')
    data = parse_toml(text, "t.toml")
    assert data["description"] == deep and data["y"] == deep + "\n"


def test_nesting_at_the_limit_is_read_and_one_more_is_refused():
    def arrays(depth):
        return "x = " + "[" * depth + "]" * depth

    parse_toml(arrays(MAX_NESTING), "t.toml")
    with pytest.raises(InputFileError, match=rf"line 1, key 'x': arrays and tables are nested more than {MAX_NESTING}"):
        parse_toml(arrays(MAX_NESTING + 1), "t.toml")


@pytest.mark.parametrize(
    "text, match",
    [
        ("a" + ".a" * 5000 + " = 1", "dotted key"),
        ('"a".' * 40 + '"a" = 1', "dotted key"),
        ("[" + "a." * 40 + "a]", "dotted key"),
        ("x = {" + "a." * 40 + "a = 1}", "dotted key"),
        ("".join(f"[{'.'.join(['t'] * k)}]\n" for k in range(1, MAX_NESTING + 3)), "more than 16 levels deep"),
        ("".join(f"[{'.'.join(['t'] * k)}]\n" for k in range(1, MAX_NESTING + 2)),
         r"key 't(\.t){16}': tables and arrays are nested more than 16"),
        ("x = [" + "1," * (MAX_TOML_VALUES + 1) + "]", "more than 20,000 keys and values"),
        ("k = 1\n" * (MAX_TOML_VALUES + 1), "more than 20,000"),
        ("x = " + "{a=" * 20_000, "nested more than"),
    ],
)
def test_hostile_toml_is_refused_quickly(text, match):
    start = time.monotonic()
    with pytest.raises(InputFileError, match=match):
        parse_toml(text, "t.toml")
    assert time.monotonic() - start < 2.0


@pytest.mark.parametrize(
    "text",
    ['"' * 1_000_000, "'" * 1_000_000, 'x = """' + '\\"' * 400_000, "x = '''" + "'" * 2 + "a" * 900_000,
     "#" * 1_000_000],
)
def test_unterminated_strings_and_quote_floods_take_linear_time(text):
    start = time.monotonic()
    with pytest.raises(InputFileError):
        loads_train_file(text, "t.toml")
    assert time.monotonic() - start < 3.0


def test_long_strings_and_keys_are_refused_with_their_key():
    with pytest.raises(InputFileError, match=r"key 'description': a string of 20,000 characters"):
        parse_toml('description = "' + "d" * 20_000 + '"', "t.toml")
    with pytest.raises(InputFileError, match=r"a key of 20,000 characters"):
        parse_toml("k" * 20_000 + " = 1", "t.toml")


# ---- any text: a train file or an InputFileError/EpicyclicError, at once, never another exception
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from epicyclic.errors import EpicyclicError  # noqa: E402

_TOML_PIECES = ["[", "]", "{", "}", "[[planetary]]", "[[brake]]", "name", "=", '"', "'", '"""', "'''", ".", ",",
                "\n", "\r\n", " ", "#", "sun", "ring", "carrier", "teeth", "1", "-2", "1e999", "nan", "inf", "x",
                "\\", "\\u001b", "housing", "stationary_ratio", "[operating_point]", "speeds", "drives", "\ufeff",
                "\x00", "true", "1979-05-27"]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(_TOML_PIECES), max_size=60).map("".join) | st.text(max_size=300))
def test_any_text_is_a_train_or_a_located_error(text):
    start = time.monotonic()
    try:
        loads_train_file(text, "t.toml")
    except EpicyclicError as exc:
        assert str(exc).startswith("t.toml:"), str(exc)
    assert time.monotonic() - start < 1.0
