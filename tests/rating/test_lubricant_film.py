"""The lubricant in the contact (epicyclic.rating.lubricant_film): oil properties and the Dowson–Higginson film.

Sources: Dowson, D.; Higginson, G. R.: Elasto-hydrodynamic lubrication, Pergamon 1966 (h/R = 1.6 G^0.6 U^0.7
W^-0.13, written here independently in SI units); the oil formulas of ISO/TR 15144-1:2014, eqs. (8)–(21)
checked as closed forms (the standard's text was not reachable, see tests/rating/test_micropitting.py).
"""

import math

import pytest

from epicyclic.rating import RatingError
from epicyclic.rating.lubricant_film import (
    OilProperties,
    film_thickness,
    reduced_modulus,
)

E_R = reduced_modulus(206000.0, 0.3, 206000.0, 0.3)
VG220 = OilProperties(220.0, 19.0)


def test_reduced_modulus_is_two_pi_z_e_squared():
    assert E_R == pytest.approx(2 / (2 * (1 - 0.3 ** 2) / 206000.0), rel=1e-12)
    assert math.sqrt(E_R / (2 * math.pi)) == pytest.approx(189.81, abs=0.01)     # Z_E of steel


def test_film_formula_is_dowson_higginson_in_si_units():
    rho, eta, alpha, v_sum, p = 12.0, 0.03, 1.8e-8, 10.0, 1200.0       # mm, Pa s, m²/N, m/s, N/mm²
    e_prime = E_R * 1e6                                               # Pa
    radius = rho * 1e-3                                               # m
    line_load = 2 * math.pi * radius * (p * 1e6) ** 2 / e_prime       # Hertz: p² = w E'/(2π R), N/m
    g, u, w = alpha * e_prime, eta * (v_sum / 2) / (e_prime * radius), line_load / (e_prime * radius)
    h_si = 1.6 * g ** 0.6 * u ** 0.7 * w ** -0.13 * radius            # m
    standard = film_thickness(rho, 1e6 * alpha * E_R, eta * v_sum / (2000 * E_R * rho), 2 * math.pi * p ** 2 / E_R ** 2)
    assert float(standard) == pytest.approx(h_si * 1e6, rel=1e-12)     # µm


def test_oil_properties_closed_forms():
    # ρ_15 = 43.37 lg ν40 + 805.5, ρ_θ = ρ_15 − 0.7 (θ − 16), α_θ = α_38 (1 + 516 (1/(θ+273) − 1/311))
    assert VG220.density_15 == pytest.approx(43.37 * math.log10(220) + 805.5)
    assert float(VG220.density(90.0)) == pytest.approx(VG220.density_15 - 0.7 * 74.0)
    assert float(VG220.kinematic_viscosity(40.0)) == pytest.approx(220.0, rel=1e-9)
    assert VG220.alpha_38 == pytest.approx(2.657e-8 * float(VG220.dynamic_viscosity(38.0)) ** 0.1348)
    assert float(VG220.pressure_viscosity(38.0)) == pytest.approx(VG220.alpha_38, rel=1e-12)
    assert float(VG220.pressure_viscosity(90.0)) < VG220.alpha_38
    pao = OilProperties(220.0, 25.0, "pao")
    assert pao.lubricant_factor == 0.8 and pao.alpha_38 < VG220.alpha_38
    with pytest.raises(RatingError, match="lubricant_type"):
        OilProperties(220.0, 19.0, "castor")
    with pytest.raises(RatingError, match="viscosity_40 must exceed"):
        OilProperties(20.0, 30.0)
