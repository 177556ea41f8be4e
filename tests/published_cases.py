"""The published cases of ``tests/published_cases.toml``: load them, compute what we get.

One source for two readers: ``tests/test_published_cases.py`` checks every case within its
tolerance; the documentation build (``docs/gen_pages.py``) renders the validation page from the
same cases and the same computed values.  Published transmission ratios are taken from
:data:`epicyclic.transmission.library.LIBRARY`, where they live with their sources.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
CASES_FILE = Path(__file__).with_suffix(".toml")
EXAMPLES = ROOT / "examples"


@dataclass(frozen=True)
class Case:
    """One published number (or formula, or label) and how we compute it."""

    quantity: str
    compute: str
    published: float | str
    formula: str | None = None
    where: str = ""
    unit: str = ""
    tolerance: float | None = None
    rel_tolerance: float | None = None
    note: str = ""
    tolerance_note: str = ""
    disagrees: str = ""

    @property
    def allowed(self) -> float:
        """The absolute deviation allowed (0 for labels)."""
        if isinstance(self.published, str):
            return 0.0
        if self.rel_tolerance is not None:
            return self.rel_tolerance * abs(self.published)
        return self.tolerance or 0.0

    def within(self, value: Any) -> bool:
        """Whether ``value`` reproduces the published value within the tolerance."""
        if isinstance(self.published, str):
            return value == self.published
        return value is not None and math.isfinite(value) and abs(value - self.published) <= self.allowed + 1e-15


@dataclass(frozen=True)
class Group:
    """Cases from one source with one setup."""

    title: str
    source: str
    setup: str
    cases: tuple[Case, ...]
    tolerance_note: str = ""

    def compute(self) -> list[Any]:
        """What we get for every case (runs ``setup`` once, then each ``compute``)."""
        namespace = _namespace()
        exec(compile(self.setup, f"<setup of {self.title}>", "exec"), namespace)
        return [eval(compile(c.compute, f"<{self.title}: {c.quantity}>", "eval"), namespace) for c in self.cases]


def _namespace() -> dict[str, Any]:
    from epicyclic.io import load_train_file
    from epicyclic.units import from_core

    return {"example": lambda name: load_train_file(EXAMPLES / f"{name}.toml"), "from_core": from_core,
            "__builtins__": __builtins__}


def _case(raw: dict[str, Any]) -> Case:
    raw = dict(raw)
    formula = raw.pop("published_formula", None)
    if formula is not None:
        raw["published"] = float(eval(formula, {"__builtins__": {}}))  # arithmetic only
    return Case(formula=formula, **raw)


def library_groups() -> list[Group]:
    """One group per library transmission with published ratios (values and sources from LIBRARY)."""
    from epicyclic.transmission.library import LIBRARY

    groups = []
    for key, entry in LIBRARY.items():
        if not entry.published_ratios:
            continue
        if not entry.schedule:
            continue  # no shift schedule (Prius): its final drive is a case of its own in the TOML file
        setup = f"from epicyclic.transmission.library import build\n\nt = build({key!r})"
        tolerance = 0.5 * 10 ** -entry.printed_digits
        cases = tuple(Case(quantity=f"gear {gear}", compute=f"t.ratio({gear!r})", published=value,
                           tolerance=tolerance) for gear, value in entry.published_ratios.items())
        groups.append(Group(title=f"{entry.title}: gear ratios", source=" ".join(entry.sources[:1]),
                            setup=setup, cases=cases,
                            tolerance_note=f"printed to {entry.printed_digits} decimals: half a unit of the last"))
    return groups


def groups() -> list[Group]:
    """Every group: those of the TOML file, then the library's published ratios."""
    data = tomllib.loads(CASES_FILE.read_text(encoding="utf-8"))
    result = []
    for raw in data["group"]:
        raw = dict(raw)
        cases = tuple(_case(c) for c in raw.pop("case"))
        result.append(Group(cases=cases, **{k: v.strip() if k == "setup" else v for k, v in raw.items()}))
    return result + library_groups()


__all__ = ["Case", "Group", "groups", "library_groups", "CASES_FILE"]
