"""The pictures of the page as ``epicyclic plot``/``animate`` draw them: units, gear, unit input, options, limits."""

from __future__ import annotations

import io
import re

import pytest

from epicyclic.limits import DPI_RANGE, FPS_RANGE, FRAMES_RANGE, SIZE_RANGE
from epicyclic.web.figures import FIGURES

from .test_app import textarea


def figure_names(html: str) -> list[str]:
    return re.findall(r'<figure class="fig" id="fig-(\w+)"', html)


def test_pictures_are_in_the_units_the_page_shows(client, examples, page_form):
    """Brandenberger's example is given in U/min, kp·cm and PS: so are its pictures, or SI if chosen."""
    data = page_form(examples["brandenberger_1952"].text)
    speed = client.post("/figure/speed", data=data).text
    power = client.post("/figure/power", data=data).text
    assert "U/min" in speed and "1/min" not in speed and "PS" in power
    si = client.post("/figure/power", data={**data, "units": "si"}).text
    assert "PS" not in si and " W" in si


def test_the_gear_and_shift_state_are_in_the_title(client, examples, page_form):
    text = examples["simpson_c4_3speed"].text
    rows = [("in", "drive", "1000 1/min", "torque", "100 N*m"), ("out", "load", "", "torque", "")]
    changed = client.post("/apply/form", data=page_form(text, *rows, gear="2"))
    lever = client.post("/figure/lever", data=page_form(textarea(changed.text), *rows, gear="2")).text
    assert "gear 2: " in lever and " engaged" in lever


def test_a_transmission_without_operating_point_is_drawn_at_the_default_point(client, examples, page_form):
    text = examples["zf_8hp70_8speed"].text
    assert "[operating_point]" not in text
    opened = client.post("/example", data={"example": "zf_8hp70_8speed"})
    assert "chart" in figure_names(opened.text)
    for kind in ("torque", "animation"):
        picture = client.post(f"/figure/{kind}", data=page_form(text))
        assert picture.status_code == 200
        assert "the default n_in = 1000 1/min, T_in = 100 N·m" in picture.text  # transmission.default_point_note
    chart = client.post("/figure/chart", data=page_form(text))  # speeds per unit input speed by its nature
    assert chart.status_code == 200 and "gear 1 highlighted" in chart.text


def test_the_speed_chart_needs_a_transmission(client, examples, page_form):
    opened = client.post("/example", data={"example": "brandenberger_1952"})
    assert "chart" not in figure_names(opened.text) and "lever" in figure_names(opened.text)
    answer = client.post("/figure/chart", data=page_form(examples["brandenberger_1952"].text, source="b.toml"))
    assert answer.status_code == 422 and "b.toml: " in answer.text and "speed chart" in answer.text


def test_the_animation_starts_with_a_set_that_rolls(client):
    """ZF 8HP first gear: P1 is held, P2 and P3 idle, P4 rolls: the animation shown first is P4's."""
    opened = client.post("/example", data={"example": "zf_8hp70_8speed"}).text
    options = re.findall(r'<option value="([^"]+)">set ', opened.split('name="fig_animation_option"')[1])
    assert options[0] == "P4" and set(options[:4]) == {"P1", "P2", "P3", "P4"}


def test_animation_size(client, examples, page_form):
    data = page_form(examples["simple_set_ring_held_sun_drives"].text)
    answer = client.post("/figure/animation", data={**data, "fig_animation_size": "640"})
    assert answer.status_code == 200 and re.search(r'<svg [^>]*width="640"', answer.text)


@pytest.mark.parametrize("field, value, says", [
    ("fig_animation_size", str(SIZE_RANGE[0] - 1), f"--size) in pixels: {SIZE_RANGE[0] - 1} is outside"),
    ("fig_animation_size", "100000", f"accepted range {SIZE_RANGE[0]} … {SIZE_RANGE[1]}"),
    ("fig_animation_size", "big", "expected a whole number"),
    ("fig_animation_size", "480.5", "expected a whole number"),
    ("fig_animation_frames", "1000000", f"--frames): 1000000 is outside the accepted range {FRAMES_RANGE[0]}"),
    ("fig_animation_fps", "0", f"--fps): 0 is outside the accepted range {FPS_RANGE[0]} … {FPS_RANGE[1]}"),
    ("fig_animation_format", "mp4", "save as html, svg, gif"),
])
def test_animation_settings_out_of_range_are_messages(client, examples, page_form, field, value, says):
    data = page_form(examples["simple_set_ring_held_sun_drives"].text)
    for path in ("/figure/animation", "/save/animation"):
        answer = client.post(path, data={**data, field: value})
        assert answer.status_code == 422 and says in answer.text, answer.text[:300]


@pytest.mark.parametrize("dpi", ["0", str(DPI_RANGE[1] + 1), "nan", "1e400"])
def test_dpi_out_of_range_is_a_message(client, examples, page_form, dpi):
    answer = client.post("/save/speed", data={**page_form(examples["brandenberger_1952"].text),
                                              "fig_speed_format": "png", "fig_speed_dpi": dpi})
    assert answer.status_code == 422 and "resolution (--dpi) of PNG" in answer.text


def test_saving_pictures(client, examples, page_form):
    from PIL import Image

    data = page_form(examples["brandenberger_1952"].text, source="brandenberger_1952.toml")
    widths = {}
    for dpi in ("50", "100"):
        png = client.post("/save/torque", data={**data, "fig_torque_format": "png", "fig_torque_dpi": dpi})
        assert png.status_code == 200 and png.headers["content-type"] == "image/png"
        assert png.headers["content-disposition"] == 'attachment; filename="brandenberger_1952-torque.png"'
        widths[dpi] = Image.open(io.BytesIO(png.content)).size[0]
    assert widths["100"] == pytest.approx(2 * widths["50"], rel=0.05)  # pixels ∝ dpi
    pdf = client.post("/save/flow", data={**data, "fig_flow_format": "pdf"})
    assert pdf.status_code == 200 and pdf.content.startswith(b"%PDF")
    svg = client.post("/save/lever", data=data)  # SVG by default
    assert svg.status_code == 200 and b"<svg" in svg.content and svg.headers["content-type"].startswith("image/svg")
    assert client.post("/save/nothing", data=data).status_code == 404


def test_saving_the_animation(client, examples, page_form):
    from PIL import Image

    data = page_form(examples["simple_set_ring_held_sun_drives"].text, source="set.toml")
    gif = client.post("/save/animation", data={**data, "fig_animation_format": "gif", "fig_animation_frames": "4",
                                               "fig_animation_fps": "2", "fig_animation_size": "200"})
    assert gif.status_code == 200 and gif.content.startswith(b"GIF89a")
    image = Image.open(io.BytesIO(gif.content))
    assert image.n_frames == 4 and image.size[0] == 200
    page = client.post("/save/animation", data={**data, "fig_animation_format": "html"})
    assert page.status_code == 200 and page.text.startswith("<!DOCTYPE html>") and "<animateTransform" in page.text
    assert page.headers["content-disposition"] == 'attachment; filename="set-animation.html"'


def test_every_kind_is_listed_with_its_formats():
    assert set(FIGURES) == {"speed", "animation", "lever", "chart", "torque", "power", "flow"}
    assert FIGURES["animation"].formats == ("html", "svg", "gif")
    assert all(k.formats == ("svg", "png", "pdf") for k in FIGURES.values() if not k.animated)
