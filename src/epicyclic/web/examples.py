"""The bundled example train descriptions (``epicyclic/data/examples/*.toml``).

They are read once when the app starts; the page names an example by its key
(the file name without ``.toml``) and gets its text from this table, so no
name the client sends ever becomes a path.  The list holds the trains of the
folder itself and of its ``transmissions/`` and ``rating/`` folders (the
ten-speed, the rated sets) and the public REXS models of ``rexs/``, which open
as ``epicyclic convert`` writes them (:attr:`Example.rexs` holds their bytes).

Examples
--------
>>> examples = bundled_examples()
>>> examples["brandenberger_1952"].title
'Brandenberger 1952, Bild 10'
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, replace
from importlib import resources
from types import MappingProxyType
from typing import Mapping

__all__ = ["Example", "bundled_examples", "DEFAULT_EXAMPLE"]

#: The example the page opens first.
DEFAULT_EXAMPLE = "brandenberger_1952"


@dataclass(frozen=True)
class Example:
    """One bundled example: key, file name, title and TOML text (a REXS model: its bytes, text empty)."""

    key: str
    file_name: str
    title: str
    text: str
    rexs: bytes = b""

    def train_text(self) -> str:
        """The TOML text the page opens: the file's, or a REXS model's as ``epicyclic convert`` writes it."""
        if not self.rexs:
            return self.text
        from ..exchange.convert import toml_text
        from ..exchange.reading import loads_rexs_document
        from ..io.toml_format import read_document

        return toml_text(read_document(loads_rexs_document(self.rexs, self.file_name)))


#: Folders of ``data/examples`` whose trains the page lists beside the folder's own (spec files and
#: CSV tables elsewhere are no trains).
TRAIN_FOLDERS = ("", "transmissions", "rating")


def _rexs_title(name: str) -> str:
    stem = name.rsplit(".", 1)[0].replace("_-_", " – ").replace("_", " ")
    return f"REXS model: {stem}"


def bundled_examples() -> Mapping[str, Example]:
    """Every example shipped with the package, by key, sorted by title."""
    root = resources.files("epicyclic").joinpath("data", "examples")
    found: dict[str, Example] = {}
    for sub in TRAIN_FOLDERS:
        folder = root.joinpath(sub) if sub else root
        if not folder.is_dir():
            continue
        for entry in sorted(folder.iterdir(), key=lambda e: e.name):
            if not entry.name.endswith(".toml") or not entry.is_file() or entry.name[:-5] in found:
                continue
            text = entry.read_text(encoding="utf-8")
            try:
                title = str(tomllib.loads(text).get("title", entry.name))
            except tomllib.TOMLDecodeError:
                title = entry.name
            found[entry.name[:-5]] = Example(entry.name[:-5], entry.name, title, text)
    rexs = root.joinpath("rexs")
    if rexs.is_dir():
        for entry in sorted(rexs.iterdir(), key=lambda e: e.name):
            if entry.name.endswith(".rexs") and entry.is_file() and entry.name[:-5] not in found:
                found[entry.name[:-5]] = Example(entry.name[:-5], entry.name, _rexs_title(entry.name), "",
                                                 entry.read_bytes())
    titles = [e.title for e in found.values()]
    for key, e in found.items():  # two files of one title (a set and its duty cycle): the file tells them apart
        if titles.count(e.title) > 1:
            found[key] = replace(e, title=f"{e.title} ({e.file_name})")
    return MappingProxyType({e.key: e for e in sorted(found.values(), key=lambda e: e.title.lower())})
