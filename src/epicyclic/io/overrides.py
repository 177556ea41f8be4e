"""``--set KEY=VALUE``: override values of a train description before it is read.

An override is applied to the parsed TOML data, *before* validation, so every message still
names the file and the key. KEY is a dotted TOML key (``operating_point.speeds.sun``, quoted
parts allowed: ``transmission.schedule."1"``); an element of an array of tables such as
``[[planetary]]`` is picked by its ``name`` or by its 1-based number (``planetary.P1.…``,
``planetary.2.…``). VALUE is a TOML value (``2000``, ``"2000 rpm"``, ``["in"]``, ``true``); text
that is not a TOML value is taken as a string, so ``operating_point.speeds.sun=2000 rpm`` works.

Examples
--------
>>> data = {"operating_point": {"speeds": {"sun": 1000}}, "planetary": [{"name": "P1"}]}
>>> data = apply_overrides(data, ['operating_point.speeds.sun="2000 rpm"',
...                               "planetary.P1.stationary_efficiency=0.97"])
>>> data["operating_point"]["speeds"]["sun"], data["planetary"][0]["stationary_efficiency"]
('2000 rpm', 0.97)
"""

from __future__ import annotations

import copy
import tomllib
from collections.abc import Mapping, Sequence
from typing import Any

from ..errors import ModelError
from ..limits import MAX_NESTING

__all__ = ["OverrideError", "apply_overrides", "parse_override"]

_EXAMPLE = 'operating_point.speeds.sun="2000 rpm"'


class OverrideError(ModelError):
    """A ``--set KEY=VALUE`` that cannot be applied (malformed, or its key does not fit the file)."""


def parse_override(text: str) -> tuple[tuple[str, ...], Any]:
    """Split ``KEY=VALUE`` into the key's parts and the value.

    Raises
    ------
    OverrideError
        No ``=``, an empty or malformed key.

    Examples
    --------
    >>> parse_override('transmission.schedule."1"=["A", "B"]')
    (('transmission', 'schedule', '1'), ['A', 'B'])
    >>> parse_override("operating_point.speeds.sun=2000 rpm")
    (('operating_point', 'speeds', 'sun'), '2000 rpm')
    """
    key, sep, raw = text.partition("=")
    if not sep or not key.strip():
        raise OverrideError(f"--set {text!r}: expected KEY=VALUE, e.g. --set {_EXAMPLE}.")
    if any(c in text for c in "\r\n\x00"):
        raise OverrideError(f"--set {text[:60]!r}: expected one KEY=VALUE on one line (no line breaks), "
                            f"e.g. --set {_EXAMPLE}.")
    not_dotted = OverrideError(f"--set {text!r}: {key.strip()!r} is not one dotted key such as "
                               f"operating_point.speeds.sun (quote parts with dots or spaces).")
    parts = _key_parts(key)
    if parts > MAX_NESTING:  # before tomllib, which takes minutes (or the stack) on a key of 60 000 parts
        raise OverrideError(f"--set {text[:60]!r}…: the key has {parts} parts; keys nest at most {MAX_NESTING} "
                            "levels deep, as in a train file (docs/limits.md).")
    try:
        nested = tomllib.loads(f"{key.strip()} = 0")
    except tomllib.TOMLDecodeError:
        raise not_dotted from None
    path: list[str] = []
    while isinstance(nested, dict):
        if len(nested) != 1:  # e.g. 'a = 1, b' or a table header: more than one key
            raise not_dotted
        (part, nested), = nested.items()
        path.append(part)
    if nested != 0:
        raise not_dotted
    if len(path) > MAX_NESTING:
        raise OverrideError(f"--set {text[:60]!r}…: the key has {len(path)} parts; keys nest at most {MAX_NESTING} "
                            "levels deep, as in a train file (docs/limits.md).")
    too_deep = OverrideError(f"--set {text[:60]!r}…: the value nests more than {MAX_NESTING} levels deep; values "
                             "nest at most that deep, as in a train file (docs/limits.md).")
    if _depth(raw) > MAX_NESTING:
        raise too_deep
    try:
        parsed = tomllib.loads(f"v = {raw.strip()}")
    except tomllib.TOMLDecodeError:
        parsed = None
    except RecursionError:  # pragma: no cover - _depth refuses such values first
        raise too_deep from None
    if parsed is not None and set(parsed) == {"v"}:
        value = parsed["v"]
    else:
        value = raw.strip()  # not a TOML value: a bare string such as 2000 rpm
    return tuple(path), value


def _key_parts(key: str) -> int:
    """How many dotted parts ``key`` has at most: the dots outside quoted parts, plus one (one linear pass)."""
    dots, quote = 0, ""
    for char in key:
        if quote:
            quote = "" if char == quote else quote
        elif char in "\"'":
            quote = char
        elif char == ".":
            dots += 1
    return dots + 1


def _depth(raw: str) -> int:
    """The deepest nesting of [ ] and { } in a value's text, outside quoted strings (linear scan)."""
    depth = deepest = 0
    quote = ""
    escaped = False
    for char in raw:
        if quote:
            if escaped:
                escaped = False
            elif char == "\\" and quote == '"':
                escaped = True
            elif char == quote:
                quote = ""
        elif char in "\"'":
            quote = char
        elif char in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif char in "]}":
            depth = max(depth - 1, 0)
    return deepest


def _pick(elements: list, part: str, text: str, where: str) -> dict:
    """The table of an array of tables named ``part`` (or numbered, from 1)."""
    tables = [e for e in elements if isinstance(e, dict)]
    if len(tables) != len(elements):
        raise OverrideError(f"--set {text!r}: {where} is an array of values, not of tables; set it whole, "
                            f"e.g. --set {where}='[\"a\", \"b\"]'.")
    named = [t for t in tables if t.get("name") == part]
    if named:
        return named[0]
    if part.isdigit() and 1 <= int(part) <= len(tables):
        return tables[int(part) - 1]
    names = ", ".join(repr(t["name"]) for t in tables if isinstance(t.get("name"), str)) or "none"
    raise OverrideError(f"--set {text!r}: no [[{where}]] named {part!r}; give a name ({names}) or a number "
                        f"from 1 to {len(tables)}.")


def apply_overrides(data: Mapping[str, Any], overrides: Sequence[str]) -> dict[str, Any]:
    """A copy of the TOML ``data`` with every ``KEY=VALUE`` of ``overrides`` applied, in order.

    A key is a dotted path (``operating_point.speeds.in``); an element of an array of
    tables is picked by its ``name`` or 1-based number (``planetary.P1.stationary_efficiency``).
    The value is read as TOML, or as a string where it is not a TOML value.

    Parameters
    ----------
    data : mapping
        A parsed TOML file (not changed).
    overrides : sequence of str
        ``KEY=VALUE`` texts, as given to ``--set``.

    Returns
    -------
    dict
        The changed copy.

    Raises
    ------
    OverrideError
        A malformed override, a key through a value that is not a table, or an element name
        that the file does not have.
    """
    result = copy.deepcopy(dict(data))
    for text in overrides:
        path, value = parse_override(text)
        node: Any = result
        for depth, part in enumerate(path[:-1]):
            where = ".".join(path[: depth + 1])
            if isinstance(node, list):
                node = _pick(node, part, text, ".".join(path[:depth]))
            elif isinstance(node, dict):
                node = node.setdefault(part, {})
            if not isinstance(node, (dict, list)):
                raise OverrideError(f"--set {text!r}: {where} is the value {node!r}, not a table, so it has "
                                    f"no key {path[depth + 1]!r}.")
        last = path[-1]
        if isinstance(node, list):
            where = ".".join(path[:-1])
            if not all(isinstance(e, dict) for e in node):
                raise OverrideError(f"--set {text!r}: {where} is an array of values, not of tables; set it "
                                    f"whole, e.g. --set {where}='[\"a\", \"b\"]'.")
            raise OverrideError(f"--set {text!r}: {where} is an array of tables; set a key of one element, "
                                f"e.g. --set {where}.{last}.KEY=VALUE.")
        node[last] = value
    return result
