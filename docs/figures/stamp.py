"""Which code draws the shipped pictures, and a digest of it: a picture older than its code is stale.

``make gallery`` (docs/gallery/make_gallery.py and docs/figures/make_figures.py) writes the digest of
the sources each set of pictures is drawn from into ``docs/figures/pictures.sha256``;
tests/docs/test_gallery.py computes the digests anew and fails, naming the set and the command, when
the code has changed since the pictures were drawn. File contents are hashed (not dates, which a
clone does not keep), in a fixed order.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
STAMP = ROOT / "docs" / "figures" / "pictures.sha256"
#: Set of pictures → the files (globs relative to the repository) that draw them.
SOURCES: dict[str, tuple[str, ...]] = {
    "gallery": ("src/epicyclic/plotting/**/*.py", "examples/*.toml", "docs/gallery/make_gallery.py"),
    "figures": ("src/epicyclic/plotting/**/*.py", "examples/brandenberger_1952.toml",
                "examples/simple_set_ring_held_sun_drives.toml", "examples/zf_8hp70_geometry.toml",
                "docs/figures/make_figures.py"),
    "web_page": ("src/epicyclic/web/templates/*", "src/epicyclic/web/static/*.js", "src/epicyclic/web/static/*.css",
                 "examples/simpson_c4_3speed.toml", "docs/figures/make_screenshots.py"),
}


def digest(name: str) -> str:
    """SHA-256 over the path and content of every source file of one set of pictures."""
    sha = hashlib.sha256()
    files = sorted({path for pattern in SOURCES[name] for path in ROOT.glob(pattern) if path.is_file()})
    for path in files:
        sha.update(path.relative_to(ROOT).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return sha.hexdigest()


def recorded() -> dict[str, str]:
    """The digests written when the pictures were last drawn (set → digest)."""
    if not STAMP.is_file():
        return {}
    pairs = (line.split() for line in STAMP.read_text(encoding="utf-8").splitlines() if line.strip())
    return {name: value for name, value in pairs}


def record(name: str) -> None:
    """Write the current digest of one set of pictures (after drawing them)."""
    stamps = recorded()
    stamps[name] = digest(name)
    STAMP.write_text("".join(f"{key} {value}\n" for key, value in sorted(stamps.items())), encoding="utf-8")
