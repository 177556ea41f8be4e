"""The bad-input corpus of the command line through the page: the same clear message, and the server keeps serving.

Every row of ``tests/cli/test_bad_input_corpus.py`` whose input is a file's
text (read by ``analyze``, ``explain``, ``gears`` or ``explore`` without
options) is sent as the editor's text (or uploaded, for raw bytes).  The page
must answer 422 within the corpus's time limit with one message that names
the file and contains the row's fragment, mark the line in the editor where
the message names a key or a line, execute nothing, and go on serving.
The rows of ``fit``, ``forces``, ``search`` and ``map`` go through the page's
forms of the same name: a bad file read by the form, or a bad option given in
the form's field for it (:data:`OPTION_FIELDS`); the message must contain the
row's fragment, with the option's name read as the field's label.  Options of
other commands have no counterpart in the page, except those of the pictures
(tests/web/test_pictures.py).
"""

from __future__ import annotations

import html
import re
import time

import pytest

from ..cli.test_bad_input_corpus import CORPUS, TIME_LIMIT_S, Bad

#: Rows the page answers differently, on purpose.
DIFFERENT = {
    # the page opens a train without operating point and asks for one in its form (no error)
    "no operating point": "the form asks for an operating point",
    "no operating point (explain)": "the form asks for an operating point",
    # a train without [transmission] is shown without a gear table
    "gears without a transmission": "no gear table",
    "explore without a transmission": "no gear table",
}


def _page_rows() -> list[Bad]:
    return [case for case in CORPUS
            if isinstance(case.file, (str, bytes)) and case.args == ("{file}",) and not case.env
            and case.command in ("analyze", "explain", "gears", "explore") and case.id not in DIFFERENT]


ROWS = _page_rows()


def test_the_page_takes_most_of_the_corpus():
    assert len(ROWS) >= 120


def _message(answer_text: str) -> str:
    found = re.findall(r'<p class="message"><strong>error:</strong> (.*?)</p>', answer_text, re.S)
    assert len(found) == 1, answer_text[:600]
    return html.unescape(found[0])


def _marked(answer_text: str) -> str:
    match = re.search(r'id="editor-status" class="editor-status" data-line="(\d*)"', answer_text)
    return match.group(1) if match else ""


@pytest.mark.parametrize("case", ROWS, ids=[case.id for case in ROWS])
def test_bad_input_through_the_page(client, page_form, case: Bad):
    start = time.monotonic()
    if isinstance(case.file, bytes):
        answer = client.post("/upload", files={"file": ("bad.toml", case.file)})
    else:
        answer = client.post("/apply/text", data=page_form(case.file, source="bad.toml"))
    elapsed = time.monotonic() - start
    assert answer.status_code == 422, (case.id, answer.status_code, answer.text[:400])
    message = _message(answer.text)
    assert message.startswith("bad.toml: ") and case.says in message, (case.id, message)
    assert "Traceback" not in answer.text and "\x1b" not in answer.text
    if isinstance(case.file, str) and re.search(r"key '|\(at line \d|: line \d", message):
        assert _marked(answer.text), (case.id, message)  # the editor marks the line the message names
    assert elapsed < TIME_LIMIT_S, (case.id, elapsed)


@pytest.mark.parametrize("case_id", sorted(DIFFERENT))
def test_rows_the_page_answers_differently_are_still_clear(client, page_form, case_id):
    case = next(c for c in CORPUS if c.id == case_id)
    answer = client.post("/apply/text", data=page_form(case.file, source="bad.toml"))
    assert answer.status_code == 200
    if "operating point" in DIFFERENT[case_id]:
        assert "The file has no operating point" in answer.text
    else:
        assert 'id="gears"' not in answer.text


#: Options of the commands with a form, and (field, what the page's message calls it).
OPTION_FIELDS = {
    "fit": {"--planets": ("planets", "planets"), "--min-clearance": ("min_clearance", "least tip clearance")},
    "forces": {},
    "search": {"--ratio": ("ratio", "target ratio"), "--tolerance": ("tolerance", "tolerance"),
               "--planets": ("planets", "planets"), "--sun": ("sun", "sun teeth"), "--ring": ("ring", "ring teeth"),
               "--module": ("module", "module")},
    "map": {"--speed": ("speed", "input speeds"), "--torque": ("torque", "input torques")},
}

#: Rows of those commands that the page's forms answer differently, on purpose.
FORM_DIFFERENT = {
    "fit without geometry or tooth counts": "the form offers only sets with tooth counts, and this file has none",
    "search without --ratio": "the form starts with a ratio",
    "map a transmission without a gear": "the form's gear field starts at the gear the page shows",
}

#: A file the search form is sent with (the search reads no file).
ANY_FILE = 'title = "t"\n[[planetary]]\nname = "P"\nsun = "s"\nring = "r"\ncarrier = "c"\nstationary_ratio = -2\n'


def _fields(case: Bad) -> dict[str, str] | None:
    """The form fields of a row's options, or None when an option has no field (--out, --format, --gear)."""
    options = OPTION_FIELDS[case.command]
    args = [a for a in case.args if a != "{file}"]
    if len(args) % 2 or any(a not in options for a in args[::2]):
        return None
    return {f"tool_{case.command}_{options[a][0]}": value for a, value in zip(args[::2], args[1::2])}


def _form_rows() -> list[Bad]:
    return [case for case in CORPUS
            if case.command in OPTION_FIELDS and isinstance(case.file, (str, type(None))) and not case.env
            and case.id not in FORM_DIFFERENT and _fields(case) is not None]


FORM_ROWS = _form_rows()


def test_the_forms_take_the_rows_of_their_commands():
    assert len(FORM_ROWS) >= 40
    assert {case.command for case in FORM_ROWS} == set(OPTION_FIELDS)


@pytest.mark.parametrize("case", FORM_ROWS, ids=[case.id for case in FORM_ROWS])
def test_bad_input_through_the_forms(client, page_form, case: Bad):
    start = time.monotonic()
    answer = client.post(f"/tool/{case.command}", data=page_form(case.file or ANY_FILE, source="bad.toml",
                                                                 **_fields(case)))
    elapsed = time.monotonic() - start
    assert answer.status_code == 422, (case.id, answer.status_code, answer.text[:400])
    message = _message(answer.text)
    option = OPTION_FIELDS[case.command].get(case.says)
    assert (option[1] if option else case.says) in message, (case.id, message)
    if not option and case.says not in ("exceed the limit",):  # about the file: named like the command line
        assert message.startswith("bad.toml: "), (case.id, message)
    assert "Traceback" not in answer.text and "\x1b" not in answer.text
    assert elapsed < TIME_LIMIT_S, (case.id, elapsed)


def test_the_server_keeps_serving_after_the_corpus(client):
    assert client.get("/healthz").text == "ok"
    assert client.post("/example", data={"example": "brandenberger_1952"}).status_code == 200
