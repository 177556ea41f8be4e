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
