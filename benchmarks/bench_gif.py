"""Benchmark: the animation's GIF, still parts drawn once and one palette, vs matplotlib's PillowWriter (same run).

Run: ``.venv/bin/python benchmarks/bench_gif.py``.  The baseline is the writer before issue 30: a
``FuncAnimation`` saved with ``PillowWriter`` (the whole figure drawn twice a frame, each frame its own
palette); the writer of :func:`epicyclic.plotting._svg.write_gif` draws the caption once, only the gears per
frame (blitting), and maps every frame to the first frame's palette.  One simple set, 48 frames, 480 px.
"""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

from epicyclic.io import load_train_file
from epicyclic.plotting import _svg
from epicyclic.plotting.animation import planetary_animation

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "simple_set_ring_held_sun_drives.toml"


def pillow_writer(fig, update, moving, frames, fps, path):
    """The baseline: matplotlib's own animation writer (as the GIF was written before)."""
    from matplotlib.animation import FuncAnimation, PillowWriter

    FuncAnimation(fig, update, frames=frames, blit=False).save(str(path), writer=PillowWriter(fps=fps), dpi=fig.dpi)


def timed(anim, path: Path, repeat: int = 3) -> tuple[float, int]:
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        anim.gif(path)
        best = min(best, time.perf_counter() - start)
    return best, os.path.getsize(path)


def main() -> None:
    anim = planetary_animation(load_train_file(EXAMPLE).solve())
    with tempfile.TemporaryDirectory() as folder:
        new = timed(anim, Path(folder) / "new.gif")
        fast = _svg._save_frames
        _svg._save_frames = pillow_writer
        try:
            old = timed(anim, Path(folder) / "old.gif", repeat=2)
        finally:
            _svg._save_frames = fast
    print(f"GIF of one simple set, {anim.frames} frames, {anim.size} px")
    print(f"  PillowWriter (baseline): {old[0]:.2f} s, {old[1] / 1024:.0f} KiB")
    print(f"  still parts once, one palette: {new[0]:.2f} s, {new[1] / 1024:.0f} KiB "
          f"({old[0] / new[0]:.1f}x faster, {old[1] / new[1]:.2f}x smaller)")


if __name__ == "__main__":
    main()
