"""Where in the TOML text a load error points: the line of the table and key the message names.

The loader's messages name the place as the command line prints it, e.g.
``"<file>: [[planetary]] #2 'P2', key 'teeth': ..."``,
``"<file>: [operating_point] speeds: unknown shaft 'x'"`` or, for bad TOML,
``"... (at line 7, column 3)"``.  :func:`locate` finds that line in the text
so that the editor can mark it; the message itself is shown unchanged.

Examples
--------
>>> text = '''title = "t"
... [[planetary]]
... name = "P1"
... [[planetary]]
... name = "P2"
... teeth = { sun = 0 }
... '''
>>> locate(text, "f.toml: [[planetary]] #2 'P2', key 'teeth': tooth counts must be positive.")
6
>>> locate(text, "f.toml: [[planetary]] #1 'P1': missing key 'sun'.")
2
>>> locate(text, "f.toml: not valid TOML: Expected '=' (at line 3, column 6).")
3
>>> locate('[transmission]\\ninput = "in"\\n[transmission.schedule]\\n"1" = ["B"]\\n"2" = []\\n',
...        "f.toml: [transmission], key 'schedule.2': gear '2' leaves the train free.")
5
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Problem", "locate", "problem"]

_TOML_POSITION = re.compile(r"\(at line (\d+), column (\d+)\)|: line (\d+)[,:]")
_ARRAY = re.compile(r"\[\[(\w+)\]\] #(\d+)")
_TABLE = re.compile(r"(?<!\[)\[([A-Za-z_][\w.]*)\](?!\]):?,?(?:\s+(?:key\s+)?'?([A-Za-z_][\w.]*))?")
_KEY = re.compile(r"key '([A-Za-z_][\w.]*…?)")
_HEADER = re.compile(r"""^\s*(\[\[|\[)\s*([A-Za-z0-9_\-."' ]+?)\s*\]\]?\s*(?:#.*)?$""")
#: Names in messages that stand for a key of the file (tooth counts are the key 'teeth').
_ALIASES = {"z_sun": "teeth", "z_planet": "teeth", "z_ring": "teeth", "z_planet_sun": "teeth",
            "z_planet_ring": "teeth", "i0": "stationary_ratio", "eta0": "stationary_efficiency"}


@dataclass(frozen=True)
class Problem:
    """A load error as the editor shows it.

    Attributes
    ----------
    message : str
        The loader's message, unchanged.
    line : int or None
        1-based line of the text it points at.
    excerpt : tuple of (int, str, bool)
        Up to five numbered lines around ``line`` (number, text, is the line).
    """

    message: str
    line: int | None = None
    excerpt: tuple[tuple[int, str, bool], ...] = ()


def _headers(lines: list[str]) -> list[tuple[int, str]]:
    """(index, header text without brackets) of every table header line."""
    return [(k, match.group(1) + match.group(2)) for k, line in enumerate(lines) if (match := _HEADER.match(line))]


def _section_end(lines: list[str], start: int) -> int:
    return next((k for k in range(start + 1, len(lines)) if _HEADER.match(lines[k])), len(lines))


def _find_key(lines: list[str], start: int, end: int, key: str) -> int | None:
    """The index of the line in ``lines[start:end]`` that sets ``key``.

    A key the message shortened (``'kkkk…'``) matches by its beginning.
    """
    name = re.escape(key[:-1]) + r"[^\s=.\]]*" if key.endswith("…") else re.escape(key)
    pattern = re.compile(rf"^\s*[\"']?{name}[\"']?\s*[.=]")
    for k in range(start, end):
        if pattern.match(lines[k]):
            return k
    return None


def _candidates(message: str, after_table: str | None) -> list[str]:
    """Keys the message may point at, most specific first (``speeds.II`` → ``speeds``, ``II``)."""
    names = [m.group(1) for m in _KEY.finditer(message)]
    if after_table:
        names.append(after_table)
    names += [alias for word, alias in _ALIASES.items() if re.search(rf"\b{word}\b", message)]
    found: list[str] = []
    for name in names:
        for part in (name, *name.replace("[", ".").split(".")):
            if part and part not in found:
                found.append(part)
    return found


def locate(text: str, message: str, fallback: str | None = None) -> int | None:
    """The 1-based line of ``text`` that ``message`` points at, or None if it names no place.

    ``fallback`` is a table (e.g. ``"operating_point"``) to point at when the
    message names no place.
    """
    position = _TOML_POSITION.search(message)
    if position:
        return int(position.group(1) or position.group(3))
    lines = text.splitlines()
    headers = _headers(lines)
    start, after = None, None
    array = _ARRAY.search(message)
    table = None if array else _TABLE.search(message)
    if array:
        matching = [k for k, h in headers if h == f"[[{array.group(1)}"]
        number = int(array.group(2))
        if 0 < number <= len(matching):
            start = matching[number - 1]
    elif table:
        start = next((k for k, h in headers if h == f"[{table.group(1)}"), None)
        after = table.group(2)
    keys = _candidates(message, after)
    if start is None:
        first = headers[0][0] if headers else len(lines)
        # a key without a table is a top-level key ("key 'title'"), or the message says "top level"
        line = next((found for key in keys if (found := _find_key(lines, 0, first, key)) is not None), None)
        if line is None:  # a top-level key that opens a table: "unknown key 'operating_points'" → [operating_points]
            line = next((k for key in keys for k, h in headers if h.lstrip("[") == key), None)
        if line is not None:
            return line + 1
        if fallback:
            return next((k + 1 for k, h in headers if h == f"[{fallback}"), None)
        return None
    if table:  # a dotted key may live in a sub-table: [transmission], key 'schedule.2' → [transmission.schedule] "2"
        for key in keys:
            head, _, rest = key.partition(".")
            sub = next((k for k, h in headers if h == f"[{table.group(1)}.{head}"), None) if rest else None
            if sub is not None and (found := _find_key(lines, sub + 1, _section_end(lines, sub), rest)) is not None:
                return found + 1
    end = _section_end(lines, start)
    line = next((found for key in keys if (found := _find_key(lines, start + 1, end, key)) is not None), None)
    return (start if line is None else line) + 1


def problem(text: str, message: str, context: int = 2, fallback: str | None = None) -> Problem:
    """A :class:`Problem` with the line and a numbered excerpt around it (see :func:`locate`)."""
    line = locate(text, message, fallback)
    if line is None:
        return Problem(message)
    lines = text.splitlines() or [""]
    line = min(max(line, 1), len(lines))
    first, last = max(1, line - context), min(len(lines), line + context)
    excerpt = tuple((k, lines[k - 1], k == line) for k in range(first, last + 1))
    return Problem(message, line, excerpt)
