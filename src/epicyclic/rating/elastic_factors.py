"""K_γ and K_Hβ computed by the elastic model of each set, as the rating's given factors with their source.

Where the ``[elastic]`` table says ``rating = ["load_sharing", "K_Hbeta"]`` (either or both), the
rating of each simple or stepped set with geometry takes, at the operating point it rates:

* K_γ = max F_n / mean F_n of the static load sharing (:func:`epicyclic.elastic.load_sharing`) at
  the set's sun torque with the errors of ``[elastic.errors]`` (none: K_γ = 1);
* K_Hβ of each of its meshes from the slice model (:func:`epicyclic.elastic.face_load`) with the
  most loaded planet's mesh force times K_A (where K_A is one number) and the misalignment and
  modifications of ``[elastic.face]`` (none: aligned and unmodified, K_Hβ = 1 but for the sun's
  torsion), c_γβ = 0.85 c_γα (ISO 6336-1, 9.3.2).

Each enters the rating as a :class:`~epicyclic.rating.given_factors.FactorValue` whose source says
"computed by the elastic model", so the report shows where the factor came from.  A factor that is
both given in ``[rating]`` and asked of the elastic model is refused.

References
----------
ISO 6336-1:2019, 6.5.9 (K_γ), 7 (K_Hβ, method A/B: from a model of the deflections);
J. Lin, R. G. Parker, J. Vib. Acoust. 121 (1999) 316–321; ISO 6336-1:2006, annex E.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from ..elastic.errors import ElasticError
from ..elastic.face_load import face_load
from ..elastic.from_geometry import ElasticSpec, lumped_model
from ..elastic.sharing import PlanetErrors, load_sharing
from .errors import RatingError
from .given_factors import FactorValue

__all__ = ["ELASTIC_FACTORS", "with_elastic_factors"]

#: The factors the elastic model can compute, by ``[rating]`` key.
ELASTIC_FACTORS = ("load_sharing", "K_Hbeta")

SOURCE = "computed by the elastic model"


def _sets(geometry: Mapping[str, Any], solution) -> list[tuple[str, Any, float]]:
    out = []
    for name, g in geometry.items():
        teeth = getattr(getattr(g, "planetary_set", None), "teeth", None)
        if teeth is None or teeth.kind not in ("simple", "stepped"):
            continue
        state = solution.elements.get(name)
        torque = abs(float(state.torques.get("sun", 0.0))) if state is not None else 0.0
        out.append((name, g, torque))
    return out


def with_elastic_factors(spec, geometry: Mapping[str, Any], elastic, solution, which) -> Any:
    """``spec`` with K_γ and/or K_Hβ of every modelled set computed by the elastic model at ``solution``.

    Parameters
    ----------
    spec : RatingSpec
    geometry : mapping element → SetGeometry
    elastic : ElasticInputs
        The file's ``[elastic]`` table (:mod:`epicyclic.io.elastic_format`).
    solution : Solution
        The operating point rated (the sun torque of each set).
    which : sequence of str
        Some of :data:`ELASTIC_FACTORS`.

    Returns
    -------
    RatingSpec

    Raises
    ------
    RatingError
        A factor both given in ``[rating]`` and asked of the elastic model; a set without torque;
        an elastic model that cannot be built (the message says why).

    References
    ----------
    ISO 6336-1:2019, 6.5.9 and 7; Lin & Parker 1999.
    """
    for key in which:
        if key not in ELASTIC_FACTORS:
            raise RatingError(f"[elastic] rating: {key!r} cannot be computed by the elastic model; use "
                              f"{' or '.join(ELASTIC_FACTORS)}.")
        if getattr(spec, key) is not None:
            raise RatingError(f"[rating] {key} is given and [elastic] rating asks the elastic model for it: give "
                              "one of them.")
    model_spec = elastic.spec if elastic is not None else ElasticSpec()
    errors = elastic.errors if elastic is not None and elastic.errors is not None else PlanetErrors()
    face = elastic.face if elastic is not None and elastic.face is not None else None
    k_a = spec.application_factor if isinstance(spec.application_factor, (int, float)) else 1.0
    gammas: dict[str, FactorValue] = {}
    betas: dict[str, FactorValue] = {}
    for name, g, torque in _sets(geometry, solution):
        if torque <= 0.0:
            raise RatingError(f"[elastic] rating: set {name!r} carries no sun torque at this operating point; "
                              "K_gamma and K_Hbeta need a load.")
        try:
            model, _ = lumped_model(g, model_spec)
            loads = load_sharing(model, torque, errors)
        except ElasticError as exc:
            raise RatingError(f"[elastic] rating, set {name!r}: {exc}") from None
        gammas[name] = FactorValue(loads.k_gamma, SOURCE, "ISO 6336-1:2019, 6.5.9 (Lin & Parker 1999 lumped model, "
                                                         "one-sided contact, the errors of [elastic.errors])")
        worst = int(loads.sun_mesh.argmax())
        for mesh, k, force in ((g.sun_mesh, model.sun_mesh, loads.sun_mesh[worst]),
                               (g.ring_mesh, model.ring_mesh, loads.ring_mesh[worst])):
            b = g.mesh_face_width(mesh)
            sun = g.gears["sun"]
            twist = (sun.root_diameter, sun.base_diameter / 2, 80000.0) if mesh is g.sun_mesh and (
                face is None or face["sun_torsion"]) else None
            result = face_load(float(force) * k_a, b, 0.85 * k / (b * 1e6),
                               misalignment=face["misalignment"] if face else 0.0,
                               modification=face["modification"] if face else None,
                               slices=face["slices"] if face else 40, torsion=twist)
            betas[f"{name}:{mesh.name}"] = FactorValue(result.k_hbeta, SOURCE, "ISO 6336-1:2019, 7 (slice model: "
                                                                               "misalignment, modifications, sun torsion)")
    out = spec
    if "load_sharing" in which:
        out = replace(out, load_sharing=gammas or None)
    if "K_Hbeta" in which:
        out = replace(out, K_Hbeta=betas or None)
    return out
