"""Running the search on Dask: an existing scheduler, a client, progress, and the same answer as a serial run."""

from __future__ import annotations

import pytest

from epicyclic.synthesis import SynthesisSpec, synthesize_spec
from epicyclic.synthesis.search import plan, search_task

SPEC = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2, "engaged": 2},
                            {"tolerance": 0.01})


def _keys(candidates):
    return sorted(c.key for c in candidates)


@pytest.fixture(scope="module")
def cluster():
    from distributed import LocalCluster

    import warnings

    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Port .* is already in use", category=UserWarning)
        c = LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None)
    with c:
        yield c


def test_existing_scheduler_gives_the_serial_answer_with_progress(cluster):
    serial = {c.key for t in plan(SPEC) for c in search_task(t).candidates}
    seen = []
    result = synthesize_spec(SPEC, scheduler=cluster.scheduler_address, progress=lambda d, n: seen.append((d, n)))
    assert set(_keys(result.candidates)) == serial and len(serial) > 0
    total = result.stats["tasks"]
    assert seen[0] == (0, total) and seen[-1] == (total, total) and len(seen) == total + 1
    assert result.stats["workers"] == 2


def test_resume_on_a_cluster_streams_and_skips_finished_tasks(cluster, tmp_path):
    path = tmp_path / "search.ckpt"
    streamed = []
    first = synthesize_spec(SPEC, scheduler=cluster.scheduler_address, checkpoint=path, announce=False,
                            on_candidates=streamed.append)
    assert len(streamed) == first.stats["tasks"] and path.exists()
    again = synthesize_spec(SPEC, scheduler=cluster.scheduler_address, checkpoint=path, announce=False)
    assert again.stats["resumed_tasks"] == again.stats["tasks"]
    assert sorted(c.key for c in again.candidates) == sorted(c.key for c in first.candidates)


def test_client_is_used_and_left_open(cluster):
    from distributed import Client

    with Client(cluster) as client:
        result = synthesize_spec(SPEC, client=client)
        assert client.status == "running"
    assert len(result) > 0


def test_candidate_efficiencies_are_physical():
    """Efficiency per gear in (0, 1] (loss >= 0), direct gears exactly 1 (no gear rolls)."""
    result = synthesize_spec(SPEC, workers=1, processes=False)
    for c in result.candidates:
        for gear, eta in c.metrics["efficiency"].items():
            assert eta is None or 0 < eta <= 1
        for gear, ratio in zip(c.gears, c.ratios):
            if abs(ratio - 1) < 1e-12:
                assert c.metrics["efficiency"][gear] == pytest.approx(1.0, abs=1e-12)


def test_unreachable_scheduler_is_a_clear_error():
    from epicyclic.synthesis import SynthesisError
    from epicyclic.synthesis.distributed import run_tasks

    with pytest.raises(SynthesisError, match="cannot reach the Dask scheduler at 'tcp://127.0.0.1:9'"):
        run_tasks(len, [[1]], scheduler="tcp://127.0.0.1:9", timeout="1s")


# ---- works wherever Python runs (issue 22): a plain script, one with worker processes, a notebook-like main
CALL = ('from epicyclic.synthesis import synthesize\n'
        'res = synthesize([2.46, 1.46, 1.0, -2.18], sets=2, elements={"brakes": 2, "clutches": 2, "engaged": 2}, '
        'workers=2{extra})\n'
        'print("found", len(res), res.stats["processes"])\n')


def _script(tmp_path, text, name="plain.py"):
    import subprocess
    import sys

    path = tmp_path / name
    path.write_text(text)
    return subprocess.run([sys.executable, str(path)], capture_output=True, text=True, timeout=300, cwd=tmp_path)


def test_a_plain_script_without_main_guard_runs_on_threads(tmp_path):
    """The documented call, as a user pastes it into a file: no `if __name__ == "__main__"`, no traceback."""
    done = _script(tmp_path, CALL.replace("{extra}", ""))
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "found 12 False"
    assert "synthesize: at most" in done.stderr and "2 local worker threads" in done.stderr  # the bound, first


def test_processes_asked_for_without_main_guard_is_a_clear_error(tmp_path):
    done = _script(tmp_path, CALL.replace("{extra}", ", processes=True"))
    assert done.returncode == 1
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("epicyclic.synthesis.spec.SynthesisError: synthesize: processes=True, but worker "
                           "processes import the main script again") and 'if __name__ == "__main__":' in last
    assert "Nanny failed" not in done.stderr and "bootstrapping" not in done.stderr


def test_processes_under_the_main_guard_and_in_a_threaded_server(tmp_path):
    call = CALL.replace("{extra}", ", processes=True").splitlines()
    guarded = "if __name__ == '__main__':\n" + "".join("    " + line + "\n" for line in call)
    done = _script(tmp_path, guarded)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "found 12 True"
    # a server thread of an unguarded script: the main thread still runs the script body, so processes are refused
    threaded = ("import threading\nerrors = []\ndef handler():\n    try:\n"
                + "".join("        " + line + "\n" for line in CALL.replace("{extra}", ", processes=True").splitlines())
                + "    except Exception as exc:\n        errors.append(exc)\n"
                "t = threading.Thread(target=handler)\nt.start()\nt.join()\nprint(type(errors[0]).__name__)\n")
    done = _script(tmp_path, threaded, "server.py")
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "SynthesisError"


def test_notebook_like_main_without_a_file_may_use_processes():
    """A notebook's (or `python -c`'s) main module has no file, so spawned workers import nothing again."""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-c", CALL.replace("{extra}", ", processes=True")], capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "found 12 True"


def test_more_local_workers_than_cores_are_capped_and_said(monkeypatch, capsys):
    # issue 30: `synthesize --workers 64` on a 2-core machine started 64 worker processes (a traceback, and
    # hundreds of leaked semaphores); the local cluster now has at most one worker per core, and says so.
    monkeypatch.setattr("os.cpu_count", lambda: 2)
    result = synthesize_spec(SPEC, workers=64, processes=False)
    assert result.stats["workers"] <= 2 and len(result) > 0
    assert "64 local workers asked for on a machine with 2 core(s): using 2" in capsys.readouterr().err
