#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""Coupled sliding and spinning friction (Coulomb-Contensou friction), exact.

A flat contact that slides with speed v and spins with angular velocity w feels
a friction force F = mu N F(eps) and a friction torque T = mu N a T(eps) that
depend on each other through one number, the ratio eps = v/(a w) (Farkas,
Bartels, Unger and Wolf, 2003).  This package computes them for any
axisymmetric pressure distribution, to a few ulp, and the dynamics they imply:
a sliding, spinning disk stops both motions at the same moment.

    >>> import spinslide
    >>> F, T = spinslide.force_torque([0.1, 1.0, 10.0])   # the paper's disk
    >>> spinslide.terminal_ratio()                          # eps_0 ~ 0.653
    >>> spinslide.simulate_throw(spinslide.Hertz(), 0.4, v0=1.0, omega0=2.0).time

Built from the C++ headers of the same version (docs/python.md).
"""

import sys as _sys
import time as _time
from typing import NamedTuple as _NamedTuple

import numpy as _np

from ._core import (  # noqa: F401  (re-exported)
    Annulus,
    Boussinesq,
    Hertz,
    PatchShape,
    PlateEnding,
    PlateFixedPoint,
    PlateThrow,
    PolygonPatch,
    Profile,
    RadialProfile,
    RatioFlowZero,
    Ring,
    Scaled,
    StopResult,
    Tabulated,
    TerminalRegime,
    TerminalState,
    UniformDisk,
    WeightedSum,
    force,
    force_at_torque,
    force_derivative,
    force_torque,
    ratio_from_force,
    ratio_from_torque,
    ratio_flow_zeros,
    simulate_throw,
    simulate_throw_si,
    stop_time,
    terminal_motion,
    terminal_ratio,
    terminal_window,
    plate_terminal_points,
    throw_plate,
    torque,
    torque_at_force,
    torque_derivative,
    trajectory,
)
from . import _core

__version__: str = _core.__version__  # the VERSION file's, compiled into the module

__all__ = [
    "Annulus", "Boussinesq", "Hertz", "Profile", "RadialProfile", "RatioFlowZero", "Ring", "Scaled",
    "StopResult", "Tabulated", "TerminalRegime", "TerminalState", "UniformDisk", "WeightedSum",
    "force", "torque", "force_torque", "force_derivative", "torque_derivative",
    "torque_at_force", "ratio_from_force", "force_at_torque", "ratio_from_torque", "coupling_curve",
    "terminal_ratio", "terminal_motion", "terminal_window", "ratio_flow_zeros",
    "simulate_throw", "simulate_throw_si", "stop_time", "trajectory", "stop_results", "StopResults",
    "project_to_limit_set", "LimitProjection", "impulse_friction", "spring_history_friction",
    "FrictionResult",
    "PolygonPatch", "PatchShape", "friction_wrench", "PlanarWrench", "friction_dissipation",
    "PatchDissipation", "throw_plate", "PlateThrow", "PlateEnding", "plate_terminal_points",
    "PlateFixedPoint",
    "limit_surface_twist", "LimitSurfacePoint", "PatchProjection", "PatchImpulse",
]


class _Arrays:
    """Named arrays (a result of a vectorized call)."""

    _fields = ()

    def __init__(self, values):
        for name in self._fields:
            setattr(self, name, values[name])

    def __repr__(self):
        inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._fields)
        return f"{type(self).__name__}({inner})"


class StopResults(_Arrays):
    """The stops of many throws: arrays of the broadcast shape of v0 and omega0.

    time, distance, angle: dimensionless stop time t*, distance s* and angle;
    terminal_ratio: the limit of eps at each stop (eps_0, inf or 0).
    """

    _fields = ("time", "distance", "angle", "terminal_ratio")


class LimitProjection(_Arrays):
    """The nearest points of the limit set: force, torque (the point), sticking
    (True where the input was inside, unchanged) and ratio (eps of the curve
    point, NaN where sticking)."""

    _fields = ("force", "torque", "sticking", "ratio")


class FrictionResult(_Arrays):
    """One step of a contact law for an array of contacts: force (..., 2), torque,
    sticking, ratio (eps of the slip, NaN where sticking); for the spring law
    also the springs' new state: displacement (..., 2), twist and curve_ratio
    (pass them to the next step)."""

    _fields = ("force", "torque", "sticking", "ratio")


class PatchProjection(_Arrays):
    """A flat patch's projection onto its limit set for arrays of trials: force
    (..., 2) and torque (the limit set's units), sticking, ratio (the slip's
    |v|/(l |omega|), NaN where sticking), and the slip: slip_velocity (..., 2)
    and slip_spin, the twist whose friction wrench is the answer (zero where
    sticking)."""

    _fields = ("force", "torque", "sticking", "ratio", "slip_velocity", "slip_spin")


class PatchImpulse(PatchProjection):
    """A flat patch's impulse law for arrays of contacts: the impulse force
    (..., 2) and torque (the angular impulse about the patch origin),
    sticking, ratio, and the velocity after the step, slip_velocity (..., 2)
    and slip_spin (zero where sticking)."""


class LimitSurfacePoint(_Arrays):
    """limit_surface_twist's result: the twist (velocity (..., 2), spin) whose
    friction wrench is the limit surface's point on each wrench's ray,
    |v|^2 + (l omega)^2 = 1, and the wrench's gauge (1 on the surface)."""

    _fields = ("velocity", "spin", "gauge")


class _SpringResult(FrictionResult):
    _fields = FrictionResult._fields + ("displacement", "twist", "curve_ratio")


def coupling_curve(profile, points=257):
    """The coupled limit curve (F(eps), T(eps)) of `profile` from pure spinning
    (0, <r>) to pure sliding (1, 0): two arrays of `points` points (>= 3), eps
    spread evenly in eps/(1 + eps) so that both ends are resolved."""
    points = int(points)
    if points < 3:
        raise ValueError("spinslide.coupling_curve: points must be at least 3")
    t = _np.linspace(0.0, 1.0, points)
    with _np.errstate(divide="ignore"):
        eps = _np.where(t < 1.0, t / _np.maximum(1.0 - t, 0.0), _np.inf)
    return profile.force_torque(eps)


class _ProgressBar:
    """A progress bar on a terminal (stderr), or a line every 10 % elsewhere."""

    def __init__(self, stream=None):
        self.stream = stream if stream is not None else _sys.stderr
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.start = _time.monotonic()
        self.last_tenth = -1

    def __call__(self, done, total):
        fraction = done / total if total else 1.0
        elapsed = _time.monotonic() - self.start
        rate = done / elapsed if elapsed > 0 else 0.0
        left = (total - done) / rate if rate > 0 else float("nan")
        if self.tty:
            width = 30
            filled = int(width * fraction)
            self.stream.write(
                f"\rthrows {done}/{total} [{'#' * filled}{'.' * (width - filled)}] "
                f"{100 * fraction:5.1f} %  {rate:,.0f}/s  {left:5.1f} s left ")
            if done == total:
                self.stream.write("\n")
        elif int(10 * fraction) > self.last_tenth:
            self.last_tenth = int(10 * fraction)
            self.stream.write(f"throws {done}/{total} ({100 * fraction:.0f} %)\n")
        self.stream.flush()


def stop_results(profile, inertia_ratio, v0, omega0, threads=0, progress=False):
    """The stops of many throws on all cores (the GIL released).

    v0, omega0: the dimensionless starts (array-likes, broadcast together; each
    >= 0).  threads: worker threads, 0 for all cores.  progress: True for a
    progress bar on stderr (a line every 10 % when stderr is not a terminal),
    or a callable progress(done, total), called about every 0.1 s.  Ctrl-C
    stops the batch.  Each result equals simulate_throw's for the same start,
    bit for bit, whatever the number of threads.  Returns StopResults.
    """
    if int(threads) < 0:
        raise ValueError("spinslide.stop_results: threads must be >= 0 (0: all cores)")
    callback = _ProgressBar() if progress is True else (progress or None)
    return StopResults(_core._stop_results(profile, inertia_ratio, v0, omega0, int(threads),
                                           callback))


def project_to_limit_set(profile, force, torque, torque_weight=None, *, metric=None,
                         start_velocity=(0.0, 0.0), start_spin=0.0):
    """The nearest point of a limit set: of a round profile's, or of a flat patch's.

    A profile: project_to_limit_set(profile, force, torque, torque_weight), the
    point of L nearest to (force, torque) in (f - force)^2 + torque_weight (t -
    torque)^2, for forces in units of mu N and torques in units of mu N a (each
    >= 0, torque_weight > 0; array-likes, broadcast).  Inside L the point sticks
    (unchanged); outside it lands on the curve at ratio eps (inf at (1, 0), 0
    at (0, <r>)).  Returns LimitProjection.

    A PolygonPatch: project_to_limit_set(patch, force, torque, metric), the
    point p of the patch's limit set nearest to the trial (force (..., 2),
    torque (...)) in (p - trial)^T M (p - trial), M = metric (..., 3, 3),
    symmetric positive definite, over (F_x, F_y, tau/l).  Everything is in the
    limit set's units: the force per unit mu N, the torque about the patch
    origin per unit mu N l, l = patch.radius.  start_velocity (..., 2) and
    start_spin: the contact's last slip (the last result's slip_velocity and
    slip_spin), which only speeds the search.  Returns PatchProjection: force,
    torque, sticking, ratio (|v|/(l |omega|) of the slip, NaN where it
    sticks), and the slip, the twist (slip_velocity, slip_spin) whose friction
    wrench is the answer (zero where it sticks).  The metric may also be
    passed as the fourth argument."""
    if isinstance(profile, PolygonPatch):
        if metric is None:
            metric = torque_weight
        if metric is None:
            raise TypeError("spinslide.project_to_limit_set(patch, force, torque, metric): "
                            "a patch needs its metric")
        return PatchProjection(_core._project_patch_to_limit_set(
            profile, force, torque, metric, start_velocity, start_spin))
    if metric is not None or torque_weight is None:
        raise TypeError("spinslide.project_to_limit_set(profile, force, torque, torque_weight): "
                        "a round profile takes a torque_weight, not a metric")
    return LimitProjection(_core._project_to_limit_set(profile, force, torque, torque_weight))


def limit_surface_twist(patch, force, torque):
    """The inverse of friction_wrench on a patch's limit surface.

    For wrenches (force (..., 2) per unit mu N, torque (...) about the patch
    origin per unit mu N, in the vertices' length unit: friction_wrench's
    units), the twist whose friction wrench is the limit surface's point on
    the wrench's ray from 0, normalised to |v|^2 + (l omega)^2 = 1, and the
    wrench's gauge: 1 on the surface, below 1 inside the set, above outside.
    Returns LimitSurfacePoint(velocity (..., 2), spin (...), gauge (...)).
    A zero or non-finite wrench raises ValueError, as does one off a point
    patch's flat set."""
    return LimitSurfacePoint(_core._limit_surface_twist(patch, force, torque))


def impulse_friction(profile, velocity, spin, inverse_mass, radius=None, normal_impulse=None,
                     friction_coefficient=None, start_ratio=0.0, *, start_velocity=(0.0, 0.0),
                     start_spin=0.0):
    """The friction impulse of one step for one contact or an array of contacts.

    A profile: impulse_friction(profile, velocity, spin, inverse_mass, radius,
    normal_impulse, friction_coefficient, start_ratio=0).  velocity (..., 2):
    the relative sliding velocity before friction in the tangent plane; spin
    (...): the relative angular velocity about the normal; inverse_mass
    (..., 3, 3): the contact's inverse mass over (v_x, v_y, w); radius: the
    patch radius a >= 0; normal_impulse: the step's normal impulse >= 0;
    friction_coefficient: mu >= 0; start_ratio: the last step's ratio (0:
    none), which only speeds the search.  All broadcast together.  Returns
    FrictionResult: force is the impulse (P_x, P_y), torque the angular
    impulse L; the exact stick or slip of the coupled law.

    A PolygonPatch: impulse_friction(patch, velocity, spin, inverse_mass, *,
    normal_impulse, friction_coefficient, start_velocity=0, start_spin=0)
    (a patch has no radius: the contact's numbers by keyword).  velocity and
    spin are the patch origin's, in the patch's axes; start_velocity and
    start_spin the last step's slip.  Returns PatchImpulse: the impulse
    (force (..., 2), torque: L about the patch origin), sticking, ratio, and
    the slip (slip_velocity, slip_spin): the velocity after the step, zero
    where it sticks."""
    if isinstance(profile, PolygonPatch):
        if radius is not None:
            raise TypeError("spinslide.impulse_friction(patch, ...): a patch has no radius; pass "
                            "normal_impulse= and friction_coefficient= by keyword")
        if normal_impulse is None or friction_coefficient is None:
            raise TypeError("spinslide.impulse_friction(patch, ...) needs normal_impulse= and "
                            "friction_coefficient=")
        return PatchImpulse(_core._patch_impulse_friction(
            profile, velocity, spin, inverse_mass, normal_impulse, friction_coefficient,
            start_velocity, start_spin))
    if radius is None or normal_impulse is None or friction_coefficient is None:
        raise TypeError("spinslide.impulse_friction(profile, velocity, spin, inverse_mass, radius, "
                        "normal_impulse, friction_coefficient) needs all seven")
    return FrictionResult(_core._impulse_friction(profile, velocity, spin, inverse_mass, radius,
                                                  normal_impulse, friction_coefficient,
                                                  start_ratio))


def spring_history_friction(profile, displacement, twist, displacement_increment,
                            twist_increment, tangential_stiffness, twisting_stiffness, radius,
                            normal_force, friction_coefficient, curve_ratio=0.0):
    """One step of the spring-history (DEM) law for one or many contacts.

    displacement (..., 2), twist, curve_ratio: the springs' state from the last
    step (zeros and 0 at first contact); displacement_increment (..., 2) and
    twist_increment: this step's relative tangential displacement and rotation;
    the stiffnesses k_t and k_theta (> 0), the patch radius a > 0, the normal
    force N >= 0 and mu >= 0.  All broadcast together.  Returns a FrictionResult
    with the springs' new displacement, twist and curve_ratio."""
    return _SpringResult(_core._spring_history_friction(
        profile, displacement, twist, curve_ratio, displacement_increment, twist_increment,
        tangential_stiffness, twisting_stiffness, radius, normal_force, friction_coefficient))


class PlanarWrench(_NamedTuple):
    """A patch's friction wrench per unit mu N: force (..., 2) and torque (...)
    about the patch origin (a tuple: force, torque = friction_wrench(...))."""

    force: _np.ndarray
    torque: _np.ndarray


class PatchDissipation(_NamedTuple):
    """A patch's dissipation D per unit mu N (...), its gradient (..., 3) in
    (v_x, v_y, omega), which is minus the wrench, and its Hessian (..., 3, 3)."""

    value: _np.ndarray
    gradient: _np.ndarray
    hessian: _np.ndarray


def friction_wrench(patch, velocity, spin):
    """The exact friction wrench of a PolygonPatch moving with planar twists.

    velocity (..., 2): the velocity of the patch origin; spin (...): the
    angular velocity (counter-clockwise positive); broadcast together.
    Returns PlanarWrench(force (..., 2), torque (...)) per unit mu N, the
    torque about the patch origin in the vertices' length unit.  A zero twist
    (v = 0 and omega = 0) or a non-finite component raises ValueError."""
    return PlanarWrench(*_core._friction_wrench(patch, velocity, spin))


def friction_dissipation(patch, velocity, spin):
    """The dissipation D = integral of p |u| dA per unit mu N of a PolygonPatch
    at planar twists (as friction_wrench), with its gradient in (v_x, v_y,
    omega), -(F_x, F_y, tau), and its Hessian (+inf in every entry where it
    diverges: a line or point patch pivoting about one of its points).
    Returns PatchDissipation(value (...), gradient (..., 3), hessian (..., 3, 3))."""
    return PatchDissipation(*_core._friction_dissipation(patch, velocity, spin))
