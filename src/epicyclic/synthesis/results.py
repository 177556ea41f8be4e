"""The ranked result of a synthesis: a table that renders itself, JSON, CSV, train files and a plot."""

from __future__ import annotations

import csv
import html
import io
import json
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from .candidate import Candidate
from .ranking import CRITERIA, Standing
from .spec import SynthesisSpec

__all__ = ["SynthesisResult"]


def _f(value: Any, digits: int = 4) -> str:
    return "—" if value is None else f"{value:.{digits}f}"


@dataclass(frozen=True)
class SynthesisResult:
    """Candidates ranked best first by weighted criteria (:mod:`~epicyclic.synthesis.ranking`).

    Attributes
    ----------
    spec : SynthesisSpec
    candidates : tuple of Candidate
        All distinct (non-isomorphic) candidates found, ranked.
    stats : dict
        Mechanisms, architectures examined, screened, fitted, seconds, workers.
    standings : tuple of Standing
        Score, criteria, weighted terms and Pareto status of each candidate, same order.
    """

    spec: SynthesisSpec
    candidates: tuple[Candidate, ...]
    stats: dict[str, Any]
    standings: tuple[Standing, ...] = ()

    def __post_init__(self) -> None:
        if not self.standings and self.candidates:
            from .ranking import rank

            candidates, standings = rank(self.candidates, dict(self.spec.weights), self.spec.module)
            object.__setattr__(self, "candidates", candidates)
            object.__setattr__(self, "standings", standings)

    def rerank(self, weights: dict[str, float] | None = None, module: float | None = None,
               diameters: Any = None) -> SynthesisResult:
        """The same candidates ranked with other weights (no search is repeated).

        Parameters
        ----------
        weights : mapping criterion → weight, optional
            Changes to the spec's weights (:data:`~epicyclic.synthesis.ranking.CRITERIA`).
        module : float, optional
            mm, for the ring diameters (default: the spec's).
        diameters : callable (candidate) → ring pitch diameters in mm, optional
            A sizing function instead of the fixed module (the hook for a load-capacity sizing).

        Returns
        -------
        SynthesisResult

        Raises
        ------
        SynthesisError
            An unknown criterion or a weight that is not a finite number >= 0.
        """
        from .ranking import check_weights, rank
        from .spec import SynthesisError

        merged = {**dict(self.spec.weights), **(weights or {})}
        check_weights(merged, lambda name, message: SynthesisError(f"rerank: weight {name!r}: {message}"))
        spec = replace(self.spec, weights=tuple(merged.items()), module=module or self.spec.module)
        candidates, standings = rank(self.candidates, merged, spec.module, diameters)
        return SynthesisResult(spec, candidates, self.stats, standings)

    @property
    def pareto(self) -> tuple[Candidate, ...]:
        """The candidates on the Pareto front, in rank order."""
        return tuple(c for c, s in zip(self.candidates, self.standings) if s.pareto)

    def explain(self, rank: int | None = None) -> str:
        """Why each top candidate (or the one of ``rank``) ranks where it does, against rank 1.

        Parameters
        ----------
        rank : int, optional
            One candidate's rank (1: the best); default: every shown candidate.

        Returns
        -------
        str
        """
        from .spec import SynthesisError

        if not self.standings:
            return "no candidates"
        if rank is not None and not 1 <= rank <= len(self.standings):
            raise SynthesisError(f"explain: rank must lie in 1…{len(self.standings)}, got {rank!r}.")
        chosen = [self.standings[rank - 1]] if rank else self.standings[:self.spec.top]
        return "\n".join(s.explain(self.standings[0]) for s in chosen)

    def __len__(self) -> int:
        return len(self.candidates)

    def __getitem__(self, index: int) -> Candidate:
        return self.candidates[index]

    @property
    def best(self) -> Candidate | None:
        return self.candidates[0] if self.candidates else None

    @property
    def top(self) -> tuple[Candidate, ...]:
        """The first ``spec.top`` candidates (what the table shows)."""
        return self.candidates[:self.spec.top]

    HEADER = ("rank", "score", "Pareto", "ratios", "max err %", "η mean", "η min", "P circ max /P_in",
              "T elem max /T_in", "T elem sum /T_in", "slip max /n_in", "n planet max /n_in", "ring ratio",
              "double shifts", "shafts",
              "teeth (z_s/z_p/z_r ×N)", "architecture")

    def _rows(self) -> list[list[str]]:
        rows = []
        for k, (c, st) in enumerate(zip(self.top, self.standings), 1):
            m = c.metrics
            teeth = " ".join(f"{t.z_sun}/{t.z_planet or '-'}/{t.z_ring}×{t.planets}" for t in c.teeth)
            rows.append([str(k), _f(st.score, 2), "yes" if st.pareto else f"no (#{st.dominated_by})",
                         " ".join(f"{r:.3f}" for r in c.ratios), _f(100 * m["ratio_error"], 2),
                         _f(m["efficiency_mean"]), _f(m["efficiency_min"]), _f(m.get("circulating_power_max"), 2),
                         _f(m["element_torque_max"], 2), _f(m.get("element_capacity"), 2),
                         _f(m.get("slip_speed_max"), 2), _f(m["planet_speed_max"], 2),
                         _f(st.values["ring_balance"] + 1, 2), str(m["double_shifts"]), str(m["shafts"]), teeth,
                         c.describe()])
        return rows

    def _footer(self) -> str:
        s = self.stats
        text = (f"{s['candidates']} candidates from {s['architectures']:,} architectures on {s['mechanisms']:,} "
                f"mechanisms ({s['screened']:,} passed screening, {s['fitted']:,} fitted); {s['tasks']} tasks "
                f"on {s['workers']} worker(s), {s['seconds']:.1f} s")
        if s.get("rejected_sizing"):
            text += (f"; {s['rejected_sizing']:,} dropped: a set no ISO 54 module up to 50 mm carries at "
                     f"{self.spec.input_torque:g} N·m (ISO 6336; lower [sizing] input_torque or a stronger [rating])")
        if not s.get("complete", True) and s.get("stopped"):
            text += (f". INCOMPLETE: {s['stopped']} after {s['tasks_done']} of {s['tasks']} tasks; the candidates are "
                     "those of the finished tasks")
        elif not s.get("complete", True):
            text += (f". INCOMPLETE: stopped at the time limit ({self.spec.time_limit:g} s) after "
                     f"{s['tasks_done']} of {s['tasks']} tasks; raise [search] time_limit for the whole space")
        return text

    def table(self) -> str:
        """Text table of the top candidates and their schedules."""
        targets = ", ".join(f"{t:g}" for t in (*self.spec.forward, *self.spec.reverse))
        lines = [f"{self.spec.title}: targets {targets} (± {100 * self.spec.tolerance:g} %), "
                 f"{self.spec.simple} simple + {self.spec.plus} plus set(s), {self.spec.brakes} brakes, "
                 f"{self.spec.clutches} clutches"]
        rows = [list(self.HEADER[:-1])] + [r[:-1] for r in self._rows()]
        widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]))]
        for k, r in enumerate(rows):
            lines.append("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())
            if k == 0:
                lines.append("  ".join("-" * w for w in widths))
        weights = dict(zip((c.name for c in CRITERIA), (c.weight for c in CRITERIA)))
        weights.update(dict(self.spec.weights))
        lines.append("score = Σ weight · criterion / scale (smaller is better): "
                     + ", ".join(f"{c.name} {weights[c.name]:g}/{c.scale:g}" for c in CRITERIA))
        for k, (c, st) in enumerate(zip(self.top[:5], self.standings), 1):
            sched = ", ".join(f"{g}: {'+'.join(v)}" for g, v in c.named_schedule.items())
            lines.append(f"#{k}: {c.describe()}\n    schedule {sched}\n    why: "
                         + st.explain(self.standings[0]).split(": ", 1)[1])
        lines.append(self._footer())
        return "\n".join(lines)

    def markdown(self) -> str:
        """The ranked candidates as a Markdown table, with the search statistics below.

        Returns
        -------
        str
        """
        lines = ["| " + " | ".join(self.HEADER) + " |", "|" + "---|" * len(self.HEADER)]
        lines += ["| " + " | ".join(c.replace("|", "\\|") for c in r) + " |" for r in self._rows()]
        return "\n".join(lines + ["", self._footer()])

    def _repr_html_(self) -> str:
        return self.html()

    def html(self, action: Callable[[int], str] | None = None, action_header: str = "") -> str:
        """The ranked table as HTML (every value escaped), with the search statistics below.

        Parameters
        ----------
        action : callable (rank) → HTML, optional
            A first cell per row (the page's "Open in editor" button); its HTML is inserted as it is.
        action_header : str, default ""
            That column's heading.

        Returns
        -------
        str
        """
        head = "".join(f"<th>{html.escape(h)}</th>" for h in ((action_header,) if action else ()) + self.HEADER)
        body = "".join("<tr>" + (f"<td>{action(k)}</td>" if action else "")
                       + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>"
                       for k, r in enumerate(self._rows(), 1))
        return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table><p>{html.escape(self._footer())}</p>"

    def candidate_toml(self, rank: int) -> str:
        """The train file of candidate ``rank`` (1: the best), as :meth:`write_toml` writes it.

        Parameters
        ----------
        rank : int

        Returns
        -------
        str

        Raises
        ------
        SynthesisError
            A rank out of range.
        """
        from .spec import SynthesisError

        if not 1 <= rank <= len(self.candidates):
            raise SynthesisError(f"candidate: rank must lie in 1…{len(self.candidates)}, got {rank!r}.")
        return self.candidates[rank - 1].toml(f"{self.spec.title}, candidate {rank}")

    def __str__(self) -> str:
        return self.table()

    def __repr__(self) -> str:
        return f"<SynthesisResult {self.spec.title!r}: {len(self)} candidates, {self.stats['seconds']:.1f} s>"

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: spec, statistics and the top candidates (ratios n_in/n_out, torques × T_in)."""
        spec = {k: v for k, v in self.spec.__dict__.items()}
        return {"spec": spec, "stats": dict(self.stats),
                "pareto_front": [k for k, s in enumerate(self.standings[:len(self.top)], 1) if s.pareto],
                "candidates": [{**c.to_dict(), **s.to_dict()} for c, s in zip(self.top, self.standings)]}

    def to_json(self) -> str:
        """:meth:`to_dict` as indented JSON text.

        Returns
        -------
        str
        """
        return json.dumps(self.to_dict(), indent=2, ensure_ascii=False)

    def to_csv(self) -> str:
        """One row per top candidate: rank, metrics, ratio per gear, architecture."""
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        gears = self.top[0].gears if self.top else []
        writer.writerow(["rank", "efficiency_mean", "efficiency_min", "element_torque_max", "planet_speed_max",
                         "double_shifts", "shafts", "ratio_error", "score", "pareto", "circulating_power_max",
                         "element_capacity", "slip_speed_max", *[f"ratio_{g}" for g in gears], "teeth",
                         "architecture"])
        for k, (c, st) in enumerate(zip(self.top, self.standings), 1):
            m = c.metrics
            writer.writerow([k, m["efficiency_mean"], m["efficiency_min"], m["element_torque_max"],
                             m["planet_speed_max"], m["double_shifts"], m["shafts"], m["ratio_error"],
                             st.to_dict()["score"], st.pareto, m.get("circulating_power_max"),
                             m.get("element_capacity"), m.get("slip_speed_max"), *c.ratios,
                             " ".join(f"{t.z_sun}/{t.z_planet or '-'}/{t.z_ring}x{t.planets}" for t in c.teeth),
                             c.describe()])
        return buffer.getvalue()

    def write_toml(self, directory: str | Path, count: int | None = None) -> list[Path]:
        """Write ``candidate_01.toml`` … for the top candidates (``analyze``/``gears`` read them).

        Parameters
        ----------
        directory : str or Path
            Folder to write into (made if missing; files replaced atomically).
        count : int, optional
            How many of the top candidates (default: all of :attr:`top`).

        Returns
        -------
        list of Path
            The files written, best first.
        """
        from ..io.output import write_atomic

        directory = Path(directory)
        return [write_atomic(directory / f"candidate_{k:02d}.toml", self.candidate_toml(k))
                for k in range(1, len(self.top[:count]) + 1)]

    def plot(self, rank: int = 1, gear: str | None = None, kind: str = "chart") -> Any:
        """Figure of candidate ``rank``: its speed chart across all gears or its lever diagram in one gear.

        Parameters
        ----------
        rank : int, default 1
            The candidate's rank (1: the best).
        gear : str, optional
            The gear highlighted on the chart, or drawn as a lever (default: the first).
        kind : {"chart", "lever"}, default "chart"
            Speed chart across the gears, or lever diagram (Benford–Leising) in ``gear``.

        Returns
        -------
        matplotlib.figure.Figure

        Raises
        ------
        SynthesisError
            A rank out of range, another kind, or an unknown gear.

        References
        ----------
        Benford & Leising 1981 (the lever analogy).
        """
        from .. import plotting
        from .spec import SynthesisError

        if not 1 <= rank <= len(self.candidates):
            raise SynthesisError(f"plot: rank must lie in 1…{len(self.candidates)}, got {rank!r}.")
        if kind not in ("lever", "chart"):
            raise SynthesisError(f"plot: kind must be 'lever' or 'chart', got {kind!r}.")
        cand = self.candidates[rank - 1]
        gear = gear or cand.gears[0]
        t = cand.transmission(f"{self.spec.title}, candidate {rank}")
        if gear not in t.gears:
            raise SynthesisError(f"plot: no gear {gear!r}; gears are {', '.join(t.gears)}.")
        if kind == "chart":
            return plotting.speed_chart(t, gear=gear).plot()
        return plotting.lever_diagram(t.analyze(gear).drive).plot()
