"""Animation: angular steps per frame match the solved speeds; Willis phases add up to the motion."""

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PIL import Image

from epicyclic.plotting import PlottingError
from epicyclic.plotting.animation import gear_outline, planetary_animation

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

SVG = "{http://www.w3.org/2000/svg}"


@pytest.mark.parametrize("case", ["brandenberger", "simple", "simple_reversed"])
def test_angular_steps_match_solved_speeds(case, request):
    # Δφ per frame = 6°·n/(fps·slowdown) for every member (n in 1/min); tolerance 1e-12 relative.
    sol = request.getfixturevalue(case)
    anim = planetary_animation(sol)
    state = sol.elements[anim.set_name]
    expected = {"sun": state.speeds["sun"], "ring": state.speeds["ring"], "carrier": state.speeds["carrier"],
                "planet": state.planet_speeds[0]}
    for frame in (0, 7):
        step = anim.step(frame)
        for member, n in expected.items():
            assert step[member] * anim.fps * anim.slowdown / 6.0 == pytest.approx(n, rel=1e-12, abs=1e-9)


def test_brandenberger_planet_speed_from_teeth(brandenberger):
    # tec-science, "Willis-Gleichung": n_P z_P = n_T (z_P + z_S) − n_S z_S with z_S = 50, z_P = 24:
    # n_P = (5280·74 − 2739.84·50)/24 = 10572 1/min.
    anim = planetary_animation(brandenberger)
    assert anim.speeds["planet"] == pytest.approx((5280 * 74 - brandenberger.speed("I") * 50) / 24, rel=1e-9)


def test_fastest_member_shown_at_the_chosen_rate(simple):
    anim = planetary_animation(simple, max_rev_per_s=0.5)
    fastest = max(abs(anim.degrees_per_second(m)) for m in anim.speeds)
    assert fastest == pytest.approx(0.5 * 360, rel=1e-12)


def test_willis_phases_add_up_to_the_real_motion(simple):
    # tec-science, "Willis-Gleichung": φ_P = φ_T + (d_S/d_P)·φ_T − (d_S/d_P)·φ_S; the ring (held) ends where it began.
    anim = planetary_animation(simple, willis=True, frames=48)
    real = planetary_animation(simple, frames=48)
    end = anim.angles(3 * anim.phase_frames)
    target = real.angles(anim.phase_frames)
    assert end == pytest.approx(target, abs=1e-9)
    after1, after2 = anim.angles(anim.phase_frames), anim.angles(2 * anim.phase_frames)
    phi_t, phi_s = target["carrier"], target["sun"]
    # phase 1: carrier only, planets locked to it, sun at rest
    assert after1["sun"] == 0 and after1["planet"] == pytest.approx(phi_t) and after1["carrier"] == pytest.approx(phi_t)
    # phase 2: planets about their own axes by (z_s/z_p)·φ_T, carrier and sun stand
    assert after2["carrier"] == pytest.approx(phi_t) and after2["sun"] == 0
    assert after2["planet"] - after1["planet"] == pytest.approx(30 / 24 * phi_t)
    # phase 3: sun by φ_S, planets back by (z_s/z_p)·φ_S
    assert end["planet"] - after2["planet"] == pytest.approx(-30 / 24 * phi_s)
    assert abs(end["ring"]) < 1e-9


def _rotations(svg_text):
    root = ET.fromstring(svg_text)
    return root, root.findall(f".//{SVG}animateTransform")


def test_svg_is_self_contained_and_rates_match(simple):
    anim = planetary_animation(simple)
    text = anim.svg()
    root, rotations = _rotations(text)
    assert "http" not in text.replace('xmlns="http://www.w3.org/2000/svg"', "")
    assert "<script" not in text
    rates = sorted(round(360 / float(r.get("dur").rstrip("s")) * (1 if float(r.get("to")) > 0 else -1), 6)
                   for r in rotations)
    # sun, carrier, and the 3 planets relative to the carrier (ring held: no animation)
    expected = [6 * anim.speeds["sun"] / anim.slowdown, 6 * anim.speeds["carrier"] / anim.slowdown]
    expected += [6 * (anim.speeds["planet"] - anim.speeds["carrier"]) / anim.slowdown] * anim.planets
    assert rates == pytest.approx(sorted(expected), rel=1e-6)
    assert text.count("<path") >= 2 + anim.planets
    # tooth counts are real: the sun outline has 5 points per tooth
    assert len(gear_outline(30, 15.0)) == 5 * 30


def test_willis_svg_uses_three_phases(simple, tmp_path):
    anim = planetary_animation(simple, willis=True)
    root, rotations = _rotations(anim.svg())
    assert rotations and all(r.get("keyTimes").count(";") == 3 for r in rotations)
    assert "Willis 1: carrier turns" in anim.svg()
    page = anim.save(tmp_path / "willis.html").read_text()
    assert page.startswith("<!DOCTYPE html>") and "<svg" in page and "animateTransform" in page


def test_gif_has_the_frames(simple, tmp_path):
    anim = planetary_animation(simple, frames=4, fps=8)
    path = anim.save(tmp_path / "a.gif")
    with Image.open(path) as im:
        assert im.format == "GIF" and im.n_frames == 4


def test_made_up_layout_and_double_planet_animate():
    from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve

    for pset in (PlanetarySet("P", "s", "r", "c", -2.0),
                 PlanetarySet.double_planet("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet_sun=17,
                                            z_planet_ring=19, z_ring=90, planets=4)):
        sol = solve(GearTrain([pset, Brake("B", "r")]),
                    OperatingPoint(speeds={"s": 1000.0}, torques={"s": 10.0}, drives=["s"], loads=["c"]))
        anim = planetary_animation(sol)
        step = anim.step()
        assert step["carrier"] * anim.fps * anim.slowdown / 6 == pytest.approx(sol.speed("c"), rel=1e-12)
        planets = [s for s in anim.shapes if s.member.startswith("planet")]
        assert len(planets) == pset.planets * (2 if pset.teeth else 1)
        ET.fromstring(anim.svg())


def test_repr_and_dict(brandenberger):
    anim = planetary_animation(brandenberger)
    assert re.search(r"slowed down \d+", repr(anim))
    assert anim.to_dict()["planets"] == 3


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"fps": 0}, "fps must be a whole number ≥ 1, got 0"),
    ({"frames": 2.5}, "frames must be a whole number ≥ 1, got 2.5"),
    ({"max_rev_per_s": -1}, "max_rev_per_s must be a positive number, got -1"),
    ({"willis": True, "frames": 2}, "Willis phases need frames ≥ 3"),
    ({"element": "nope"}, "no planetary set named 'nope'"),
])
def test_errors(brandenberger, kwargs, message):
    with pytest.raises(PlottingError, match=message):
        planetary_animation(brandenberger, **kwargs)


def test_bad_suffix(brandenberger, tmp_path):
    with pytest.raises(PlottingError, match=r"suffix '.mp4'; expected one of .svg, .html, .gif"):
        planetary_animation(brandenberger).save(tmp_path / "a.mp4")


def test_gif_draws_the_ring_as_an_internal_gear(simple, tmp_path):
    """The GIF's ring is a rim with inward teeth, as in the SVG: its inside is empty (no filled disk with
    outward teeth); the pixel between two planets at the planets' axis radius shows the background."""
    import math

    from epicyclic.plotting._svg import _ring_annulus

    anim = planetary_animation(simple)
    ring = next(s for s in anim.shapes if s.member == "ring")
    rim, teeth = (polygon for polygon in _ring_annulus(ring).to_polygons(closed_only=True))
    radii = [math.hypot(*xy) for xy in teeth]
    assert max(math.hypot(*xy) for xy in rim) == pytest.approx(ring.radius + 3.5 * ring.module)
    assert min(radii) < ring.radius < max(radii) < ring.radius + 3.5 * ring.module  # teeth inside the rim

    def area(points):
        return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, [*points[1:], points[0]]))

    assert area(rim) * area(teeth) < 0  # wound the other way: a hole under the non-zero fill rule
    gif = anim.gif(tmp_path / "set.gif")
    with Image.open(gif) as image:
        frame = image.convert("RGB")
        planets = sorted({(s.axis, s.offset) for s in anim.shapes if s.member.startswith("planet")})
        axis, offset = planets[0]
        between = math.radians(offset + 180.0 / len(planets))  # halfway to the next planet, frame 0
        from epicyclic.plotting._gears import extent

        R = extent(anim.shapes)
        scale = frame.width / (2 * R)
        x = frame.width / 2 + axis * math.cos(between) * scale
        y = frame.width / 2 - axis * math.sin(between) * scale
        assert min(frame.getpixel((int(x), int(y)))) > 240, "the ring's inside is filled"


def test_a_slow_set_is_shown_sped_up_not_slowed_down_below_one():
    """At 1 1/min the fastest member (the sun) is shown faster than it turns: at the default 0.25 rev/s
    = 15 1/min the caption says "sped up 15×", never "slowed down 0.0667×"."""
    from epicyclic import Brake, GearTrain, OperatingPoint, PlanetarySet, solve

    train = GearTrain([PlanetarySet.simple("P", sun="sun", ring="ring", carrier="carrier", z_sun=30, z_planet=24,
                                           z_ring=78), Brake("B", "ring")])
    slow = solve(train, OperatingPoint(speeds={"sun": 1.0}, torques={"sun": 1.0}, drives=["sun"], loads=["carrier"]))
    anim = planetary_animation(slow)
    caption = " ".join(anim.caption())
    assert anim.slowdown == pytest.approx(1 / 15)
    assert "shown sped up 15×" in caption and "slowed down" not in caption and "sped up 15×" in repr(anim)


def test_a_set_given_by_i0_says_its_planet_speed_is_schematic():
    from epicyclic.io import load_train_file

    anim = planetary_animation(load_train_file(EXAMPLES / "plus_set_reduction.toml").solve())
    planets = anim.caption()[1]
    assert anim.schematic and anim.schematic_planets
    assert "planet:" in planets and "(schematic: of the drawn teeth, not in the file)" in planets


def test_a_set_with_its_own_teeth_has_no_schematic_planet(simple):
    anim = planetary_animation(simple)
    assert not anim.schematic_planets and "schematic" not in " ".join(anim.caption())


def test_the_gif_draws_its_still_parts_once_and_keeps_one_small_palette(tmp_path, monkeypatch):
    """Issue 30: the GIF took 4-8 s and 1.5 MB for one simple set: every frame drew the whole figure twice (the
    caption's text was most of the time) and PIL gave each frame its own palette. Now the still parts are drawn
    once (matplotlib blitting), the moving ones per frame, every frame in the first frame's palette."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image

    from epicyclic.io import load_train_file
    from epicyclic.plotting.animation import planetary_animation

    draws = []
    original = FigureCanvasAgg.draw
    monkeypatch.setattr(FigureCanvasAgg, "draw", lambda self, *a, **k: draws.append(1) or original(self, *a, **k))
    anim = planetary_animation(load_train_file(EXAMPLES / "simple_set_ring_held_sun_drives.toml").solve(), frames=12)
    path = anim.gif(tmp_path / "set.gif")
    assert len(draws) == 1  # the whole figure once, not twice per frame
    with Image.open(path) as image:
        assert image.n_frames == 12 and image.info["duration"] == 10 * round(100 / anim.fps)
        colours = len(image.getpalette()) // 3
        assert colours <= 64
        first = image.convert("RGB")
        image.seek(6)
        assert image.convert("RGB").tobytes() != first.tobytes()  # it moves
