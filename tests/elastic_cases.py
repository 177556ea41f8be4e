"""Published example systems of the lumped-parameter literature, with their inputs.

* Lin & Parker 1999 (J. Vib. Acoust. 121, 316–321), Table 1 (parameters) and Table 2 (natural
  frequencies, Hz, for 3, 4 and 5 equally spaced planets).  The paper itself was not reachable
  from here; the table values are those transcribed, with the parameters, in the test file
  ``tests/test_lin_parker_99.py`` of the open drivetrain package of G. F. S. Rebouças
  (github.com/gfsReboucas, "Lin and Parker 1999 Table 1 / Lin thesis Table C.1").
* Cooley & Parker 2012 (J. Vib. Acoust. 134, 061014), Table 1 (parameters) and the natural
  frequencies at Ω = 0 divided by √(k_p/m_p), from the same transcription.
"""

import math

from epicyclic.elastic.lumped import Body, PlanetaryLumpedModel, equally_spaced


def _body(mass, inertia_over_r2, diameter_mm):
    r = diameter_mm * 1e-3 / 2
    return Body(mass, inertia_over_r2 * r * r, r)


def lin_parker_1999(planets: int, angles=None) -> PlanetaryLumpedModel:
    """Table 1: m/(I/r²) kg: carrier 5.43/6.29, ring 2.35/3.00, sun 0.4/0.39, planet 0.66/0.61;
    base diameters sun 77.4, ring 275, planet 100.3 mm, carrier 176.8 mm (twice the centre distance);
    k_sp = k_rp = 5e8, k_p = k_c = k_r = k_s = 1e8 N/m, k_ru = 1e9 N/m, k_cu = k_su = 0; α = 24.6°."""
    r_r = 275.0e-3 / 2
    return PlanetaryLumpedModel(
        _body(5.43, 6.29, 176.8), _body(2.35, 3.00, 275.0), _body(0.4, 0.39, 77.4), _body(0.66, 0.61, 100.3),
        angles or equally_spaced(planets), 5e8, 5e8, 1e8,
        supports={"carrier": (1e8, 0.0), "ring": (1e8, 1e9 * r_r ** 2), "sun": (1e8, 0.0)},
        sun_pressure_angle=math.radians(24.6), ring_pressure_angle=math.radians(24.6))


#: Lin & Parker 1999, Table 2: rotational (simple), translational (double), planet (N − 3) modes, Hz.
LIN_PARKER_1999 = {
    3: {"rotational": [0.0, 1475.7, 1930.3, 2658.3, 7462.8, 11775.3],
        "translational": [743.2, 1102.4, 1896.0, 2276.4, 6986.3, 9647.9], "planet": []},
    4: {"rotational": [0.0, 1536.6, 1970.6, 2625.7, 7773.6, 13071.1],
        "translational": [727.0, 1091.0, 1892.8, 2342.5, 7189.9, 10437.6], "planet": [1808.2, 5963.8, 6981.7]},
    5: {"rotational": [0.0, 1567.4, 2006.1, 2614.8, 8065.4, 14253.1],
        "translational": [710.0, 1072.0, 1888.1, 2425.3, 7382.4, 11172.3], "planet": [1808.2, 5963.8, 6981.7]},
}


def cooley_parker_2012(planets: int) -> PlanetaryLumpedModel:
    """Table 1: m/(I/r²) kg: carrier 12.0/6.80, ring 7.64/8.09, sun 3.0/1.75, planet 1.86/1.25;
    base diameters sun 55.75, ring 109.7, planet 27.0 mm, carrier 88.6 mm; k_sp = k_rp = 1e8,
    k_s = 2e7, k_r = 1e8, k_c = 5e7, k_p = 1e7 N/m; k_su = 2e7, k_ru = k_cu = 1e8 N/m; α = 20°."""
    r = lambda d: d * 1e-3 / 2  # noqa: E731
    return PlanetaryLumpedModel(
        _body(12.0, 6.80, 88.6), _body(7.64, 8.09, 109.7), _body(3.0, 1.75, 55.75), _body(1.86, 1.25, 27.0),
        equally_spaced(planets), 1e8, 1e8, 1e7,
        supports={"carrier": (5e7, 1e8 * r(88.6) ** 2), "ring": (1e8, 1e8 * r(109.7) ** 2),
                  "sun": (2e7, 2e7 * r(55.75) ** 2)})


#: Cooley & Parker 2012 at Ω = 0: ω/√(k_p/m_p) by type.
COOLEY_PARKER_2012 = {
    3: {"rotational": [0.9296, 1.090, 1.358, 1.931, 5.566, 7.741],
        "translational": [0.7432, 1.018, 1.265, 1.487, 4.976, 6.282], "planet": []},
    4: {"rotational": [0.9077, 1.046, 1.317, 2.013, 5.809, 8.383],
        "translational": [0.7199, 1.001, 1.317, 1.481, 5.153, 6.488], "planet": [0.9617, 4.320, 5.672]},
    5: {"rotational": [0.8802, 1.019, 1.281, 2.090, 6.030, 8.986],
        "translational": [0.6992, 0.9863, 1.344, 1.496, 5.317, 6.693], "planet": [0.9617, 4.320, 5.672]},
}
