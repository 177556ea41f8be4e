"""The worked solution: every equation the solver used, with the numbers substituted.

:func:`explain` reads a :class:`~epicyclic.results.Solution` and writes out,
in the notation of the sources, how it follows from the givens:

1. the givens (elements, stationary ratios and efficiencies, operating point);
2. kinematics — the Willis equation of every set, ``n1 − n3 = i0·(n2 − n3)``
   (Brandenberger's eq. (1) with ac/bd = 1/i0), the ratio of every stage, the
   clutches and brakes;
3. statics with losses — per set the rolling power (Wälzleistung)
   ``P_w1 = M1'·(n1 − n3)·π/30``, its sign w (which central member drives
   relative to the carrier) and Brandenberger's power equation for the
   stationary carrier with η0 on the driving side, e.g. eq. (7)
   ``M1'·(n1 − n3)·η0 + M2'·(n2 − n3) = 0``, then ``M3' = −(M1' + M2')``
   (eq. 8) and the loss ``P_w1·(1 − η0^w)``;
4. the torque balance of every shaft;
5. the results: powers, efficiency, self-locking, circulating power.

Indices follow Brandenberger: 1 = first central member (sun), 2 = second
central member (ring), 3 = carrier (Steg); primes mark values with friction.
For a fixed-axis stage 1 = first, 2 = second shaft, 3 = housing (n3 = 0).
``lang="de"`` gives the German terms (Steg, Sonnenrad, Hohlrad,
Standübersetzung, Wälzleistung, Kupplungsleistung, Wirkungsgrad).

Examples
--------
>>> from epicyclic.demo import brandenberger_1952
>>> from epicyclic import solve
>>> text = explain(solve(*brandenberger_1952())).text()
>>> "M1'·(n1 − n3)·η0 + M2'·(n2 − n3) = 0" in text
True

References
----------
Brandenberger 1952, eqs. (1), (3'), (7), (8), (9) and Bild 8–9; Queitsch,
eqs. 26–29; tec-science, "Willis-Gleichung".
"""

from __future__ import annotations

import math

import html
from dataclasses import dataclass
from typing import Any

from .errors import EpicyclicError
from .io.tables import fmt
from .model import Brake, Clutch, GearStage, PlanetarySet
from .results.render import port_labels
from .results.solution import Solution
from .results.zero import clean
from .text import markdown_text
from .units import Units, as_units

__all__ = ["Step", "Explanation", "explain", "LANGUAGES"]

_T = {
    "en": {
        "title": "Worked solution",
        "given": "1. Given",
        "kinematics": "2. Kinematics (Willis equation)",
        "statics": "3. Torques with losses (Brandenberger's loss rule)",
        "balance": "4. Torque balance at every shaft",
        "results": "5. Results",
        "sun": "sun", "ring": "ring", "carrier": "carrier", "first": "first shaft", "second": "second shaft",
        "housing": "housing", "first_central": "first central gear", "second_central": "second central gear",
        "set": "planetary set", "stage": "gear stage", "clutch": "clutch", "brake": "brake",
        "i0": "stationary ratio i0", "eta0": "stationary efficiency η0", "ratio": "ratio i", "eta": "efficiency η",
        "from_losses": "from its loss models at this point (step 6)",
        "engaged": "engaged", "open": "open",
        "speeds": "given speeds", "torques": "given torques", "powers": "given powers",
        "drives": "drives", "loads": "loads",
        "willis": "Willis equation (Brandenberger eq. 1 with ac/bd = 1/i0)",
        "stage_kin": "stage (Brandenberger eq. 5)",
        "clutch_kin": "engaged clutch: both shafts turn together",
        "brake_kin": "engaged brake: the shaft stands still",
        "open_kin": "open: no condition (slip speed {slip})",
        "speeds_res": "speeds",
        "rolling": "rolling power (Wälzleistung) P_w1 = M1'·(n1 − n3)·π/30",
        "coupling": "coupling power (Kupplungsleistung) P_k1 = M1'·n3·π/30",
        "w_plus": "P_w1 > 0: member 1 drives relative to the carrier, w = +1 (Brandenberger Bild 8)",
        "w_minus": "P_w1 < 0: member 2 drives relative to the carrier, w = −1 (Brandenberger Bild 9)",
        "w_zero": "P_w1 = 0: no rolling power, no loss, w = 0 (eq. 3')",
        "eq7": "power equation for the stationary carrier, η0 (= η1·η2) on the driving side (Brandenberger eq. 7)",
        "eq7b": "power equation for the stationary carrier, η0 on the driving side (Brandenberger Bild 9)",
        "eq3": "power equation for the stationary carrier without loss (Brandenberger eq. 3')",
        "eq8": "torque sum (Brandenberger eqs. 2 and 8)",
        "loss": "loss V = P_w1·(1 − η0^w)",
        "lossless": "lossless element (η = 1): M1·(n1 − n3) + M2·(n2 − n3) = 0",
        "shift": "clutches and brakes carry torque without loss",
        "balance_rule": "external torque = Σ torques the shaft passes to the elements (eq. 2)",
        "power_rule": "P = M·ω = M·n·π/30 in W, N·m, 1/min (positive: drive, negative: load)",
        "power_factor": "in the units here: P [{power}] = {factor} · M [{torque}] · n [{speed}]",
        "input": "input power", "output": "output power", "total_loss": "total loss",
        "efficiency": "efficiency η = P_out/P_in", "selflock": "SELF-LOCKING",
        "circulating": "circulating power (power around a closed loop, Blindleistung) / input power",
        "largest": "largest element power / input power",
        "indeterminate": "not defined (the torque split is statically indeterminate)",
        "signs": "signs: a torque M acts on the shaft from outside; power P = M·ω > 0 flows into the train",
        "none": "none",
        "roles": {}, "warning": "warning",
    },
    "de": {
        "title": "Lösungsweg",
        "given": "1. Gegeben",
        "kinematics": "2. Drehzahlen (Willis-Gleichung)",
        "statics": "3. Drehmomente mit Reibung (Verlustregel nach Brandenberger)",
        "balance": "4. Momentengleichgewicht an jeder Welle",
        "results": "5. Ergebnisse",
        "sun": "Sonnenrad", "ring": "Hohlrad", "carrier": "Steg", "first": "erste Welle", "second": "zweite Welle",
        "housing": "Gehäuse", "first_central": "erstes Zentralrad", "second_central": "zweites Zentralrad",
        "set": "Umlaufradsatz", "stage": "Standgetriebe", "clutch": "Kupplung", "brake": "Bremse",
        "i0": "Standübersetzung i0", "eta0": "Standwirkungsgrad η0", "ratio": "Übersetzung i",
        "from_losses": "aus seinen Verlustmodellen in diesem Betriebspunkt (Schritt 6)",
        "eta": "Wirkungsgrad η",
        "engaged": "geschlossen", "open": "offen",
        "speeds": "gegebene Drehzahlen", "torques": "gegebene Drehmomente", "powers": "gegebene Leistungen",
        "drives": "Antrieb", "loads": "Abtrieb",
        "willis": "Willis-Gleichung (Brandenberger Gl. 1 mit ac/bd = 1/i0)",
        "stage_kin": "Standgetriebe (Brandenberger Gl. 5)",
        "clutch_kin": "geschlossene Kupplung: beide Wellen drehen gleich",
        "brake_kin": "geschlossene Bremse: die Welle steht still",
        "open_kin": "offen: keine Bedingung (Schlupfdrehzahl {slip})",
        "speeds_res": "Drehzahlen",
        "rolling": "Wälzleistung P_w1 = M1'·(n1 − n3)·π/30",
        "coupling": "Kupplungsleistung P_k1 = M1'·n3·π/30",
        "w_plus": "P_w1 > 0: Glied 1 treibt gegenüber dem Steg, w = +1 (Brandenberger Bild 8)",
        "w_minus": "P_w1 < 0: Glied 2 treibt gegenüber dem Steg, w = −1 (Brandenberger Bild 9)",
        "w_zero": "P_w1 = 0: keine Wälzleistung, kein Verlust, w = 0 (Gl. 3')",
        "eq7": "Leistungsgleichung bei stillstehendem Steg, η0 (= η1·η2) auf der treibenden Seite (Brandenberger Gl. 7)",
        "eq7b": "Leistungsgleichung bei stillstehendem Steg, η0 auf der treibenden Seite (Brandenberger Bild 9)",
        "eq3": "Leistungsgleichung bei stillstehendem Steg ohne Reibung (Brandenberger Gl. 3')",
        "eq8": "Momentensumme (Brandenberger Gl. 2 und 8)",
        "loss": "Verlustleistung V = P_w1·(1 − η0^w)",
        "lossless": "verlustfreies Glied (η = 1): M1·(n1 − n3) + M2·(n2 − n3) = 0",
        "shift": "Kupplungen und Bremsen übertragen Moment ohne Verlust",
        "balance_rule": "äusseres Moment = Σ der Momente, die die Welle an die Glieder abgibt (Gl. 2)",
        "power_rule": "P = M·ω = M·n·π/30 in W, N·m, 1/min (positiv: Antrieb, negativ: Abtrieb)",
        "power_factor": "in den Einheiten hier: P [{power}] = {factor} · M [{torque}] · n [{speed}]",
        "input": "Antriebsleistung", "output": "Abtriebsleistung", "total_loss": "Verlustleistung gesamt",
        "efficiency": "Wirkungsgrad η = P_ab/P_an", "selflock": "SELBSTHEMMUNG",
        "circulating": "Blindleistung (in einer geschlossenen Schleife umlaufende Leistung) / Antriebsleistung",
        "largest": "grösste Leistung an einem Glied / Antriebsleistung",
        "indeterminate": "nicht bestimmt (die Momentenaufteilung ist statisch unbestimmt)",
        "signs": "Vorzeichen: ein Moment M wirkt von aussen auf die Welle; P = M·ω > 0 fliesst hinein",
        "none": "keine",
        "roles": {"drive": "Antrieb", "load": "Abtrieb", "external": "von aussen", "held": "festgehalten",
                  "internal": "innen"},
        "warning": "Warnung",
        "selflock_formal": "formaler Wirkungsgrad {formal}",
        "selflock_text": "das Getriebe ist in dieser Leistungsflussrichtung selbsthemmend{formal}{where}. Von der "
                         "anderen Seite antreiben oder den Wirkungsgrad erhöhen.",
        "selflock_where": "; Selbsthemmung ab {where}",
    },
}

#: The languages :func:`explain` speaks.
LANGUAGES = tuple(_T)


@dataclass(frozen=True)
class Step:
    """One step of the worked solution: a heading and its lines."""

    title: str
    lines: tuple[str, ...]


@dataclass(frozen=True)
class Explanation:
    """A worked solution; renders as text, Markdown, HTML or plain data.

    Attributes
    ----------
    title : str
    lang : str
    units : Units
    steps : tuple of Step
    """

    title: str
    lang: str
    units: Units
    steps: tuple[Step, ...]

    def text(self) -> str:
        """Plain text, one step per paragraph."""
        parts = [f"{self.title}\n{'=' * len(self.title)}"]
        for step in self.steps:
            parts.append(step.title + "\n" + "\n".join("  " + line for line in step.lines))
        return "\n\n".join(parts) + "\n"

    def markdown(self) -> str:
        """Markdown: a heading per step, equations as code."""
        parts = [f"# {markdown_text(self.title)}"]
        for step in self.steps:  # equations as indented code: shown literally, no escaping needed
            parts.append(f"## {markdown_text(step.title)}\n\n" + "\n".join(f"    {line}" for line in step.lines))
        return "\n\n".join(parts) + "\n"

    def html(self) -> str:
        """An HTML fragment (headings and preformatted equations)."""
        body = "".join(
            f"<h3>{html.escape(s.title)}</h3><pre>{html.escape(chr(10).join(s.lines))}</pre>" for s in self.steps
        )
        return f"<div class='epicyclic-explanation'><h2>{html.escape(self.title)}</h2>{body}</div>"

    _repr_html_ = html

    def to_dict(self) -> dict[str, Any]:
        """The worked solution as JSON-ready data.

        Returns
        -------
        dict
            ``title``, ``lang``, ``units`` (:meth:`Units.to_dict <epicyclic.units.Units.to_dict>`)
            and ``steps``: a list of ``{title, lines}`` in the order of the text.
        """
        return {"title": self.title, "lang": self.lang, "units": self.units.to_dict(),
                "steps": [{"title": s.title, "lines": list(s.lines)} for s in self.steps]}

    def __str__(self) -> str:
        return self.text()



def _central(element: PlanetarySet, port: str) -> str:
    """Translation key of a set's central member: first/second central gear for two rings or two suns."""
    label = element.teeth.label(port) if element.teeth is not None else port
    return {"first": "first_central", "second": "second_central"}.get(label, label)

def _p(value: float) -> str:
    """A number for substitution: negative values in parentheses."""
    text = fmt(value)
    return f"({text})" if text.startswith("-") else text


def explain(solution: Solution, units: Units | None = None, lang: str = "en", title: str | None = None, *,
            losses=None, spin=None, gear: str | None = None, input: str | None = None) -> Explanation:
    """Write out the worked solution of ``solution``.

    Parameters
    ----------
    solution : Solution
        From :func:`epicyclic.solve`.
    units : Units or mapping quantity → unit, optional
        Units of the substituted numbers (core units by default), e.g. a
        file's ``f.units`` or ``{"speed": "U/min", "torque": "kp*cm", "power": "PS"}``.  The
        equations of step 3 are homogeneous, so any consistent units serve.
    lang : {"en", "de"}
        Language of the text; ``"de"`` uses the sources' German terms.
    title : str, optional
        Heading (default: the train's name).
    losses : mapping element → ElementLosses, optional
        The loss models the solution was solved with (a file's ``f.losses``): step 6 writes out
        η0 at the point, μ and H_V of every mesh and the drag torques.
    spin : SpinLosses, optional
        The spin losses (a file's ``f.spin``): the oil at its temperature and every source.
    gear : str, optional
        The gear (a pump pressure by gear).
    input : str, optional
        The transmission's input (drives the pump by default).

    Returns
    -------
    Explanation

    Raises
    ------
    EpicyclicError
        For an unknown language.

    References
    ----------
    Brandenberger 1952, eqs. (1), (2), (3'), (5), (7), (8), (9).
    """
    if lang not in _T:
        raise _ArgumentError(f"explain: lang must be one of {', '.join(LANGUAGES)}, got {lang!r}.")
    if not isinstance(solution, Solution):
        hint = " (a train file: explain(f.solve(), f.units))" if hasattr(solution, "solve") else ""
        raise _ArgumentError(f"explain: solution must be a Solution from epicyclic.solve, got a "
                             f"{type(solution).__name__}{hint}.")
    t = _T[lang]
    u = as_units(units, "explain: units")
    n = u.speed_from_core
    m = u.torque_from_core
    p = u.power_from_core
    train, op = solution.train, solution.operating_point
    heading = f"{t['title']}: {title or train.name}"

    given: list[str] = []
    # η0 of these comes from their loss models at the point (mesh friction, bearing factor), not from the file
    modelled = {name for name, model in (losses or {}).items()
                if model.has_mesh_model or model.bearing_efficiency != 1.0}
    for element in train.elements:
        if isinstance(element, PlanetarySet):
            given.append(
                f"{t['set']} {element.name!r}: 1 = {t[_central(element, 'sun')]} {element.sun!r}, "
                f"2 = {t[_central(element, 'ring')]} {element.ring!r}, "
                f"3 = {t['carrier']} {element.carrier!r}; {t['i0']} = (n1 − n3)/(n2 − n3) = "
                f"{fmt(element.stationary_ratio)}, {t['eta0']} "
                + (t["from_losses"] if element.name in modelled else f"= {fmt(element.stationary_efficiency)}")
            )
        elif isinstance(element, GearStage):
            given.append(
                f"{t['stage']} {element.name!r}: 1 = {element.first!r}, 2 = {element.second!r}, 3 = {t['housing']}; "
                f"{t['ratio']} = n1/n2 = {fmt(element.ratio)}, {t['eta']} "
                + (t["from_losses"] if element.name in modelled else f"= {fmt(element.efficiency)}")
            )
        elif isinstance(element, Clutch):
            state = t["engaged"] if element.engaged else t["open"]
            given.append(f"{t['clutch']} {element.name!r}: {element.first!r} – {element.second!r}, {state}")
        elif isinstance(element, Brake):
            state = t["engaged"] if element.engaged else t["open"]
            given.append(f"{t['brake']} {element.name!r}: {element.shaft!r} – {t['housing']}, {state}")
    for key, values, conv, unit in (("speeds", op.speeds, n, u.speed), ("torques", op.torques, m, u.torque),
                                    ("powers", op.powers, p, u.power)):
        if values:
            given.append(f"{t[key]}: " + ", ".join(f"{s} = {fmt(conv(v))} {unit}" for s, v in values.items()))
    given.append(f"{t['drives']}: {', '.join(solution.drives) or t['none']}; "
                 f"{t['loads']}: {', '.join(solution.loads) or t['none']}")
    given.append(t["signs"])

    speed = {s: n(state.speed) for s, state in solution.shafts.items()}
    kin: list[str] = []
    for element in train.elements:
        state = solution.elements[element.name]
        if isinstance(element, PlanetarySet):
            n1, n2, n3 = speed[element.sun], speed[element.ring], speed[element.carrier]
            kin.append(f"{element.name}: {t['willis']}: n1 − n3 = i0·(n2 − n3)")
            kin.append(f"    {_p(n1)} − {_p(n3)} = {_p(element.stationary_ratio)}·({_p(n2)} − {_p(n3)})"
                       f"   →   {fmt(n1 - n3)} = {fmt(element.stationary_ratio * (n2 - n3))}")
        elif isinstance(element, GearStage):
            n1, n2 = speed[element.first], speed[element.second]
            kin.append(f"{element.name}: {t['stage_kin']}: n1 = i·n2")
            kin.append(f"    {_p(n1)} = {_p(element.ratio)}·{_p(n2)}   →   {fmt(n1)} = {fmt(element.ratio * n2)}")
        elif element.engaged:
            if isinstance(element, Clutch):
                kin.append(f"{element.name}: {t['clutch_kin']}: n_{element.first} = n_{element.second} = "
                           f"{fmt(speed[element.first])}")
            else:
                kin.append(f"{element.name}: {t['brake_kin']}: n_{element.shaft} = 0")
        else:
            kin.append(f"{element.name}: " + t["open_kin"].format(slip=f"{fmt(n(state.slip_speed or 0.0))} {u.speed}"))
    kin.append(f"{t['speeds_res']} [{u.speed}]: " + ", ".join(
        f"n_{s} = {fmt(v)}" for s, v in speed.items()))

    statics: list[str] = []
    for element in train.elements:
        state = solution.elements[element.name]
        if isinstance(element, (Clutch, Brake)):
            continue
        statics.extend(_lever_lines(element, state, t, n, m, p, u))
    if train.shift_elements:
        statics.append(t["shift"])

    balance: list[str] = [t["balance_rule"]]
    for shaft, sstate in solution.shafts.items():
        parts = [(e.name, port_labels(solution, e)[port], tq) for e in solution.elements.values()
                 for port, tq in e.torques.items() if e.ports[port] == shaft]
        if not parts:
            continue
        terms = " + ".join(f"M_{name}.{port}" for name, port, _ in parts)
        numbers = " + ".join(_p(m(tq)) for _, _, tq in parts)
        total = sum(m(tq) for _, _, tq in parts)
        scale = max(abs(m(tq)) for _, _, tq in parts)
        balance.append(f"{shaft}: M_{shaft} = {terms} = {numbers} = {_zero(total, scale)} {u.torque}")

    # P = M·ω holds in SI; in other units one factor turns torque × speed into power (1 unit each)
    factor = p(math.pi / 30.0 / (m(1.0) * n(1.0)))
    results: list[str] = [t["power_rule"]]
    if not math.isclose(factor, math.pi / 30.0, rel_tol=1e-12):
        results.append(t["power_factor"].format(power=u.power, factor=fmt(factor, 6), torque=u.torque,
                                                speed=u.speed))
    for shaft, sstate in solution.shafts.items():
        if sstate.role in ("drive", "load") or (sstate.torque != 0 and sstate.role != "housing"):
            results.append(
                f"P_{shaft} = {fmt(factor, 6)} · {_p(m(sstate.torque))} {u.torque} · {_p(speed[shaft])} {u.speed} = "
                f"{fmt(p(sstate.power))} {u.power} ({t['roles'].get(sstate.role, sstate.role)})"
            )
    results.append(f"{t['input']} = {fmt(p(solution.input_power))} {u.power}, "
                   f"{t['output']} = {fmt(p(solution.output_power))} {u.power}, "
                   f"{t['total_loss']} = {fmt(p(solution.loss))} {u.power}")
    if solution.self_locking is not None:
        results.append(f"{t['selflock']}: {_self_locking_text(solution.self_locking, t)}")
    elif solution.efficiency is not None:
        results.append(f"{t['efficiency']} = {fmt(p(solution.output_power))} / {fmt(p(solution.input_power))} "
                       f"= {fmt(solution.efficiency, 4)}")
    circ = solution.circulation
    if circ.indeterminate:
        results.append(f"{t['circulating']}: {t['indeterminate']}")
    elif circ.ratio is not None:
        loops = "".join(f" ({loop.describe()}: {fmt(p(loop.power))} {u.power})" for loop in circ.loops)
        results.append(f"{t['circulating']} = {fmt(circ.ratio, 4)}{loops}; "
                       f"{t['largest']} = {fmt(circ.largest_element_ratio, 4)}")
    results.extend(f"{t['warning']}: {w}" for w in solution.warnings)

    steps = (
        Step(t["given"], tuple(given)),
        Step(t["kinematics"], tuple(kin)),
        Step(t["statics"], tuple(statics)),
        Step(t["balance"], tuple(balance)),
        Step(t["results"], tuple(results)),
    )
    from .explain_losses import loss_step

    extra = loss_step(solution, losses, spin, lang, gear=gear, input=input)
    if extra is not None:
        steps += (Step(*extra),)
    return Explanation(heading, lang, u, steps)


def _lever_lines(element, state, t, n, m, p, u) -> list[str]:
    """Rolling power, loss direction, power equation, torque sum and loss of one set or stage."""
    a, b, c = list(state.ports)
    m1, m2, m3 = (m(state.torques[k]) for k in (a, b, c))
    n1, n2, n3 = (n(state.speeds[k]) for k in (a, b, c))
    eta = element.stationary_efficiency if isinstance(element, PlanetarySet) else element.efficiency
    w = state.loss_direction
    from .explain_losses import model_efficiency

    applied = model_efficiency(state)  # η0 the solver used: a loss model's at this point, or the element's
    if applied is not None:
        eta = applied
    label = f"{element.name} (1 = {state.ports[a]!r}, 2 = {state.ports[b]!r}, 3 = {state.ports[c]!r})"
    lines = [f"{label}:"]
    if eta == 1.0 and not any(state.loss_sources.values()):
        lines.append("    " + t["lossless"])
        lines.append(f"    {_p(m1)}·({_p(n1)} − {_p(n3)}) + {_p(m2)}·({_p(n2)} − {_p(n3)}) = "
                     f"{fmt(m1 * (n1 - n3) + m2 * (n2 - n3), 4)} ≈ 0")
    else:
        k = fmt(p(math.pi / 30.0 / (m(1.0) * n(1.0))), 6)  # P = k·M·n in the units shown (see step 5)
        lines.append(f"    {t['rolling']} = {k}·{_p(m1)}·({_p(n1)} − {_p(n3)}) = {fmt(p(state.rolling_power))} {u.power}")
        if isinstance(element, PlanetarySet):
            lines.append(f"    {t['coupling']} = {k}·{_p(m1)}·{_p(n3)} = {fmt(p(state.coupling_power))} {u.power}")
        key = {1: "w_plus", -1: "w_minus", 0: "w_zero"}[w]
        lines.append("    " + t[key])
        first, second = m1 * (n1 - n3), m2 * (n2 - n3)
        if w == 1:
            lines.append(f"    {t['eq7']}:")
            lines.append("    M1'·(n1 − n3)·η0 + M2'·(n2 − n3) = 0")
            lines.append(f"    {_p(m1)}·({_p(n1)} − {_p(n3)})·{fmt(eta)} + {_p(m2)}·({_p(n2)} − {_p(n3)}) = "
                         f"{fmt(first * eta)} + {_p(second)} = {_zero(first * eta + second, first)}")
        elif w == -1:
            lines.append(f"    {t['eq7b']}:")
            lines.append("    M1'·(n1 − n3) + M2'·(n2 − n3)·η0 = 0")
            lines.append(f"    {_p(m1)}·({_p(n1)} − {_p(n3)}) + {_p(m2)}·({_p(n2)} − {_p(n3)})·{fmt(eta)} = "
                         f"{fmt(first)} + {_p(second * eta)} = {_zero(first + second * eta, first)}")
        else:
            lines.append(f"    {t['eq3']}: M1'·(n1 − n3) + M2'·(n2 − n3) = 0")
        lines.append(f"    {t['loss']} = {fmt(p(state.rolling_power))}·(1 − {fmt(eta)}^{w:+d}) = "
                     f"{fmt(p(state.loss))} {u.power}")
    lines.append(f"    {t['eq8']}: M3' = −(M1' + M2') = −({_p(m1)} + {_p(m2)}) = {fmt(m3)} {u.torque}")
    return lines



def _self_locking_text(locked, t: dict) -> str:
    """The solver's self-locking message, or its sentence in the explanation's language."""
    if "selflock_text" not in t:
        return locked.message
    formal = (" (" + t["selflock_formal"].format(formal=fmt(locked.formal_efficiency, 4)) + ")"
              if locked.formal_efficiency is not None else "")
    where = ", ".join(f"{name}: η0 < {eta:.6g}" for name, eta in locked.thresholds.items())
    return t["selflock_text"].format(formal=formal, where=t["selflock_where"].format(where=where) if where else "")

def _zero(value: float, scale: float) -> str:
    """Show a residual that is zero to round-off as 0."""
    return fmt(clean(value, scale))


class _ArgumentError(EpicyclicError, ValueError):
    """An argument :func:`explain` cannot use (an unsupported language, no solution)."""

