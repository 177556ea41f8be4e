"""Regenerate the pictures of docs/plotting.md: ``.venv/bin/python docs/figures/make_figures.py``.

Brandenberger 1952, Bild 10 example (the Bild 8 situation: system I drives
relative to the carrier) and a simple set (30/24/78, ring held, sun drives).
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from epicyclic import solve  # noqa: E402
from epicyclic.demo import brandenberger_1952  # noqa: E402
from epicyclic.io import load_train_file  # noqa: E402
from epicyclic.plotting import KINDS, planetary_animation, save_plot  # noqa: E402

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def main() -> None:
    cases = {
        "brandenberger": solve(*brandenberger_1952()),
        "simple": load_train_file(ROOT / "examples" / "simple_set_ring_held_sun_drives.toml").solve(),
    }
    for name, solution in cases.items():
        for kind in KINDS:
            print(save_plot(solution, kind, HERE / f"{name}_{kind}.png", dpi=90))
    simple = cases["simple"]
    print(planetary_animation(simple).save(HERE / "simple_animation.svg"))
    print(planetary_animation(simple, willis=True).save(HERE / "simple_willis.svg"))
    print(planetary_animation(simple, frames=32, fps=12).gif(HERE / "simple_animation.gif", dpi=50))
    print(planetary_animation(cases["brandenberger"], frames=32, fps=12).gif(HERE / "brandenberger_animation.gif",
                                                                            dpi=50))


if __name__ == "__main__":
    main()
