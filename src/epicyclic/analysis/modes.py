"""Single-set conveniences on top of the general solver.

* :func:`two_shaft_modes` — the seven two-shaft ratios of Queitsch's Tafel 1,
  each with the efficiency in both directions of power flow.  Every number
  comes from :func:`epicyclic.solve` on a train of one set plus a brake (or a
  clutch for direct drive); nothing is hand-coded here.
* :func:`three_shaft_speeds` — three-shaft operation: two speeds given, the
  third (and the planet speeds) from the Willis equation.

References
----------
Queitsch, Tafel 1 and eqs. 12, 20, 21; Brandenberger 1952, Bild 3–4 (ranges 1–7);
tec-science, "Willis-Gleichung" (fixed sun / ring / carrier).
"""

from __future__ import annotations

import html
from dataclasses import dataclass, replace

from ..errors import ModelError
from ..model.elements import Brake, Clutch
from ..model.operating_point import OperatingPoint
from ..model.planetary import PlanetarySet
from ..model.train import GearTrain
from ..solver.assembly import matrices
from ..solver.kinematics import solve_speeds
from ..solver.solve import solve
from ..units import to_core

__all__ = ["TwoShaftMode", "ModeTable", "two_shaft_modes", "three_shaft_speeds", "QUEITSCH_TAFEL_1"]

#: Queitsch Tafel 1: (column, input, output, held shaft or None for direct drive, ratio formula in s).
QUEITSCH_TAFEL_1 = (
    ("I", "carrier", "sun", "ring", "1/(1-s)"),
    ("II", "carrier", "ring", "sun", "-s/(1-s)"),
    ("III", "ring", "sun", "carrier", "1/s"),
    ("IV", "ring", "carrier", "sun", "(1-s)/(-s)"),
    ("V", "sun", "ring", "carrier", "s"),
    ("VI", "sun", "carrier", "ring", "1-s"),
    ("VII", "sun", "ring", None, "1"),
)


@dataclass(frozen=True)
class TwoShaftMode:
    """One two-shaft operating mode of a planetary set.

    Attributes
    ----------
    label : str
        Queitsch's Tafel 1 column (I … VII).
    input, output : str
        Member driven from outside and member delivering power.
    held : str or None
        The member held by a brake; None for direct drive (two members joined).
    ratio : float
        n_input / n_output.
    formula : str
        The ratio in terms of s = i0 (Queitsch).
    efficiency : float or None
        Efficiency input → output; None if that direction self-locks.
    reverse_efficiency : float or None
        Efficiency output → input (power from the other side); None if it self-locks.
    threshold, reverse_threshold : float or None
        The η0 below which the direction self-locks (None if it never does).
    """

    label: str
    input: str
    output: str
    held: str | None
    ratio: float
    formula: str
    efficiency: float | None
    reverse_efficiency: float | None
    threshold: float | None = None
    reverse_threshold: float | None = None

    @property
    def self_locking(self) -> bool:
        return self.efficiency is None

    @property
    def reverse_self_locking(self) -> bool:
        return self.reverse_efficiency is None


@dataclass(frozen=True)
class ModeTable:
    """The seven two-shaft modes of a set (Queitsch Tafel 1) with efficiencies."""

    stationary_ratio: float
    stationary_efficiency: float
    modes: tuple[TwoShaftMode, ...]

    def __getitem__(self, label: str) -> TwoShaftMode:
        for mode in self.modes:
            if mode.label == label:
                return mode
        raise KeyError(f"no mode {label!r}; modes are I … VII (Queitsch Tafel 1)")

    def __iter__(self):
        return iter(self.modes)

    def __len__(self) -> int:
        return len(self.modes)

    def rows(self) -> list[list[str]]:
        """The table's rows as formatted cells, one per mode (columns: :attr:`HEADERS`).

        Ratios to 6 significant digits, efficiencies to 4 decimals; a direction that
        self-locks reads ``self-locking (η0 < threshold)``.

        Returns
        -------
        list of list of str
        """
        def eff(value: float | None, threshold: float | None) -> str:
            if value is None:
                return "self-locking" + (f" (η0 < {threshold:.4g})" if threshold else "")
            return f"{value:.4f}"

        return [
            [m.label, m.input, m.output, m.held or "— (clutch)", m.formula, f"{m.ratio:.6g}",
             eff(m.efficiency, m.threshold), eff(m.reverse_efficiency, m.reverse_threshold)]
            for m in self.modes
        ]

    HEADERS = ("mode", "input", "output", "held", "i in s", "ratio n_in/n_out", "η in→out", "η out→in")

    def table(self) -> str:
        """The seven modes as an aligned plain-text table, under a line naming i0 and η0.

        Returns
        -------
        str

        References
        ----------
        Queitsch, Tafel 1 (the seven two-shaft ratios in s = i0).

        Examples
        --------
        >>> print(two_shaft_modes(-2.0, 0.97).table().splitlines()[0])
        two-shaft modes of a set with i0 = s = -2, η0 = 0.97 (Queitsch, Tafel 1)
        """
        rows = self.rows()
        widths = [max(len(h), *(len(r[k]) for r in rows)) for k, h in enumerate(self.HEADERS)]
        lines = [
            f"two-shaft modes of a set with i0 = s = {self.stationary_ratio:.6g}, "
            f"η0 = {self.stationary_efficiency:.4g} (Queitsch, Tafel 1)",
            "  ".join(h.ljust(w) for h, w in zip(self.HEADERS, widths)),
            "  ".join("-" * w for w in widths),
        ]
        lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths)) for r in rows]
        return "\n".join(lines)

    def to_dict(self) -> dict:
        """The table as JSON-ready data: i0, η0 and every mode's fields.

        Returns
        -------
        dict
            ``stationary_ratio``, ``stationary_efficiency`` and ``modes``: a list of
            ``{label, input, output, held, formula, ratio, efficiency, reverse_efficiency,
            threshold, reverse_threshold}`` (efficiencies ``None`` where a direction
            self-locks; ``held`` ``None`` for direct drive).
        """
        return {
            "stationary_ratio": self.stationary_ratio,
            "stationary_efficiency": self.stationary_efficiency,
            "modes": [
                {
                    "label": m.label, "input": m.input, "output": m.output, "held": m.held,
                    "formula": m.formula, "ratio": m.ratio, "efficiency": m.efficiency,
                    "reverse_efficiency": m.reverse_efficiency, "threshold": m.threshold,
                    "reverse_threshold": m.reverse_threshold,
                }
                for m in self.modes
            ],
        }

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self.HEADERS)
        body = "".join(
            "<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in self.rows()
        )
        return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"

    def __str__(self) -> str:
        return self.table()


def _as_set(stationary_ratio: float | PlanetarySet, stationary_efficiency: float | None) -> PlanetarySet:
    if isinstance(stationary_ratio, PlanetarySet):
        base = stationary_ratio
        if stationary_efficiency is not None:
            base = replace(base, stationary_efficiency=stationary_efficiency)
        return replace(base, name="set", sun="sun", ring="ring", carrier="carrier")
    return PlanetarySet("set", "sun", "ring", "carrier", stationary_ratio,
                        1.0 if stationary_efficiency is None else stationary_efficiency)


def _direction(planetary: PlanetarySet, held: str | None, drive: str, load: str) -> tuple[float, float | None, float | None]:
    """(ratio, efficiency or None, threshold or None) for power from ``drive`` to ``load``."""
    holder = Brake("held", held) if held else Clutch("joined", "sun", "ring")
    train = GearTrain([planetary, holder], name="two-shaft mode")
    op = OperatingPoint(speeds={drive: 1000.0}, torques={drive: 1.0}, drives=[drive], loads=[load])
    solution = solve(train, op)
    ratio = solution.speed(drive) / solution.speed(load)
    if solution.self_locking is not None:
        threshold = solution.self_locking.thresholds.get("set")
        return ratio, None, threshold
    return ratio, solution.efficiency, None


def two_shaft_modes(
    stationary_ratio: float | PlanetarySet, stationary_efficiency: float | None = None
) -> ModeTable:
    """The seven two-shaft ratios of a set with efficiencies in both directions.

    Parameters
    ----------
    stationary_ratio : float or PlanetarySet
        i0 = s, or a set (its ratio and η0 are used).
    stationary_efficiency : float, optional
        η0 in (0, 1]; default the set's, or 1.

    Returns
    -------
    ModeTable

    References
    ----------
    Queitsch, Tafel 1 (ratios in s); Brandenberger 1952, eq. 7 (loss rule).

    Examples
    --------
    >>> table = two_shaft_modes(-2.0, 0.97)
    >>> round(table["VI"].ratio, 9), round(table["VI"].efficiency, 4)   # sun → carrier, ring held: 1 − s
    (3.0, 0.98)
    """
    planetary = _as_set(stationary_ratio, stationary_efficiency)
    modes = []
    for label, drive, load, held, formula in QUEITSCH_TAFEL_1:
        ratio, forward, threshold = _direction(planetary, held, drive, load)
        _, backward, reverse_threshold = _direction(planetary, held, load, drive)
        modes.append(TwoShaftMode(label, drive, load, held, ratio, formula, forward, backward,
                                  threshold, reverse_threshold))
    return ModeTable(planetary.stationary_ratio, planetary.stationary_efficiency, tuple(modes))


def three_shaft_speeds(planetary: PlanetarySet, **speeds: float | str) -> dict[str, float]:
    """Three-shaft operation: give two of ``sun``, ``ring``, ``carrier`` (1/min), get all.

    Parameters
    ----------
    planetary : PlanetarySet
        The set (its tooth counts give the planet speed).
    **speeds : float, str or pint.Quantity
        Exactly two of ``sun``, ``ring``, ``carrier`` (the members, not the shaft names), in
        1/min or with a unit (``sun="1500 U/min"``).

    Returns
    -------
    dict
        ``sun``, ``ring``, ``carrier`` (and ``planet``, ``planet_relative``) in 1/min.

    Raises
    ------
    ModelError
        Not exactly two known members given.
    UnitError
        A speed that cannot be read or is no speed.

    The result also holds ``planet`` (absolute) and ``planet_relative`` (to
    the carrier) when the set has tooth counts (the first planet gear).

    References
    ----------
    Queitsch, eq. 12: (1 − s)·n_51 + s·n_41 − n_21 = 0; tec-science, "Willis-Gleichung", Grundgleichung.

    Examples
    --------
    >>> s = PlanetarySet.simple("P", sun="s", ring="r", carrier="c", z_sun=30, z_planet=24, z_ring=78)
    >>> {k: round(v, 3) + 0.0 for k, v in three_shaft_speeds(s, sun=1000, ring=0).items()}
    {'sun': 1000.0, 'ring': 0.0, 'carrier': 277.778, 'planet': -625.0, 'planet_relative': -902.778}
    """
    roles = ("sun", "ring", "carrier")
    unknown = set(speeds) - set(roles)
    if unknown:
        raise ModelError(f"three_shaft_speeds: unknown member(s) {sorted(unknown)}; give two of sun, ring, carrier.")
    if len(speeds) != 2:
        raise ModelError(
            f"three_shaft_speeds: give exactly two of sun, ring, carrier (the set has two degrees of "
            f"freedom), got {len(speeds)}: {sorted(speeds)}."
        )
    local = _as_set(planetary, None)
    train = GearTrain([local], name="three-shaft operation")
    given = {k: to_core(v, "speed", field=f"three_shaft_speeds: {k}") for k, v in speeds.items()}
    solved = solve_speeds(matrices(train, ()), given)
    result = {r: solved[r] for r in roles}
    if local.teeth is not None:
        relative = local.teeth.planet_factors[0] * (result["sun"] - result["carrier"])
        result["planet"] = result["carrier"] + relative
        result["planet_relative"] = relative
    return result
