"""MkDocs hooks of the documentation site (``hooks:`` in mkdocs.yml).

* The API reference's navigation file (``reference/api/SUMMARY.md``, written by docs/gen_pages.py and
  read by mkdocs-literate-nav) is not built as a page of its own.
* Every tutorial shows the output of the commands it runs: at build time each ``sh`` block of a page
  under ``tutorials/`` is run, line by line, in a fresh folder holding ``examples/`` (a link) and the
  files the page saved before it (``<!-- docs-test: file NAME -->`` TOML blocks; ``python`` blocks run
  in one namespace per page, as tests/docs/test_examples.py runs them), and a block with the output
  follows it. Long-running commands (``serve``, ``synthesize``) and blocks marked
  ``<!-- docs-test: skip (reason) -->`` are not run. A command that fails fails the build.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

from mkdocs.structure.files import InclusionLevel

ROOT = Path(__file__).resolve().parents[1]
NAV_FILE = "reference/api/SUMMARY.md"
SHELLS = {"sh", "bash", "shell"}
LONG_RUNNING = {"serve", "synthesize"}
#: Output longer than this many lines is shown folded (click to open).
FOLD_AFTER = 40
_FENCE = re.compile(r"^(`{3,})\s*([\w+-]*)\s*$")
_SKIP = re.compile(r"<!--\s*docs-test:\s*skip\s*\((.+)\)\s*-->")
_FILE = re.compile(r"<!--\s*docs-test:\s*file\s+([\w.-]+)\s*-->")


def on_files(files, config):
    """Keep the literate-nav file of the API reference out of the built pages (it is navigation only)."""
    nav = files.get_file_from_path(NAV_FILE)
    if nav is not None:
        nav.inclusion = InclusionLevel.EXCLUDED
    return files


def on_page_markdown(markdown: str, page, config, files) -> str:
    """A tutorial page with the output of each of its shell blocks after the block."""
    if not page.file.src_uri.startswith("tutorials/"):
        return markdown
    with tempfile.TemporaryDirectory(prefix="epicyclic-docs-") as folder:
        work = Path(folder)
        (work / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
        return _with_outputs(markdown, work, page.file.src_uri)


def _with_outputs(markdown: str, work: Path, where: str) -> str:
    lines = markdown.splitlines()
    out: list[str] = []
    namespace: dict = {"__name__": "__docs__"}
    i = 0
    while i < len(lines):
        match = _FENCE.match(lines[i])
        if not match:
            out.append(lines[i])
            i += 1
            continue
        fence, lang = match.groups()
        before = lines[i - 1] if i else ""
        start = i
        i += 1
        while i < len(lines) and not lines[i].strip().startswith(fence):
            i += 1
        body = "\n".join(lines[start + 1:i]) + "\n"
        out.extend(lines[start:i + 1])
        i += 1
        if _SKIP.search(before):
            continue
        lang = lang.lower()
        if lang == "toml" and (name := _FILE.search(before)):
            (work / name.group(1)).write_text(body, encoding="utf-8")
        elif lang == "python":
            cwd = os.getcwd()
            try:
                os.chdir(work)
                with contextlib.redirect_stdout(io.StringIO()):  # the page shows its values in pycon blocks
                    exec(compile(body, f"{where}:{start + 1}", "exec"), namespace)
            finally:
                os.chdir(cwd)
        elif lang in SHELLS:
            shown = _run_block(body, work, f"{where}:{start + 1}")
            if shown:
                out.extend(_output_block(shown))
    return "\n".join(out) + "\n"


def _run_block(code: str, work: Path, where: str) -> str:
    """The commands of one shell block and what each prints, as a console transcript."""
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
           "MPLBACKEND": "Agg", "COLUMNS": "100", "NO_COLOR": "1", "TERM": "dumb"}
    transcript: list[str] = []
    joined = code.replace("\\\n", " ")
    for line in joined.splitlines():
        command = line.split("  #")[0].strip()
        if not command or command.startswith("#"):
            continue
        words = shlex.split(command, comments=True)
        if words[:1] == ["epicyclic"] and len(words) > 1 and words[1] in LONG_RUNNING:
            continue
        if words[:1] == ["epicyclic"] and not set(command) & set("|;&<>$`"):
            argv = [sys.executable, "-m", "epicyclic", *words[1:]]
            done = subprocess.run(argv, cwd=work, env=env, capture_output=True, text=True, timeout=300)
        else:
            done = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", command], cwd=work, env=env,
                                  capture_output=True, text=True, timeout=300)
        if done.returncode != 0:
            raise RuntimeError(f"{where}: `{command}` exits {done.returncode}:\n{done.stdout[-2000:]}\n"
                               f"{done.stderr[-2000:]}")
        printed = (done.stdout + done.stderr).rstrip()
        transcript.append(f"$ {command}")
        if printed:
            transcript.append(printed)
    return "\n".join(transcript) if len(transcript) > sum(t.startswith("$ ") for t in transcript) else ""


def _output_block(text: str) -> list[str]:
    """An admonition holding the transcript (folded when it is long)."""
    rows = text.splitlines()
    marker = "???" if len(rows) > FOLD_AFTER else "???+"
    fence = "````" if "```" in text else "```"
    return ["", f'{marker} example "Output (run when this page was built)"', "",
            f"    {fence}text", *(f"    {row}" if row else "" for row in rows), f"    {fence}", ""]
