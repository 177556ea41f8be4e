"""Every code example of the documentation runs.

``python`` blocks run in page order in one namespace per page (a tutorial builds on its earlier
blocks); ``pycon`` blocks (``>>>`` sessions) run as doctests in the same namespace, so the output
they show is checked; ``sh`` / ``bash`` / ``console`` blocks (``$`` prompts stripped) run line by
line and every line must succeed (``epicyclic serve``, which runs until stopped, and ``epicyclic synthesize``,
which starts a Dask cluster, are parsed with their options, not started): a plain ``epicyclic …`` command runs in-process through typer's
test runner (the same app as the installed command, without a new interpreter per line — the
installed command itself is tested in tests/test_package.py), anything else (other programs, pipes,
redirections, ``||``) in bash with the installed ``epicyclic`` on the PATH; ``toml`` blocks must parse, and a
``toml`` block preceded by ``<!-- docs-test: file NAME -->`` is also saved as NAME for the blocks after it (the
page tells the reader to save it so).  Each page
runs in a fresh folder that holds ``examples/`` (a link), so outputs never land in the repository.
A block preceded by ``<!-- docs-test: skip (reason) -->`` is not run; the reason is required.
"""

from __future__ import annotations

import doctest
import os
import shlex
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
PAGES = sorted(p for p in DOCS.rglob("*.md"))
SHELLS = {"sh", "bash", "console", "shell"}
_FENCE = re.compile(r"^(\s*)(`{3,})\s*([\w+-]*)")
_SKIP = re.compile(r"<!--\s*docs-test:\s*skip\s*\((.+)\)\s*-->")
_FILE = re.compile(r"<!--\s*docs-test:\s*file\s+([\w.-]+)\s*-->")


def code_blocks(path: Path) -> list[tuple[str, str, int, bool]]:
    """(language, code, line number, skipped) of every fenced block of a Markdown page."""
    lines = path.read_text(encoding="utf-8").splitlines()
    blocks, i = [], 0
    while i < len(lines):
        match = _FENCE.match(lines[i])
        if not match:
            i += 1
            continue
        indent, fence, lang = match.groups()
        skipped = i > 0 and bool(_SKIP.search(lines[i - 1]))
        start, body = i + 1, []
        i += 1
        while i < len(lines) and not lines[i].strip().startswith(fence):
            body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i].lstrip())
            i += 1
        blocks.append((lang.lower(), "\n".join(body) + "\n", start, skipped))
        i += 1
    return blocks


def _workdir(tmp_path: Path) -> Path:
    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    return tmp_path


def _shell_lines(code: str, lang: str) -> list[str]:
    """The commands of a shell block: prompts stripped, continuation lines joined, comments dropped."""
    lines = code.splitlines()
    if lang == "console":  # only the prompted lines are commands
        lines = [line[2:] for line in lines if line.startswith("$ ")]
    joined = "\n".join(lines).replace("\\\n", " ")
    return [line for line in joined.splitlines() if line.strip() and not line.lstrip().startswith("#")]


def _epicyclic_args(line: str) -> list[str] | None:
    """The arguments of a plain ``epicyclic …`` line; None if the line needs a shell."""
    lexer = shlex.shlex(line, posix=True, punctuation_chars=True)
    lexer.whitespace_split = True
    lexer.commenters = "#"
    tokens = list(lexer)
    if not tokens or tokens[0] != "epicyclic" or "$" in line or "`" in line:
        return None
    if any(t and set(t) <= set("();<>|&") for t in tokens):
        return None
    return tokens[1:]


#: Commands that run until stopped (a server) or start a computing cluster (which may be remote):
#: their command lines are parsed with every option, not run (tests/synthesis runs synthesize).
LONG_RUNNING = {"serve", "synthesize"}


def _parse_only(args: list[str], where: str, line: str) -> None:
    """Check a long-running command's options the way the command would, without starting it."""
    from typer.main import get_command

    from epicyclic.cli.main import app

    group = get_command(app)
    command = group.get_command(group.make_context("epicyclic", [args[0]], resilient_parsing=True), args[0])
    assert command is not None, f"{where}: `{line}`: no command {args[0]!r}"
    try:
        command.make_context(args[0], list(args[1:]))
    except Exception as exc:  # click's usage errors
        pytest.fail(f"{where}: `{line}` does not parse: {exc}")


def _run_shell_line(line: str, where: str, work: Path, env: dict[str, str]) -> None:
    args = _epicyclic_args(line)
    if args and args[0] in LONG_RUNNING:
        _parse_only(args, where, line)
        return
    if args is not None:
        from typer.testing import CliRunner

        from epicyclic.cli.main import app

        result = CliRunner().invoke(app, args, env={"COLUMNS": "100"})
        assert result.exit_code == 0, f"{where}: `{line}` exits {result.exit_code}:\n{result.output[-3000:]}" \
            + (f"\n{result.exception!r}" if result.exception and not isinstance(result.exception, SystemExit) else "")
        return
    done = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", line], cwd=work, env=env,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, f"{where}: `{line}` fails (exit {done.returncode}):\n" \
                                 f"{done.stdout[-2000:]}\n{done.stderr[-2000:]}"


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(DOCS)) for p in PAGES])
def test_page_examples_run(page, tmp_path, monkeypatch):
    work = _workdir(tmp_path)
    monkeypatch.chdir(work)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    namespace: dict = {"__name__": "__docs__"}
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
           "MPLBACKEND": "Agg", "COLUMNS": "100"}
    lines = page.read_text(encoding="utf-8").splitlines()
    for lang, code, line, skipped in code_blocks(page):
        where = f"{page.relative_to(ROOT)}:{line}"
        save_as = _FILE.search(lines[line - 2]) if line >= 2 else None  # the line before the opening fence
        if skipped:
            continue
        if lang == "python":
            try:
                exec(compile(code, where, "exec"), namespace)
            except Exception as exc:  # report the page and line, not this file
                pytest.fail(f"{where}: the Python example fails: {type(exc).__name__}: {exc}")
        elif lang == "pycon":
            test = doctest.DocTestParser().get_doctest(code, namespace, where, str(page), line)
            runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
            report: list[str] = []
            runner.run(test, out=report.append, clear_globs=False)
            assert not runner.failures, f"{where}: the session's output differs:\n" + "".join(report)
        elif lang in SHELLS:
            for command in _shell_lines(code, lang):
                _run_shell_line(command, where, work, env)
        elif lang == "toml":
            try:
                tomllib.loads(code)
            except tomllib.TOMLDecodeError as exc:
                pytest.fail(f"{where}: the TOML example does not parse: {exc}")
            if save_as:
                (work / save_as.group(1)).write_text(code, encoding="utf-8")


def test_skips_give_a_reason_and_pages_have_examples():
    runnable = 0
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        assert "docs-test: skip" not in text or _SKIP.search(text), f"{page}: a skip needs '(reason)'"
        runnable += sum(1 for lang, _, _, skipped in code_blocks(page)
                        if not skipped and (lang in ("python", "pycon") or lang in SHELLS))
    assert runnable >= 30
