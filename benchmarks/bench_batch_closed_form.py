"""Batch solver vs a hand-written closed form of the same train (issue 11).

Brandenberger's closed train (1952, Bild 10) over 10**6 operating points: speed and torque of the
drive shaft II random, both directions of power flow (so both loss-direction patterns occur); I is
connected, its role follows from the solution. The closed form writes the train's equations out by
hand for exactly this train — Willis (Brandenberger eq. 1) for the set, n_III = 3.52·n_II for the
stage, the torque ratios with η0 on the driving side (eqs. 7, 7', 9), the balance of the internal
shaft III — and returns the same arrays as `solve_batch`: every speed, external torque and power,
every port torque, the loss per element, input and output power, loss, efficiency, self-locking.
The run checks that the arrays agree to round-off, then times both.

Target (issue 11): `solve_batch` within 3× of the closed form.

Run:  .venv/bin/python benchmarks/bench_batch_closed_form.py [points]
"""

from __future__ import annotations

import sys
import time

import numpy as np

from epicyclic.demo import brandenberger_1952
from epicyclic.solver.batch import solve_batch

I0 = (24 * 42) / (50 * 30)  # stationary ratio of the set, (n_I − n_III)/(n_II − n_III): bd/ac
STAGE = (44 / 40) * (64 / 20)  # n_III / n_II of the stage e/f·g/h
ETA_SET = ETA_STAGE = 0.9  # η1η2 = η3η4 = 0.9
RPM = np.pi / 30


def closed_form(speed_ii: np.ndarray, torque_ii: np.ndarray) -> dict[str, np.ndarray]:
    """Every result of the train at (n_II, M_II), written out by hand (no solver)."""
    n_ii = speed_ii
    n_iii = STAGE * n_ii
    n_i = n_iii + I0 * (n_ii - n_iii)
    w_i, w_ii, w_iii = n_i * RPM, n_ii * RPM, n_iii * RPM

    def torques(e_set, e_stage):
        a, b = I0 * e_set, STAGE * e_stage  # T_ring = −a·T_sun (set), T_second = −b·T_first (stage)
        t_sun = -torque_ii / (a + b * (1 - a))  # balance of II: T_ring + T_second = M_II; of III: T_carrier + T_first = 0
        return t_sun, -a * t_sun, -(1 - a) * t_sun, (1 - a) * t_sun, -b * (1 - a) * t_sun

    t_sun0, _, _, t_first0, _ = torques(1.0, 1.0)  # lossless: the direction of the rolling power
    w_set = np.sign(t_sun0 * (w_i - w_iii))  # rolling power of the set, sun relative to carrier
    w_stage = np.sign(t_first0 * w_iii)  # rolling power of the stage (its carrier is the housing)
    t_sun, t_ring, t_carrier, t_first, t_second = torques(ETA_SET ** w_set, ETA_STAGE ** w_stage)
    t_housing = -(t_first + t_second)
    p_i, p_ii = t_sun * w_i, torque_ii * w_ii
    ideal_i, ideal_ii = t_sun0 * w_i, torque_ii * w_ii  # roles of the connected shafts: lossless signs
    drive = np.where(ideal_i > 0, p_i, 0.0) + np.where(ideal_ii > 0, p_ii, 0.0)
    load = -np.where(ideal_i < 0, p_i, 0.0) - np.where(ideal_ii < 0, p_ii, 0.0)
    loss_set = t_sun * w_i + t_ring * w_ii + t_carrier * w_iii
    loss_stage = t_first * w_iii + t_second * w_ii
    with np.errstate(divide="ignore", invalid="ignore"):
        efficiency = np.where(drive > 0, load / drive, np.nan)
    zero = np.zeros_like(n_ii)
    return {
        "speed I": n_i, "speed II": n_ii, "speed III": n_iii, "speed housing": zero,
        "torque I": t_sun, "torque II": torque_ii, "torque III": zero, "torque housing": t_housing,
        "power I": p_i, "power II": p_ii,
        "port planetary.sun": t_sun, "port planetary.ring": t_ring, "port planetary.carrier": t_carrier,
        "port stage.first": t_first, "port stage.second": t_second, "port stage.housing": t_housing,
        "loss planetary": loss_set, "loss stage": loss_stage,
        "input power": drive, "output power": load, "loss": loss_set + loss_stage,
        "efficiency": efficiency, "self-locking": np.zeros(n_ii.shape, dtype=bool),
    }


def from_batch(result) -> dict[str, np.ndarray]:
    """The same arrays, read from a BatchSolution."""
    out = {f"speed {s}": result.speeds[s] for s in ("I", "II", "III", "housing")}
    out |= {f"torque {s}": result.torques[s] for s in ("I", "II", "III", "housing")}
    out |= {f"power {s}": result.powers[s] for s in ("I", "II")}
    out |= {f"port {e}.{p}": result.port_torques[(e, p)] for e, p in (
        ("planetary", "sun"), ("planetary", "ring"), ("planetary", "carrier"),
        ("stage", "first"), ("stage", "second"), ("stage", "housing"))}
    out |= {f"loss {e}": result.losses[e] for e in ("planetary", "stage")}
    out |= {"input power": result.input_power, "output power": result.output_power, "loss": result.loss,
            "efficiency": result.efficiency, "self-locking": result.self_locking}
    return out


def operating_points(count: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    speed = rng.uniform(200.0, 3000.0, count) * rng.choice([-1.0, 1.0], count)
    torque = rng.uniform(1.0, 30.0, count) * rng.choice([-1.0, 1.0], count)
    return speed, torque


def best_of(repeats: int, function, *args) -> tuple[float, object]:
    times, result = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        result = function(*args)
        times.append(time.perf_counter() - start)
    return min(times), result


def main(points: int = 1_000_000, repeats: int = 5) -> None:
    train, _ = brandenberger_1952()
    speed, torque = operating_points(points)

    def batch(s, t):
        return solve_batch(train, speeds={"II": s}, torques={"II": t}, connected=["I"])

    batch(speed[:1000], torque[:1000])  # warm-up (imports, caches)
    closed_time, closed = best_of(repeats, closed_form, speed, torque)
    batch_time, result = best_of(repeats, batch, speed, torque)
    solved = from_batch(result)
    worst = 0.0
    for key, expected in closed.items():
        got = solved[key]
        if expected.dtype == bool:
            assert np.array_equal(got, expected), key
            continue
        scale = np.nanmax(np.abs(expected)) or 1.0
        assert np.array_equal(np.isnan(got), np.isnan(expected)), key
        worst = max(worst, float(np.nanmax(np.abs(got - expected))) / scale)
    print(f"points                          {points:>12,d}   (best of {repeats})")
    print(f"loss-direction patterns         {result.patterns:>12d}")
    print(f"closed form (numpy, by hand)    {closed_time * 1e3:>12.1f} ms  ({closed_time / points * 1e9:.0f} ns/point)")
    print(f"solve_batch                     {batch_time * 1e3:>12.1f} ms  ({batch_time / points * 1e9:.0f} ns/point)")
    print(f"ratio solve_batch / closed form {batch_time / closed_time:>12.2f}   (target ≤ 3)")
    print(f"arrays agree: {len(closed)} arrays, largest difference {worst:.1e} of the array's scale")
    if worst > 1e-9:
        raise SystemExit("batch and closed form disagree")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
