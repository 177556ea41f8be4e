"""The compiled screening kernel (numba) returns exactly the numpy path's placements.

The kernel (:mod:`epicyclic.synthesis.kernel`) fuses the range test over boxes (corner values of
multilinear determinants, Moore 1966), the union/count test and Glover's (1967) matching into
compiled loops doing the same IEEE operations in the same order, so the placements, their boxes and
their order must be *equal*, not close: checked on the whole Simpson space, a sample of the ZF 8HP
space (published ratios) and random targets on three-set mechanisms.  Without numba the package
runs its numpy path (checked in a fresh interpreter with ``EPICYCLIC_NUMBA=0``).
"""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from epicyclic.synthesis import SynthesisSpec, enumerate_mechanisms, kernel
from epicyclic.synthesis.mechanisms import canonical_members
from epicyclic.synthesis.screening import layout, screen
from epicyclic.synthesis.search import _mechanisms, bounds

EIGHT_FORWARD = np.array([4.6957, 3.1304, 2.1039, 1.6667, 1.2845, 1.0, 0.8392, 0.6667])  # ZF 8HP 70
EIGHT_REVERSE = np.array([-3.2968])

needs_numba = pytest.mark.skipif(not kernel.AVAILABLE, reason="numba is not installed (pip install epicyclic[fast])")


def _same(mech, lay, low, high, forward, reverse, tolerance, levels, **flags):
    args = (mech, lay, low, high, np.asarray(forward, float), np.asarray(reverse, float), tolerance)
    compiled = screen(*args, levels=levels, kernel=True, **flags)
    reference = screen(*args, levels=levels, kernel=False, **flags)
    assert compiled == reference, mech
    return len(compiled[0])


@needs_numba
def test_compiled_equals_numpy_on_the_simpson_space():
    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"tolerance": 0.01})
    low, high = bounds(spec)
    kept = 0
    for engaged in spec.engaged:
        for mech in _mechanisms(spec, engaged):
            lay = layout(mech.shafts, spec.brakes, spec.clutches, engaged)
            for prune in (True, False):
                kept += _same(mech, lay, low, high, spec.forward, spec.reverse, spec.tolerance, spec.levels,
                              prune=prune)
    assert kept > 0


@needs_numba
def test_compiled_equals_numpy_on_a_sample_of_the_8hp_space():
    """The ZF 8HP's mechanism (S1=S2, C1=R4, R2=S3, R3=S4) and two drawn at random, 8HP 70 ratios."""
    mechs = enumerate_mechanisms(("simple",) * 4, 4, max_members_per_shaft=2)
    eight = canonical_members((0, 1, 2, 0, 3, 4, 3, 5, 6, 5, 2, 7), ("simple",) * 4)
    lay = layout(8, 2, 3, 3)
    low, high = np.full(4, -4.0), np.full(4, -1.5)
    rng = np.random.default_rng(7)
    sample = [m for m in mechs if m.members == eight] + [mechs[k] for k in rng.choice(len(mechs), 2, replace=False)]
    kept = sum(_same(m, lay, low, high, EIGHT_FORWARD, EIGHT_REVERSE, 0.01, 2) for m in sample)
    assert len(sample) == 3 and kept > 0


@needs_numba
def test_compiled_equals_numpy_on_random_targets():
    mechs = enumerate_mechanisms(("simple",) * 3, 3)
    lay = layout(6, 2, 2, 2)
    low, high = np.full(3, -4.5), np.full(3, -1.4)
    rng = np.random.default_rng(11)
    kept = 0
    for k in rng.choice(len(mechs), size=12, replace=False):
        forward = np.sort(rng.uniform(0.6, 4.0, size=3))[::-1]
        kept += _same(mechs[k], lay, low, high, forward, [-rng.uniform(1.5, 4.0)], 0.02, 2)
    assert kept > 0


def test_kernel_asked_for_without_numba_is_refused(monkeypatch):
    monkeypatch.setattr(kernel, "AVAILABLE", False)
    assert kernel.use_kernel(None) is False and kernel.use_kernel(False) is False
    with pytest.raises(ImportError, match=r"epicyclic\[fast\]"):
        kernel.use_kernel(True)


def test_the_package_screens_without_numba():
    """A fresh interpreter with the kernel switched off: numpy path, the same placements as this one's."""
    code = ("import numpy as np; from epicyclic.synthesis import kernel, enumerate_mechanisms;"
            "from epicyclic.synthesis.screening import layout, screen;"
            "m = enumerate_mechanisms(('simple',) * 2, 3, free_input=True)[3];"
            "p, n = screen(m, layout(m.shafts, 2, 2, 2), np.full(2, -4.0), np.full(2, -1.5),"
            " np.array([2.46, 1.46, 1.0]), np.array([-2.18]), 0.01);"
            "print(kernel.AVAILABLE, n, [(q.input, q.output, q.elements, q.boxes) for q in p])")
    env = dict(os.environ, EPICYCLIC_NUMBA="0")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True).stdout
    m = enumerate_mechanisms(("simple",) * 2, 3, free_input=True)[3]
    p, n = screen(m, layout(m.shafts, 2, 2, 2), np.full(2, -4.0), np.full(2, -1.5), np.array([2.46, 1.46, 1.0]),
                  np.array([-2.18]), 0.01)
    assert out.strip() == f"False {n} {[(q.input, q.output, q.elements, q.boxes) for q in p]}"


@needs_numba
def test_compiled_four_engaged_cofactors_are_bit_equal():
    """Four engaged (9 shafts): the compiled Laplace expansion gives the numpy path's determinants bit for bit."""
    from epicyclic.synthesis.kinematics import combination_determinants, corner_points, element_rows

    mechs = enumerate_mechanisms(("simple",) * 4, 5)
    rng = np.random.default_rng(5)
    lay = layout(9, 1, 4, 4)
    corners = corner_points(np.full(4, -4.0), np.full(4, -1.5))
    for k in rng.choice(len(mechs), size=1, replace=False):
        args = (mechs[k], corners, lay.combos, element_rows(9))
        compiled, reference = combination_determinants(*args, compiled=True), combination_determinants(*args)
        assert compiled.tobytes() == reference.tobytes()  # bit-equal, signed zeros included
    funcs = rng.normal(size=(3, 45, 5)) * 10.0 ** rng.integers(-8, 8, size=(3, 45, 1))  # scales far apart
    from epicyclic.synthesis.kinematics import _cofactors

    assert _cofactors(funcs, lay.combos, True).tobytes() == _cofactors(funcs, lay.combos).tobytes()


@needs_numba
def test_compiled_equals_numpy_with_four_engaged():
    """A 9-shaft mechanism, 1 brake + 4 clutches, four targets that thousands of placements pass: equal placements."""
    mechs = enumerate_mechanisms(("simple",) * 4, 5)
    lay = layout(9, 1, 4, 4)
    kept = _same(mechs[3], lay, np.full(4, -4.0), np.full(4, -1.5), np.array([3.2, 1.9, 1.0]), [-2.6], 0.01, 1)
    assert kept > 1000


@needs_numba
def test_the_compiled_loops_are_cached_in_the_user_cache_folder(tmp_path):
    """Issue 30: numba's cache went into the installed package's folder (fails on a read-only install)."""
    code = "from epicyclic.synthesis import kernel; import numba; print(kernel.cache_directory(), numba.config.CACHE_DIR)"
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["XDG_CACHE_HOME"] = str(tmp_path)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True).stdout
    folder, used = out.split()
    assert folder == used == str(tmp_path / "epicyclic" / "numba")
    env["EPICYCLIC_CACHE_DIR"] = str(tmp_path / "mine")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True).stdout
    assert out.split() == [str(tmp_path / "mine" / "numba")] * 2
