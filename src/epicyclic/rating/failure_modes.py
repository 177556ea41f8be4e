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
:class:`~epicyclic.rating.errors.RatingError` naming the key.  A mesh that does not turn in any of
its load cases (a set that turns as a block in a transmission's gear: no rolling, no sliding) has no
lubricant film and no flash temperature: its modes are not rated and :func:`idle_note` says so in
the mesh's notes.  Where it stands still in some cases of a batch only (the cases of several gears
rated together, as a duty cycle's damage sums do), the modes are not rated over that batch either,
and the note says in how many cases and how to rate them (by gear).

References
----------
ISO/TS 6336-22:2018 (micropitting); ISO/TS 6336-20:2017, ISO/TS 6336-21:2017 (scuffing);
ISO/TS 6336-4:2019 (tooth flank fracture).
"""

from __future__ import annotations

import numpy as np

__all__ = ["failure_modes", "idle_note"]


def _requested(spec) -> list[str]:
    return [name for name in ("micropitting", "scuffing") if getattr(spec, name, None) is not None]


def idle_note(inp, speed) -> str | None:
    """The note of a mesh whose modes are not rated because it stands still in some or all cases, else None.

    Parameters
    ----------
    inp : MeshInput
    speed : float or ndarray
        Speed of gear 1 relative to the carrier (1/min), one per load case.

    Returns
    -------
    str or None

    References
    ----------
    ISO/TS 6336-22:2018, clause 7 (the film needs the sum velocity); ISO/TS 6336-20:2017, clause 5 (the
    flash temperature needs the sliding velocity).
    """
    modes = _requested(inp.spec)
    still = np.abs(np.asarray(speed, dtype=float)).reshape(-1) == 0
    if not modes or not np.any(still):
        return None
    why = "no rolling, no lubricant film, no flash temperature"
    if np.all(still):
        return f"{' and '.join(modes)} not rated: the mesh does not turn (gear 1 at 0 1/min relative to the carrier: {why})"
    return (f"{' and '.join(modes)} not rated over these load cases: the mesh stands still in {int(still.sum())} of "
            f"{still.size} ({why}); rate the cases of each gear on their own (epicyclic rate --gear G)")


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
    if idle_note(inp, speed) is not None:
        return ()
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
