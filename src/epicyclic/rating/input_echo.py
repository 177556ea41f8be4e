"""The input echo of a rating report: what was rated, as a calculation report prints it first.

:func:`echo_sections` lists, from the mesh inputs that the rating used
(:func:`~epicyclic.rating.train.mesh_inputs`):

* the rating's general inputs: standard, required life, minimum safeties, ISO 1328-1 edition,
  material quality, lubricant, the micropitting and scuffing inputs where given;
* per set or stage, per gear: z, x, m_n, α_n, β, b, d, d_a, d_f; material with its treatment,
  hardness and scale, σ_Hlim, σ_Flim; the tool that cuts the gear (a rack-type tool, a pinion-type
  cutter, or "ISO's closed form" of the basic rack where none is given); accuracy grade; roughness;
  rim thickness;
* every given factor (K_A, K_γ, K_v, K_Hβ, K_Fβ, K_Hα, K_Fα per mesh; f_pb, f_fα, f_Hβ per gear;
  f_sh, C_a) with its value and where it applies.

References
----------
ISO 6336-1:2019, clauses 4–6 (symbols, the influence factors); ISO 21771:2007 (gear geometry);
KISSsoft AG, *KISSsoft calculation report of a cylindrical gear pair* (the input section first).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from .given_factors import GEAR_DEVIATIONS, MESH_FACTORS
from .report_render import Section, iso_symbol

__all__ = ["ECHO_GEAR_HEAD", "echo_sections"]

ECHO_GEAR_HEAD = ["quantity", "symbol", "unit"]


def _num(value, digits: int = 4) -> str:
    from .report import _fmt

    return "" if value is None else _fmt(value) if digits == 4 else f"{float(value):.{digits}f}"


def _tool(tool, spec) -> str:
    if tool is None:
        return f"ISO's closed form, ρ_fP* {spec.tool_tip_radius:g}"
    data = tool.to_dict()
    kind = "cutter" if "teeth" in data else "hob"
    names = {"teeth": "z0", "profile_shift": "x0", "addendum": "h_a0*", "tip_radius": "ρ_a0*",
             "protuberance": "pr*", "protuberance_angle": "α_pr"}
    if kind == "hob":
        names["tip_radius"] = "ρ_fP*"
        names["addendum"] = "h_fP*"
    parts = [f"{names.get(k, k)} {_num(v) if isinstance(v, (int, float)) else v}" for k, v in data.items()
             if v is not None and k != "kind"]
    return f"{kind}: {', '.join(parts)}"


def _gear_rows(element: str, gears: Mapping[str, tuple], spec) -> list[list[str]]:
    """Rows quantity × gear of one set or stage; ``gears``: name → (GearGeometry, face width, internal)."""
    names = list(gears)

    def row(name, symbol, unit, pick):
        return [name, symbol, unit, *(pick(n, *gears[n]) for n in names)]

    def material(n):
        return spec.material_of(element, n)

    def hardness(n, *_):
        m = material(n)
        return f"{_num(m.hardness)} {m.hardness_scale or ''}".strip() if m.hardness else "not given"

    return [
        row("number of teeth", "z", "1", lambda n, g, b, i: f"{g.teeth} (internal)" if i else str(g.teeth)),
        row("profile shift coefficient", "x", "1", lambda n, g, b, i: _num(g.profile_shift)),
        row("normal module", "m_n", "mm", lambda n, g, b, i: _num(g.rack.module)),
        row("normal pressure angle", "α_n", "°", lambda n, g, b, i: _num(g.rack.pressure_angle)),
        row("helix angle", "β", "°", lambda n, g, b, i: _num(g.rack.helix_angle)),
        row("face width", "b", "mm", lambda n, g, b, i: _num(b)),
        row("reference diameter", "d", "mm", lambda n, g, b, i: _num(g.reference_diameter)),
        row("tip diameter", "d_a", "mm", lambda n, g, b, i: _num(g.tip_diameter)),
        row("root diameter", "d_f", "mm", lambda n, g, b, i: _num(g.root_diameter)),
        row("material", "", "", lambda n, *_: material(n).name),
        row("heat treatment (ISO 6336-5)", "", "", lambda n, *_: f"{material(n).treatment}, {material(n).quality}"),
        row("surface hardness", "", "", hardness),
        row("endurance limit for contact stress", "σ_Hlim", "N/mm²", lambda n, *_: _num(material(n).sigma_Hlim)),
        row("nominal stress number (bending)", "σ_Flim", "N/mm²", lambda n, *_: _num(material(n).sigma_Flim)),
        row("modulus of elasticity", "E", "N/mm²", lambda n, *_: _num(material(n).E)),
        row("tool", "", "", lambda n, g, b, i: _tool(spec.tool_of(element, n, i), spec)),
        row("accuracy grade (ISO 1328-1)", "Q", "1", lambda n, *_: str(spec.grade_of(element, n))),
        row("flank roughness", "R_zH", "µm", lambda n, *_: _num(spec.roughness_of("flank_roughness", element, n))),
        row("root roughness", "R_zF", "µm", lambda n, *_: _num(spec.roughness_of("root_roughness", element, n))),
        row("rim thickness", "s_R", "mm", lambda n, *_: _num(spec.rim_of(element, n)) or "solid"),
    ]


def _general_rows(spec) -> list[list[str]]:
    rows = [["standard", "", "", f"ISO 6336:{spec.standard}, method B"],
            ["required life", "L_h", "h", _num(spec.life)],
            ["minimum safety (pitting)", "S_Hmin", "1", _num(spec.S_Hmin)],
            ["minimum safety (tooth root)", "S_Fmin", "1", _num(spec.S_Fmin)],
            ["accuracy standard", "", "", f"ISO 1328-1:{spec.accuracy_standard}"],
            ["life factors at 10¹⁰ cycles", "", "", str(spec.long_life)],
            ["lubricant viscosity at 40 °C", "ν_40", "mm²/s", _num(spec.viscosity_40)],
            ["lubricant viscosity at 100 °C", "ν_100", "mm²/s", _num(spec.viscosity_100) or "not given"]]
    for name, mode in (("micropitting", spec.micropitting), ("scuffing", spec.scuffing)):
        if mode is not None:
            data = {k: v for k, v in mode.to_dict().items() if v is not None and not isinstance(v, (Mapping, list))}
            rows.append([f"{name} inputs", "", "", ", ".join(f"{k} = {v:g}" if isinstance(v, float) else f"{k} = {v}"
                                                             for k, v in data.items())])
    return rows


def _given_rows(planned, spec) -> list[list[str]]:
    rows = []
    for p in planned:
        inp = p.input
        for key, symbol in MESH_FACTORS.items():
            value = spec.given_factor(key, inp.element, inp.mesh.name)
            if value is None and key == "load_sharing" and getattr(inp, "load_sharing_source", "") == "given":
                rows.append([inp.element, inp.mesh.name, iso_symbol(symbol), _num(inp.load_sharing),
                             "given by the geometry"])
            elif value is not None:
                rows.append([inp.element, inp.mesh.name, iso_symbol(symbol), _num(value.value),
                             value.clause or f"rating.{key}"])
        for gear in inp.gears:
            for key in GEAR_DEVIATIONS:
                dev = spec.deviation_of(key, inp.element, gear)
                if dev is not None:
                    rows.append([inp.element, f"{inp.mesh.name} ({gear})", f"{key} [µm]", _num(dev),
                                 f"rating.{key} (measured)"])
    for key, symbol in (("shaft_deflection", "f_sh [µm]"), ("tip_relief", "C_a [µm]")):
        if getattr(spec, key, None):
            rows.append(["all", "all", symbol, _num(getattr(spec, key)), f"rating.{key}"])
    seen, out = set(), []
    for r in rows:  # a mesh input of each planet pass is listed once
        if tuple(r) not in seen:
            seen.add(tuple(r))
            out.append(r)
    return out


def echo_sections(planned: Sequence, spec) -> list[Section]:
    """The input echo: general inputs, the gears of each set or stage, the given factors.

    Parameters
    ----------
    planned : sequence of PlannedMesh
        The first item of :func:`~epicyclic.rating.train.mesh_inputs` (what the rating rates).
    spec : RatingSpec

    Returns
    -------
    list of Section

    References
    ----------
    ISO 6336-1:2019, clauses 4–6; ISO 21771:2007.
    """
    out = [Section("Inputs of the rating", ["quantity", "symbol", "unit", "value"], _general_rows(spec), level=2,
                   literal=(3,))]
    elements: dict[str, dict[str, tuple]] = {}
    for p in planned:
        inp = p.input
        for name, g in zip(inp.gears, (inp.mesh.gear1, inp.mesh.gear2)):
            elements.setdefault(inp.element, {}).setdefault(name, (g, inp.face_width, g.internal))
    for element, gears in elements.items():
        out.append(Section(f"Inputs: the gears of {element}", ECHO_GEAR_HEAD + list(gears),
                           _gear_rows(element, gears, spec), level=3))
    given = _given_rows(planned, spec)
    out.append(Section("Inputs: given factors", ["element", "mesh", "symbol", "value", "source"], given, level=3,
                       literal=(4,), notes=() if given else ("no factor given: every load factor computed by its clause",)))
    return out
