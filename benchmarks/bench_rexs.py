"""Reading REXS: epicyclic's safe reader and mapping vs a bare parse of the same file (issue 19).

The FVA-Workbench planetary stage (examples/rexs, 112 KB, 97 components, 140 relations) and the
Bearinx two-stage gearbox (44 KB, 4 load cases): the naive baseline is ``xml.etree.ElementTree``
parsing the bytes (no entity protection, no limits, no mapping); epicyclic's path is
``epicyclic.io.load_train_file`` (defusedxml parse with depth and count limits, typed values, members,
mapping onto the train document, the train file reader).  The JSON container of the gearbox is timed too.

Run:  .venv/bin/python benchmarks/bench_rexs.py [repeats]
"""

from __future__ import annotations

import json
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

from epicyclic.io import load_train_file

ROOT = Path(__file__).resolve().parents[1]
FILES = [ROOT / "examples" / "rexs" / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexs",
         ROOT / "examples" / "rexs" / "FVA-Industriegetriebe_2stufig_1-4.rexs",
         ROOT / "tests" / "exchange" / "fixtures" / "FVA-Industriegetriebe_2stufig_1-4.rexsj"]


def best(function, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main(repeats: int = 20) -> None:
    print(f"{'file':48s} {'bare parse [ms]':>16s} {'epicyclic [ms]':>15s} {'ratio':>6s}")
    for path in FILES:
        data = path.read_bytes()
        parse = ET.fromstring if path.suffix == ".rexs" else json.loads
        bare = best(lambda data=data, parse=parse: parse(data), repeats)
        ours = best(lambda path=path: load_train_file(path), repeats)
        print(f"{path.name:48s} {bare * 1e3:16.2f} {ours * 1e3:15.2f} {ours / bare:6.1f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 20)
