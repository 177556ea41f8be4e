"""The bundled example train descriptions (``epicyclic/data/examples/*.toml``).

They are read once when the app starts; the page names an example by its key
(the file name without ``.toml``) and gets its text from this table, so no
name the client sends ever becomes a path.

Examples
--------
>>> examples = bundled_examples()
>>> examples["brandenberger_1952"].title
'Brandenberger 1952, Bild 10'
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib import resources
from types import MappingProxyType
from typing import Mapping

__all__ = ["Example", "bundled_examples", "DEFAULT_EXAMPLE"]

#: The example the page opens first.
DEFAULT_EXAMPLE = "brandenberger_1952"


@dataclass(frozen=True)
class Example:
    """One bundled example: key, file name, title and TOML text."""

    key: str
    file_name: str
    title: str
    text: str


def bundled_examples() -> Mapping[str, Example]:
    """Every example shipped with the package, by key, sorted by title."""
    folder = resources.files("epicyclic").joinpath("data", "examples")
    found = []
    if folder.is_dir():
        for entry in folder.iterdir():
            if not entry.name.endswith(".toml") or not entry.is_file():
                continue
            text = entry.read_text(encoding="utf-8")
            try:
                title = str(tomllib.loads(text).get("title", entry.name))
            except tomllib.TOMLDecodeError:
                title = entry.name
            found.append(Example(entry.name[:-5], entry.name, title, text))
    return MappingProxyType({e.key: e for e in sorted(found, key=lambda e: e.title.lower())})
