"""The speed chart across gears reads with many gears: every slip point is named, coincident points are
set side by side, tick labels do not overlap."""

from __future__ import annotations

from pathlib import Path

import pytest

from epicyclic.plotting._labels import overlapping_pairs
from epicyclic.plotting.speed_chart import _dodge, _engaged_label, speed_chart
from epicyclic.transmission import Transmission

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def chart_8hp():
    return speed_chart(Transmission.from_file(EXAMPLES / "zf_8hp70_8speed.toml"), gear="1")


def test_every_slip_point_is_labelled(chart_8hp):
    fig = chart_8hp.plot()
    try:
        slip_axes = fig.axes[1]
        names = [t.get_text() for t in slip_axes.texts if not t.get_text().startswith("largest")]
        assert len(names) == sum(len(row) for row in chart_8hp.slips.values())  # one label per open element and gear
        assert set(names) == set(chart_8hp.slips)
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)


def test_coincident_points_are_told_apart(chart_8hp):
    """In 6th gear (direct drive, C+D+E) every shaft turns at n_in: the points are spread around the gear."""
    offsets = _dodge(chart_8hp.speeds, chart_8hp.gears)
    at_one = [name for name, row in chart_8hp.speeds.items() if abs(row["6"] - 1.0) < 1e-9]
    assert len(at_one) >= 5
    xs = sorted(offsets[(name, "6")] for name in at_one)
    assert len(set(xs)) == len(xs) and abs(sum(xs)) < 1e-12  # distinct, centred on the gear
    alone = [name for name, row in chart_8hp.speeds.items() if abs(row["4"] - 1.8) < 0.05]  # s12's own point
    assert alone and all((name, "4") not in offsets for name in alone)


def test_tick_labels_do_not_overlap_with_four_engaged_elements():
    assert _engaged_label(("A", "B", "C")) == "A+B+C"
    assert _engaged_label(("A", "B", "C", "D")) == "A+B+\nC+D"


def test_labels_of_the_chart_do_not_overlap(chart_8hp):
    fig = chart_8hp.plot()
    try:
        texts = [t for ax in fig.axes for t in ax.texts]
        assert not overlapping_pairs(fig, texts, pad=1.0)
        for ax in fig.axes:
            assert not overlapping_pairs(fig, ax.get_xticklabels(), pad=0.0)
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)
