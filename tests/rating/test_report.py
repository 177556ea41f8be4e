"""The factor rows of the rating reports: each load factor's source and clause, S_min beside each safety, symbols
and units as ISO 6336-1 clause 4 and SI write them (σ_H, K_Hβ, µm, N/mm²)."""

import re
from pathlib import Path

from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.rating.report import FACTOR_HEAD, SUMMARY_HEAD, iso_symbol, iso_unit

RATED = str(Path(__file__).resolve().parents[2] / "examples" / "rating" / "simple_set.toml")
runner = CliRunner()
LOAD_FACTORS = ("K_A", "K_γ", "K_v", "K_Hβ", "K_Fβ", "K_Hα", "K_Fα")


def _rows(text: str) -> dict[str, str]:
    rows = {}
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("quantity"))  # the first factor table
    for line in lines[start:]:
        for symbol in LOAD_FACTORS + ("f_pb", "S_Hmin", "S_Fmin", "S_H"):
            if f"  {symbol} " in line and symbol not in rows:  # the symbol column
                rows[symbol] = line
    return rows


def test_every_load_factor_row_says_given_or_computed_and_its_clause():
    text = runner.invoke(app, ["rate", RATED]).stdout
    rows = _rows(text)
    for symbol in LOAD_FACTORS:
        assert ("given" in rows[symbol] or "computed" in rows[symbol]) and "ISO 6336-1:2019" in rows[symbol], symbol
    assert "computed" in rows["K_v"] and "6.3 (method B)" in rows["K_v"]
    assert "given" in rows["K_A"] and "µm" in rows["f_pb"] and "ISO 1328-1:2013, grade 6" in rows["f_pb"]
    assert "given / computed" in text and " um " not in text and "sigma_H" not in text


def test_the_minimum_beside_every_safety():
    assert SUMMARY_HEAD[SUMMARY_HEAD.index("S_H") + 1] == "S_Hmin"
    assert SUMMARY_HEAD[SUMMARY_HEAD.index("S_F") + 1] == "S_Fmin"
    rows = _rows(runner.invoke(app, ["rate", RATED]).stdout)
    assert re.search(r"S_Hmin\s+1\s+1\s+1\s+given", rows["S_Hmin"])
    assert re.search(r"S_Fmin\s+1\s+1.4\s+1.4\s+given", rows["S_Fmin"])
    markdown = runner.invoke(app, ["rate", RATED, "-f", "markdown"]).stdout
    assert "| S_Hmin |" in markdown and "| S_Fmin |" in markdown and "σ_HP [N/mm²]" in markdown
    page = runner.invoke(app, ["rate", RATED, "-f", "html"]).stdout
    assert "<th>given / computed</th>" in page and "<th>S_Fmin</th>" in page and "K_Hβ" in page


def test_below_minimum_marks_stay_in_the_safety_columns():
    page = runner.invoke(app, ["rate", RATED, "--set", "operating_point.torques.in=\"3000 N*m\"", "-f", "html"]).stdout
    assert "class='below'" in page
    assert FACTOR_HEAD.index("gear 1") == 3 and FACTOR_HEAD.index("gear 2") == 4


def test_symbols_and_units():
    assert [iso_symbol(s) for s in ("sigma_FP", "K_Falpha", "F_betax", "rho_F", "Z_epsilon", "y_alpha")] == [
        "σ_FP", "K_Fα", "F_βx", "ρ_F", "Z_ε", "y_α"]
    assert iso_unit("sqrt(N/mm^2)") == "√(N/mm²)" and iso_unit("N/(mm*µm)") == "N/(mm·µm)"
