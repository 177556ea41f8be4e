"""The ISO 6336-5 lines of the material data file against an independent transcription.

ISO 6336-5:2016, Table 1: σ_lim = A · x + B over a hardness range, per treatment and quality
grade.  The reference is the transcription with the table's row numbers in hakangunes258/mekanika
(``Services/Iso6336Material.cs``), made independently of this project's file; the ME lines also
agree with waa552/fyp-website (``data.js``).  Rows as numbered there.
"""

from __future__ import annotations

import warnings

import pytest

from epicyclic.rating import RatingError, RatingWarning
from epicyclic.rating.materials import _data, allowable_stress_numbers

# (treatment, quality, contact (A, B), bending (A, B), hardness range, Table 1 rows)
TABLE_1 = [
    ("St", "ML", (1.000, 190), (0.455, 69), (110, 210), "1, 5"),
    ("St", "MQ", (1.000, 190), (0.455, 69), (110, 210), "1, 5"),
    ("St", "ME", (1.520, 250), (0.386, 147), (110, 210), "2, 6"),
    ("St(cast)", "ML", (0.986, 131), (0.313, 62), (140, 210), "3, 7"),
    ("St(cast)", "MQ", (0.986, 131), (0.313, 62), (140, 210), "3, 7"),
    ("St(cast)", "ME", (1.143, 237), (0.254, 137), (140, 210), "4, 8"),
    ("V", "ML", (1.313, 188), (0.423, 104), (200, 360), "24, 30"),
    ("V", "MQ", (1.313, 373), (0.425, 187), (200, 360), "25, 31"),
    ("V", "ME", (2.213, 260), (0.358, 231), (200, 390), "26, 32"),
    ("V(cast)", "ML", (1.276, 298), (0.364, 161), (200, 360), "35, 39"),
    ("V(cast)", "MQ", (1.276, 298), (0.364, 161), (200, 360), "35, 39"),
    ("V(cast)", "ME", (1.350, 356), (0.356, 186), (200, 360), "36, 40"),
    ("Eh", "ML", (0.0, 1300), (0.0, 312), (600, 800), "41, 44"),
    ("Eh", "MQ", (0.0, 1500), (0.0, 425), (660, 800), "42, 45"),
    ("Eh", "ME", (0.0, 1650), (0.0, 525), (660, 800), "43, 48"),
    ("NT", "ML", (0.0, 1125), (0.0, 270), (650, 900), "56, 62"),
    ("NT", "MQ", (0.0, 1250), (0.0, 420), (650, 900), "57, 63"),
    ("NT", "ME", (0.0, 1450), (0.0, 468), (650, 900), "58, 64"),
    ("NV", "ML", (0.0, 788), (0.0, 258), (450, 650), "59, 65"),
    ("NV", "MQ", (0.0, 998), (0.0, 363), (450, 650), "60, 66"),
    ("NV", "ME", (0.0, 1217), (0.0, 432), (450, 650), "61, 67"),
]


@pytest.mark.parametrize(("treatment", "quality", "contact", "bending", "hardness_range", "rows"), TABLE_1,
                         ids=[f"{t}-{q}" for t, q, *_ in TABLE_1])
def test_every_line_is_the_table_line(treatment, quality, contact, bending, hardness_range, rows):
    low, high = hardness_range
    for x in (low, (low + high) / 2, high):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # inside the range: no warning
            h, f = allowable_stress_numbers(treatment, x, quality)
        assert h == pytest.approx(contact[0] * x + contact[1], abs=1e-9), f"Table 1 row {rows}"
        assert f == pytest.approx(bending[0] * x + bending[1], abs=1e-9), f"Table 1 row {rows}"
    # just outside the range: a warning naming the table, and the line's end value
    with pytest.warns(RatingWarning, match="ISO 6336-5:2016, Table 1"):
        assert allowable_stress_numbers(treatment, high + 10, quality) == allowable_stress_numbers(
            treatment, high, quality)
    with pytest.warns(RatingWarning, match=f"range {low}-{high}"):
        allowable_stress_numbers(treatment, low - 10, quality)


def test_the_file_holds_no_line_the_table_does_not():
    known = {(t, q) for t, q, *_ in TABLE_1}
    for treatment, lines in _data()["treatment"].items():
        for quality in lines["sigma_Hlim"]:
            assert (treatment, quality) in known, (treatment, quality)
        assert set(lines["sigma_Hlim"]) == set(lines["sigma_Flim"]) == {"ML", "MQ", "ME"}


def test_an_unknown_quality_names_the_choices():
    with pytest.raises(RatingError, match="quality must be one of ML, MQ, ME"):
        allowable_stress_numbers("Eh", 700, "MX")
