"""Regenerate the pictures of docs/plotting.md, the efficiency-map how-to and the shift map:
``.venv/bin/python docs/figures/make_figures.py``.

Brandenberger 1952, Bild 10 example (the Bild 8 situation: system I drives
relative to the carrier; in the paper's units U/min, kp·cm, PS) and a simple
set (30/24/78, ring held, sun drives).  ``make gallery`` runs this too.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from epicyclic.io import load_train_file  # noqa: E402
from epicyclic.plotting import KINDS, figure_subject, planetary_animation, save_plot  # noqa: E402

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def efficiency_map_figure() -> Path:
    """docs/how-to/efficiency-map.md: the ZF 8HP 70 with geometry and losses, gear 3, 100 × 100 points."""
    import numpy as np

    from epicyclic.losses import efficiency_map

    emap = efficiency_map(load_train_file(ROOT / "examples" / "zf_8hp70_geometry.toml"),
                          np.linspace(500, 6000, 100), np.linspace(10, 500, 100), gear="3")
    path = HERE / "zf_8hp70_gear3_map.png"
    emap.plot().savefig(path, dpi=80)
    return path


def shift_map_figure() -> Path:
    """docs/shift-map.md: the ZF 8HP 70 with spin losses, 8 gears, 90 × 70 output points, the bundled schedule."""
    import numpy as np

    from epicyclic.io.shift_schedule_csv import read_shift_schedule
    from epicyclic.transmission import CarryLimits, Transmission, shift_map

    smap = shift_map(Transmission.from_file(ROOT / "examples" / "zf_8hp70_spin_losses.toml"),
                     np.linspace(50, 9000, 90), np.linspace(10, 2100, 70), limits=CarryLimits((800, 6000), 450.0),
                     schedule=read_shift_schedule(ROOT / "examples" / "schedules" / "zf_8hp70_upshift.csv"))
    path = HERE / "shift-map-8hp.png"
    smap.plot().savefig(path, dpi=70)
    return path


def main() -> None:
    cases = {name: figure_subject(load_train_file(ROOT / "examples" / f"{stem}.toml"))
             for name, stem in (("brandenberger", "brandenberger_1952"), ("simple", "simple_set_ring_held_sun_drives"))}
    for name, s in cases.items():
        for kind in KINDS:
            print(save_plot(s.solution, kind, HERE / f"{name}_{kind}.png", dpi=90, context=s.context))
    simple, brandenberger = cases["simple"], cases["brandenberger"]
    print(planetary_animation(simple.solution, context=simple.context).save(HERE / "simple_animation.svg"))
    print(planetary_animation(simple.solution, willis=True, context=simple.context).save(HERE / "simple_willis.svg"))
    print(planetary_animation(simple.solution, frames=32, fps=12, size=300, context=simple.context)
          .gif(HERE / "simple_animation.gif", dpi=60))
    print(planetary_animation(brandenberger.solution, frames=32, fps=12, size=300, context=brandenberger.context)
          .gif(HERE / "brandenberger_animation.gif", dpi=60))
    print(efficiency_map_figure())
    print(shift_map_figure())
    from stamp import record  # beside this script

    record("figures")  # the pictures are as new as the code that drew them (tests/docs/test_gallery.py)


if __name__ == "__main__":
    main()
