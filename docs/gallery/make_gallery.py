"""Regenerate the gallery: every file in examples/ × every kind of picture (``make gallery``).

Writes ``docs/gallery/<example>/<kind>.png`` (speed, torque, power, lever,
flow and, for a transmission, chart), the animation of each example's busiest
planetary set (largest rolling power) as SVG and GIF, and ``docs/gallery.md`` that shows them all.
With ``--html PATH`` it also writes an HTML page of the same gallery (for a
look in a browser; not part of the docs).

Each example is drawn as ``epicyclic plot`` draws it: at its operating point,
or, for a transmission without one, at unit input speed and torque in its
first gear (the figures say so).

Usage::

    .venv/bin/python docs/gallery/make_gallery.py [--html out/gallery.html]
"""

from __future__ import annotations

import argparse
import html
import shutil
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from epicyclic.io import load_train_file  # noqa: E402
from epicyclic.plotting import KINDS, figure_subject, planetary_animation, save_plot  # noqa: E402

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
DOC = ROOT / "docs" / "gallery.md"
#: Resolution of the PNGs and size of the animations: small enough for the repository.
DPI, SVG_SIZE, GIF_SIZE, GIF_FRAMES, COLOURS = 72, 420, 200, 12, 128
NAMES = {"speed": "speed plan and speed ranges", "torque": "torques", "power": "powers as areas",
         "lever": "lever diagram", "flow": "power flow", "chart": "speed chart across gears"}


def _small(png: Path) -> None:
    """Re-save a PNG with a palette of COLOURS colours (flat drawings: a third of the size, same look)."""
    from PIL import Image

    with Image.open(png) as im:
        small = im.convert("RGB").quantize(colors=COLOURS, method=Image.Quantize.MEDIANCUT)
    small.save(png, optimize=True)


def render(path: Path) -> dict:
    """Every picture of one example; returns what was written (paths relative to docs/)."""
    spec = load_train_file(path)
    subject = figure_subject(spec)
    folder = HERE / path.stem
    folder.mkdir(parents=True, exist_ok=True)
    kinds = list(KINDS) + (["chart"] if subject.transmission is not None else [])
    pictures = []
    for kind in kinds:
        out = save_plot(subject.solution, kind, folder / f"{kind}.png", dpi=DPI, context=subject.context,
                        transmission=subject.transmission)
        _small(out)
        pictures.append((kind, out.relative_to(DOC.parent).as_posix()))
    # the set that works hardest in this state (largest rolling power), so that something turns
    sets = subject.solution.train.planetary_sets
    pset = max(sets, key=lambda s: abs(subject.solution.elements[s.name].rolling_power))
    anim = planetary_animation(subject.solution, pset.name, context=subject.context, size=SVG_SIZE)
    svg = anim.save(folder / "animation.svg")
    small = planetary_animation(subject.solution, pset.name, context=subject.context, size=GIF_SIZE,
                                frames=GIF_FRAMES, fps=8)
    gif = small.gif(folder / "animation.gif", dpi=60)
    return {"stem": path.stem, "title": spec.title or spec.train.name, "description": spec.description,
            "file": f"../examples/{path.name}", "notes": (f"gear {subject.gear}" if subject.gear else "",
                                                            *subject.context.notes),
            "pictures": pictures, "set": pset.name,
            "svg": svg.relative_to(DOC.parent).as_posix(), "gif": gif.relative_to(DOC.parent).as_posix()}


def markdown(entries: list[dict]) -> str:
    lines = ["# Gallery", "",
             "Every example in `examples/` drawn in every kind of picture, as `epicyclic plot` and",
             "`epicyclic animate` draw it. Regenerate with `make gallery` (this page included).",
             "A transmission without an operating point is drawn in its first gear at unit input speed and",
             "torque; other gears: `epicyclic plot FILE --gear G`. Figures use each file's `[units]`.", ""]
    lines += [f"- [{e['title']}](#{e['stem']})" for e in entries]
    for e in entries:
        lines += ["", f"## {e['stem']}", "", f"**{e['title']}** — `{e['file'][3:]}`"]
        if e["description"]:
            lines += ["", e["description"]]
        notes = "; ".join(n for n in e["notes"] if n)
        if notes:
            lines += ["", f"*{notes}*"]
        for kind, picture in e["pictures"]:
            lines += ["", f"### {NAMES[kind]}", "", f"![{e['stem']}: {NAMES[kind]}]({picture})"]
        lines += ["", f"### animation of set {e['set']}", "",
                  f"![{e['stem']}: animation of set {e['set']}]({e['svg']})", "",
                  f"The animated SVG plays in a browser; [the same as GIF]({e['gif']})."]
    return "\n".join(lines) + "\n"


def page(entries: list[dict], target: Path) -> str:
    """The gallery as one HTML page next to ``target`` (images referenced relative to it)."""
    def rel(p: str) -> str:
        return Path(shutil.os.path.relpath(DOC.parent / p, target.parent)).as_posix()

    parts = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>epicyclic gallery</title>",
             "<style>body{font-family:sans-serif;max-width:80rem;margin:1rem auto;padding:0 1rem}"
             "img,object{max-width:100%;border:1px solid #ddd;margin:.3rem 0}</style></head><body>",
             "<h1>Gallery</h1>"]
    for e in entries:
        parts.append(f"<h2>{html.escape(e['stem'])}</h2><p><b>{html.escape(e['title'])}</b> "
                     f"{html.escape('; '.join(n for n in e['notes'] if n))}</p>")
        for kind, picture in e["pictures"]:
            parts.append(f"<h3>{NAMES[kind]}</h3><img src='{rel(picture)}' alt='{kind}'>")
        parts.append(f"<h3>animation</h3><img src='{rel(e['gif'])}' alt='gif'> "
                     f"<img src='{rel(e['svg'])}' alt='svg' style='width:420px'>")
    parts.append("</body></html>")
    return "\n".join(parts)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--html", type=Path, help="also write an HTML page of the gallery here")
    parser.add_argument("examples", nargs="*", type=Path, help="only these files (default: all of examples/)")
    args = parser.parse_args(argv)
    files = args.examples or sorted((ROOT / "examples").glob("*.toml"))
    entries = []
    for path in files:
        entries.append(render(path))
        print(f"drew {path.name}: {', '.join(k for k, _ in entries[-1]['pictures'])}, animation")
    if not args.examples:
        DOC.write_text(markdown(entries), encoding="utf-8")
        print(f"wrote {DOC}")
        sys.path.insert(0, str(ROOT / "docs" / "figures"))
        from stamp import record

        record("gallery")  # the pictures are as new as the code that drew them (tests/docs/test_gallery.py)
    if args.html:
        args.html.parent.mkdir(parents=True, exist_ok=True)
        args.html.write_text(page(entries, args.html.resolve()), encoding="utf-8")
        print(f"wrote {args.html}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
