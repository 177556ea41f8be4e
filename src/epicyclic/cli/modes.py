"""``epicyclic modes``: the seven two-shaft ratios of one set with efficiencies both ways.

Give tooth counts (``--sun``, ``--ring`` and, for double or stepped planets,
``--planet-sun``/``--planet-ring``) or the stationary ratio ``--i0`` (a number
or an expression such as ``"(24/50)*(42/30)"``), and ``--eta0``.  Numbers come
from :func:`epicyclic.analysis.modes.two_shaft_modes`, i.e. from the general
solver.

References
----------
Queitsch, Tafel 1; Brandenberger 1952, eq. 7.
"""

from __future__ import annotations

import json
from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..errors import EpicyclicError, ModelError
from ..io.expressions import evaluate
from ..io.located import located
from ..io.tables import ReportTable
from ..limits import RATIO_RANGE, LimitError
from ..model import PlanetarySet
from ._common import check_finite, emit, guarded

__all__ = ["SetKind", "ModesFormat", "modes", "planetary_from_options"]


class SetKind(str, Enum):
    """Planet arrangements."""

    simple = "simple"
    double = "double"
    stepped = "stepped"


class ModesFormat(str, Enum):
    """Output formats of ``modes``."""

    table = "table"
    json = "json"
    markdown = "markdown"


def planetary_from_options(kind: SetKind, sun: int | None, ring: int | None, planet: int | None,
                           planet_sun: int | None, planet_ring: int | None, external_ring: bool,
                           i0: str | None, eta0: float) -> PlanetarySet:
    """The set the options describe (raises ModelError on missing or conflicting options)."""
    teeth_given = any(v is not None for v in (sun, ring, planet, planet_sun, planet_ring))
    if i0 is not None:
        if teeth_given:
            raise ModelError("modes: give tooth counts (--sun, --ring, ...) or --i0, not both.")
        ratio = evaluate(i0, "--i0")
        if ratio != 0 and not RATIO_RANGE[0] <= abs(ratio) <= RATIO_RANGE[1]:
            raise LimitError(f"--i0: |{ratio:.6g}| is outside the accepted {RATIO_RANGE[0]:g} … "
                             f"{RATIO_RANGE[1]:g} (see docs/limits.md).", "--i0")
        return PlanetarySet("set", "sun", "ring", "carrier", ratio, eta0)
    if sun is None or ring is None:
        raise ModelError("modes: give --sun and --ring tooth counts (and --planet-sun/--planet-ring for "
                         "double or stepped planets), or the stationary ratio --i0.")
    common = dict(sun="sun", ring="ring", carrier="carrier", z_sun=sun, z_ring=ring, stationary_efficiency=eta0)
    if kind is SetKind.simple:
        if planet_sun is not None or planet_ring is not None:
            raise ModelError("modes: --planet-sun/--planet-ring are for --kind double or stepped; a simple set "
                             "takes --planet.")
        if planet is None:
            if (ring - sun) % 2:
                raise ModelError(f"modes: z_ring - z_sun = {ring} - {sun} is odd, so no standard planet fits; "
                                 "give --planet.")
            planet = (ring - sun) // 2
        return PlanetarySet.simple("set", z_planet=planet, **common)
    if planet_sun is None or planet_ring is None:
        raise ModelError(f"modes: --kind {kind.value} needs --planet-sun and --planet-ring.")
    if kind is SetKind.double:
        return PlanetarySet.double_planet("set", z_planet_sun=planet_sun, z_planet_ring=planet_ring, **common)
    return PlanetarySet.stepped("set", z_planet_sun=planet_sun, z_planet_ring=planet_ring,
                                ring_internal=not external_ring, **common)


#: The model's field names and the options that give them (longest first: z_planet_sun before z_planet).
_OPTIONS = (("z_planet_ring", "--planet-ring"), ("z_planet_sun", "--planet-sun"), ("z_planet", "--planet"),
            ("z_sun", "--sun"), ("z_ring", "--ring"), ("stationary_efficiency", "--eta0"),
            ("stationary_ratio", "--i0"))


def _with_option(exc: EpicyclicError) -> EpicyclicError:
    """A model error about the set, located at the option that gave the value."""
    message = str(exc)
    option = next((opt for name, opt in _OPTIONS if name in message), "")
    return located(exc, "modes", option, owner="planetary set 'set'") if option else exc


@guarded
def modes(
    sun: Annotated[Optional[int], typer.Option(help="Teeth of the sun (first central gear).")] = None,
    ring: Annotated[Optional[int], typer.Option(help="Teeth of the ring (second central gear).")] = None,
    planet: Annotated[Optional[int], typer.Option(help="Planet teeth (simple set; default (ring − sun)/2).")] = None,
    kind: Annotated[SetKind, typer.Option(help="simple, double (plus set) or stepped planets.")] = SetKind.simple,
    planet_sun: Annotated[Optional[int], typer.Option(help="Planet gear meshing the sun (double/stepped).")] = None,
    planet_ring: Annotated[Optional[int], typer.Option(
        help="Planet gear meshing the ring (double/stepped).")] = None,
    external_ring: Annotated[bool, typer.Option(
        help="Stepped set whose second central gear is external (Brandenberger's a/b·c/d).")] = False,
    i0: Annotated[Optional[str], typer.Option(
        help="Stationary ratio i0 instead of teeth: a number or an expression like '(24/50)*(42/30)'.")] = None,
    eta0: Annotated[float, typer.Option(help="Stationary efficiency η0 in (0, 1].")] = 1.0,
    format: Annotated[ModesFormat, typer.Option("--format", "-f", help="Output format.")] = ModesFormat.table,
    out: Annotated[Optional[Path], typer.Option("--out", "-o", help="Write to this file instead of stdout.")] = None,
) -> None:
    """The seven two-shaft ratios of a set (Queitsch Tafel 1) with efficiencies in both directions."""
    try:
        planetary = planetary_from_options(kind, sun, ring, planet, planet_sun, planet_ring, external_ring, i0, eta0)
    except EpicyclicError as exc:
        raise _with_option(exc) from None
    from ..analysis.modes import two_shaft_modes  # imported here: other commands start faster

    table = two_shaft_modes(planetary)
    check_finite(table.to_dict(), "modes")
    if format is ModesFormat.json:
        text = json.dumps(table.to_dict(), indent=2, ensure_ascii=False) + "\n"
    elif format is ModesFormat.markdown:
        caption = (f"Two-shaft modes, i0 = {table.stationary_ratio:.6g}, η0 = {table.stationary_efficiency:.4g}"
                   " (Queitsch, Tafel 1)")
        text = ReportTable(caption, tuple(table.HEADERS), tuple(tuple(r) for r in table.rows())).markdown() + "\n"
    else:
        text = table.table() + "\n"
    emit(text, out)
