"""Entry point of the ``epicyclic`` command (typer application).

Each sub-command lives in its own module of this package and is registered
here.  Exit codes: 0 success, 2 bad input (one-paragraph message, no
traceback), 1 internal error.
"""

from __future__ import annotations

from typing import Annotated

import typer

from ._common import OneLineErrors

app = typer.Typer(
    cls=OneLineErrors,
    name="epicyclic",
    help="Analyse epicyclic (planetary) gear trains: speeds, torques, losses, efficiency, pictures.",
    no_args_is_help=True,
    add_completion=True,
    rich_markup_mode=None,  # help texts name TOML tables: '[rating]' prints as written, never read as markup
)


def _print_version(value: bool) -> None:
    if value:
        from .. import __version__

        typer.echo(f"epicyclic {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[bool, typer.Option(
        "--version", callback=_print_version, is_eager=True, help="Print the version and exit.")] = False,
) -> None:
    """epicyclic — planetary gear train analysis."""


from . import analyze as _analyze, explain as _explain, modes as _modes  # noqa: E402

app.command("analyze")(_analyze.analyze)
app.command("modes")(_modes.modes)
app.command("explain")(_explain.explain)

from . import gears as _gears  # noqa: E402

app.command("gears")(_gears.gears)
app.command("explore")(_gears.explore)

from . import plot as _plot  # noqa: E402

app.command("plot")(_plot.plot)
app.command("animate")(_plot.animate)

from . import geometry as _geometry  # noqa: E402

app.command("fit")(_geometry.fit)
app.command("forces")(_geometry.forces)
app.command("search")(_geometry.search)

from . import datasheet as _datasheet  # noqa: E402

app.command("datasheet")(_datasheet.datasheet)

from . import export as _export  # noqa: E402

app.command("export")(_export.export)

from . import efficiency_map as _efficiency_map  # noqa: E402

app.command("map")(_efficiency_map.efficiency_map)

from . import shift_map as _shift_map  # noqa: E402

app.command("shiftmap")(_shift_map.shift_map)

from . import cycle as _cycle  # noqa: E402

app.command("cycle")(_cycle.cycle)

from . import synthesize as _synthesize  # noqa: E402

app.command("synthesize")(_synthesize.synthesize)

from . import rate as _rate  # noqa: E402

app.command("rate")(_rate.rate)

from . import duty as _duty  # noqa: E402

app.command("duty")(_duty.duty)

from . import size as _size  # noqa: E402

app.command("size")(_size.size)

from . import convert as _convert  # noqa: E402

app.command("convert")(_convert.convert)

from . import dynamics as _dynamics  # noqa: E402

app.command("shift")(_dynamics.shift)
app.command("launch")(_dynamics.launch)

from . import serve as _serve  # noqa: E402

app.command("serve")(_serve.serve)

from . import elastic as _elastic  # noqa: E402

app.command("vibration")(_elastic.vibration)
app.command("sharing")(_elastic.sharing)


def main() -> None:
    """Console-script entry point."""
    app()


if __name__ == "__main__":
    main()
