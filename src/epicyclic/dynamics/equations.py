"""Equations of motion of a gear train whose shift elements stick or slip.

The state is the vector ω of the moving shafts' angular velocities (rad/s).  With the mass
matrix J of the train's kinetic energy (:class:`~epicyclic.dynamics.Inertias`), the external
torques M (drive, load, the slipping elements' friction) and the reactions of the constraints,

    J ω̇ + G λ = M,        C ω̇ = 0,

where C holds one Willis row per planetary set or stage (the solver's constraint matrix, see
:attr:`epicyclic.solver.assembly.TrainMatrices.kinematics`), one row ω_first − ω_second per
sticking clutch or brake, and a row for an output held at its speed; λ are the torques the
shafts exert on the constraints (a set's sun torque, a sticking element's torque, the
dynamometer's torque).  The column of G of a set is its torque split, (1, −i0 η0^w, −(1 − i0 η0^w))
on (sun, ring, carrier): the engine's loss rule (Brandenberger 1952, eq. 7) with w the direction of
the rolling power λ (ω_sun − ω_carrier), found so that it agrees with its own solution (the quasi-
static rule of :mod:`epicyclic.solver`, applied at each instant).  Without losses G = Cᵀ and the
constraints do no work; with losses the power a set absorbs, λ (ω_a − k_b ω_b − k_c ω_c) ≥ 0, is
its mesh loss.  The number of degrees of freedom is the number of shafts less the rank of C: it
changes as elements lock or slip, and so does the system (one factorisation per mode and loss
pattern, cached).

A slipping element carries its torque T against its slip, −T sgn(Δω) on the first shaft and
+T sgn(Δω) on the second; at Δω = 0 the direction is the one it breaks away in.

References
----------
Brandenberger 1952, eq. 7 (losses by the direction of rolling power); Benford, H. L., Leising,
M. B.: *The lever analogy: a new tool in transmission analysis*, SAE 810102 (1981) (a shift as a
change of the lever's constraints); Hairer, E., Wanner, G.: *Solving Ordinary Differential
Equations II*, 2nd ed., Springer 1996, §VII.1 (index-1 form of constrained mechanical systems,
the saddle-point system of accelerations and multipliers).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np
import scipy.linalg

from ..model.elements import Brake
from ..model.train import GearTrain
from ..solver.assembly import matrices
from .drive import HeldSpeed
from .errors import DynamicsError
from .friction import Freewheel, WetElement
from .inertia import Inertias
from .pressure import PressureProfile

__all__ = ["TrainDynamics", "Mode", "Evaluation", "RELATIVE_SPEED_ZERO", "REVERSAL_BAND"]

#: A set's speed relative to its carrier below this share of the largest shaft speed is round-off of a set
#: that turns as a block: it rolls no power (w = 0), as the static solver's exact speed classes say.
RELATIVE_SPEED_ZERO = 1e-9
#: Speed of a set relative to its carrier (rad/s) below which its loss exponent w goes linearly through zero
#: (continuous across the reversal of its rolling power): 0.5 rad/s ≈ 5 1/min, stated default.
REVERSAL_BAND = 0.5


@dataclass(frozen=True)
class Mode:
    """Which elements stick, and the direction each slipping element slips (or breaks away) in."""

    locked: frozenset[str]
    signs: Mapping[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "signs", MappingProxyType(dict(self.signs)))


@dataclass(frozen=True, eq=False)
class Evaluation:
    """Accelerations, reactions and powers of one state (SI units)."""

    accelerations: np.ndarray  # ω̇ per moving shaft, rad/s²
    lever_torques: np.ndarray  # λ per set or stage (its sun/first torque), N·m
    element_torques: dict  # element → torque the first shaft exerts on it (sticking: the reaction), N·m
    element_slips: dict  # element → ω_first − ω_second, rad/s
    element_powers: dict  # element → slip power T |Δω| ≥ 0, W
    drive_torque: float
    load_torque: float  # torque the output exerts on the load (held: the dynamometer's), N·m
    input_power: float
    load_power: float
    mesh_power: float
    pattern: tuple[float, ...]  # the loss exponent w of every set or stage (fractional inside the reversal band)


@dataclass(frozen=True, eq=False)
class TrainDynamics:
    """A train with its inertias, shift elements, pressures, drive and load: the right-hand side of the motion.

    Parameters
    ----------
    train : GearTrain
        Its engaged flags are ignored (a :class:`Mode` says which elements stick).
    input, output : str
        The driven and the loaded shaft.
    inertias : Inertias
    elements : mapping name → WetElement or Freewheel
        Models of the clutches and brakes; an element without a model is open and carries nothing.
    pressures : mapping name → PressureProfile
        The pressure of every wet element (missing: 0).
    drive : Engine or TorqueTrace
    load : OutputTorque, HeldSpeed or VehicleLoad

    Raises
    ------
    DynamicsError
        A model for an element the train does not have, a freewheel on a planetary set, or a shaft that
        can move with no inertia (the motion would be undetermined).
    """

    train: GearTrain
    input: str
    output: str
    inertias: Inertias
    elements: Mapping[str, Any]
    pressures: Mapping[str, PressureProfile]
    drive: Any
    load: Any
    reversal_band: float = REVERSAL_BAND

    def __post_init__(self) -> None:
        if isinstance(self.reversal_band, bool) or not isinstance(self.reversal_band, (int, float)) \
                or not 0 < self.reversal_band <= 100:
            raise DynamicsError(f"dynamics: reversal_band must be in (0, 100] rad/s, got {self.reversal_band!r:.40}.")
        shift = {e.name: e for e in self.train.shift_elements}
        for name, model in self.elements.items():
            if name not in shift:
                raise DynamicsError(f"dynamics: {name!r} is not a clutch or brake of the train; shift elements are "
                                    f"{', '.join(repr(s) for s in shift) or 'none'}.")
            if not isinstance(model, (WetElement, Freewheel)):
                raise DynamicsError(f"dynamics: element {name!r} must be a WetElement or Freewheel model.")
        for name in self.pressures:
            if not isinstance(self.elements.get(name), WetElement):
                raise DynamicsError(f"dynamics: a pressure is given for {name!r}, which has no wet clutch model "
                                    "([clutch.capacity]).")
        object.__setattr__(self, "elements", MappingProxyType(dict(self.elements)))
        object.__setattr__(self, "pressures", MappingProxyType(dict(self.pressures)))
        moving = self.train.moving_shafts
        index = {s: k for k, s in enumerate(moving)}
        for role in ("input", "output"):
            if getattr(self, role) not in index:
                raise DynamicsError(f"dynamics: {role} {getattr(self, role)!r} is not a moving shaft of the train.")
        open_train = self.train.with_engaged([])
        mats = matrices(open_train, [self.input, self.output])
        self._set("levers", mats.levers)
        self._set("index", index)
        self._set("gear_rows", np.array(mats.kinematics, dtype=float).reshape(len(mats.levers), len(moving)))
        self._set("lever_columns", [tuple(index.get(s, -1) for s in lever.shafts) for lever in mats.levers])
        self._set("element_columns", {name: (index[e.first], index.get(e.second, -1)) if not isinstance(e, Brake)
                                      else (index[e.shaft], -1) for name, e in shift.items()})
        mass = self.inertias.matrix(self.train)
        mass[index[self.input], index[self.input]] += getattr(self.drive, "inertia", 0.0)
        mass[index[self.output], index[self.output]] += getattr(self.load, "inertia", 0.0)
        self._set("mass", mass)
        self._set("held", isinstance(self.load, HeldSpeed))
        self._set("cache", {})
        self._check_inertia()

    def _set(self, name: str, value: Any) -> None:
        object.__setattr__(self, name, value)

    def _check_inertia(self) -> None:
        rows = self.gear_rows
        basis = scipy.linalg.null_space(rows) if rows.size else np.eye(len(self.index))
        if basis.shape[1] == 0:
            return
        reduced = basis.T @ self.mass @ basis
        eig = np.linalg.eigvalsh(reduced)
        if eig[0] <= 1e-12 * max(1.0, float(np.max(np.abs(self.mass)))):
            vector = basis @ np.linalg.eigh(reduced)[1][:, 0]
            moving = [s for s, k in self.index.items() if abs(vector[k]) > 1e-6]
            raise DynamicsError(
                "dynamics: the train can move without kinetic energy (shaft(s) "
                f"{', '.join(repr(s) for s in moving)} have no inertia); give [dynamics.inertia] for them "
                "(kg m^2), e.g. 0.001.")

    # ------------------------------------------------------------------ structure
    @property
    def shafts(self) -> tuple[str, ...]:
        """The moving shafts, in the order of ω."""
        return tuple(self.index)

    def kinetic_energy(self, omega: np.ndarray) -> float:
        """½ ωᵀ J ω, J."""
        return 0.5 * float(omega @ self.mass @ omega)

    def constraints(self, locked: frozenset[str]) -> np.ndarray:
        """C of a mode: the Willis rows, one row per sticking element, the held output's row."""
        rows = [self.gear_rows]
        for name in sorted(locked):
            row = np.zeros(len(self.index))
            first, second = self.element_columns[name]
            row[first] = 1.0
            if second >= 0:
                row[second] = -1.0
            rows.append(row[None, :])
        if self.held:
            row = np.zeros(len(self.index))
            row[self.index[self.output]] = 1.0
            rows.append(row[None, :])
        return np.vstack(rows)

    def degrees_of_freedom(self, locked: frozenset[str]) -> int:
        """Speeds still free in the mode (the held output counts as a constraint)."""
        c = self.constraints(locked)
        return len(self.index) - int(np.linalg.matrix_rank(c))

    def _factors(self, k: int, w: float) -> tuple[float, float]:
        """(k_b, k_c) = (i0 η0^w, 1 − i0 η0^w) of lever k; w may be fractional inside the reversal band."""
        lever = self.levers[k]
        if w in (-1.0, 0.0, 1.0):
            return lever.factors(int(w))
        k_b = lever.ratio * lever.efficiency ** w
        return k_b, 1.0 - k_b

    def _system(self, locked: frozenset[str], pattern: tuple[float, ...]):
        key = (locked, pattern)
        found = self.cache.get(key)
        if found is not None:
            return found
        n = len(self.index)
        regular = self.cache.get(("regular", locked))
        if regular is None:
            c = self.constraints(locked)
            regular = self.cache[("regular", locked)] = (c, bool(np.linalg.matrix_rank(c) == c.shape[0]))
        c, full_rank = regular
        g = c.T.copy()
        for k, w in enumerate(pattern):
            k_b, k_c = self._factors(k, w)
            column = np.zeros(n)
            for col, coef in zip(self.lever_columns[k], (1.0, -k_b, -k_c)):
                if col >= 0:
                    column[col] += coef
            g[:, k] = column
        m = c.shape[0]
        a = np.zeros((n + m, n + m))
        a[:n, :n] = self.mass
        a[:n, n:] = g
        a[n:, :n] = c
        if not full_rank:  # redundant locking: the torque split is statically indeterminate
            # the split of least Σ (port torque)² as the static solver gives it: a set's ports carry
            # λ (1, k_b, k_c), a clutch's or brake's λ (1, 1); the minimum-norm solution in those weights
            weights = np.ones(m)
            for k in range(len(self.levers)):
                k_b, k_c = self._factors(k, pattern[k])
                weights[k] = math.sqrt(1.0 + k_b * k_b + k_c * k_c)
            weights[len(self.levers):len(self.levers) + len(locked)] = math.sqrt(2.0)
            scaled = a.copy()
            scaled[:, n:] /= weights
            inverse = np.linalg.pinv(scaled)
            inverse[n:, :] /= weights[:, None]
            found = (inverse[:, :n].copy(), g)
        else:
            try:
                inverse = np.linalg.inv(a)
                if not np.all(np.isfinite(inverse)):
                    raise np.linalg.LinAlgError
            except np.linalg.LinAlgError:
                inverse = np.linalg.pinv(a)
            found = (inverse[:, :n].copy(), g)  # the right-hand side is zero in the constraint rows
        if all(w in (-1.0, 0.0, 1.0) for w in pattern):  # the band's fractional systems are not kept
            self.cache[key] = found
        return found

    def breakpoints(self) -> tuple[float, ...]:
        """The corners of every pressure profile and of time tables of the drive and load, s."""
        times = {t for profile in self.pressures.values() for t, _ in profile.points}
        for source in (self.drive, self.load):
            if type(source).__name__ in ("TorqueTrace", "OutputTorque"):
                times |= {x for x, _ in source.rows}
        return tuple(sorted(times))

    # ------------------------------------------------------------------ evaluation
    def pressure(self, name: str, t: float) -> float:
        """The pressure of element ``name`` at time t, Pa (0 without a profile).

        Parameters
        ----------
        name : str
        t : float
            s.

        Returns
        -------
        float
        """
        profile = self.pressures.get(name)
        return profile(t) if profile is not None else 0.0

    def static_capacity(self, name: str, t: float) -> float:
        """The torque a wet element holds while sticking at time t (infinite for a freewheel), N·m.

        Parameters
        ----------
        name : str
        t : float
            s.

        Returns
        -------
        float
        """
        model = self.elements.get(name)
        if isinstance(model, WetElement):
            return model.static_capacity(self.pressure(name, t))
        return math.inf if isinstance(model, Freewheel) else 0.0

    def slip(self, name: str, omega: np.ndarray) -> float:
        """ω_first − ω_second of element ``name``, rad/s.

        Parameters
        ----------
        name : str
        omega : ndarray
            rad/s per moving shaft.

        Returns
        -------
        float
        """
        first, second = self.element_columns[name]
        return omega[first] - (omega[second] if second >= 0 else 0.0)

    def evaluate(self, t: float, omega: np.ndarray, mode: Mode, pattern: tuple[float, ...] | None = None) -> Evaluation:
        """The accelerations and reactions at time t in ``mode``, the loss pattern agreeing with its own torques.

        Parameters
        ----------
        t : float
            s.
        omega : ndarray
            rad/s per moving shaft.
        mode : Mode
        pattern : tuple of float, optional
            The loss exponents to start from (their signs; default: the last ones used).

        Returns
        -------
        Evaluation

        References
        ----------
        Brandenberger 1952, eq. 7 (w = sign of the rolling power).
        """
        omega = np.asarray(omega, dtype=float)
        n = len(self.index)
        rhs_torques = np.zeros(n)
        i_in, i_out = self.index[self.input], self.index[self.output]
        drive = float(self.drive.torque(omega[i_in], t))
        rhs_torques[i_in] += drive
        load = 0.0 if self.held else float(self.load.torque(omega[i_out], t))
        rhs_torques[i_out] -= load
        torques, slips, powers = {}, {}, {}
        for name, model in self.elements.items():
            if name in mode.locked:
                continue
            s = self.slip(name, omega)
            slips[name] = s
            if isinstance(model, Freewheel):
                torques[name], powers[name] = 0.0, 0.0
                continue
            sign = mode.signs.get(name, 0.0)  # fixed within a mode: smooth up to the lock-up event
            if sign == 0.0 and s != 0.0:
                sign = math.copysign(1.0, s)
            tau = model.torque(self.pressure(name, t), s) * sign
            first, second = self.element_columns[name]
            rhs_torques[first] -= tau
            if second >= 0:
                rhs_torques[second] += tau
            torques[name] = tau
            powers[name] = tau * s  # = T |Δω| within the mode, smooth through the lock-up event
        key = ("pattern", mode.locked)
        levers = len(self.levers)
        # the rolling direction of each set: ±1 outside the reversal band, rel/band inside it (the loss
        # exponent goes continuously through 0 where the set's speed relative to its carrier reverses)
        speed_floor = RELATIVE_SPEED_ZERO * float(np.max(np.abs(omega))) if omega.size else 0.0
        directions = []
        for k in range(levers):
            a, _, c = self.lever_columns[k]
            rel = (omega[a] if a >= 0 else 0.0) - (omega[c] if c >= 0 else 0.0)
            if abs(rel) <= speed_floor:  # a set turning as a block (or at rest) rolls nothing
                directions.append(0.0)
            elif self.levers[k].efficiency == 1.0 or abs(rel) >= self.reversal_band:
                directions.append(math.copysign(1.0, rel))
            else:
                directions.append(rel / self.reversal_band)
        signs = self.cache.get(key, (0.0,) * levers) if pattern is None else tuple(
            math.copysign(1.0, w) if w else 0.0 for w in pattern)  # the sign of each set's torque λ
        seen: set = set()
        for _ in range(2 * levers + 2):
            current = tuple(d * g_sign for d, g_sign in zip(directions, signs))
            inverse, g = self._system(mode.locked, current)
            x = inverse @ rhs_torques
            lam = x[n:]
            new = tuple(0.0 if lam[k] == 0.0 else math.copysign(1.0, lam[k]) for k in range(levers))
            if new == signs:
                break
            if new in seen:  # no sign agrees with itself: the flipping sets carry (almost) no torque
                flipping = {k for old in seen for k in range(levers) if old[k] != new[k]}
                signs = tuple(0.0 if k in flipping else w for k, w in enumerate(new))
                current = tuple(d * g_sign for d, g_sign in zip(directions, signs))
                inverse, g = self._system(mode.locked, current)
                x = inverse @ rhs_torques
                lam = x[n:]
                break
            seen.add(signs)
            signs = new
        self.cache[key] = signs
        accelerations = x[:n]
        for j, name in enumerate(sorted(mode.locked)):
            torques[name] = float(lam[levers + j])
            slips[name] = 0.0
            powers[name] = 0.0
        mesh = float(lam[:levers] @ (g[:, :levers].T @ omega)) if levers else 0.0
        if self.held:
            load = float(lam[-1])
        pattern = current
        return Evaluation(accelerations, lam[:levers].copy(), torques, slips, powers, drive, load,
                          drive * omega[i_in], load * omega[i_out], mesh, pattern)
