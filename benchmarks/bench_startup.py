"""Start-up: `epicyclic analyze examples/brandenberger_1952.toml` against `python -c "import numpy"`.

The baseline is the least any numpy program pays: start Python and import numpy. The command
starts Python, imports the CLI (typer, numpy, the engine), reads the file (units without pint),
solves and prints the table. Both run as fresh processes, alternating, so that a busy machine
slows both alike; the figure is the ratio of the medians (the minima are printed too).
Target (issue 11): ratio ≤ 3.

The package's bytecode is compiled first (``compileall``), as pip does when it installs a package:
numpy's is, and with PYTHONDONTWRITEBYTECODE set (as on some CI machines) an editable checkout would
otherwise compile every module from source at each start — about 80 ms more, measured 2026-11-23.

Run:  .venv/bin/python benchmarks/bench_startup.py [runs]
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
BASELINE = [sys.executable, "-c", "import numpy"]
COMMAND = [str(BIN / "epicyclic"), "analyze", "examples/brandenberger_1952.toml"]


def wall(command: list[str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed: {done.stderr.decode()[-500:]}")
    return elapsed


def main(runs: int = 21) -> None:
    import compileall

    import epicyclic

    compileall.compile_dir(Path(epicyclic.__file__).parent, quiet=1)  # see the module docstring
    wall(BASELINE), wall(COMMAND)  # warm the file cache
    base, command = [], []
    for _ in range(runs):
        base.append(wall(BASELINE))
        command.append(wall(COMMAND))
    ratio = statistics.median(command) / statistics.median(base)
    print(f"runs (alternating)                        {runs:>8d}")
    print(f"python -c 'import numpy'   median / min   {statistics.median(base) * 1e3:8.1f} / {min(base) * 1e3:6.1f} ms")
    print(f"epicyclic analyze (Bild 10) median / min  {statistics.median(command) * 1e3:8.1f} / {min(command) * 1e3:6.1f} ms")
    print(f"ratio of medians                          {ratio:8.2f}   (target ≤ 3)")
    print(f"ratio of minima                           {min(command) / min(base):8.2f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 21)
