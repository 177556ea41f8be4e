"""Write a mapped REXS document as a readable, commented TOML train file (:mod:`tomlkit`).

Every element, shaft and operating point is followed back to its REXS
component in a comment (``# REXS planetary_stage 9 'Planetenstufe [9]'``);
the header names the file, its REXS version and writing program, and what was
ignored; the load spectrum (all load cases, the first of which is
``[operating_point]``), the gear materials and the lubricant as given are
listed in comments.  The text reads back to the same train.

Examples
--------
>>> text = document_toml({"title": "t", "planetary": [{"name": "P", "sun": "s", "ring": "r", "carrier": "c",
...                        "teeth": {"sun": 30, "planet": 24, "ring": 78}}]}, {"planetary.P": "planetary_stage 9"})
>>> print(text.splitlines()[3])
# REXS planetary_stage 9
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

__all__ = ["document_toml"]


def _value(value: Any, inline: bool = False):
    import tomlkit

    if isinstance(value, Mapping):
        table = tomlkit.inline_table() if inline else tomlkit.table()
        for k, v in value.items():
            table[k] = _value(v, True)
        return table
    if isinstance(value, (list, tuple)) and not inline and value and all(isinstance(v, Mapping) for v in value):
        tables = tomlkit.aot()  # [[duty_cycle.case]] and the like
        for v in value:
            tables.append(_value(v))
        return tables
    if isinstance(value, (list, tuple)):
        array = tomlkit.array()
        for v in value:
            array.append(_value(v, True))
        return array
    return value


def _comment(line: str):
    """A TOML comment of ``line``: one line, no control characters (text from a REXS file may hold them)."""
    import tomlkit

    from ..text import terminal_text

    return tomlkit.comment(" ".join(terminal_text(line).split()))


def document_toml(data: Mapping[str, Any], origins: Mapping[str, str] | None = None, header: list[str] = (),
                  footer: list[str] = ()) -> str:
    """The TOML text of the train document ``data``, commented with the REXS ``origins``.

    Parameters
    ----------
    data : mapping
        A train document (:attr:`~epicyclic.exchange.RexsDocument.data`).
    origins : mapping str → str, optional
        ``"planetary.P"`` / ``"shaft.S"`` ... → the REXS component(s) it came from.
    header, footer : list of str
        Comment lines at the top and the end.

    Returns
    -------
    str
    """
    import tomlkit

    origins = origins or {}
    doc = tomlkit.document()
    for line in header:
        doc.add(_comment(line))
    if header:
        doc.add(tomlkit.nl())
    for key in ("title", "description"):
        if key in data:
            doc[key] = data[key]
    if "shafts" in data:
        doc["shafts"] = _value(data["shafts"])
    shafts = [(k.partition(".")[2], v) for k, v in origins.items() if k.startswith("shaft.")]
    if shafts:
        doc.add(tomlkit.nl())
        doc.add(_comment("Shafts (members) and the REXS components they are made of:"))
        for name, origin in shafts:
            doc.add(_comment(f"  {name!r}: {origin}"))
    for key in ("units", "lubricant"):
        if key in data:
            doc.add(tomlkit.nl())
            doc[key] = _value(data[key])
    for kind in ("planetary", "gear", "clutch", "brake"):
        if kind not in data:
            continue
        array = tomlkit.aot()
        for element in data[kind]:
            table = tomlkit.table()
            origin = origins.get(f"{kind}.{element.get('name')}")
            if origin:
                table.add(_comment(f"REXS {origin}"))
            for k, v in element.items():
                if isinstance(v, Mapping) and k in ("geometry", "losses"):
                    continue
                table[k] = _value(v, True)
            for k in ("geometry", "losses"):
                if k in element:
                    table[k] = _value(element[k])
            array.append(table)
        doc.add(tomlkit.nl())
        doc[kind] = array
    for key in ("transmission", "operating_point"):
        if key in data:
            doc.add(tomlkit.nl())
            table = tomlkit.table()
            for k, v in data[key].items():
                table[k] = _value(v, not (key == "transmission" and k == "schedule"))
            doc[key] = table
    written = {"title", "description", "shafts", "units", "lubricant", "planetary", "gear", "clutch", "brake",
               "transmission", "operating_point"}
    for key in [k for k in data if k not in written]:  # [rating], [duty_cycle], [pump], [[seal]], ...
        doc.add(tomlkit.nl())
        if not isinstance(data[key], Mapping):  # an array of tables ([[seal]], [[churning]]) or a value
            doc[key] = _value(data[key])
            continue
        table = tomlkit.table()
        for k, v in data[key].items():
            table[k] = _value(v, not isinstance(v, (Mapping, list)) or isinstance(v, list) and not all(
                isinstance(x, Mapping) for x in v) or not v)
        doc[key] = table
    text = tomlkit.dumps(doc)
    if footer:
        text += "\n" + "".join(f"# {line}\n" if line else "#\n" for line in footer)
    return text
