"""A library of classic planetary transmissions, built from published data.

Each entry holds the tooth counts (as stationary ratios i0 = −z_ring/z_sun for
a simple set, +z_ring/z_sun for a double-planet set), the fixed connections,
the shift elements, the shift schedule and the *published* gear ratios, with
the source of every number.  The same data are written as TOML files to
``examples/`` (:func:`to_toml`), so the files and the Python objects cannot
drift apart (a test compares them).

Entries
-------
``simpson_c4``
    Ford C4 three-speed (Simpson gearset, 1964–1981).
``ravigneaux_aod``
    Ford AOD four-speed (one Ravigneaux gearset).
``lepelletier_6hp26``
    ZF 6HP 26 six-speed (Lepelletier: simple set + Ravigneaux set).
``zf_8hp70``
    ZF 8HP 70 eight-speed (four simple sets, two brakes, three clutches).
``prius_psd``
    Toyota Prius (3rd gen.) power-split device with motor reduction set,
    counter and final gears: a two-degree-of-freedom train, no schedule.

References
----------
See the ``sources`` of each entry (:data:`LIBRARY`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from types import MappingProxyType

from ..errors import ModelError
from ..model import Brake, Clutch, GearStage, GearTrain, PlanetarySet
from .transmission import Transmission

__all__ = ["LibraryEntry", "LIBRARY", "entry", "build_train", "build", "names", "to_toml"]


@dataclass(frozen=True)
class SetSpec:
    """One planetary set: shafts and published tooth counts.

    ``kind`` is ``"simple"`` (i0 = −z_ring/z_sun) or ``"double"`` (double
    planet, i0 = +z_ring/z_sun); ``planet`` is the planet tooth count where it
    is published (simple sets only), else None.
    """

    name: str
    sun: str
    ring: str
    carrier: str
    z_sun: int
    z_ring: int
    kind: str = "simple"
    planet: int | None = None

    @property
    def stationary_ratio(self) -> Fraction:
        """i0 as an exact fraction (Queitsch eq. 4)."""
        sign = -1 if self.kind == "simple" else 1
        return Fraction(sign * self.z_ring, self.z_sun)

    def ratio_text(self) -> str:
        """i0 as the TOML string ``"-z_ring/z_sun"`` (unreduced, as published)."""
        sign = "-" if self.kind == "simple" else ""
        return f"{sign}{self.z_ring}/{self.z_sun}"


@dataclass(frozen=True)
class LibraryEntry:
    """A published transmission: topology, schedule, published ratios, sources."""

    key: str
    title: str
    sets: tuple[SetSpec, ...]
    clutches: tuple[tuple[str, str, str], ...]  # (name, first, second)
    brakes: tuple[tuple[str, str], ...]  # (name, shaft)
    stages: tuple[tuple[str, str, str, tuple[tuple[int, int, str], ...]], ...] = ()
    schedule: Mapping[str, tuple[str, ...]] = field(default_factory=dict)
    input: str | None = None
    output: str | None = None
    published_ratios: Mapping[str, float] = field(default_factory=dict)
    printed_digits: int = 3
    sources: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    units: Mapping[str, str] = field(default_factory=dict)
    operating_point: tuple[str, ...] = ()  # TOML lines of an [operating_point] table in the example file


def _entry(**kw) -> LibraryEntry:
    kw["schedule"] = MappingProxyType(dict(kw.get("schedule", {})))
    kw["published_ratios"] = MappingProxyType(dict(kw.get("published_ratios", {})))
    return LibraryEntry(**kw)


_ENTRIES = [
    _entry(
        key="simpson_c4",
        title="Ford C4 three-speed automatic (Simpson gearset)",
        sets=(
            SetSpec("front", sun="sun", ring="front_ring", carrier="out", z_sun=33, z_ring=72),
            SetSpec("rear", sun="sun", ring="out", carrier="rear_carrier", z_sun=33, z_ring=72),
        ),
        clutches=(("forward", "in", "front_ring"), ("high_reverse", "in", "sun")),
        brakes=(("intermediate", "sun"), ("low_reverse", "rear_carrier")),
        schedule={"1": ("forward", "low_reverse"), "2": ("forward", "intermediate"),
                  "3": ("forward", "high_reverse"), "R": ("high_reverse", "low_reverse")},
        input="in", output="out",
        published_ratios={"1": 2.46, "2": 1.46, "3": 1.00, "R": -2.18},
        printed_digits=2,
        sources=(
            "Ratios: 'Ford C4 transmission' (Wikipedia, copy at piglix.com/piglix/Ford_C5_transmission): "
            "'Ratios are 2.46 low, 1.46 second and direct high'; reverse 2.18:1 from "
            "ford-torino.de/zahlen-fakten/getriebeuebersicht/c4-automatikgetriebe ('Reverse: 2,18:1').",
            "Tooth counts (sun 33, ring 72 in both sets) and connections (common sun, front carrier = rear "
            "ring = output, forward clutch to the front ring, high/reverse clutch to the sun, intermediate "
            "band on the sun, low/reverse band on the rear carrier): public reference data "
            "github.com/pablomarcel/gearsets, transmissions/in/transmission_spec_ford_c4.json "
            "(preset 'ford_c4_reference').",
        ),
        notes=("The one-way clutch (sprag) on the rear carrier in first gear is modelled as the "
               "low/reverse brake engaged (drive direction).",),
    ),
    _entry(
        key="ravigneaux_aod",
        title="Ford AOD four-speed automatic overdrive (Ravigneaux gearset)",
        sets=(
            # forward (small) sun 30 meshes the short pinions: double-planet path to the ring
            SetSpec("Pfwd", sun="forward_sun", ring="ring", carrier="carrier", z_sun=30, z_ring=72,
                    kind="double"),
            # reverse (large) sun 36 meshes the long pinions: simple path to the ring
            SetSpec("Prev", sun="reverse_sun", ring="ring", carrier="carrier", z_sun=36, z_ring=72),
        ),
        clutches=(("forward", "in", "forward_sun"), ("direct", "in", "carrier"), ("reverse", "in", "reverse_sun")),
        brakes=(("intermediate_od", "reverse_sun"), ("low_reverse", "carrier")),
        schedule={"1": ("forward", "low_reverse"), "2": ("forward", "intermediate_od"),
                  "3": ("forward", "direct"), "4": ("direct", "intermediate_od"),
                  "R": ("reverse", "low_reverse")},
        input="in", output="ring",
        published_ratios={"1": 2.40, "2": 1.47, "3": 1.00, "4": 0.67, "R": -2.00},
        printed_digits=2,
        sources=(
            "Tooth counts (front/reverse sun 36, rear/forward sun 30, ring 72), ratio formulas and ratios "
            "2.4, 1.47, 1, 0.67: ATRA TSB 89-30 'Transmission Math - Part II', Ravigneaux section "
            "(copies: svx-iw.com/svxiw/article/?article=63 and workshop-manuals.com, Yugo TSB ATRATB8930).",
            "Members per gear (1st: 30-tooth sun in, carrier held; 2nd: 36-tooth sun held; 3rd: direct; "
            "OD: carrier in, 36-tooth sun held; reverse: 36-tooth sun in, carrier held, -2.0): "
            "compass-at.com, 'Gear Ratios' table (AOD).",
        ),
        notes=("The Ravigneaux gearset is two sets sharing ring and carrier: the forward sun drives the "
               "ring through short and long pinions (double planet, i0 = +72/30), the reverse sun through "
               "the long pinions only (i0 = -72/36).",
               "In the real AOD third gear splits torque between a hydraulic and a mechanical path; "
               "kinematically both clutches turn with the input, as modelled here."),
    ),
    _entry(
        key="lepelletier_6hp26",
        title="ZF 6HP 26 six-speed automatic (Lepelletier gearset)",
        sets=(
            SetSpec("P1", sun="housing", ring="in", carrier="c1", z_sun=37, z_ring=71),
            SetSpec("P2", sun="small_sun", ring="out", carrier="carrier", z_sun=31, z_ring=85, kind="double"),
            SetSpec("P3", sun="large_sun", ring="out", carrier="carrier", z_sun=38, z_ring=85),
        ),
        clutches=(("A", "c1", "small_sun"), ("B", "c1", "large_sun"), ("E", "in", "carrier")),
        brakes=(("C", "large_sun"), ("D", "carrier")),
        schedule={"1": ("A", "D"), "2": ("A", "C"), "3": ("A", "B"), "4": ("A", "E"),
                  "5": ("B", "E"), "6": ("C", "E"), "R": ("B", "D")},
        input="in", output="out",
        published_ratios={"1": 4.171, "2": 2.340, "3": 1.521, "4": 1.143, "5": 0.867, "6": 0.691,
                          "R": -3.403},
        printed_digits=3,
        sources=(
            "Ratios 4.171, 2.340, 1.521, 1.143, 0.867, 0.691, R -3.403: 'ZF 6HP transmission', Gear Ratios "
            "table, row 6HP 26 (Wikipedia; copy at cavac.at/cavacopedia/ZF_6HP_transmission).",
            "Gearset concept (front simple set with fixed sun driving a Ravigneaux set; clutches A, B, E, "
            "brakes C, D): 'Lepelletier gear mechanism' (en.wikipedia.org/wiki/Lepelletier_gear_mechanism); "
            "US patent 5,106,352 (Lepelletier).",
            "Tooth counts S1 37, R1 71, Ravigneaux small sun 31, large sun 38, ring 85: the 'In-Depth "
            "Analysis' table of the same Wikipedia article (row 6HP 26). The stored copy available while "
            "building this file did not show that table, so these counts are checked only through the "
            "seven printed ratios they reproduce (test_library.py).",
        ),
    ),
    _entry(
        key="zf_8hp70",
        title="ZF 8HP 70 eight-speed automatic (pilot series 2008)",
        sets=(
            SetSpec("P1", sun="s12", ring="r1", carrier="c1r4", z_sun=48, z_ring=96),
            SetSpec("P2", sun="s12", ring="r2s3", carrier="in", z_sun=48, z_ring=96),
            SetSpec("P3", sun="r2s3", ring="r3s4", carrier="c3", z_sun=69, z_ring=111),
            SetSpec("P4", sun="r3s4", ring="c1r4", carrier="out", z_sun=23, z_ring=85),
        ),
        clutches=(("C", "in", "r3s4"), ("D", "c3", "out"), ("E", "r2s3", "r3s4")),
        brakes=(("A", "s12"), ("B", "r1")),
        schedule={"1": ("A", "B", "C"), "2": ("A", "B", "E"), "3": ("B", "C", "E"), "4": ("B", "D", "E"),
                  "5": ("B", "C", "D"), "6": ("C", "D", "E"), "7": ("A", "C", "D"), "8": ("A", "D", "E"),
                  "R": ("A", "B", "D")},
        input="in", output="out",
        published_ratios={"1": 4.6957, "2": 3.1304, "3": 2.1039, "4": 1.6667, "5": 1.2845, "6": 1.0000,
                          "7": 0.8392, "8": 0.6667, "R": -3.2968},
        printed_digits=4,
        sources=(
            "Tooth counts S1 48 R1 96, S2 48 R2 96, S3 69 R3 111, S4 23 R4 85, ratios (4 decimals) and "
            "per-gear efficiencies at eta0 = 0.98 / 0.97 per set: 'ZF 8HP transmission', 'In-Depth "
            "Analysis With Assessment' table, row 8HP 70 (2008 pilot series) (Wikipedia; copy at "
            "wikiwand.com/en/articles/ZF_8HP_transmission).",
            "Connections and shift schedule (1 ABC, 2 ABE, 3 BCE, 4 BDE, 5 BCD, 6 CDE, 7 ACD, 8 ADE, "
            "R ABD): Jeep 8HP75 service information, 'Functional Description - Planetary Gear Components' "
            "(turbine -> clutch C -> sun 4; ring 2 -> clutch E -> sun 4; sun 4 + ring 3; clutch D joins "
            "gear train 3 to the output) and US patent 8,016,708 B2 (ZF, 2011), claim 1 (A: shaft 3 to "
            "housing, B: shaft 4 to housing, C: shafts 1-5).",
        ),
    ),
    _entry(
        key="prius_psd",
        title="Toyota Prius (3rd generation, P410) power-split device",
        sets=(
            SetSpec("PSD", sun="mg1", ring="ring", carrier="engine", z_sun=30, z_ring=78, planet=23),
            SetSpec("MSR", sun="mg2", ring="ring", carrier="housing", z_sun=22, z_ring=58, planet=18),
        ),
        clutches=(),
        brakes=(),
        stages=(("counter", "ring", "counter", ((54, 55, "external"),)),
                ("final", "counter", "wheels", ((24, 77, "external"),))),
        published_ratios={"final_drive": 3.267},
        printed_digits=3,
        sources=(
            "Tooth counts power split sun 30, pinion 23, ring 78; motor speed reduction sun 22, pinion 18, "
            "ring 58; counter drive 54, driven 55; final drive 24, driven 77; 'Total Final Drive Ratio: "
            "3.267:1': PriusChat, post 1048061 (from Toyota's 2010 Prius New Car Features).",
            "Connections (sun - MG1, carrier - engine, ring - counter drive gear (output); MG2 on the "
            "reduction sun, reduction carrier fixed): Toyota repair manual, 'Power split planetary gear "
            "unit' construction (copy at zatonevkredit.ru/repair_manuals).",
        ),
        notes=("Two degrees of freedom: give two of engine, mg1, wheels (or ring) speeds.",
               "Operating point: steady cruise, engine 2000 rpm at 100 N*m, wheels 700 rpm (about 80 km/h "
               "with a 0.30 m rolling radius); MG2 drives with 3.6 kW, about what MG1 generates (battery "
               "neutral, losses aside).",),
        units={"speed": "rpm", "torque": "N*m", "power": "kW"},
        operating_point=('speeds = { engine = "2000 rpm", wheels = "700 rpm" }',
                         'torques = { engine = "100 N*m" }',
                         'powers = { mg2 = "3.6 kW" }',
                         'drives = ["engine", "mg2"]',
                         'loads = ["mg1", "wheels"]'),
    ),
]

LIBRARY: Mapping[str, LibraryEntry] = MappingProxyType({e.key: e for e in _ENTRIES})


def names() -> tuple[str, ...]:
    """Keys of the library entries."""
    return tuple(LIBRARY)


def entry(key: str) -> LibraryEntry:
    """The library entry ``key`` (see :func:`names`)."""
    try:
        return LIBRARY[key]
    except KeyError:
        raise ModelError(
            f"transmission library: no entry {key!r}; entries are {', '.join(repr(k) for k in LIBRARY)}."
        ) from None


def build_train(key: str, stationary_efficiency: float = 1.0) -> GearTrain:
    """The gear train of entry ``key`` with η0 = ``stationary_efficiency`` per set.

    Examples
    --------
    >>> train = build_train("simpson_c4", 0.98)
    >>> [s.stationary_ratio for s in train.planetary_sets]
    [-2.1818181818181817, -2.1818181818181817]
    """
    e = entry(key)
    elements: list = []
    for s in e.sets:
        if s.planet is not None:
            elements.append(PlanetarySet.simple(
                s.name, sun=s.sun, ring=s.ring, carrier=s.carrier, z_sun=s.z_sun, z_planet=s.planet,
                z_ring=s.z_ring, stationary_efficiency=stationary_efficiency))
        else:
            elements.append(PlanetarySet(s.name, s.sun, s.ring, s.carrier, float(s.stationary_ratio),
                                         stationary_efficiency))
    for name, first, second, meshes in e.stages:
        elements.append(GearStage.from_teeth(name, first, second, list(meshes), stationary_efficiency))
    elements += [Clutch(n, a, b, engaged=False) for n, a, b in e.clutches]
    elements += [Brake(n, s, engaged=False) for n, s in e.brakes]
    return GearTrain(elements, name=e.title)


def build(key: str, stationary_efficiency: float = 1.0) -> Transmission:
    """The :class:`~epicyclic.transmission.Transmission` of entry ``key``.

    Raises
    ------
    ModelError
        The entry has no shift schedule (the two-degree-of-freedom Prius
        device); use :func:`build_train` for it.

    Examples
    --------
    >>> t = build("zf_8hp70")
    >>> round(t.ratio("1"), 4), round(t.ratio("R"), 4)
    (4.6957, -3.2968)
    """
    e = entry(key)
    if not e.schedule:
        raise ModelError(
            f"transmission library: entry {key!r} has no shift schedule (it is a "
            f"{len(e.sets)}-set train with more than one degree of freedom); use build_train({key!r})."
        )
    return Transmission(build_train(key, stationary_efficiency), e.schedule, e.input, e.output, name=e.title)


def to_toml(key: str, stationary_efficiency: float = 0.98) -> str:
    """The entry as a TOML file in the project's train-file format, sources as comments."""
    e = entry(key)
    lines = [f"# {e.title}", "#", "# Sources:"]
    for src in e.sources:
        lines.append(f"#  - {src}")
    for note in e.notes:
        lines.append(f"# Note: {note}")
    if e.published_ratios:
        shown = ", ".join(f"{g}: {v:.{e.printed_digits}f}" for g, v in e.published_ratios.items())
        lines.append(f"# Published ratios: {shown}")
    lines += ["# Generated from epicyclic.transmission.library (keep both in step: tests compare them).", ""]
    lines.append(f'title = "{e.title}"')
    if e.units:
        lines += ["", "[units]", *(f'{k} = "{v}"' for k, v in e.units.items())]
    for s in e.sets:
        lines += ["", "[[planetary]]", f'name = "{s.name}"', f'sun = "{s.sun}"', f'ring = "{s.ring}"',
                  f'carrier = "{s.carrier}"']
        if s.planet is not None:
            lines.append(f"teeth = {{ sun = {s.z_sun}, planet = {s.planet}, ring = {s.z_ring} }}")
        else:
            lines.append(f'stationary_ratio = "{s.ratio_text()}"')
        lines.append(f"stationary_efficiency = {stationary_efficiency}")
    for name, first, second, meshes in e.stages:
        lines += ["", "[[gear]]", f'name = "{name}"', f'first = "{first}"', f'second = "{second}"',
                  "meshes = [" + ", ".join(f'[{a}, {b}, "{k}"]' for a, b, k in meshes) + "]",
                  f"efficiency = {stationary_efficiency}"]
    for name, first, second in e.clutches:
        lines += ["", "[[clutch]]", f'name = "{name}"', f'first = "{first}"', f'second = "{second}"',
                  "engaged = false"]
    for name, shaft in e.brakes:
        lines += ["", "[[brake]]", f'name = "{name}"', f'shaft = "{shaft}"', "engaged = false"]
    if e.schedule:
        lines += ["", "[transmission]", f'input = "{e.input}"', f'output = "{e.output}"', "",
                  "[transmission.schedule]"]
        for gear, engaged in e.schedule.items():
            lines.append(f'"{gear}" = [' + ", ".join(f'"{n}"' for n in engaged) + "]")
    if e.operating_point:
        lines += ["", "[operating_point]", *e.operating_point]
    return "\n".join(lines) + "\n"
