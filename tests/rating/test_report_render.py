"""One rendering path for the rating reports (text, Markdown, HTML): ISO symbols and SI units in every format,
the printable HTML (print style sheet, page breaks, header with the file name and the date).

Sources: ISO 6336-1:2019, clause 4 (the symbols σ_H, K_Hβ, ρ_fP …); ISO 80000-1:2009 (µm, N/mm²); W3C, CSS
Paged Media Module Level 3 and CSS Fragmentation Module Level 3 (``@page``, ``break-before``, ``break-inside``).
"""

import re

import pytest

from epicyclic.rating.report_render import (
    Section,
    html_page,
    iso_symbol,
    iso_text,
    iso_unit,
    render_html,
    render_markdown,
    render_text,
)

SECTIONS = [Section("Inputs", ["quantity", "symbol", "value"], [["tip radius", "rho_fP", "0.25"],
                                                               ["key", "K_Hbeta", "rating.K_Hbeta"]], literal=(2,)),
            Section("P1: sun-planet sigma_H", ["quantity", "symbol", "unit", "gear 1"],
                    [["contact stress", "sigma_H", "N/mm^2", "900"], ["safety factor for pitting", "S_H", "1", "0.9 !"],
                     ["minimum safety factor for pitting", "S_Hmin", "1", "1"]], (3,),
                    ("K_Hbeta by method C (f_Hbeta = 9.5 um)",), page_break=True, ok=False),
            Section("P1: planet-ring", ["quantity", "symbol", "unit", "gear 1"],
                    [["film thickness", "lambda_GF", "1", "0.3"]], page_break=True)]


@pytest.mark.parametrize("ascii_, iso", [("sigma_HP", "σ_HP"), ("K_Hbeta", "K_Hβ"), ("theta_intS", "ϑ_intS"),
                                         ("S_lambda", "S_λ"), ("Y_deltarelT", "Y_δrelT"), ("c_gamma_alpha", "c_γα")])
def test_symbols_as_iso_6336_1_writes_them(ascii_, iso):
    assert iso_symbol(ascii_) == iso
    assert iso_text(f"the {ascii_} of the mesh") == f"the {iso} of the mesh"


@pytest.mark.parametrize("ascii_, si", [("um", "µm"), ("N/mm^2", "N/mm²"), ("N/(mm*um)", "N/(mm·µm)"),
                                        ("N*s/m^2", "N·s/m²"), ("mm^2/s", "mm²/s"), ("sqrt(N/mm^2)", "√(N/mm²)")])
def test_units_as_si_writes_them(ascii_, si):
    assert iso_unit(ascii_) == si


def test_text_keeps_words_and_file_keys():
    # words that hold the letters of a unit or a Greek name are not symbols; a [rating] key stays a key
    assert iso_text("maximum sum of betas, rating.K_Hbeta, tool_tip_radius") == \
        "maximum sum of betas, rating.K_Hbeta, tool_tip_radius"
    assert iso_text("f_Hbeta = 9.5 um, rho_fP* = 0.25") == "f_Hβ = 9.5 µm, ρ_fP* = 0.25"


@pytest.mark.parametrize("render", [render_text, render_markdown, render_html])
def test_every_format_renders_the_same_rows_with_iso_symbols(render):
    out = render(SECTIONS)
    for cell in ("σ_H", "ρ_fP", "N/mm²", "9.5 µm", "K_Hβ by method C", "λ_GF", "S_Hmin", "rating.K_Hbeta"):
        assert cell in out, cell
    assert not re.search(r"\bum\b|sigma_|lambda_|rho_|N/mm\^2", out)


def test_the_shortfall_is_marked_in_every_format():
    assert "0.9 !" in render_text(SECTIONS) and "0.9 !" in render_markdown(SECTIONS)
    html = render_html(SECTIONS)
    assert "<td class='below'" in html and ">0.9</td>" in html and "<h3 class='below'" in html


def test_each_mesh_opens_a_page_of_its_own():
    html = render_html(SECTIONS)
    assert html.count("<div class='mesh'>") == 2 and html.count("</div>") == 2
    assert html.index("Inputs") < html.index("<div class='mesh'>")  # the echo is not a mesh


def test_a_row_that_does_not_fit_its_head_is_refused():
    with pytest.raises(ValueError, match="2 cells under 3 column heads"):
        Section("bad", ["a", "b", "c"], [["1", "2"]])


def test_the_printable_page_has_the_print_style_sheet_and_the_header():
    page = html_page("ZF 8HP", render_html(SECTIONS), source="examples/x.toml", date="2026-12-08")
    assert page.startswith("<!DOCTYPE html>") and "<meta charset='utf-8'>" in page
    style = re.search(r"<style>(.*)</style>", page).group(1)
    assert "@page{size:A4" in style and "@media print" in style
    assert "div.mesh,section.rating{break-before:page" in style  # a page break before each mesh and each gear
    assert "thead{display:table-header-group}" in style  # the head repeats on a new page
    assert "tr,td,th{break-inside:avoid" in style  # rows are not cut
    header = re.search(r"<header class='page'>(.*?)</header>", page).group(1)
    assert "examples/x.toml" in header and "2026-12-08" in header
    # the title that a browser prints at the top of every page holds the file and the date too
    assert re.search(r"<title>examples/x.toml — 2026-12-08 — ZF 8HP — rating</title>", page)
