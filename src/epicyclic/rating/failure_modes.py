"""The failure modes beyond pitting and root that a mesh's rating inputs ask for.

:func:`failure_modes` is called by :func:`~epicyclic.rating.mesh_rating.rate_mesh` with the mesh's
input and its ISO 6336 rating; it returns one :class:`~epicyclic.rating.mode_results.ModeRating`
per mode whose inputs the :class:`~epicyclic.rating.spec.RatingSpec` gives:

* ``spec.micropitting`` → micropitting, ISO/TS 6336-22:2018 Method B
  (:func:`~epicyclic.rating.micropitting_rating.rate_micropitting`);
* ``spec.scuffing`` → scuffing by the integral temperature (``scuffing_integral``, ISO/TS 6336-21) and
  the flash temperature method (``scuffing_flash``, ISO/TS 6336-20)
  (:func:`~epicyclic.rating.scuffing.rating.scuffing_modes`);
* ``spec.flank_fracture`` → tooth flank fracture and the hardened layer, ISO/TS 6336-4:2019
  simplified (:func:`~epicyclic.rating.flank_fracture.rating.rate_flank_fracture`).

A mode without inputs is not rated (and not reported); a mode whose inputs are incomplete raises
:class:`~epicyclic.rating.errors.RatingError` naming the key.

References
----------
ISO/TS 6336-22:2018 (micropitting); ISO/TS 6336-20:2017, ISO/TS 6336-21:2017 (scuffing);
ISO/TS 6336-4:2019 (tooth flank fracture).
"""

from __future__ import annotations

__all__ = ["failure_modes"]


def failure_modes(inp, rating, torque, speed) -> tuple:
    """The :class:`~epicyclic.rating.mode_results.ModeRating` s of the modes ``inp.spec`` asks for.

    Parameters
    ----------
    inp : MeshInput
    rating : MeshRating
        The ISO 6336 rating of the same load.
    torque, speed : float or ndarray
        Torque on gear 1 per planet (N·m) and its speed (1/min), one per load case.

    Returns
    -------
    tuple of ModeRating

    References
    ----------
    ISO/TS 6336-22:2018.
    """
    out = []
    if getattr(inp.spec, "micropitting", None) is not None:
        from .micropitting_rating import rate_micropitting

        out.append(rate_micropitting(inp, rating, torque, speed))
    if getattr(inp.spec, "scuffing", None) is not None:
        from .scuffing.rating import scuffing_modes

        out.extend(scuffing_modes(inp, rating))
    if getattr(inp.spec, "flank_fracture", None) is not None:
        from .flank_fracture.rating import rate_flank_fracture

        out.append(rate_flank_fracture(inp, rating, torque, speed))
    return tuple(out)
