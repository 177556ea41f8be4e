"""Typed values from TOML tables, each error naming the file, the table and the key.

:class:`TableReader` is the base of the train file reader
(:mod:`epicyclic.io.toml_format`): it checks keys, reads strings, names,
booleans, whole numbers, numbers (or arithmetic expressions) and
efficiencies, and locates model errors in the file.  Every message quotes
what was given shortened to a few dozen characters, so a hostile value never
floods the terminal.

Examples
--------
>>> r = TableReader("t.toml")
>>> r.integer(3.5, "planets", "[[planetary]] #1 'P'")
Traceback (most recent call last):
...
epicyclic.io.source.InputFileError: t.toml: [[planetary]] #1 'P', key 'planets': expected a whole number, got a number 3.5.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping
from typing import Any

from ..errors import EpicyclicError
from ..limits import MAX_NAME_CHARS, RATIO_RANGE
from ..text import short
from .expressions import evaluate
from .located import located
from .source import InputFileError

__all__ = ["TableReader", "kind_of"]


def kind_of(value: object) -> str:
    """'a string', 'an integer', ... for messages."""
    return {bool: "a boolean", int: "an integer", float: "a number", str: "a string", list: "an array",
            dict: "a table"}.get(type(value), type(value).__name__)


def _close(word: str, options: set[str]) -> str | None:
    match = difflib.get_close_matches(word[:100], sorted(options), n=1, cutoff=0.6)
    return match[0] if match else None


def at_key(where: str, key: str) -> str:
    """``"[[gear]] #1 'G', key 'ratio'"``."""
    return f"{where}, key {key!r}"


class TableReader:
    """Read typed values out of parsed TOML tables; errors name ``source`` and the key.

    Parameters
    ----------
    source : str
        The file name (or ``"<string>"``), the first word of every message.
    """

    def __init__(self, source: str):
        self.source = source

    # ---- messages
    def error(self, where: str, message: str) -> InputFileError:
        """An :class:`InputFileError` ``"<source>: <where>: <message>"``."""
        return InputFileError(f"{self.source}: {where}: {message}", self.source, where)

    def wrap(self, where: str, exc: EpicyclicError, owner: str = "") -> EpicyclicError:
        """Locate a model error in the file, keeping its class (see :func:`~epicyclic.io.located.located`)."""
        return located(exc, self.source, where, owner)

    def check_keys(self, table: Mapping[str, Any], allowed: set[str], where: str) -> None:
        unknown = [k for k in table if k not in allowed]
        if unknown:
            close = _close(unknown[0], allowed)
            raise self.error(
                where,
                f"unknown key {short(unknown[0])}; expected one of {', '.join(sorted(allowed))}"
                + (f" (did you mean {close!r}?)" if close else "") + ".",
            )

    def table(self, value: object, where: str) -> Mapping[str, Any]:
        if not isinstance(value, dict):
            raise self.error(where, f"expected a table, got {kind_of(value)} {short(value)}.")
        return value

    def require(self, table: Mapping[str, Any], key: str, where: str) -> Any:
        if key not in table:
            raise self.error(where, f"missing key {key!r}.")
        return table[key]

    # ---- values
    def string(self, table: Mapping[str, Any], key: str, where: str, default: str | None = None) -> str:
        """A non-empty string."""
        if key not in table and default is not None:
            return default
        value = self.require(table, key, where)
        if not isinstance(value, str) or not value.strip():
            raise self.error(at_key(where, key), f"expected a non-empty string, got {kind_of(value)} {short(value)}.")
        return value

    def name(self, table: Mapping[str, Any], key: str, where: str) -> str:
        """A name of a shaft, element or gear: a short string without control characters."""
        value = self.string(table, key, where)
        self.check_name(value, at_key(where, key))
        return value

    def check_name(self, value: str, where: str) -> str:
        if len(value) > MAX_NAME_CHARS:
            raise self.error(where, f"the name {short(value, 30)} is {len(value)} characters long; at most "
                                    f"{MAX_NAME_CHARS} are accepted (see docs/limits.md).")
        if not value.isprintable() or value != value.strip():
            raise self.error(where, f"the name {short(value)} contains control characters or leading/trailing "
                                    "spaces; use letters, digits and punctuation.")
        return value

    def boolean(self, table: Mapping[str, Any], key: str, where: str, default: bool) -> bool:
        value = table.get(key, default)
        if not isinstance(value, bool):
            raise self.error(at_key(where, key), f"expected true or false, got {kind_of(value)} {short(value)}.")
        return value

    def integer(self, value: object, key: str, where: str) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.error(at_key(where, key), f"expected a whole number, got {kind_of(value)} {short(value)}.")
        return value

    def number(self, value: object, key: str, where: str, unit: str | None = None) -> float:
        """A plain number or an arithmetic expression string.

        With ``unit`` (the key's fixed unit, ``"h"``, ``"µm"``; ``"1"`` for a pure number) a string may end
        in that unit (``"20000 h"``), and one that is neither is refused naming the unit, not with the
        expression grammar's hint.
        """
        if isinstance(value, bool):
            raise self.error(at_key(where, key), f"expected a number, got the boolean {value!r}.")
        if isinstance(value, (int, float)):
            try:
                number = float(value)
            except OverflowError:  # an integer beyond double precision
                raise self.error(at_key(where, key), f"the number {short(value, 30)} is beyond double precision "
                                                     "(about 1.8e308).") from None
            if not math.isfinite(number):
                raise self.error(at_key(where, key), f"expected a finite number, got {value!r}.")
            return number
        if isinstance(value, str):
            text = value.strip()
            for spelled in ((unit, "um") if unit == "µm" else (unit,)) if unit and unit != "1" else ():
                if text.endswith(spelled):
                    text = text[: -len(spelled)].strip()
                    break
            try:
                return evaluate(text, "expression")
            except EpicyclicError as exc:
                if unit:
                    wanted = "a plain number (no unit)" if unit == "1" else f"a number in {unit} (e.g. 2 or '2 {unit}')"
                    raise self.error(at_key(where, key), f"expected {wanted}, got {short(value)}.") from None
                raise self.wrap(at_key(where, key), exc, "expression") from None
        raise self.error(at_key(where, key), f"expected a number or an expression such as '(24/50)*(42/30)', "
                                             f"got {kind_of(value)} {short(value)}.")

    def ratio(self, value: object, key: str, where: str) -> float:
        """A speed ratio (number or expression) with 1e-6 <= |ratio| <= 1e6 (or exactly 0, for the model)."""
        ratio = self.number(value, key, where)
        low, high = RATIO_RANGE
        if ratio != 0 and not low <= abs(ratio) <= high:
            raise self.error(at_key(where, key), f"|{ratio:.6g}| is outside the accepted {low:g} … {high:g}; "
                                                 "no gear stage or set has such a ratio (see docs/limits.md).")
        return ratio

    def efficiency(self, value: object, key: str, where: str) -> float:
        eta = self.number(value, key, where)
        if not 0.0 < eta <= 1.0:
            raise self.error(at_key(where, key), f"expected an efficiency in (0, 1] (1 = lossless), got "
                                                 f"{short(value)}. Give e.g. 0.98, not a percentage or a loss.")
        return eta

    def array_of_tables(self, data: Mapping[str, Any], key: str) -> list[Mapping[str, Any]]:
        value = data.get(key, [])
        if isinstance(value, dict):
            raise self.error(f"[{key}]", f"write [[{key}]] (an array of tables, one per element), not [{key}].")
        if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
            raise self.error(f"[[{key}]]", f"expected an array of tables, got {kind_of(value)}.")
        return value

    def names(self, value: object, key: str, where: str) -> tuple[str, ...]:
        """A list of names (a single string is one name)."""
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list) or not all(isinstance(n, str) for n in value):
            raise self.error(at_key(where, key), f"expected a list of names, got {kind_of(value)} {short(value)}.")
        for n in value:
            self.check_name(n, at_key(where, key))
        if len(set(value)) != len(value):
            twice = next(n for n in value if value.count(n) > 1)
            raise self.error(at_key(where, key), f"names {twice!r} twice.")
        return tuple(value)
