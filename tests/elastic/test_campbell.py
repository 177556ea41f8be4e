"""Campbell diagram: crossings against the closed form n = 60 f/(l z_s |r_s − r_c|) and the phasing rules."""

import math

import numpy as np
import pytest

from elastic_cases import lin_parker_1999
from epicyclic.elastic import ElasticError, frequencies_at_speeds, natural_modes
from epicyclic.elastic.campbell import campbell_diagram

Z_S, Z_R = 31, 69  # (31 + 69)/4 = 25: assembles with 4 equally spaced planets
RATIOS = {"sun": 1.0, "carrier": Z_S / (Z_S + Z_R)}  # ring fixed (Willis)


def test_crossings_at_rest_are_the_closed_form():
    model = lin_parker_1999(4)
    rest = natural_modes(model)
    c = campbell_diagram(model, Z_S, Z_R, RATIOS, np.linspace(0.0, 30000.0, 3001), mesh_harmonics=2,
                         gyroscopic=False)
    rel = abs(RATIOS["sun"] - RATIOS["carrier"])
    mesh1 = [x for x in c.crossings if x.order == "mesh x1"]
    expected = 60.0 * rest.frequencies / (Z_S * rel)
    assert len(mesh1) == np.count_nonzero((expected > 0) & (expected <= 30000.0))
    for x in mesh1:
        assert x.speed == pytest.approx(expected[x.mode - 1], rel=1e-9)
        assert x.frequency == pytest.approx(rest.frequencies[x.mode - 1], rel=1e-9)
    # phasing: z_s = 31, N = 4: (31 + 1)/4 integer -> the first harmonic excites only translational modes
    for x in mesh1:
        assert x.excited == (x.kind == "translational")
    # second harmonic: 62/4 not integer, (62 +- 1)/4 not integer -> planet modes only
    for x in c.crossings:
        if x.order == "mesh x2":
            assert x.excited == (x.kind == "planet")


def test_operating_range_filters_and_renders():
    model = lin_parker_1999(4)
    c = campbell_diagram(model, Z_S, Z_R, RATIOS, np.linspace(0.0, 30000.0, 301), operating=(5000.0, 8000.0))
    assert c.crossings and all(5000.0 <= x.speed <= 8000.0 for x in c.crossings)
    # at speed the type comes from the gyroscopic mode shape; the phasing rule of z_s = 31, N = 4 still decides
    assert all(x.excited == (x.kind == "translational") for x in c.crossings if x.order == "mesh x1")
    assert {x.kind for x in c.crossings} <= {"rotational", "translational", "planet"}
    assert "mesh x1" in c.table() and "| order |" in c.markdown() and "<table>" in c._repr_html_()
    data = c.to_dict()
    assert data["crossings"][0]["speed_rpm"] == c.crossings[0].speed
    assert "crossings" in repr(c)


def test_vectorised_speeds_equal_a_per_point_loop():
    model = lin_parker_1999(5)
    speeds = np.linspace(0.0, 800.0, 9)
    batch = frequencies_at_speeds(model, speeds)
    one = np.vstack([frequencies_at_speeds(model, s) for s in speeds])
    assert batch == pytest.approx(one, rel=1e-10, abs=1e-8)


def test_bad_input():
    model = lin_parker_1999(3)
    with pytest.raises(ElasticError, match="ratios"):
        campbell_diagram(model, Z_S, Z_R, {"moon": 1.0}, [0.0, 1.0])
    with pytest.raises(ElasticError, match="ascending"):
        campbell_diagram(model, Z_S, Z_R, RATIOS, [1.0, 0.0])
    with pytest.raises(ElasticError, match="operating"):
        campbell_diagram(model, Z_S, Z_R, RATIOS, [0.0, 1.0], operating=(2.0, 1.0))
    with pytest.raises(ElasticError, match="mesh_harmonics"):
        campbell_diagram(model, Z_S, Z_R, RATIOS, [0.0, 1.0], mesh_harmonics=-1)
    assert math.isfinite(campbell_diagram(model, Z_S, Z_R, RATIOS, [0.0, 1.0]).natural.sum())
