"""What the page sends: the TOML text, the operating-point form and the reader's choices.

The TOML text in the editor is the one source of truth.  The operating-point
form is a structured editor of its ``[operating_point]`` table: when the form
changes, :func:`write_operating_point` writes the form into the text (with
:mod:`tomlkit`, which keeps the rest of the file, comments included) and the
text is read again with :func:`epicyclic.io.loads_train_file`, so the page
reports bad values with the same messages as the command line.

Everything here is plain data (frozen dataclasses of strings) so that it can
be sent to a worker process.

Examples
--------
>>> text = '''[[planetary]]
... name = "P"
... sun = "s"
... ring = "r"
... carrier = "c"
... stationary_ratio = -2
... [[brake]]
... name = "B"
... shaft = "r"
... '''
>>> rows = (ShaftRow("s", "drive", "1500", "torque", "10 N*m"), ShaftRow("c", "load"))
>>> print(write_operating_point(text, rows, gear=""))  # doctest: +ELLIPSIS
[[planetary]]
...
[operating_point]
speeds = {s = 1500}
torques = {s = "10 N*m"}
drives = ["s"]
loads = ["c"]
<BLANKLINE>
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from ..errors import EpicyclicError
from ..limits import MAX_SHAFTS
from ..text import terminal_text

__all__ = ["FormError", "PageState", "ShaftRow", "UNIT_CHOICES", "UNIT_PRESETS", "LANGUAGES", "MOMENTS", "ROLES",
           "EOLS", "clean_text", "operating_rows", "default_operating_rows", "write_operating_point",
           "write_operating_points", "units_of"]

#: The units selector beside the file's ``[units]``: (speed, torque, power) of each choice, any unit that
#: :class:`epicyclic.units.Units` reads (rpm, hp and SI prefixes included).
UNIT_PRESETS: dict[str, tuple[str, str, str]] = {
    "si": ("1/min", "N*m", "W"),
    "kw": ("1/min", "N*m", "kW"),
    "rpm-kw": ("rpm", "N*m", "kW"),
    "rpm-hp": ("rpm", "lbf*ft", "hp"),
    "rads-kw": ("rad/s", "N*m", "kW"),
    "mw": ("1/min", "kN*m", "MW"),
}
#: Choices of the units selector: the file's ``[units]`` or one of :data:`UNIT_PRESETS`.
UNIT_CHOICES = ("file", *UNIT_PRESETS)
#: Line endings of the file that is open (the TOML download is written with them).
EOLS = ("lf", "crlf")
#: Languages of ``explain``.
LANGUAGES = ("en", "de")
#: Roles a shaft can have in the form ("" = neither drive nor load).
ROLES = ("", "drive", "load")
#: What the second value of a row is.
MOMENTS = ("torque", "power")
#: At most this many shaft rows (a train's shafts, :data:`epicyclic.limits.MAX_SHAFTS`), characters per
#: value (longer than any value the loader accepts, so that it gives its own message) and of a name.
MAX_ROWS, MAX_VALUE, MAX_NAME = MAX_SHAFTS, 1000, 200


class FormError(EpicyclicError, ValueError):
    """A form field the page did not send as expected (a hand-made request)."""


def clean_text(value: object, field_name: str, limit: int, *, single_line: bool = True) -> str:
    """A form value as text: at most ``limit`` characters, no control characters in one-line fields.

    Raises
    ------
    FormError
        Too long or not text.
    """
    if value is None:
        return ""
    if not isinstance(value, str):
        raise FormError(f"form field {field_name!r}: expected text, got a file or other data.")
    if len(value) > limit:
        raise FormError(f"form field {field_name!r}: {len(value)} characters, at most {limit} allowed.")
    if single_line:  # one rule for control characters: the command line's (epicyclic.text)
        value = terminal_text(value.replace("\t", " ").replace("\n", " ")).strip()
    return value


@dataclass(frozen=True)
class ShaftRow:
    """One row of the operating-point form: a shaft, its role, its speed and a torque or power.

    Values are the text the user typed: a plain number (in the file's unit)
    or a number with a unit (``"1500 rpm"``); empty means "not given".
    """

    shaft: str
    role: str = ""
    speed: str = ""
    moment: str = "torque"
    value: str = ""

    def __post_init__(self) -> None:
        if self.role not in ROLES:
            raise FormError(f"operating point form: role of shaft {self.shaft!r} must be one of "
                            f"{', '.join(repr(r) for r in ROLES)}, got {self.role!r}.")
        if self.moment not in MOMENTS:
            raise FormError(f"operating point form: shaft {self.shaft!r}: expected 'torque' or 'power', "
                            f"got {self.moment!r}.")


@dataclass(frozen=True)
class PageState:
    """Everything one request of the page carries.

    Parameters
    ----------
    text : str
        The TOML train description in the editor.
    source : str
        Its name for messages (an example's file name, an uploaded file's name
        or ``"editor"``); never used as a path.
    rows : tuple of ShaftRow
        The operating-point form (used when the form was changed).
    gear : str
        The gear of a transmission ("" for none).
    units : {"file", "si", "kw", "rpm-kw", "rpm-hp", "rads-kw", "mw"}
        The file's ``[units]`` or a preset of :data:`UNIT_PRESETS`.
    lang : {"en", "de"}
    eol : {"lf", "crlf"}
        The line endings of the file as opened, kept in the TOML download.
    extra : mapping of str to str
        The fields of the geometry forms (``tool_<tool>_<field>``) and of the
        pictures (``fig_<kind>_<setting>``).
    """

    text: str
    source: str = "editor"
    rows: tuple[ShaftRow, ...] = ()
    gear: str = ""
    units: str = "file"
    lang: str = "en"
    extra: Mapping[str, str] = field(default_factory=dict)
    eol: str = "lf"

    def __post_init__(self) -> None:
        if self.eol not in EOLS:
            raise FormError(f"line endings must be one of {', '.join(EOLS)}, got {self.eol!r}.")
        if self.units not in UNIT_CHOICES:
            raise FormError(f"units must be one of {', '.join(UNIT_CHOICES)}, got {self.units!r}.")
        if self.lang not in LANGUAGES:
            raise FormError(f"language must be one of {', '.join(LANGUAGES)}, got {self.lang!r}.")

    @classmethod
    def from_form(cls, form: Any, *, max_text: int) -> PageState:
        """Read the page's form (a Starlette ``FormData`` or any mapping with ``getlist``).

        Raises
        ------
        FormError
            A field that is too long, a wrong count of row fields, an unknown choice.
        """
        def one(name: str, default: str = "", limit: int = MAX_VALUE) -> str:
            return clean_text(form.get(name, default), name, limit) or default

        columns = {name: [clean_text(v, name, MAX_VALUE) for v in form.getlist(name)]
                   for name in ("shaft", "role", "speed", "moment", "value")}
        count = len(columns["shaft"])
        if count > MAX_ROWS:
            raise FormError(f"operating point form: {count} shafts, at most {MAX_ROWS}.")
        if any(len(v) != count for v in columns.values()):
            raise FormError("operating point form: every shaft row needs shaft, role, speed, moment and value.")
        rows = tuple(ShaftRow(*values) for values in zip(*columns.values()))
        extra = {k: clean_text(v, k, MAX_VALUE) for k, v in form.multi_items()
                 if k.startswith(("tool_", "fig_"))}
        return cls(
            text=clean_text(form.get("toml", ""), "toml", max_text, single_line=False),
            source=one("source", "editor", MAX_NAME),
            rows=rows,
            gear=one("gear"),
            units=one("units", "file"),
            lang=one("lang", "en"),
            extra=extra,
            eol=one("eol", "lf"),
        )


def units_of(choice: str, file_units: Any) -> Any:
    """The :class:`~epicyclic.units.Units` the page shows for the selector's ``choice``."""
    from ..units import Units

    return file_units if choice == "file" else Units(*UNIT_PRESETS[choice])


def restored_state(query: Mapping[str, str]) -> dict[str, Any]:
    """What the page's address holds (a reload or a shared link): gear, operating-point rows, tab, units and
    language, read as form values are (too long, unknown or malformed parts are left out, never an error).

    ``op`` is JSON: a list of ``[shaft, role, speed, moment, value]`` rows.
    """
    import json

    def text(name: str, limit: int = MAX_VALUE) -> str:
        try:
            return clean_text(query.get(name, ""), name, limit)
        except FormError:
            return ""

    rows: list[ShaftRow] = []
    try:
        given = json.loads(query.get("op", "") or "[]")
        if isinstance(given, list) and len(given) <= MAX_ROWS:
            for row in given:
                if isinstance(row, list) and len(row) == 5 and all(isinstance(v, str) for v in row):
                    rows.append(ShaftRow(*(clean_text(v, "op", MAX_VALUE) for v in row)))
    except (ValueError, FormError):
        rows = []
    units, lang = text("units"), text("lang")
    return {"restore_rows": tuple(rows), "restore_gear": text("gear"),
            "restore_tab": text("tab", 40), "restore_units": units if units in UNIT_CHOICES else "file",
            "restore_lang": lang if lang in LANGUAGES else "en"}


# ---------------------------------------------------------------------- reading the form from a file
def _shown(value: object) -> str:
    """A TOML value as the form shows it (numbers without a trailing ``.0``)."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    return str(value)


def operating_rows(data: Mapping[str, Any], shafts: Sequence[str]) -> tuple[ShaftRow, ...]:
    """The form rows of a file's ``[operating_point]`` (``data`` from :mod:`tomllib`), one per shaft."""
    op = data.get("operating_point", {})
    op = op if isinstance(op, dict) else {}

    def group(key: str) -> dict[str, Any]:
        value = op.get(key, {})
        return value if isinstance(value, dict) else {}

    def names(key: str) -> list[str]:
        value = op.get(key, [])
        return [value] if isinstance(value, str) else [v for v in value if isinstance(v, str)] if isinstance(
            value, list) else []

    speeds, torques, powers = group("speeds"), group("torques"), group("powers")
    drives, loads = names("drives"), names("loads")
    rows = []
    for shaft in shafts:
        role = "drive" if shaft in drives else "load" if shaft in loads else ""
        moment, value = ("power", powers[shaft]) if shaft in powers else ("torque", torques.get(shaft, ""))
        rows.append(ShaftRow(shaft, role, _shown(speeds.get(shaft, "")), moment, _shown(value)))
    return tuple(rows)


def default_operating_rows(shafts: Sequence[str], input: str, output: str) -> tuple[ShaftRow, ...]:
    """The operating point of a transmission without one: the default point of
    :func:`epicyclic.transmission.default_operating_point` (written with its units, 1/min and N·m, so that it
    holds in any file's ``[units]``), as :func:`epicyclic.plotting.figure_subject` solves it."""
    from ..transmission import DEFAULT_INPUT_SPEED, DEFAULT_INPUT_TORQUE

    speed, torque = f"{DEFAULT_INPUT_SPEED:g} 1/min", f"{DEFAULT_INPUT_TORQUE:g} N*m"
    return tuple(
        ShaftRow(s, "drive", speed, "torque", torque) if s == input
        else ShaftRow(s, "load") if s == output else ShaftRow(s)
        for s in shafts
    )


# ---------------------------------------------------------------------- writing the form into the file
def _value(text: str) -> float | int | str:
    """A typed value: a plain number stays a number (the file's unit), anything else stays text."""
    try:
        number = int(text)
    except ValueError:
        try:
            number = float(text)
        except ValueError:
            return text
        return number if math.isfinite(number) else text
    return number if abs(number) < 2**63 else text


def write_operating_point(text: str, rows: Sequence[ShaftRow], gear: str) -> str:
    """``text`` with its ``[operating_point]`` table replaced by the form's values.

    The rest of the text, comments and layout included, is kept (:mod:`tomlkit`).

    Raises
    ------
    tomllib.TOMLDecodeError
        ``text`` is not valid TOML (the caller reports it like the loader).
    """
    return write_operating_points(text, rows, (gear,))[0]


def write_operating_points(text: str, rows: Sequence[ShaftRow], gears: Sequence[str]) -> tuple[str, ...]:
    """:func:`write_operating_point` for each of ``gears``, the text parsed once (tomlkit is the slow part).

    Raises
    ------
    tomllib.TOMLDecodeError
        ``text`` is not valid TOML.
    """
    import tomlkit

    tomllib.loads(text)  # the same parser as the loader decides what is valid
    document = tomlkit.parse(text)
    table = tomlkit.table()
    for key, quantity in (("speeds", None), ("torques", "torque"), ("powers", "power")):
        values = tomlkit.inline_table()
        for row in rows:
            given = row.speed if quantity is None else (row.value if row.moment == quantity else "")
            if given:
                values[row.shaft] = _value(given)
        if values:
            table[key] = values
    for key, role in (("drives", "drive"), ("loads", "load")):
        names = [row.shaft for row in rows if row.role == role]
        if names:
            table[key] = names
    if "operating_point" not in document:
        document.add(tomlkit.nl())
        document.add("operating_point", tomlkit.table())
    texts = []
    for gear in gears:
        written = table.copy()
        if gear:
            written["gear"] = gear
        document["operating_point"] = written
        texts.append(tomlkit.dumps(document))
    return tuple(texts)
