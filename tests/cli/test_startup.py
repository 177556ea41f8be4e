"""Fast start: heavy modules are imported only by the commands that need them (issue 11).

The start-up time itself is measured by benchmarks/bench_startup.py (docs/performance.md); this
test guards the cause: what a plain import, and `epicyclic analyze` of the sources' units, load.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("matplotlib", "pint", "rich", "epicyclic.geometry", "epicyclic.plotting")


def loaded_after(code: str) -> list[str]:
    probe = f"{code}\nimport json, sys\nprint(json.dumps(sorted(sys.modules)))"
    done = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("module", ["epicyclic", "epicyclic.cli.main"])
def test_importing_loads_nothing_heavy(module):
    loaded = loaded_after(f"import {module}")
    heavy = HEAVY + ("epicyclic.transmission", "epicyclic.explain", "epicyclic.analysis")
    assert [m for m in heavy if m in loaded] == []
    if module == "epicyclic":
        assert "typer" not in loaded


def test_analyze_with_the_sources_units_loads_nothing_heavy():
    code = ("from epicyclic.cli.main import app\n"
            "try:\n    app(['analyze', 'examples/brandenberger_1952.toml'], standalone_mode=False)\n"
            "except SystemExit:\n    pass")
    loaded = loaded_after(code)
    assert "epicyclic.solver" in loaded  # it did solve
    assert [m for m in HEAVY if m in loaded] == []
