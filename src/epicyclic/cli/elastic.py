"""``epicyclic vibration FILE`` and ``epicyclic sharing FILE``: the planetary sets as elastic systems.

``vibration``: natural frequencies and mode types of every simple, stepped or double-planet set with a
geometry table
(Lin & Parker 1999), the mesh phasing (which mesh harmonics excite which mode type) and the
Campbell diagram's crossings over a speed range.  ``sharing`` (simple and stepped sets): the static load of every planet
and K_γ from the errors of the ``[elastic]`` table, over torque, over a carrier revolution
(with run-outs) and as a Monte-Carlo distribution (with tolerances).  Stiffnesses come from the
``[elastic]`` table or the stated defaults (``docs/elastic.md``); the defaults taken are listed.
Exit codes: 0, 2 bad input, 1 internal error.
"""

from __future__ import annotations

import html
import json
from pathlib import Path
from typing import Annotated, Any, Optional

import typer

from ._common import FormatOption, OutOption, OutputFormat, SetOption, check_finite, emit, guarded, load

__all__ = ["vibration", "sharing"]


def _sets(file: Path, overrides: list[str] | None):
    """(train file, [(name, geometry, model, defaults taken, element state or None)]) of the simple sets."""
    from ..elastic.errors import ElasticError
    from ..elastic.from_geometry import ElasticSpec, lumped_model
    from ..model import PlanetarySet

    train_file = load(file, None, overrides)
    inputs = train_file.elastic
    spec = inputs.spec if inputs is not None else ElasticSpec()
    chosen = inputs.set_name if inputs is not None else None
    sets = [e for e in train_file.train.elements if isinstance(e, PlanetarySet) and e.name in train_file.geometry
            and e.teeth is not None and e.teeth.kind in ("simple", "stepped", "double")]
    if chosen is not None:
        if chosen not in {e.name for e in sets}:
            raise ElasticError(f"[elastic] set: {chosen!r} is no simple set with a geometry table; the file has "
                               f"{', '.join(repr(e.name) for e in sets) or 'none'}.")
        sets = [e for e in sets if e.name == chosen]
    if not sets:
        raise ElasticError(f"{file}: no simple planetary set with a geometry table ([planetary.geometry] with module "
                           "and face_width); the elastic models need one (docs/elastic.md).")
    state = None
    if train_file.operating_point is not None:
        state = train_file.solve().elements
    out = []
    for element in sets:
        try:
            model, taken = lumped_model(train_file.geometry[element.name], spec)
        except ElasticError as exc:
            raise ElasticError(f"[[planetary]] {element.name!r}: {exc}") from None
        out.append((element, train_file.geometry[element.name], model, taken,
                    state.get(element.name) if state is not None else None))
    return train_file, out


def _page(title: str, sections: list[tuple[str, Any]], format: OutputFormat) -> str:
    """Sections (heading, result with table/markdown/_repr_html_ or a list of lines) in one document."""
    if format is OutputFormat.markdown:
        body = [f"# {title}"]
        for head, part in sections:
            body += [f"## {head}", part.markdown() if hasattr(part, "markdown") else "\n".join(f"- {x}" for x in part)]
        return "\n\n".join(body) + "\n"
    if format is OutputFormat.html:
        body = [f"<h1>{html.escape(title)}</h1>"]
        for head, part in sections:
            inner = part._repr_html_() if hasattr(part, "_repr_html_") else \
                "<ul>" + "".join(f"<li>{html.escape(x)}</li>" for x in part) + "</ul>"
            body.append(f"<h2>{html.escape(head)}</h2>{inner}")
        return ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>" + html.escape(title)
                + "</title></head><body>" + "".join(body) + "</body></html>\n")
    body = [title, "=" * len(title)]
    for head, part in sections:
        body += ["", head, "-" * len(head), part.table() if hasattr(part, "table") else "\n".join(part)]
    return "\n".join(body) + "\n"


def _ratios(element, state) -> tuple[dict[str, float], str]:
    """Member speeds per unit sun speed: from the operating point, else the ring held (stated)."""
    if state is not None and state.speeds.get("sun"):
        n_s = state.speeds["sun"]
        return ({m: state.speeds[m] / n_s for m in ("sun", "ring", "carrier")},
                "member speeds in the ratios of the operating point")
    i0 = element.teeth.stationary_ratio          # Willis: n_c = n_s/(1 - i0) with the ring held
    return {"sun": 1.0, "ring": 0.0, "carrier": 1.0 / (1.0 - i0)}, "ring held, sun driving (no operating point)"


def _face_loads(geometry, model, loads, face: dict) -> dict:
    """Face load of the sun and ring mesh of the most loaded planet (c_γβ = 0.85 c_γα, ISO 6336-1, 9.3.2)."""
    from ..elastic.face_load import face_load

    worst = int(loads.sun_mesh.argmax())
    out = {}
    for name, mesh, k, force in (("sun", geometry.sun_mesh, model.sun_mesh, loads.sun_mesh[worst]),
                                 ("ring", geometry.ring_mesh, model.ring_mesh, loads.ring_mesh[worst])):
        b = geometry.mesh_face_width(mesh)
        c_gamma_beta = 0.85 * k / (b * 1e6)                        # N/(mm µm)
        sun = geometry.gears["sun"]
        torsion = (sun.root_diameter, sun.base_diameter / 2, 80000.0) if name == "sun" and face["sun_torsion"] \
            else None                                              # the sun twists (steel, G = 80 GPa)
        height = (mesh.gear1.tip_diameter - mesh.gear1.root_diameter) / 2
        out[name] = face_load(float(force), b, c_gamma_beta, misalignment=face["misalignment"],
                              modification=face["modification"], slices=face["slices"], tooth_height=height,
                              torsion=torsion)
    return out


@guarded
def vibration(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with a geometry table per set.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    points: Annotated[int, typer.Option(help="Speeds of the Campbell diagram.", min=2, max=100000)] = 1000,
    harmonics: Annotated[int, typer.Option(help="Mesh harmonics drawn and listed.", min=1, max=20)] = 3,
    gyroscopic: Annotated[bool, typer.Option("--gyroscopic/--at-rest",
                                             help="Natural frequencies at the carrier speed or at rest.")] = True,
    plot: Annotated[Optional[Path], typer.Option(help="Also draw the Campbell diagram (.svg or .png).")] = None,
    set_: SetOption = None,
) -> None:
    """Natural frequencies and mode types, mesh phasing and Campbell crossings of every simple set with geometry."""
    import numpy as np

    from ..elastic.campbell import campbell_diagram
    from ..elastic.modes import natural_modes
    from ..elastic.phasing import mesh_phasing

    train_file, sets = _sets(file, set_)
    inputs = train_file.elastic
    sections: list[tuple[str, Any]] = []
    data: dict[str, Any] = {"title": f"vibration of {train_file.title}", "sets": {}}
    for element, _, model, taken, state in sets:
        modes = natural_modes(model)
        phasing = mesh_phasing(element.teeth.sun, element.teeth.ring, model.planet_angles)
        ratios, basis = _ratios(element, state)
        n_op = abs(state.speeds["sun"]) if state is not None and state.speeds.get("sun") else None
        span = inputs.speed_range if inputs is not None and inputs.speed_range else (0.0, 1.5 * n_op if n_op else 6000.0)
        band = inputs.operating_range if inputs is not None else None
        campbell = campbell_diagram(model, element.teeth.sun, element.teeth.ring, ratios,
                                    np.linspace(span[0], span[1], points), mesh_harmonics=harmonics,
                                    operating=band, gyroscopic=gyroscopic)
        notes = [f"defaults taken: {t}" for t in taken] or ["every stiffness given in [elastic]"]
        notes.append(f"Campbell diagram: sun speed {span[0]:g} … {span[1]:g} 1/min, {points} points; {basis}")
        sections += [(f"{element.name}: natural modes", modes), (f"{element.name}: mesh phasing", phasing),
                     (f"{element.name}: Campbell crossings", campbell), (f"{element.name}: inputs", notes)]
        data["sets"][element.name] = {"modes": modes.to_dict(), "phasing": phasing.to_dict(harmonics),
                                      "campbell": {k: v for k, v in campbell.to_dict().items()
                                                   if k in ("crossings", "orders", "operating_rpm", "gyroscopic")},
                                      "defaults_taken": taken, "notes": notes}
        if plot is not None:
            from ..plotting.elastic import save_campbell

            save_campbell(campbell, plot if len(sets) == 1 else plot.with_stem(f"{plot.stem}-{element.name}"),
                          title=f"{element.name}: Campbell diagram")
    check_finite(data, file, "vibration")
    if format is OutputFormat.json:
        emit(json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n", out)
        return
    emit(_page(data["title"], sections, format), out)


@guarded
def sharing(
    file: Annotated[Path, typer.Argument(help="Train description (.toml) with a geometry table per set.")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    torque: Annotated[Optional[float], typer.Option(help="Sun torque, N m (default: the operating point's).")] = None,
    plot: Annotated[Optional[Path], typer.Option(
        help="Also draw the load per planet over a carrier revolution (and, with [elastic.face], the face load "
             "to NAME-face.svg).")] = None,
    set_: SetOption = None,
) -> None:
    """Load of every planet and K_γ from the [elastic] errors: over torque, a carrier revolution, Monte Carlo."""
    import math

    import numpy as np

    from ..elastic.errors import ElasticError
    from ..elastic.sharing import (PlanetErrors, load_sharing, monte_carlo_sharing, sharing_over_revolution,
                                   sharing_over_torque)
    from ..geometry.errors import GeometryError
    from ..geometry.load_sharing import default_load_sharing, tabulated_load_sharing

    train_file, sets = _sets(file, set_)
    inputs = train_file.elastic
    sections: list[tuple[str, Any]] = []
    data: dict[str, Any] = {"title": f"load sharing of {train_file.title}", "sets": {}}
    skipped = [e.name for e, *_ in sets if e.teeth.kind == "double"]
    sets = [entry for entry in sets if entry[0].teeth.kind != "double"]
    if not sets:
        raise ElasticError(f"sharing: the load sharing of double-planet sets ({', '.join(map(repr, skipped))}) is not "
                           "modelled yet; epicyclic vibration gives their modes.")
    if skipped:
        data["skipped"] = {name: "double-planet set: load sharing not modelled" for name in skipped}
        sections.append(("skipped", [f"{name}: a double-planet set, its load sharing is not modelled" for name in
                                     skipped]))
    for element, geometry, model, taken, state in sets:
        t = torque
        if t is None:
            if state is None or not state.torques.get("sun"):
                raise ElasticError(f"sharing: [[planetary]] {element.name!r} has no sun torque: give an "
                                   "[operating_point] or --torque (N m).")
            t = abs(state.torques["sun"])
        if not math.isfinite(t) or t <= 0:
            raise ElasticError(f"--torque must be a finite sun torque > 0 in N m, got {t!r}.")
        errors = inputs.errors if inputs is not None and inputs.errors is not None else PlanetErrors()
        loads = load_sharing(model, t, errors)
        sweep = sharing_over_torque(model, t * np.geomspace(0.1, 10.0, 9), errors)
        sections += [(f"{element.name}: planet loads", loads), (f"{element.name}: K_gamma over torque", sweep)]
        entry: dict[str, Any] = {"loads": loads.to_dict(), "over_torque": sweep.to_dict(), "defaults_taken": taken}
        revolution = None
        if errors.sun_runout or errors.ring_runout or plot is not None:
            i0 = element.teeth.stationary_ratio  # ring held: the sun turns -i0 times against the carrier
            revolution = sharing_over_revolution(model, t, errors, np.linspace(0.0, 360.0, 361),
                                                 sun_turns=-i0, ring_turns=-1.0)
            sections.append((f"{element.name}: over a carrier revolution (ring held)", revolution))
            entry["over_revolution"] = revolution.to_dict()
        if inputs is not None and inputs.tolerances is not None:
            mc = monte_carlo_sharing(model, t, inputs.tolerances, inputs.draws, inputs.seed)
            sections.append((f"{element.name}: Monte Carlo", mc))
            entry["monte_carlo"] = mc.to_dict()
        if inputs is not None and inputs.face is not None:
            faces = _face_loads(geometry, model, loads, inputs.face)
            for mesh_name, face in faces.items():
                sections.append((f"{element.name}: face load, {mesh_name} mesh of the most loaded planet", face))
                entry.setdefault("face_load", {})[mesh_name] = face.to_dict()
            if plot is not None:
                from ..plotting.elastic import save_face_load

                name = f"{plot.stem}-face" if len(sets) == 1 else f"{plot.stem}-{element.name}-face"
                save_face_load({f"{m} mesh": f for m, f in faces.items()}, plot.with_stem(name),
                               title=f"{element.name}: load along the face width, most loaded planet")
        notes = [f"computed K_gamma = {loads.k_gamma:.4f} at {t:g} N m (one-sided contact, errors of [elastic])"]
        planets = element.planets
        try:
            table = tabulated_load_sharing(planets, "floating_sun")
            notes.append(f"for comparison: {table}")
        except GeometryError as exc:  # more planets than the table covers
            notes.append(f"for comparison: no table value ({exc})")
        used = geometry.load_sharing
        rated = inputs is not None and "load_sharing" in inputs.rating
        notes.append("the forces use " + (f"the file's K_gamma = {used:g}" if used is not None else
                                          f"the default K_gamma = {default_load_sharing(planets):g} (ABS rules)")
                     + "; epicyclic rate uses " + ("the computed K_gamma ([elastic] rating)" if rated else
                                                   "the [rating] or that value ([elastic] rating = "
                                                   "[\"load_sharing\"] makes it take the computed one)"))
        notes += [f"defaults taken: {x}" for x in taken]
        sections.append((f"{element.name}: notes", notes))
        entry["notes"] = notes
        data["sets"][element.name] = entry
        if plot is not None and revolution is not None:
            from ..plotting.elastic import save_planet_loads

            save_planet_loads(revolution, plot if len(sets) == 1 else plot.with_stem(f"{plot.stem}-{element.name}"),
                              title=f"{element.name}: load per planet over a carrier revolution")
    check_finite(data, file, "sharing")
    if format is OutputFormat.json:
        emit(json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n", out)
        return
    emit(_page(data["title"], sections, format), out)
