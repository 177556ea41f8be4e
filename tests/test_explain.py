"""The worked solution (epicyclic.explain)."""

from __future__ import annotations

from pathlib import Path

import pytest

from epicyclic import Brake, Clutch, GearTrain, OperatingPoint, PlanetarySet, solve
from epicyclic.demo import brandenberger_1952
from epicyclic.errors import EpicyclicError
from epicyclic.explain import LANGUAGES, explain
from epicyclic.io import load_train_file

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_brandenberger_equation_7_with_numbers_in_core_units():
    # Brandenberger 1952, eq. (7): M1'(n1 − n3)η1η2 + M2'(n2 − n3) = 0; core units N·m, 1/min.
    e = explain(solve(*brandenberger_1952()))
    text = e.text()
    assert "M1'·(n1 − n3)·η0 + M2'·(n2 − n3) = 0" in text
    assert "(-6.53205)·(2739.84 − 5280)·0.9 + 3.95059·(1500 − 5280)" in text
    # eq. (9) for the stage: the driving side (II) carries η
    assert "M1'·(n1 − n3) + M2'·(n2 − n3)·η0 = 0" in text
    assert [s.title[:2] for s in e.steps] == ["1.", "2.", "3.", "4.", "5."]
    assert e.to_dict()["steps"][1]["lines"][0].startswith("planetary: Willis equation")
    assert str(e) == text and e.markdown().startswith("# Worked solution") and "<pre>" in e._repr_html_()


def test_every_shaft_balances_to_zero_and_results_end_the_text():
    f = load_train_file(EXAMPLES / "brandenberger_1952.toml")
    e = explain(f.solve(), f.units)
    balance = e.steps[3].lines[1:]
    assert any(line.startswith("III:") and line.endswith("= 0 kp*cm") for line in balance)
    assert e.steps[-1].lines[-2].startswith("efficiency η = P_out/P_in")


def test_german_terms():
    text = explain(solve(*brandenberger_1952()), lang="de").text()
    # Brandenberger's set has two suns (a, d external): its systems I and II are the first and second
    # central gear (Zentralrad), not sun and ring; a simple set's Sonnenrad/Hohlrad: tests/io/test_reports.py.
    for term in ("Lösungsweg", "Steg", "erstes Zentralrad", "zweites Zentralrad", "Standübersetzung", "Standwirkungsgrad",
                 "Wälzleistung", "Kupplungsleistung", "Wirkungsgrad", "Momentengleichgewicht"):
        assert term in text
    assert set(LANGUAGES) == {"en", "de"}


def test_shift_elements_lossless_sets_and_self_locking_are_explained():
    train = GearTrain([
        PlanetarySet("P", "sun", "ring", "carrier", -2.0, 1.0),
        Brake("B", "ring"),
        Clutch("C", "sun", "carrier", engaged=False),
    ])
    op = OperatingPoint(speeds={"sun": 3000}, torques={"sun": 10}, drives=["sun"], loads=["carrier"])
    text = explain(solve(train, op)).text()
    assert "engaged brake: the shaft stands still: n_ring = 0" in text
    assert "open: no condition (slip speed 2000 1/min)" in text
    assert "lossless element (η = 1)" in text
    locked = load_train_file(EXAMPLES / "plus_set_self_locking.toml").solve()
    assert "SELF-LOCKING" in explain(locked).text()


def test_unknown_language():
    with pytest.raises(EpicyclicError, match="lang must be one of en, de, got 'fr'"):
        explain(solve(*brandenberger_1952()), lang="fr")


def test_german_explanation_has_no_english_roles_or_self_locking_text():
    """`explain --lang de` printed "(drive)", "(load)" and the solver's English self-locking sentence
    (validation pass).  The German sentence carries the same numbers: formal efficiency and the
    threshold η0 < 1/i0 of the plus set (Brandenberger 1952, text to Bild 9)."""
    locked = load_train_file(EXAMPLES / "plus_set_self_locking.toml").solve()
    text = explain(locked, lang="de").text()
    assert "(drive)" not in text and "(load)" not in text and "(Antrieb)" in text and "(Abtrieb)" in text
    assert "self-locks" not in text
    assert "SELBSTHEMMUNG: das Getriebe ist in dieser Leistungsflussrichtung selbsthemmend" in text
    assert f"plus: η0 < {1 / 1.02:.6g}" in text and "(formaler Wirkungsgrad -1.55)" in text
    assert explain(locked).text().count(locked.self_locking.message) == 1  # English: the solver's message


def test_explain_takes_units_as_a_mapping_and_names_wrong_arguments():
    # regression: explain(sol, units="PS") and explain(train_file) raised AttributeError from deep inside
    f = load_train_file(Path(__file__).resolve().parents[1] / "examples" / "brandenberger_1952.toml")
    sol = f.solve()
    assert str(explain(sol, {"speed": "U/min", "torque": "kp*cm", "power": "PS"})) == str(explain(sol, f.units))
    with pytest.raises(EpicyclicError, match=r"explain: units: expected Units\(.*got str 'PS'"):
        explain(sol, units="PS")
    with pytest.raises(EpicyclicError, match=r"got a TrainFile \(a train file: explain\(f\.solve\(\), f\.units\)\)"):
        explain(f)


@pytest.mark.parametrize("name, lang", [("brandenberger_1952.toml", "en"), ("brandenberger_1952.toml", "de"),
                                        ("simple_set_ring_held_sun_drives.toml", "en")])
def test_power_equals_torque_times_speed_in_the_units_shown(name, lang):
    """Every substituted P = k·M·n holds with the numbers printed beside it, in the file's units (kp·cm,
    U/min, PS: k = 9.80665e-2·π/30/735.499 = 1.39626e-5; SI: k = π/30), not SI numbers under other units."""
    import math
    import re

    f = load_train_file(EXAMPLES / name)
    text = explain(f.solve(), f.units, lang=lang).text()
    number = r"\(?(-?[\d.]+(?:e[-+]?\d+)?)\)?"
    products = re.findall(rf"P_\w+ = {number} · {number} \S+ · {number} \S+ = {number} ", text)
    assert len(products) >= 2
    for k, torque, speed, power in products:
        assert float(k) * float(torque) * float(speed) == pytest.approx(float(power), rel=2e-5)
    rolling = re.findall(rf"P_w1 = M1'·\(n1 − n3\)·π/30 = {number}·{number}·\({number} − {number}\) = {number} ", text)
    assert rolling
    for k, torque, n1, n3, power in rolling:
        assert float(k) * float(torque) * (float(n1) - float(n3)) == pytest.approx(float(power), rel=2e-5, abs=1e-9)
    if name.startswith("brandenberger"):
        assert float(products[0][0]) == pytest.approx(0.0980665 * math.pi / 30 / 735.49875, rel=1e-5)


@pytest.mark.parametrize("lang, says", [("en", "stationary efficiency η0 from its loss models at this point (step 6)"),
                                        ("de", "Standwirkungsgrad η0 aus seinen Verlustmodellen")])
def test_a_set_with_geometry_losses_does_not_open_with_eta0_of_one(lang, says):
    # issue 30: `explain` on a set with geometry losses opened with "stationary efficiency η0 = 1" before
    # step 6 computed η0 = 0.991944 at the point
    from epicyclic.io import load_train_file

    f = load_train_file("examples/geometry_simple_set.toml")
    text = str(explain(f.solve(), f.units, lang, losses=f.losses, spin=f.spin))
    assert says in text and "η0 = 1\n" not in text and "η0 = 1," not in text
    assert ("0.991944" in text) and text.index(says) < text.index("0.991944")
