"""The public loss functions refuse what a hostile user gives them, with the project's own errors (issue 20).

Each case was a wrong number or a bare Python/numpy exception before: ``mesh_efficiency(-0.1, 0.2)``
gave 1.02, ``mesh_efficiency(2, 0.9)`` −0.8, ``schlenk_friction`` with viscosity 0 and
``undercut_limit(0)`` a ZeroDivisionError, ``efficiency_map`` any number of points and a speed/torque
shape mismatch in ``solve_batch_with_losses`` numpy's "shape mismatch".
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic.errors import EpicyclicError, OperatingPointError
from epicyclic.geometry import undercut
from epicyclic.geometry.errors import GeometryError
from epicyclic.io import load_train_file
from epicyclic.limits import MAX_MAP_POINTS, LimitError
from epicyclic.losses import LossModelError, efficiency_map, mesh_efficiency, schlenk_friction, solve_batch_with_losses

FILE = "examples/geometry_simple_set.toml"


@pytest.mark.parametrize("friction, loss_factor, argument", [
    (-0.1, 0.2, "friction"),            # gave 1.02
    (2.0, 0.9, "friction"),             # gave -0.8 (μ ≥ 1)
    (0.9, 1.5, "loss_factor"),          # μ H_V = 1.35 ≥ 1: gave -0.35
    (0.05, -0.2, "loss_factor"),
    (float("nan"), 0.2, "friction"),
    (0.05, float("inf"), "loss_factor"),
    (np.array([0.05, -0.01]), 0.2, "friction"),
    ("0.05", 0.2, "friction"),
    (True, 0.2, "friction"),
])
def test_mesh_efficiency_refuses(friction, loss_factor, argument):
    with pytest.raises(LossModelError, match=argument):
        mesh_efficiency(friction, loss_factor)


def test_mesh_efficiency_still_computes():
    # Fernandes et al. 2015 (C40 gear): μ = 0.0256, H_V = 0.1986 → η = 1 − μ H_V
    assert mesh_efficiency(0.0256, 0.1986) == pytest.approx(1 - 0.0256 * 0.1986, rel=1e-15)
    assert isinstance(mesh_efficiency(0.0256, 0.1986), float)
    assert mesh_efficiency(np.array([0.0, 0.05]), 0.2).tolist() == pytest.approx([1.0, 0.99])
    assert mesh_efficiency(0.0, 0.2) == 1.0


@pytest.mark.parametrize("keyword, value", [
    ("viscosity", 0.0), ("viscosity", -1.0), ("viscosity", float("nan")), ("roughness", 0.0),
    ("radius", 0.0), ("lubricant_factor", 0.0),
])
def test_schlenk_friction_refuses(keyword, value):
    args = dict(load_per_width=159.3, sum_velocity=5.27, radius=8.38, viscosity=49.85, roughness=0.355,
                lubricant_factor=0.65)
    args[keyword] = value
    with pytest.raises(LossModelError, match=keyword):
        schlenk_friction(**args)


def test_schlenk_friction_refuses_a_load_that_is_no_number():
    with pytest.raises(LossModelError, match="load_per_width"):
        schlenk_friction("heavy", 5.0, 8.0, 50.0, 0.4)


@pytest.mark.parametrize("kwargs, argument", [
    ({"pressure_angle": 0}, "pressure_angle"), ({"pressure_angle": 90}, "pressure_angle"),
    ({"pressure_angle": float("nan")}, "pressure_angle"), ({"helix_angle": 90}, "helix_angle"),
    ({"addendum": 0}, "addendum"), ({"addendum": -1}, "addendum"),
])
def test_undercut_limit_refuses(kwargs, argument):
    with pytest.raises(GeometryError, match=argument):
        undercut.undercut_limit(**kwargs)


def test_undercut_limit_still_computes():
    # z_g = 2/sin²20° (DIN 3960)
    assert undercut.undercut_limit(20.0) == pytest.approx(2 / math.sin(math.radians(20)) ** 2)


def test_efficiency_map_has_the_command_line_point_limit():
    f = load_train_file(FILE)
    speeds = np.linspace(100, 6000, 1001)
    torques = np.linspace(1, 500, MAX_MAP_POINTS // 1001 + 1)
    with pytest.raises(LimitError, match="efficiency_map: speeds × torques.*1,000,000|at most 1000000"):
        efficiency_map(f, speeds, torques)


def test_solve_batch_with_losses_shape_mismatch_names_the_arguments():
    f = load_train_file(FILE)
    with pytest.raises(OperatingPointError, match=r"speeds\['in'\] has shape \(3,\).*torques\['in'\] has shape \(4,\)"):
        solve_batch_with_losses(f.train, dict(f.losses), speeds={"in": np.full(3, 1000.0)},
                                torques={"in": np.ones(4)}, drives=["in"], loads=["out"])
    # and it is one of the project's errors (exit 2 on the command line), not numpy's
    assert issubclass(OperatingPointError, EpicyclicError)
