"""Solve a train whose elements have loss models: the general solver, fed with the models' losses.

The loss models of :mod:`epicyclic.losses.element` depend on the state they
act in (the mesh friction on the tooth load and the sliding speed), and the
state on the losses.  Both are found by a fixed-point iteration around the
general solver:

1. solve without losses: the loads and speeds of every element;
2. evaluate each element's models there: its efficiency factors by source
   (mesh, bearing) and its drag torques;
3. solve with these (Brandenberger's rule applies the factors in the direction
   of the rolling power; the drag torques act on the members' shafts);
4. re-evaluate at the new loads and repeat until no factor changes by more
   than ``tolerance`` (two or three rounds: μ depends on the load as F^0.2).

The drag torques depend on the speeds only, which the losses do not change.
The batch form does the same over arrays of operating points, each round one
batch solve.

The spin losses (:class:`~epicyclic.losses.spin.SpinLosses`: open clutch drag,
pump, churning, windage, seals) are torques on shafts at the oil temperature,
given to the solver by source.  With ``temperature = "thermal"`` an outer
fixed point finds the sump temperature: solve, take the load-dependent losses,
find the ϑ where the housing sheds them plus the spin losses at ϑ
(:func:`~epicyclic.losses.thermal.steady_temperature`), re-evaluate the spin
losses there and solve again, until ϑ changes by less than
:data:`TEMPERATURE_TOLERANCE` (at most :data:`MAX_THERMAL_ITERATIONS` rounds).

References
----------
Brandenberger 1952, eqs. 3', 7 (η0 in the direction of the rolling power);
ISO/TR 14179-2:2001 (μ_mZ from the load: evaluated at the state it acts in);
ISO/TR 14179-1:2001 (thermal equilibrium P_V = P_Q).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from dataclasses import replace

from ..model.elements import HOUSING
from ..model.operating_point import OperatingPoint
from ..model.train import GearTrain
from ..solver import solve
from ..solver.batch import BatchSolution, solve_batch
from .element import ElementLosses
from .errors import LossModelError
from .spin import SpinLosses, SpinState
from .thermal import steady_temperature

__all__ = ["solve_with_losses", "solve_batch_with_losses", "TOLERANCE", "MAX_ITERATIONS",
           "TEMPERATURE_TOLERANCE", "MAX_THERMAL_ITERATIONS"]

#: Largest change of any efficiency factor between two rounds at convergence.
TOLERANCE = 1e-12
#: Rounds of the fixed-point iteration before giving up.
MAX_ITERATIONS = 30
#: Largest change of the sump temperature (K) between two thermal rounds at convergence.
TEMPERATURE_TOLERANCE = 1e-7
#: Rounds of the thermal fixed point before giving up.
MAX_THERMAL_ITERATIONS = 40


def _models(train: GearTrain, losses: Mapping[str, ElementLosses]) -> dict[str, ElementLosses]:
    """The models of the train's elements (a transmission's models apply to every gear)."""
    names = {e.name: e for e in train.elements}
    out = {}
    for name, model in losses.items():
        if not isinstance(model, ElementLosses):
            raise LossModelError(f"losses[{name!r}] must be an ElementLosses, got {type(model).__name__}.")
        if name not in names:
            raise LossModelError(
                f"losses: the train has no element {name!r}; its elements are "
                f"{', '.join(repr(n) for n in names)}."
            )
        element = names[name]
        if type(element) is not type(model.element) or element.shafts != model.element.shafts:
            raise LossModelError(
                f"losses[{name!r}] was built for another element (shafts {model.element.shafts}, here "
                f"{element.shafts}); build it from this train's element."
            )
        out[name] = model
    return out


def _state(models, speeds, port_torques, viscosity=None):
    """Factors and drag torques of every model at the given element states (η_oil per point, if given)."""
    efficiencies, torques = {}, {}
    for name, model in models.items():
        state = model.evaluate(speeds(model), port_torques(model), viscosity)
        efficiencies[name] = dict(state.factors)
        torques[name] = dict(state.torques)
    return efficiencies, torques


def _merged(loss_torques, spin: SpinState | None):
    """The models' drag torques and the spin losses' torques by source, in one ``loss_torques``."""
    if spin is None or not spin.torques:
        return loss_torques
    out = {name: dict(value) for name, value in loss_torques.items()}
    for host, by_source in spin.torques.items():
        own = out.pop(host, None)
        merged = {"drag": own} if own else {}
        merged.update({source: dict(shafts) for source, shafts in by_source.items()})
        out[host] = merged
    return out


def _viscosity(spin: SpinState | None):
    """η_oil (mPa·s) at the spin state's oil temperature, for Schlenk's friction; None without an oil."""
    return None if spin is None or spin.viscosity is None else spin.viscosity


def _checked_spin(spin, train: GearTrain, input: str | None) -> SpinLosses | None:
    if spin is None:
        return None
    if not isinstance(spin, SpinLosses):
        raise LossModelError(f"losses: spin must be a SpinLosses, got {type(spin).__name__}.")
    if spin.is_empty:
        return None
    spin.check(train, input)
    return spin


def _thermal_round(spin: SpinLosses, state, spin_state: SpinState, speeds, shape, train, gear, input):
    """The next sump temperature: where the housing sheds the load-dependent losses plus the spin losses."""
    load_dependent = np.maximum(np.nan_to_num(np.asarray(state.loss, dtype=float) - spin_state.total), 0.0)

    def loss(temperature):
        return load_dependent + spin.evaluate(speeds, temperature, train=train, gear=gear, input=input).total

    return steady_temperature(spin.housing, loss, shape)


def _change(old, new) -> float:
    if old is None:
        return np.inf
    change = 0.0
    for name, factors in new.items():
        for source, value in factors.items():
            change = max(change, float(np.max(np.abs(np.asarray(value) - np.asarray(old[name][source])),
                                              initial=0.0)))
    return change


def solve_with_losses(train: GearTrain, operating_point: OperatingPoint, losses: Mapping[str, ElementLosses], *,
                      tolerance: float = TOLERANCE, max_iterations: int = MAX_ITERATIONS,
                      spin: SpinLosses | None = None, gear: str | None = None, input: str | None = None):
    """Solve ``train`` at an operating point with the elements' loss models.

    Parameters
    ----------
    train : GearTrain
    operating_point : OperatingPoint
    losses : mapping element name → ElementLosses
        Elements without a model keep their own η0.
    tolerance : float
        Convergence of the efficiency factors.
    max_iterations : int
    spin : SpinLosses, optional
        The spin losses (clutch drag, pump, churning, windage, seals) at the oil temperature,
        fixed or from the thermal balance.
    gear : str, optional
        The gear ``train`` is in (a pump pressure by gear).
    input : str, optional
        The transmission's input (drives a pump that names no shaft).

    Returns
    -------
    Solution
        Each element's losses split by source in ``elements[name].loss_sources``
        (``mesh``, ``bearing``, ``drag``, ``clutch_drag``, ``churning``, ``windage``, W), the
        pump's and seals' in ``housing_loss_sources``, the oil temperature in ``oil_temperature``.

    Raises
    ------
    LossModelError
        A model for an element the train does not have, no convergence, or no steady sump
        temperature.
    """
    models = _models(train, losses)
    spin = _checked_spin(spin, train, input)
    if spin is None and not models:
        return solve(train, operating_point)
    state = solve(train, operating_point, lossless=True)
    oil = None if spin is None else _OilState(spin, {s: np.asarray(state.shafts[s].speed) for s in train.shafts
                                                     if s != HOUSING}, (), train, gear, input)

    def speeds(model):
        e = state.elements[model.name]
        return {p: e.speeds[p] for p in model.ports if p != "housing"}

    def torques(model):
        e = state.elements[model.name]
        return {p: e.torques[p] for p in model.ports if p != "housing"}

    def run(efficiencies, loss_torques):
        return solve(train, operating_point, efficiencies=efficiencies or None, loss_torques=loss_torques or None)

    for state, temperature in _fixed_point(models, oil, speeds, torques, run, tolerance, max_iterations, ""):
        pass
    if oil is None:
        return state
    warning = spin.oil.extrapolation_warning(float(temperature)) if spin.oil is not None else None
    viscosity = float(spin.oil.dynamic_viscosity(float(temperature))) if spin.oil is not None else None
    return state.replace(oil_temperature=float(temperature), oil_viscosity=viscosity,
                         **({"warnings": (*state.warnings, warning)} if warning else {}))


class _OilState:
    """The spin losses at the current oil temperature, and the thermal balance's next temperature."""

    def __init__(self, spin: SpinLosses, speeds, shape, train, gear, input):
        self.spin, self.speeds, self.shape = spin, speeds, shape
        self.where = dict(train=train, gear=gear, input=input)
        self.temperature = np.full(shape, _start_temperature(spin)) if shape else np.asarray(_start_temperature(spin))
        self.state = spin.evaluate(speeds, self.temperature, **self.where)

    def update(self, solution) -> float:
        """Move to the temperature of the heat balance at ``solution``'s losses; the change, K (0 if fixed)."""
        if not self.spin.thermal:
            return 0.0
        new = _thermal_round(self.spin, solution, self.state, self.speeds, self.shape, **self.where)
        change = float(np.max(np.abs(new - self.temperature), initial=0.0))
        self.temperature = new
        self.state = self.spin.evaluate(self.speeds, new, **self.where)
        return change


def _fixed_point(models, oil, speeds, torques, run, tolerance, max_iterations, where):
    """Yield (state, oil temperature) of each round until the factors and the temperature settle.

    One loop for both fixed points: each round evaluates the mesh models at the last state and the
    oil temperature, solves, and moves the temperature to the heat balance of that solution; once it
    moves by no more than :data:`TEMPERATURE_TOLERANCE` it stays, and the factors settle at it.
    """
    previous, settled = None, False
    rounds = max_iterations + (MAX_THERMAL_ITERATIONS if oil is not None and oil.spin.thermal else 0)
    for _ in range(rounds):
        spin_state = None if oil is None else oil.state
        temperature = None if oil is None else oil.temperature
        efficiencies, loss_torques = _state(models, speeds, torques, _viscosity(spin_state))
        state = run(efficiencies, _merged(loss_torques, spin_state))
        yield state, temperature
        mesh_change = _change(previous, efficiencies) if models else 0.0
        previous = efficiencies
        if not settled:  # the temperature moves until it settles, then stays (the factors settle at it)
            settled = oil is None or oil.update(state) <= TEMPERATURE_TOLERANCE
        if mesh_change <= tolerance and settled:
            return
    if settled:
        raise LossModelError(
            f"losses: the load-dependent efficiencies did not settle in {max_iterations} rounds{where}; the train "
            "is too close to self-locking for the friction model (check the friction inputs)."
        )
    raise _no_thermal_fixed_point()


def _start_temperature(spin: SpinLosses) -> float:
    """The given oil temperature, or the first guess of the thermal balance (60 K above the air)."""
    if spin.temperature is not None:
        return spin.temperature
    return spin.housing.ambient + 60.0 if spin.housing is not None else 80.0


def _no_thermal_fixed_point() -> LossModelError:
    return LossModelError(
        f"losses: the sump temperature did not settle in {MAX_THERMAL_ITERATIONS} rounds of the thermal "
        "balance (losses and temperature keep pushing each other); give a fixed [lubricant] temperature or check "
        "the [housing] and the loss inputs."
    )


def solve_batch_with_losses(train: GearTrain, losses: Mapping[str, ElementLosses], *,
                            speeds: Mapping[str, object], torques: Mapping[str, object] | None = None,
                            powers: Mapping[str, object] | None = None, drives: Sequence[str] = (),
                            loads: Sequence[str] = (), tolerance: float = TOLERANCE,
                            max_iterations: int = MAX_ITERATIONS, spin: SpinLosses | None = None,
                            gear: str | None = None, input: str | None = None) -> BatchSolution:
    """:func:`solve_with_losses` over arrays of operating points (see :func:`~epicyclic.solver.batch.solve_batch`).

    Each round is one batch solve with per-point efficiency factors and drag torques,
    evaluated at the state of the previous round (the first from a solve with unit
    mesh factors), until no factor changes by more than ``tolerance``.

    Parameters
    ----------
    train : GearTrain
        The train.
    losses : mapping element name → ElementLosses
        Loss models; elements without one keep their own η0.
    speeds, torques, powers : mapping shaft → array_like
        Given speeds (1/min), torques (N·m), powers (W); arrays broadcast to one shape.
    drives, loads : sequence of str
        Driving and driven shafts, as in :class:`~epicyclic.OperatingPoint`.
    tolerance : float, default 1e-12
        Largest change of an efficiency factor between rounds at convergence.
    max_iterations : int, default 30
        Most rounds.
    spin : SpinLosses, optional
        Spin losses at the oil temperature (fixed, or the thermal balance at every point).
    gear : str, optional
        The gear ``train`` is in (a pump pressure by gear).
    input : str, optional
        The transmission's input (drives a pump that names no shaft).

    Returns
    -------
    BatchSolution
        Arrays over the points (speeds, torques, powers, efficiency, self-locking).

    Raises
    ------
    LossModelError
        A model for an element the train does not have, or no convergence within
        ``max_iterations`` (a train too close to self-locking).

    References
    ----------
    Brandenberger 1952, eqs. 3', 7; ISO/TR 14179-2:2001.
    """
    models = _models(train, losses)
    common = dict(speeds=speeds, torques=torques, powers=powers, drives=drives, loads=loads)
    spin = _checked_spin(spin, train, input)
    if spin is None and not models:
        return solve_batch(train, **common)
    state = solve_batch(train, efficiencies={name: {"mesh": 1.0} for name in models} or None, **common)
    oil = None if spin is None else _OilState(spin, {s: state.speeds[s] for s in train.shafts if s != HOUSING},
                                              state.shape, train, gear, input)

    def element_speeds(model):
        return {p: state.speeds[shaft] for p, shaft in model.ports.items() if p != "housing"}

    def element_torques(model):
        return {p: state.port_torques[(model.name, p)] for p in model.ports if p != "housing"}

    def run(efficiencies, loss_torques):
        return solve_batch(train, efficiencies=efficiencies or None, loss_torques=loss_torques or None, **common)

    for state, temperature in _fixed_point(models, oil, element_speeds, element_torques, run, tolerance,
                                           max_iterations, " at some operating points"):
        pass
    return state if oil is None else replace(state, oil_temperature=np.array(temperature))
