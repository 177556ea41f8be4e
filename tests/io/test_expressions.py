"""The safe arithmetic parser for ratios (epicyclic.io.expressions)."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from epicyclic.errors import ModelError
from epicyclic.io.expressions import ExpressionError, evaluate


@pytest.mark.parametrize(
    "text, expected",
    [
        ("(24/50)*(42/30)", 0.672),  # Brandenberger 1952, Bild 10: i0 = (b/a)(d/c)
        ("(44/40)*(64/20)", 3.52),  # Brandenberger 1952, eq. 5 inverted: n3/n2
        ("-78/30", -2.6),
        ("+1.5", 1.5),
        ("2**-1", 0.5),
        ("1e3 / 4", 250.0),
        (" 3 ", 3.0),
    ],
)
def test_evaluates_arithmetic(text, expected):
    assert evaluate(text) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize(
    "text, match",
    [
        ("__import__('os').system('true')", "found a function call"),
        ("os", "found a name"),
        ("(1).real", "found an attribute"),
        ("[1][0]", "found a subscript"),
        ("1 < 2", "found a comparison"),
        ("'a'", "found the constant 'a'"),
        ("True", "found the constant True"),
        ("1 // 2", "found the operator FloorDiv"),
        ("(24/50", "not a valid arithmetic expression"),
        ("1/0", "divides by zero"),
        ("2**100", "exponent 100"),
        ("(-1)**0.5", "finite real"),
        ("", "empty string"),
        ("1" * 201, "at most 200"),
    ],
)
def test_rejects_everything_else(text, match):
    with pytest.raises(ExpressionError, match=match) as info:
        evaluate(text, "stationary_ratio")
    assert isinstance(info.value, ModelError)
    assert str(info.value).startswith("stationary_ratio")


def test_rejects_a_non_string():
    with pytest.raises(ExpressionError, match="expected an expression string"):
        evaluate(3)  # type: ignore[arg-type]


@given(st.lists(st.tuples(st.integers(1, 500), st.integers(1, 500)), min_size=1, max_size=4))
def test_products_of_fractions_match_exact_arithmetic(pairs):
    text = "*".join(f"({a}/{b})" for a, b in pairs)
    exact = 1
    for a, b in pairs:
        exact *= Fraction(a, b)
    assert evaluate(text) == pytest.approx(float(exact), rel=1e-12)


# ---- any text: a finite number or an ExpressionError, at once, and no warning on stderr
_EXPRESSION_PIECES = ["9", "**", "*", "/", "+", "-", "(", ")", "1e308", "0", ".", "2", "e", "j", "[", "]", "__",
                      "import", "lambda", ":", ",", " ", "16", "17", "-16", "1e-320", "~", "//", "%", "<", "if"]


@given(st.lists(st.sampled_from(_EXPRESSION_PIECES), max_size=40).map("".join) | st.text(max_size=220))
def test_any_text_is_a_finite_number_or_an_expression_error(text):
    import math
    import time
    import warnings

    start = time.monotonic()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            value = evaluate(text, "ratio")
        except ExpressionError as exc:
            assert str(exc).startswith("ratio:")
        else:
            assert math.isfinite(value)
    assert not caught, caught[0].message  # a SyntaxWarning would be a second line on stderr
    assert time.monotonic() - start < 0.5
