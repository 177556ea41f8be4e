"""An assembled set is checked numerically (issue 31): no gear penetrates its mate, and the play is the backlash.

With the sun (or ring) held, the planet is turned about its centre until its outline first
penetrates the mate's, both ways (bisection on the dense generated outlines, each gear's boundary
as r(θ) about its centre).  For involute flanks the normal backlash is the pinion's base radius
times that angular play, j_bn = r_b1 Δφ (transverse; × cos β_b for the normal section): it must
equal ISO 21771's j_bn of the mesh (:attr:`MeshGeometry.backlash`, eqs. 62–63) and be shared
equally by both flanks (the layout centres each tooth in its space), at several meshing phases.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from epicyclic import PlanetarySet
from epicyclic.export import ExportError, set_drawing
from epicyclic.export.layout import mesh_phases
from epicyclic.geometry import SetGeometry

#: The angular play is found to 1e-9 rad; the outlines' chords leave well below 0.5 µm.
TOL_MM = 5e-4


def industrial() -> SetGeometry:
    # docs/geometry.md: 20/37/97, m = 3, x = 0.6/0.3/0.3173 (ISO), a = 87.96 mm, A_sn = -60 µm (j_bn 115.4/110.9 µm)
    p = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out", z_sun=20, z_planet=37, z_ring=97, planets=3)
    return SetGeometry.create(p, module=3.0, x_sun=0.6, x_planet=0.3, x_ring=0.3173, center_distance=87.96,
                              thickness_allowance=-0.06, face_width=30.0)


def standard() -> SetGeometry:
    p = PlanetarySet.simple("Q", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=4)
    return SetGeometry.create(p, module=2.0, thickness_allowance=-0.05)


def _polar(points: np.ndarray, centre):
    rel = points - np.asarray(centre)
    return np.arctan2(rel[:, 1], rel[:, 0]), np.hypot(rel[:, 0], rel[:, 1])


def _boundary(points, centre):
    """The outline as r(θ) about ``centre`` (each ray from the centre crosses a generated outline once)."""
    theta, radius = _polar(points, centre)
    order = np.argsort(theta)
    theta, radius = theta[order], radius[order]

    def r(at):
        return np.interp(at, theta, radius, period=2 * math.pi)
    return r


def _play(planet, mate) -> tuple[float, float]:
    """The planet's turn (about its centre, ``mate`` held) to first overlap of the exported outlines, both ways, rad.

    Overlap: a planet point inside the mate (radius below the mate's r(θ), above it for a ring) or a mate
    point inside the planet; only the points near the mesh are tested.
    """
    centre = np.asarray(planet.centre)
    pts, fixed = planet.dense_polygon(), mate.dense_polygon()
    mate_r = _boundary(fixed, (0.0, 0.0))
    planet_r = _boundary(pts, centre)  # in the planet's frame as placed; turned by ε it is r(θ - ε)
    reach = planet.tip_diameter / 2 + 0.5
    near_fixed = fixed[np.hypot(*(fixed - centre).T) < reach]
    edge = mate.tip_diameter / 2
    radius0 = np.hypot(*pts.T)
    near_pts = pts[(radius0 > edge - 0.5) if mate.internal else (radius0 < edge + 0.5)] - centre
    th_f, r_f = _polar(near_fixed, centre)

    def overlaps(eps: float) -> bool:
        c, s = math.cos(eps), math.sin(eps)
        moved = near_pts @ np.array([[c, s], [-s, c]]) + centre
        theta, radius = _polar(moved, (0.0, 0.0))
        inside = radius > mate_r(theta) if mate.internal else radius < mate_r(theta)
        return bool(inside.any() or (r_f < planet_r(th_f - eps)).any())

    assert not overlaps(0.0), "the assembled gears overlap"
    out = []
    for sign in (1.0, -1.0):
        low, high = 0.0, math.pi / planet.teeth
        assert overlaps(sign * high)
        while high - low > 1e-9:
            mid = 0.5 * (low + high)
            low, high = (low, mid) if overlaps(sign * mid) else (mid, high)
        out.append(sign * low)
    return out[0], out[1]


@pytest.mark.parametrize("phase", [0.0, 3.7, 11.0])
def test_assembled_industrial_set_has_its_backlash_at_every_phase(phase):
    geometry = industrial()
    drawing = set_drawing(geometry, phase=phase)
    sun, planet, ring = drawing.gears[0], drawing.gears[1], drawing.gears[-1]
    r_b = planet.base_diameter / 2
    for mate, mesh in ((sun, geometry.sun_mesh), (ring, geometry.ring_mesh)):
        plus, minus = _play(planet, mate)
        assert plus > 0 > minus  # no overlap as assembled
        assert r_b * (plus - minus) == pytest.approx(mesh.backlash, abs=TOL_MM)  # j_bn = r_b Δφ (spur)
        assert r_b * plus == pytest.approx(-r_b * minus, abs=TOL_MM)  # centred: half the backlash each flank


def _start_of_active_profile(mesh) -> float:
    """d_Nf1 of the pinion (ISO 21771: where the mate's tip circle meets the line of action), mm."""
    r_b1, r_b2 = mesh.gear1.base_diameter / 2, mesh.gear2.base_diameter / 2
    reach = math.sqrt((mesh.gear2.tip_diameter / 2) ** 2 - r_b2 ** 2)
    along = mesh.center_distance * math.sin(mesh.alpha_wt)
    return 2 * math.hypot(r_b1, reach - along if mesh.internal else along - reach)


def test_every_planet_of_a_four_planet_set_meshes_with_sun_and_ring():
    geometry = standard()
    drawing = set_drawing(geometry, phase=5.0)
    sun, ring = drawing.gears[0], drawing.gears[-1]
    assert len(drawing.gears) == 6
    planet_form = drawing.gears[1].profile.form_diameter
    # the sun's tip meets the planet's involute (d_Nf1 >= d_Ff1); the standard ring's tip (h_a* = 1) reaches the
    # planet's root fillet (d_Nf1 < d_Ff1, 45.22 < 45.31 mm): there the play is less than the flanks' j_bn
    assert _start_of_active_profile(geometry.sun_mesh.__class__(geometry.gears["planet"], geometry.gears["sun"],
                                                               working_center_distance=geometry.sun_mesh.center_distance)) > planet_form
    assert _start_of_active_profile(geometry.ring_mesh) < planet_form
    plays = []
    for planet in drawing.gears[1:-1]:
        r_b = planet.base_diameter / 2
        plus, minus = _play(planet, sun)
        assert plus > 0 > minus
        assert r_b * (plus - minus) == pytest.approx(geometry.sun_mesh.backlash, abs=TOL_MM)
        plus, minus = _play(planet, ring)
        assert plus > 0 > minus  # no overlap as assembled
        plays.append(r_b * (plus - minus))
    assert max(plays) == pytest.approx(geometry.ring_mesh.backlash, abs=TOL_MM)  # where the fillet is not reached
    assert min(plays) < geometry.ring_mesh.backlash - 5e-3  # the ring tip on the planet's fillet


def test_phase_rules_roll_like_the_carrier_held_train():
    # carrier held: the sun turned by θ turns the planets by -θ z_s/z_p and the ring by -θ z_s/z_r (Willis)
    theta = 0.01
    s0, p0, r0 = mesh_phases(30, 24, 78, [0.0, math.pi / 2], 0.0)
    s1, p1, r1 = mesh_phases(30, 24, 78, [0.0, math.pi / 2], theta)
    assert p1[0] - p0[0] == pytest.approx(-theta * 30 / 24, abs=1e-12)
    assert r1 - r0 == pytest.approx(-theta * 30 / 78, abs=1e-12)


def test_a_set_that_does_not_assemble_equally_is_drawn_at_the_possible_angles_with_a_warning():
    p = PlanetarySet.simple("U", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78, planets=5)
    drawing = set_drawing(SetGeometry.create(p, module=2.0, thickness_allowance=-0.05))
    assert any("check 'assembly'" in w for w in drawing.warnings)
    assert len(drawing.gears) == 7


def test_pointed_teeth_are_refused_and_undercut_warned():
    p = PlanetarySet.simple("X", sun="s", ring="r", carrier="c", z_sun=12, z_planet=24, z_ring=60, planets=3)
    with pytest.raises(ExportError, match="check 'tip thickness'"):
        set_drawing(SetGeometry.create(p, module=2.0, x_sun=1.2, x_planet=-1.2))
    drawing = set_drawing(SetGeometry.create(p, module=2.0, thickness_allowance=-0.05))
    assert any("check 'undercut'" in w for w in drawing.warnings)


def test_only_simple_sets_are_laid_out():
    p = PlanetarySet.double_planet("D", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=18, z_planet_ring=18,
                                   z_ring=90, planets=3)
    with pytest.raises(ExportError, match="only simple sets"):
        set_drawing(SetGeometry.create(p, module=2.0))
