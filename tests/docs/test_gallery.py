"""The gallery (docs/gallery.md, ``make gallery``) shows every file in examples/ in every kind of picture.

The gallery is generated and committed; an example added later must be drawn too
(five examples were missing from it once).  Regenerate with ``make gallery``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
GALLERY = ROOT / "docs" / "gallery"
KINDS = ("speed", "torque", "power", "lever", "flow")


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_is_in_the_gallery(path):
    page = (ROOT / "docs" / "gallery.md").read_text(encoding="utf-8")
    kinds = KINDS + (("chart",) if "[transmission]" in path.read_text(encoding="utf-8") else ())
    pictures = [f"gallery/{path.stem}/{kind}.png" for kind in kinds] + [f"gallery/{path.stem}/animation.svg",
                                                                          f"gallery/{path.stem}/animation.gif"]
    missing = [p for p in pictures if not (ROOT / "docs" / p).is_file() or p not in page]
    assert not missing, f"{path.name}: not in the gallery: {missing}; run `make gallery`"


def test_the_gallery_holds_no_example_that_is_gone():
    stems = {p.stem for p in EXAMPLES}
    folders = {p.name for p in GALLERY.iterdir() if p.is_dir() and p.name != "__pycache__"}
    assert folders <= stems, f"gallery folders without an example: {sorted(folders - stems)}"


@pytest.mark.parametrize("name", ["gallery", "figures", "web_page"])
def test_shipped_pictures_are_not_older_than_the_code_that_draws_them(name):
    """docs/figures/pictures.sha256 holds the digest of the drawing code (src/epicyclic/plotting, the
    examples, the scripts) as it was when the pictures were drawn: changed code means stale pictures."""
    import sys

    sys.path.insert(0, str(ROOT / "docs" / "figures"))
    from stamp import SOURCES, digest, recorded

    assert recorded().get(name) == digest(name), (
        f"the {name} pictures are older than the code that draws them ({', '.join(SOURCES[name])} changed "
        f"since); run `make gallery` and commit the pictures with docs/figures/pictures.sha256")
