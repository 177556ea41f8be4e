"""A published calculation report of a real planetary stage, reproduced to its printed digits: the geometry
of NREL 5 MW gearbox stage 1 as KISSsoft prints it (ISO 21771:2007).

Source: KISSsoft Release 03/2017 calculation report "CALCULATION OF A SPUR PLANETARY GEAR STAGE", file
``stage_01`` (NREL 5 MW reference gearbox, stage 1), in the public repository gfsReboucas/Drivetrain,
``@NREL_5MW/stage_01.rtf``; only its printed numbers are used. Inputs as printed: m_n = 45 mm, α_n = 20°,
spur, z = 19 / 17 / −56 (three planets), x = 0.6170 / 0.8021 / −0.5013 (ISO 21771 sign: the ring's z and
x are negative), tip alteration k·m_n = −10.861 mm on sun and planet, ISO 53 profiles (h_aP* = 1,
h_fP* = 1.25), centre distance a = 863.000 mm. The report's ring tooth-root and load figures are in
tests/rating/test_published_examples.py.

Tolerance: half a unit of the last printed digit, widened where the report's inputs are printed coarser
than their effect: the shifts to 4 decimals move a diameter by up to 2·m_n·0.00005 = 0.0045 mm.
"""

from __future__ import annotations

import math

import pytest

from epicyclic.geometry.gear import BasicRack, GearGeometry, MeshGeometry

RACK = BasicRack(45.0, addendum=1.0, dedendum=1.25)
TIP = 10.861 / 45.0
SUN = GearGeometry(19, RACK, 0.6170, tip_shortening=TIP)
PLANET = GearGeometry(17, RACK, 0.8021, tip_shortening=TIP)
RING = GearGeometry(56, RACK, -0.5013, internal=True)
X_DIGITS = 2 * 45.0 * 0.00005  # mm: a diameter's uncertainty from the shifts printed to 4 decimals


@pytest.mark.parametrize("gear, reference, base, tip, root", [
    (SUN, 855.000, 803.437, 978.808, 798.030),
    (PLANET, 765.000, 718.865, 905.470, 724.692),
    (RING, 2520.000, 2368.025, 2475.118, 2677.618),
], ids=["sun", "planet", "ring"])
def test_diameters_as_printed(gear, reference, base, tip, root):
    assert gear.reference_diameter == pytest.approx(reference, abs=5e-4)
    assert gear.base_diameter == pytest.approx(base, abs=5e-4)
    assert gear.tip_diameter == pytest.approx(tip, abs=X_DIGITS)
    assert gear.root_diameter == pytest.approx(root, abs=X_DIGITS)


@pytest.mark.parametrize("pinion, gear, reference_a, alpha_wt, d_w, path", [
    (SUN, PLANET, 810.000, 28.118, (910.944, 815.056), 148.093),
    (PLANET, RING, 877.500, 17.161, (752.359, 2478.359), 169.815),
], ids=["sun-planet", "planet-ring"])
def test_meshes_as_printed(pinion, gear, reference_a, alpha_wt, d_w, path):
    coaxial = MeshGeometry(pinion, gear)  # from the shifts alone: both meshes run at 863.000 mm
    assert coaxial.center_distance == pytest.approx(863.000, abs=X_DIGITS)
    mesh = MeshGeometry(pinion, gear, working_center_distance=863.000)  # as built, the report's a
    assert mesh.reference_center_distance == pytest.approx(reference_a, abs=5e-4)
    assert math.degrees(mesh.alpha_wt) == pytest.approx(alpha_wt, abs=5e-4)
    assert mesh.operating_pitch_diameters == pytest.approx(d_w, abs=5e-4)
    base_pitch = math.pi * 45.0 * math.cos(math.radians(20.0))
    assert base_pitch == pytest.approx(132.846, abs=5e-4)  # p_et as printed
    assert mesh.contact_ratio * base_pitch == pytest.approx(path, abs=X_DIGITS)  # length of path g_α
