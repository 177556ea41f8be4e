"""The page's synthesis: a search from target ratios, run in a worker, its progress and candidates in a folder.

The Synthesis tab reads a specification from its form (the keys of a
synthesis spec file: ``[targets]``, ``[sets]``, ``[elements]``, ``[bounds]``,
``[search]``; :mod:`epicyclic.synthesis.spec`) or from a pasted spec file.
The form is written as the spec file's TOML text and read with
:meth:`~epicyclic.synthesis.SynthesisSpec.from_text`, so the page searches
exactly the text it shows and a bad value is named by its table and key, as
in a file (``synthesis form: [bounds], key 'sun': ...``).

Three answers, each computed in a worker of :mod:`epicyclic.web.jobs`:

* :func:`estimate_view` — the search's size before it runs: the estimate from
  counting formulas (instant) and the bound over the enumerated mechanisms
  (:mod:`epicyclic.synthesis.estimate`), or the refusal of a search larger
  than the page runs (``epicyclic synthesize`` runs those);
* :func:`search_view` — the search itself, as ``epicyclic synthesize`` runs it
  on one worker thread (no Dask cluster, no process pool): its announcement
  and progress go to ``progress.json`` in the search's folder (read by the
  server, :mod:`epicyclic.web.synthesis_routes`) and every finished task to a
  task log (:func:`~epicyclic.synthesis.checkpoint.log_task`);
* :func:`partial_view` — the candidates of a search that was stopped
  (Cancel, the page's time limit): the finished tasks of the log, ranked.

The result is the synthesis's own ranked table
(:meth:`~epicyclic.synthesis.results.SynthesisResult.html`) with an "Open in
editor" button per candidate that carries the candidate's train file, the text
``epicyclic synthesize --out-dir`` writes
(:meth:`~epicyclic.synthesis.results.SynthesisResult.candidate_toml`).

References
----------
Kahraman, Ligata, Kienzle & Zini (2004), J. Mech. Des. 126(6), 1071–1081 (the search);
Naunheimer et al. (2011), *Automotive Transmissions*, section 6.2 (ratio series).
"""

from __future__ import annotations

import functools
import hashlib
import html
import json
import math
import sys
import time
import traceback
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Mapping

from ..errors import EpicyclicError
from .jobs import failure
from .render import Reply, Verbatim, render

__all__ = ["SpecField", "FIELDS", "MODES", "PAGE_ARCHITECTURES", "PAGE_SECONDS", "spec_text", "read_spec",
           "estimate_view", "search_view", "partial_view", "candidate_name", "read_progress"]

#: The largest search the page runs (architectures, the bound over the enumerated mechanisms): about 20 s of
#: screening at the measured rate; larger ones are for ``epicyclic synthesize``.
PAGE_ARCHITECTURES = 2 * 10**7
#: Seconds after which the page stops a search (it keeps the candidates found by then and says so).
PAGE_SECONDS = 60.0
#: Where the spec comes from: the form's fields, or a pasted spec file.
MODES = ("form", "toml")
#: What the messages call the two sources.
SOURCES = {"form": "synthesis form", "toml": "pasted spec"}
#: Longest pasted spec, characters.
MAX_SPEC = 64 * 1024


@dataclass(frozen=True)
class SpecField:
    """One field of the synthesis form: the spec key it fills (``table``, ``key``), its label and default.

    ``kind``: ``"numbers"`` (comma-separated), ``"integers"``, ``"number"``, ``"integer"``, ``"pair"`` /
    ``"integer pair"`` (``A..B``), ``"members"`` (sun, ring, carrier), ``"yes/no"`` or ``"text"``.
    An empty optional field is left out of the spec (the spec's default holds).
    """

    key: str
    table: str
    label: str
    default: str
    kind: str
    optional: bool = False
    hint: str = ""

    @property
    def name(self) -> str:
        """The form field's name: ``synth_<key>``."""
        return f"synth_{self.key}"


#: The form: the spec's keys the page asks for, starting as the Simpson (Ford C4) three-speed of
#: ``examples/synthesis/simpson_3speed.toml`` (Wikipedia, "Ford C4 transmission"), a search of about 1 s.
FIELDS: tuple[SpecField, ...] = (
    SpecField("title", "", "title", "three-speed, Simpson (Ford C4) ratios", "text"),
    SpecField("forward", "targets", "forward ratios n_in/n_out", "2.46, 1.46, 1.00", "numbers"),
    SpecField("reverse", "targets", "reverse ratios (< 0)", "-2.18", "numbers", optional=True),
    SpecField("tolerance", "targets", "tolerance (relative, 0.01 = 1 %)", "0.01", "number"),
    SpecField("simple", "sets", "simple sets", "2", "integer"),
    SpecField("plus", "sets", "double-planet (plus) sets", "0", "integer"),
    SpecField("brakes", "elements", "brakes", "2", "integer"),
    SpecField("clutches", "elements", "clutches", "2", "integer"),
    SpecField("engaged", "elements", "engaged per gear (empty: every feasible)", "", "integers", optional=True),
    SpecField("stationary_ratio", "bounds", "|i0| range", "1.5..4", "pair"),
    SpecField("sun", "bounds", "sun teeth", "17..80", "integer pair"),
    SpecField("planet", "bounds", "planet teeth", "17..80", "integer pair"),
    SpecField("planets", "bounds", "planets", "3, 4, 5", "integers"),
    SpecField("hunting", "bounds", "hunting-tooth sets only", "no", "yes/no"),
    SpecField("free_input", "search", "separate input shaft", "yes", "yes/no"),
    SpecField("max_members_per_shaft", "search", "most members per shaft (empty: no limit)", "", "integer",
              optional=True),
    SpecField("input_members", "search", "input on", "sun, ring, carrier", "members"),
    SpecField("output_members", "search", "output on", "sun, ring, carrier", "members"),
    SpecField("top", "search", "candidates shown", "20", "integer"),
)


# ---------------------------------------------------------------------- the form as a spec file
def _bad(source: str, field: SpecField, message: str) -> EpicyclicError:
    from ..synthesis import SynthesisError

    where = f"[{field.table}], key {field.key!r}" if field.table else f"key {field.key!r}"
    return SynthesisError(f"{source}: {where} ({field.label}): {message}")


def _number(text: str, field: SpecField, source: str, whole: bool) -> float | int:
    try:
        value = float(text)
    except ValueError:
        raise _bad(source, field, f"expected a {'whole number' if whole else 'number'}, got {text[:40]!r}.") from None
    if not whole or not math.isfinite(value):
        return value  # NaN and infinities go on to the spec, which names them
    if not value.is_integer():
        raise _bad(source, field, f"expected a whole number, got {text[:40]!r}.")
    return int(value)


def _value(field: SpecField, text: str, source: str) -> Any:
    """The spec value of one form field (None: left out)."""
    if not text:
        if field.optional:
            return None
        raise _bad(source, field, "a value is needed.")
    kind = field.kind
    if kind == "text":
        return text
    if kind == "yes/no":
        if text not in ("yes", "no"):
            raise _bad(source, field, f"expected yes or no, got {text[:40]!r}.")
        return text == "yes"
    if kind == "members":
        return [part.strip() for part in text.split(",") if part.strip()]
    if kind in ("pair", "integer pair"):
        parts = text.split("..") if ".." in text else text.split(",")
        if len(parts) != 2:
            raise _bad(source, field, f"expected a range such as {field.default}, got {text[:40]!r}.")
        return [_number(p.strip(), field, source, kind == "integer pair") for p in parts]
    if kind in ("numbers", "integers"):
        parts = [p.strip() for p in text.replace(";", ",").split(",") if p.strip()]
        return [_number(p, field, source, kind == "integers") for p in parts]
    return _number(text, field, source, kind == "integer")


def _text(values: Mapping[str, str], name: str, limit: int = 400) -> str:
    from .state import clean_text

    return clean_text(values.get(name), name, limit)


def form_data(values: Mapping[str, str]) -> dict[str, Any]:
    """The spec (as the tables of its TOML file) of the form's ``values`` (``synth_<key>`` → text)."""
    data: dict[str, Any] = {}
    for field in FIELDS:
        text = _text(values, field.name)
        value = _value(field, text if field.name in values else field.default, SOURCES["form"])
        if value is None:
            continue
        if field.table:
            data.setdefault(field.table, {})[field.key] = value
        else:
            data[field.key] = value
    return data


def spec_text(values: Mapping[str, str]) -> tuple[str, str]:
    """(TOML text, source name) of the spec the page searches: the form's, written as a spec file, or the pasted one.

    Parameters
    ----------
    values : mapping of str to str
        The synthesis form: ``synth_mode`` (``"form"`` or ``"toml"``), ``synth_spec`` (the pasted text) and
        the fields of :data:`FIELDS`.
    """
    import tomlkit

    from .state import clean_text

    mode = _text(values, "synth_mode") or "form"
    if mode not in MODES:
        from ..synthesis import SynthesisError

        raise SynthesisError(f"synthesis: the spec comes from {' or '.join(MODES)}, got {mode[:40]!r}.")
    if mode == "toml":
        text = clean_text(values.get("synth_spec"), "synth_spec", MAX_SPEC, single_line=False)
        return text.replace("\r\n", "\n"), SOURCES["toml"]
    data = form_data(values)
    header = "# Synthesis specification written by the page (epicyclic serve); `epicyclic synthesize` reads it.\n"
    return header + tomlkit.dumps(data), SOURCES["form"]


def read_spec(values: Mapping[str, str]) -> tuple[Any, str]:
    """(SynthesisSpec, its TOML text) of the form's ``values`` (see :func:`spec_text`).

    Parameters
    ----------
    values : mapping of str to str

    Raises
    ------
    SynthesisError
        A bad field or key, named by its table and key.
    """
    from ..synthesis import SynthesisError, SynthesisSpec

    text, source = spec_text(values)
    if not text.strip():
        raise SynthesisError(f"{source}: the text is empty; paste a synthesis spec ([targets], [sets], [elements]) "
                             "or fill in the form.")
    return SynthesisSpec.from_text(text, source), text


# ---------------------------------------------------------------------- size and refusal
def _refusal(size: Any, bound: int, seconds: float) -> str:
    return (f"this search has {size.describe()}, more than the page runs ({bound:.3g} architectures, stopped "
            f"after {seconds:g} s). Run it on the command line, where it has every worker and a checkpoint: save "
            "the spec below as spec.toml and run `epicyclic synthesize spec.toml --out-dir candidates` (add "
            "--scheduler for a cluster); or narrow it here ([elements] engaged, [search] max_members_per_shaft, "
            "separate input shaft no, fewer sets or elements).")


def _sized(spec: Any, bound: int, seconds: float) -> tuple[Any, Any, Any, str]:
    """(estimate, exact bound, plan, refusal or "") of a spec: the estimate first, the enumeration only when the
    estimate is within the page's bound."""
    from ..synthesis.estimate import check, count, estimate
    from ..synthesis.search import plan

    first = estimate(spec)
    check(spec, first)  # the spec's own max_architectures
    if first.architectures > bound:
        return first, None, None, _refusal(first, bound, seconds)
    tasks = plan(spec, 1)
    size = count(spec, (m for t in tasks for m in t.mechanisms))
    check(spec, size)
    return first, size, tasks, _refusal(size, bound, seconds) if size.architectures > bound else ""


def _guard(action):
    """Bad input as the page's problem box (422), anything else as an internal error (500), never a traceback."""
    @functools.wraps(action)
    def wrapper(*args: Any, **kwargs: Any) -> Reply:
        try:
            return action(*args, **kwargs)
        except EpicyclicError as exc:
            return failure(str(exc), 422)
        except MemoryError:
            raise  # the worker's memory limit: the pool says so (epicyclic.web.jobs)
        except Exception as exc:  # a bug: say so, keep serving
            traceback.print_exc(file=sys.stderr)
            return failure(f"internal error: {type(exc).__name__}: {exc}. This is a bug in epicyclic; please report "
                           "it with the synthesis spec.", 500)

    return wrapper


@_guard
def estimate_view(values: Mapping[str, str], bound: int = PAGE_ARCHITECTURES, seconds: float = PAGE_SECONDS) -> Reply:
    """The size of the form's search before it runs, with the Run button or the page's refusal.

    Parameters
    ----------
    values : mapping of str to str
        The synthesis form.
    bound : int
        Largest search the page runs, architectures.
    seconds : float
        The page's time limit of a search.
    """
    spec, text = read_spec(values)
    first, size, tasks, refused = _sized(spec, bound, seconds)
    return Reply(render("synthesis_estimate.html", first=first, size=size, tasks=len(tasks or ()), refused=refused,
                        spec=spec, text=Verbatim(text), bound=bound, seconds=seconds))


# ---------------------------------------------------------------------- the search
class _Progress:
    """What a running search tells the server: ``progress.json`` (replaced atomically) and the task log."""

    def __init__(self, folder: Path, total: int):
        self.folder, self.keys = folder, set()
        self.state = {"done": 0, "total": total, "found": 0, "started": time.time(), "announce": ""}
        self.write()

    def write(self) -> None:
        from ..io.output import write_atomic

        write_atomic(self.folder / "progress.json", json.dumps(self.state))

    def announce(self, text: str) -> None:
        self.state["announce"] = f"{self.state['announce']}\n{text}".strip()
        self.write()

    def progress(self, done: int, total: int) -> None:
        self.state.update(done=done, total=total, found=len(self.keys))
        self.write()

    def task(self, index: int, result: Any) -> None:
        from ..synthesis.checkpoint import log_task

        log_task(self.folder / "tasks.log", index, result)
        self.keys.update(c.key for c in result.candidates)


def read_progress(folder: str | Path) -> dict[str, Any] | None:
    """The progress a search wrote in ``folder`` (None before it starts).

    Parameters
    ----------
    folder : str or Path
    """
    try:
        return json.loads((Path(folder) / "progress.json").read_text())
    except (OSError, ValueError):
        return None


def _page_spec(spec: Any, seconds: float) -> Any:
    """The spec as the page runs it: within the page's time limit."""
    return replace(spec, time_limit=min(spec.time_limit or seconds, seconds))


def candidate_name(text: str, rank: int) -> str:
    """The file name of a candidate opened in the editor: ``candidate_NN-<hash>.toml`` (the hash of its text, so
    that edits kept in the browser for a candidate of another search never come back in this one).

    Parameters
    ----------
    text : str
        The candidate's train file.
    rank : int
    """
    return f"candidate_{rank:02d}-{hashlib.sha256(text.encode()).hexdigest()[:8]}.toml"


def _open_button(result: Any, rank: int) -> str:
    text = result.candidate_toml(rank)
    return (f'<button type="button" class="open-candidate" data-open-candidate="{rank}" '
            f'data-name="{candidate_name(text, rank)}" data-toml="{html.escape(text, quote=True)}" '
            f'title="open candidate {rank} in the editor as a new document">Open in editor</button>')


def _result(result: Any, note: str) -> Reply:
    table = result.html(lambda rank: _open_button(result, rank), "open")
    return Reply(render("synthesis_result.html", result=result, table=table, note=note,
                        explanation=result.explain() if len(result) else "", text=result.table()))


@_guard
def search_view(values: Mapping[str, str], folder: str, bound: int = PAGE_ARCHITECTURES,
                seconds: float = PAGE_SECONDS) -> Reply:
    """Run the form's search (one worker thread), its progress in ``folder``; the ranked candidates.

    Parameters
    ----------
    values : mapping of str to str
        The synthesis form.
    folder : str
        The search's folder (made by the server): ``progress.json`` and the task log go there.
    bound : int
        Largest search the page runs, architectures (a larger one is refused before it starts).
    seconds : float
        The page's time limit: the search stops after it and says so.
    """
    from ..synthesis import SynthesisError, synthesize_spec

    spec, _ = read_spec(values)
    _, _, tasks, refused = _sized(spec, bound, seconds)
    if refused:
        raise SynthesisError(f"{spec.source}: {refused}")
    page = _page_spec(spec, seconds)
    progress = _Progress(Path(folder), len(tasks))
    result = synthesize_spec(page, workers=1, processes=False, chunk=1, announce=progress.announce,
                             progress=progress.progress, on_task=progress.task)
    note = ""
    if not result.stats.get("complete", True) and page.time_limit != spec.time_limit:
        result = replace(result, stats={**result.stats, "stopped": f"stopped at the page's limit of {seconds:g} s"})
        note = "The page stops a search after its time limit; `epicyclic synthesize` runs it whole."
    return _result(result, note)


@_guard
def partial_view(values: Mapping[str, str], folder: str, reason: str, seconds: float = PAGE_SECONDS) -> Reply:
    """The candidates of a stopped search: its finished tasks (the task log in ``folder``), ranked.

    Parameters
    ----------
    values : mapping of str to str
        The synthesis form the search ran.
    folder : str
        The search's folder.
    reason : str
        Why it stopped ("cancelled", ...), said in the result.
    seconds : float
        The page's time limit.
    """
    from ..synthesis.checkpoint import logged_tasks
    from ..synthesis.estimate import count, estimate
    from ..synthesis.search import assemble, plan

    spec, _ = read_spec(values)
    page = _page_spec(spec, seconds)
    state = read_progress(folder) or {}
    tasks = plan(page, 1)
    done = logged_tasks(Path(folder) / "tasks.log")
    results = [done.get(k) for k in range(len(tasks))]
    elapsed = time.time() - state["started"] if "started" in state else 0.0
    result = assemble(page, results, estimate(page), count(page, (m for t in tasks for m in t.mechanisms)),
                      seconds=elapsed, stopped=reason)
    kept = f"{len(result)} candidate(s) of the {result.stats['tasks_done']} finished task(s) are kept"
    return _result(result, f"The search was {reason}; {kept}.")
