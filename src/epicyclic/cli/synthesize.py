"""``epicyclic synthesize SPEC.toml``: transmissions that give target ratios (runs on Dask).

Reads a synthesis specification (targets, sets, shift elements, bounds; see
``docs/synthesis.md``), searches on a local Dask cluster or, with
``--scheduler ADDRESS``, on an existing one, shows progress per task on
stderr and prints the ranked candidates.  ``--out-dir`` writes a train file
per candidate (``epicyclic gears`` and ``analyze`` read them), ``--csv`` a
table, ``--plot`` the speed chart across gears (or lever diagram) of the best candidate.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from ..limits import MAX_SYNTHESIS_TOP, MAX_SYNTHESIS_WORKERS
from ._common import FormatOption, OutOption, OutputFormat, emit, guarded

__all__ = ["synthesize"]


def _progress(quiet: bool):
    from ..synthesis.progress import ProgressLine

    return None if quiet else ProgressLine()


@guarded
def synthesize(
    spec: Annotated[Path, typer.Argument(help="Synthesis specification (.toml): [targets], [sets], "
                                              "[elements], [bounds], [search].")],
    format: FormatOption = OutputFormat.table,
    out: OutOption = None,
    scheduler: Annotated[Optional[str], typer.Option("--scheduler", help="Address of a running Dask scheduler "
                                                      "(tcp://host:8786); default: a local cluster.")] = None,
    workers: Annotated[Optional[int], typer.Option("--workers", min=1, max=MAX_SYNTHESIS_WORKERS,
                                                    help="Workers of the local cluster (default: CPU count; a "
                                                         "bigger cluster: --scheduler).")] = None,
    top: Annotated[Optional[int], typer.Option("--top", min=1, max=MAX_SYNTHESIS_TOP,
                                                help="Candidates to show and write (default: the spec's "
                                                     "search.top).")] = None,
    out_dir: Annotated[Optional[Path], typer.Option("--out-dir", help="Write candidate_NN.toml per shown "
                                                     "candidate into this folder.")] = None,
    csv: Annotated[Optional[Path], typer.Option("--csv", help="Also write the table as CSV.")] = None,
    plot: Annotated[Optional[Path], typer.Option("--plot", help="Speed chart across the gears of the best "
                                                  "candidate (.png, .svg or .pdf).")] = None,
    plot_kind: Annotated[str, typer.Option("--plot-kind", help="chart (speed chart across gears) or lever "
                                            "(lever diagram in the first gear).")] = "chart",
    processes: Annotated[Optional[bool], typer.Option("--processes/--threads", help="Local workers as "
                                                       "processes or as threads of this process (default: threads "
                                                       "for a small search, processes for a big one).")] = None,
    checkpoint: Annotated[Optional[Path], typer.Option("--checkpoint", help="Keep finished tasks in this file "
                                                        "(written atomically); run again with it to resume an "
                                                        "interrupted search.")] = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress on stderr.")] = False,
) -> None:
    """Search planetary transmissions (ties, shift elements, schedule, teeth) that give the target ratios."""
    from dataclasses import replace

    from ..io.output import refuse_input
    from ..synthesis import SynthesisSpec, synthesize_spec

    # every output is checked before the search, which may take long
    for option, path in (("--out", out), ("--csv", csv), ("--plot", plot), ("--checkpoint", checkpoint)):
        if path is not None:
            refuse_input(path, [spec], option)
    if plot is not None:
        from ..plotting import FIGURE_SUFFIXES
        from ..plotting._common import check_suffix

        check_suffix(plot, FIGURE_SUFFIXES, "synthesize --plot")
    if plot_kind not in ("chart", "lever"):
        from ..synthesis import SynthesisError

        raise SynthesisError(f"--plot-kind must be 'chart' or 'lever', got {plot_kind!r:.40}.")
    if out_dir is not None and out_dir.exists() and not out_dir.is_dir():
        from ..io.output import OutputError

        raise OutputError(f"--out-dir: {out_dir} exists and is not a folder; give a folder for the candidate files.",
                          str(out_dir))
    parsed = SynthesisSpec.from_file(spec)
    if top:
        parsed = replace(parsed, top=top)
    if out_dir is not None:  # no candidate file may replace the specification (or any other input)
        for k in range(1, parsed.top + 1):
            refuse_input(out_dir / f"candidate_{k:02d}.toml", [spec], "--out-dir")
    result = synthesize_spec(parsed, scheduler=scheduler, workers=workers, processes=processes,
                             progress=_progress(quiet), announce=lambda text: typer.echo(text, err=True),
                             checkpoint=checkpoint)
    if out_dir is not None:
        paths = result.write_toml(out_dir)
        typer.echo(f"wrote {len(paths)} candidate file(s) to {out_dir.resolve()}", err=True)
    if csv is not None:
        emit(result.to_csv(), csv)
    if plot is not None and result.best is not None:
        from ..io.output import atomic_path
        from ..plotting import save_figure

        with atomic_path(plot) as temporary:
            save_figure(result.plot(kind=plot_kind), temporary)
        typer.echo(f"wrote {plot.resolve()}", err=True)
    if format is OutputFormat.json:
        text = result.to_json()
    elif format is OutputFormat.markdown:
        text = result.markdown()
    elif format is OutputFormat.html:
        text = ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>epicyclic synthesize</title></head><body>"
                + result._repr_html_() + "</body></html>")
    else:
        text = result.table() if len(result) else result.table() + (
            "\nno transmission found before the time limit: raise [search] time_limit or resume with --checkpoint."
            if not result.stats.get("complete", True) else
            "\nno transmission meets the targets: widen targets.tolerance or bounds.stationary_ratio, or add "
            "elements.")
    emit(text, out)
