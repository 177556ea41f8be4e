"""Benchmark: shifts as they happen on the ZF 8HP 70 (examples/dynamics/zf_8hp70_shift.toml).

Run:  .venv/bin/python benchmarks/bench_dynamics.py [shifts] [naive_step_s]

* one 1 s upshift 2 → 3 with every element modelled (five wet packs, the four sets with their losses,
  engine map and vehicle road load) at 1 ms output steps: :func:`epicyclic.dynamics.shift.simulate_shift`
  (``solve_ivp`` DOP853 with terminal events), best of 5; goal ≤ 0.5 s;
* a sweep of ``shifts`` (default 100) such shifts over the throttle 10 … 100 %; goal ≤ 20 s;
* the naive baseline in the same run: the same equations (:meth:`TrainDynamics.evaluate`) stepped by a
  fixed-step RK4 loop at ``naive_step_s`` (default 1e-4 s), stick–slip decided once per step (an element
  locks in the step its slip changes sign, breaks away in the step its torque exceeds its capacity), with
  its lock-up time and energy balance beside the event-based run's.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import math
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from epicyclic.dynamics import Mode
from epicyclic.dynamics.integrate import project, settle
from epicyclic.dynamics.shift import simulate_shift
from epicyclic.io import loads_train_file
from epicyclic.io.dynamics_format import dynamics_spec
from epicyclic.transmission import Transmission

EXAMPLE = ROOT / "examples" / "dynamics" / "zf_8hp70_shift.toml"


def naive(dynamics, omega0, locked, t_end, dt):
    """Fixed-step RK4 with stick–slip decided per step; returns (lock-up times, energy residual / energy in)."""
    mode = settle(dynamics, 0.0, omega0, Mode(frozenset(locked), {}))
    omega = project(dynamics, omega0, mode.locked)
    ke0 = dynamics.kinetic_energy(omega)
    e_in = e_out = e_loss = 0.0
    locks = []
    steps = int(round(t_end / dt))

    def rates(t, w, m):
        r = dynamics.evaluate(t, w, m)
        return r.accelerations, r.input_power, r.load_power, r.mesh_power + sum(r.element_powers.values()), r

    for k in range(steps):
        t = k * dt
        signs = {name: (math.copysign(1.0, dynamics.slip(name, omega)) if dynamics.slip(name, omega) else
                        mode.signs.get(name, 0.0)) for name in dynamics.elements if name not in mode.locked}
        mode = Mode(mode.locked, signs)
        a1, p1, q1, l1, r = rates(t, omega, mode)
        a2, p2, q2, l2, _ = rates(t + dt / 2, omega + dt / 2 * a1, mode)
        a3, p3, q3, l3, _ = rates(t + dt / 2, omega + dt / 2 * a2, mode)
        a4, p4, q4, l4, _ = rates(t + dt, omega + dt * a3, mode)
        new = omega + dt / 6 * (a1 + 2 * a2 + 2 * a3 + a4)
        e_in += dt / 6 * (p1 + 2 * p2 + 2 * p3 + p4)
        e_out += dt / 6 * (q1 + 2 * q2 + 2 * q3 + q4)
        e_loss += dt / 6 * (l1 + 2 * l2 + 2 * l3 + l4)
        locked = set(mode.locked)
        for name in list(signs):  # a slip that changed sign in the step: lock
            if signs[name] and dynamics.slip(name, new) * signs[name] < 0 and dynamics.static_capacity(name, t) > 0:
                locked.add(name)
                locks.append((name, t + dt))
        for name in list(locked & set(mode.locked)):  # a torque beyond the capacity: break away
            if abs(r.element_torques[name]) > dynamics.static_capacity(name, t):
                locked.discard(name)
        if locked != set(mode.locked):
            mode = Mode(frozenset(locked), mode.signs)
            new = project(dynamics, new, mode.locked)
        omega = new
    residual = e_in - e_out - e_loss - (dynamics.kinetic_energy(omega) - ke0)
    return locks, abs(residual) / max(abs(e_in), 1.0)


def main() -> None:
    shifts = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    naive_step = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-4
    text = EXAMPLE.read_text(encoding="utf-8")
    transmission = Transmission.from_train_file(loads_train_file(text, str(EXAMPLE)))
    spec = dynamics_spec(text, str(EXAMPLE), transmission)
    print(f"python {platform.python_version()}, numpy {np.__version__}, {platform.machine()}")
    simulate_shift(transmission, spec, "2", "3")  # warm-up: imports, caches
    times, cpu = [], []
    for _ in range(5):
        start, start_cpu = time.perf_counter(), time.process_time()
        result = simulate_shift(transmission, spec, "2", "3")
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print(f"one 1 s upshift 2->3, 1 ms output steps ({result.traces.time.size} points, {result.events} events): "
          f"wall best {min(times):.3f} s, median {sorted(times)[2]:.3f} s; CPU best {min(cpu):.3f} s "
          f"(goal <= 0.5 s); lock-up of C at "
          f"{result.phases['inertia phase'][1]:.6f} s, energy residual {result.balance.relative_residual:.1e}")
    start, start_cpu = time.perf_counter(), time.process_time()
    worst = 0.0
    completed = 0
    for throttle in np.linspace(0.1, 1.0, shifts):
        r = simulate_shift(transmission, spec, "2", "3", throttle=float(throttle))
        worst = max(worst, r.balance.relative_residual)
        completed += r.completed
    sweep, sweep_cpu = time.perf_counter() - start, time.process_time() - start_cpu
    print(f"{shifts} shifts 2->3 over throttle 10...100 %: wall {sweep:.2f} s, CPU {sweep_cpu:.2f} s (goal <= 20 s), "
          f"{completed} completed, "
          f"worst energy residual {worst:.1e}")
    # the naive baseline: the same dynamics and pressures, a fixed-step loop
    import epicyclic.dynamics.shift as shift_module
    from epicyclic.dynamics.shift import _dynamics, shift_elements  # noqa: F401  (the run's own set-up)

    captured = {}
    original = shift_module.integrate

    def capture(dynamics, omega0, mode, t_end, **kw):
        captured.update(dynamics=dynamics, omega0=omega0, mode=mode, t_end=t_end)
        return original(dynamics, omega0, mode, t_end, **kw)

    shift_module.integrate = capture
    try:
        simulate_shift(transmission, spec, "2", "3")
    finally:
        shift_module.integrate = original
    start, start_cpu = time.perf_counter(), time.process_time()
    locks, residual = naive(captured["dynamics"], captured["omega0"], captured["mode"].locked, captured["t_end"],
                            naive_step)
    naive_s, naive_cpu = time.perf_counter() - start, time.process_time() - start_cpu
    lock = next((t for name, t in locks if name == "C"), float("nan"))
    print(f"naive fixed-step RK4 at {naive_step:g} s, stick-slip per step: wall {naive_s:.2f} s, CPU {naive_cpu:.2f} s "
          f"({naive_cpu / min(cpu):.0f}x the event-based run's CPU); lock-up of C at {lock:.6f} s "
          f"(event-based {result.phases['inertia phase'][1]:.6f} s), energy residual {residual:.1e}")


if __name__ == "__main__":
    main()
