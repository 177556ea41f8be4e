"""DXF export of a five-planet set: the B-spline outline against a naive polyline of the dense profile (issue 31).

Set 21/39/99, m_n = 2 mm, five planets (T/N = 120/5 = 24: equally spaced), A_sn = -50 µm. Timed (after
one warm-up run: imports, first profile): generating the five outlines at an assembling phase and writing
the DXF. The naive baseline writes the same generated profiles as one LINE per pair of their points (what
a program without curve fitting does), through the same ezdxf; both files are read back and their
entities counted. The target: the DXF of a five-planet set in at most 1 s.

Run:  .venv/bin/python benchmarks/bench_export.py
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

import ezdxf

from epicyclic import PlanetarySet
from epicyclic.export import set_drawing
from epicyclic.export.dxf import write_dxf
from epicyclic.geometry import SetGeometry


def geometry() -> SetGeometry:
    p = PlanetarySet.simple("P5", sun="s", ring="r", carrier="c", z_sun=21, z_planet=39, z_ring=99, planets=5)
    return SetGeometry.create(p, module=2.0, thickness_allowance=-0.05)


def spline_export(path: Path) -> None:
    write_dxf(set_drawing(geometry()), path)


def naive_export(path: Path) -> None:
    drawing = set_drawing(geometry())  # the same generated profiles, written point to point
    doc = ezdxf.new("R2010")
    msp = doc.modelspace()
    for gear in drawing.gears:
        pts = gear.dense_polygon(0.01)
        for a, b in zip(pts, list(pts[1:]) + [pts[0]]):
            msp.add_line(tuple(a), tuple(b))
    doc.saveas(path)


def timed(run, path: Path, repeat: int) -> list[float]:
    run(path)  # warm-up
    out = []
    for _ in range(repeat):
        start = time.perf_counter()
        run(path)
        out.append(time.perf_counter() - start)
    return out


def main(repeat: int = 5) -> None:
    with tempfile.TemporaryDirectory() as folder:
        fast, slow = Path(folder) / "spline.dxf", Path(folder) / "naive.dxf"
        t_fast = timed(spline_export, fast, repeat)
        t_slow = timed(naive_export, slow, max(1, repeat // 2))
        n_fast = len(ezdxf.readfile(fast).modelspace())
        n_slow = len(ezdxf.readfile(slow).modelspace())
        size_fast, size_slow = fast.stat().st_size, slow.stat().st_size
    print(f"B-spline outline: median {statistics.median(t_fast):.3f} s (min {min(t_fast):.3f}), "
          f"{n_fast} entities, {size_fast / 1e6:.2f} MB")
    print(f"naive LINE polyline: median {statistics.median(t_slow):.3f} s, {n_slow} entities, "
          f"{size_slow / 1e6:.2f} MB")
    print(f"target <= 1 s: {'met' if statistics.median(t_fast) <= 1.0 else 'NOT met'}; "
          f"{statistics.median(t_slow) / statistics.median(t_fast):.1f}x faster than the naive export")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)
