#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""The dynamics against tests/reference/throw_reference.csv (nested quadrature
in 100-digit arithmetic), against scipy's solve_ivp, and the batch API."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import spinslide
from conftest import relative, rows

PROFILES = {
    "uniform_disk": spinslide.UniformDisk,
    "hertz": spinslide.Hertz,
    "boussinesq": spinslide.Boussinesq,
    "cd_annulus": lambda: spinslide.Annulus(0.125),
    "ring_and_core": lambda: spinslide.WeightedSum(
        [(0.75, spinslide.Ring()), (0.25, spinslide.Scaled(spinslide.UniformDisk(), 0.125))]),
}


def test_throws_against_the_quadrature_reference():
    """1e-12 relative, the C++ tests' bound; the terminal ratio to 1e-14."""
    table = rows("throw_reference.csv")
    worst = {"time": 0.0, "distance": 0.0, "angle": 0.0, "ratio": 0.0}
    for r in table:
        p = PROFILES[r["profile"]]()
        g, v0, w0 = (float.fromhex(r[k]) for k in ("gamma", "v0", "omega0"))
        s = spinslide.simulate_throw(p, g, v0, w0)
        assert spinslide.stop_time(p, g, v0, w0) == s.time
        for key in ("time", "distance", "angle"):
            worst[key] = max(worst[key], relative(getattr(s, key), r[key]))
        if float(r["eps_final"]) != 0:
            worst["ratio"] = max(worst["ratio"], relative(s.terminal.ratio, r["eps_final"]))
    print("largest relative errors against throw_reference.csv:", worst)
    assert len(table) >= 80
    assert max(worst["time"], worst["distance"], worst["angle"]) <= 1e-12
    assert worst["ratio"] <= 1e-14


def test_a_throw_against_solve_ivp():
    """dv/dt = -F(v/w), dw/dt = -T(v/w)/gamma integrated by scipy (DOP853)
    until both speeds are 1e-9 of their start: the same stop, distance and
    angle to the ODE solver's accuracy."""
    gamma, v0, w0 = 0.5, 1.3, 2.1
    disk = spinslide.UniformDisk()

    def rhs(_, y):
        v, w, _s, _a = y
        f, t = disk.force_torque(max(v, 0.0) / max(w, 1e-300))
        return [-f, -t / gamma, v, w]

    def nearly_stopped(_, y):
        return max(y[0] / v0, y[1] / w0) - 1e-9

    nearly_stopped.terminal = True
    sol = solve_ivp(rhs, (0, 10), [v0, w0, 0, 0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=nearly_stopped)
    exact = spinslide.simulate_throw(disk, gamma, v0, w0)
    t_end = sol.t_events[0][0]
    assert t_end == pytest.approx(exact.time, rel=1e-8)
    assert sol.y[2, -1] == pytest.approx(exact.distance, rel=1e-8)
    assert sol.y[3, -1] == pytest.approx(exact.angle, rel=1e-8)
    ratio = sol.y[0, -1] / sol.y[1, -1]
    assert ratio == pytest.approx(spinslide.terminal_ratio(), rel=1e-4)


def test_trajectory_arrays_and_the_observer():
    h = spinslide.Hertz()
    r = spinslide.simulate_throw(h, 0.4, 1.0, 2.0, trajectory=True)
    tr = r.trajectory
    assert set(tr) == {"time", "speed", "spin", "ratio", "distance", "angle"}
    assert tr["time"][-1] == r.time and tr["speed"][-1] == 0 and tr["spin"][-1] == 0
    assert np.all(np.diff(tr["time"]) > 0)
    times = np.linspace(0, 1.1 * r.time, 200)
    sampled = spinslide.trajectory(h, 0.4, 1.0, 2.0, times)
    assert np.array_equal(sampled["time"], times)
    assert np.all(np.diff(sampled["speed"]) <= 0) and sampled["distance"][-1] == r.distance
    assert spinslide.simulate_throw(h, 0.4, 1.0, 2.0).trajectory is None
    # At the integrator's own steps, trajectory() gives the observer's samples.
    again = spinslide.trajectory(h, 0.4, 1.0, 2.0, tr["time"])
    for key in ("speed", "spin", "distance", "angle"):
        assert np.array_equal(again[key], tr[key])


def test_si_throw_is_the_dimensionless_one_scaled():
    a, mu, g = 0.06, 0.3, 9.81
    v0, w0 = 1.2, 40.0
    si = spinslide.simulate_throw_si(spinslide.Hertz(), radius=a, friction_coefficient=mu,
                                     gravity=g, inertia_ratio=0.4, v0=v0, omega0=w0)
    d = spinslide.simulate_throw(spinslide.Hertz(), 0.4, v0 / (mu * math.sqrt(g * a)),
                                 w0 * math.sqrt(a / g) / mu)
    assert si.time == pytest.approx(d.time * math.sqrt(a / g), rel=1e-14)
    assert si.distance == pytest.approx(d.distance * mu * a, rel=1e-14)
    assert si.angle == pytest.approx(d.angle * mu, rel=1e-14)


def test_stop_results_are_simulate_throw_bit_for_bit_on_any_number_of_threads():
    p = spinslide.Boussinesq()
    v0 = np.linspace(0.05, 3.0, 60).reshape(6, 10)
    w0 = np.linspace(0.1, 2.0, 10)  # broadcast against v0's rows
    one = spinslide.stop_results(p, 0.6, v0, w0, threads=1)
    two = spinslide.stop_results(p, 0.6, v0, w0, threads=2)
    assert one.time.shape == (6, 10)
    for k in ("time", "distance", "angle", "terminal_ratio"):
        assert np.array_equal(getattr(one, k), getattr(two, k), equal_nan=True)
    for i in (0, 17, 59):
        s = spinslide.simulate_throw(p, 0.6, v0.flat[i], w0[i % 10])
        assert (one.time.flat[i], one.distance.flat[i], one.angle.flat[i]) == (
            s.time, s.distance, s.angle)


def test_stop_results_progress_and_interruption():
    calls = []
    spinslide.stop_results(spinslide.UniformDisk(), 0.5, np.linspace(0.1, 2, 500), 1.0,
                           progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (500, 500)

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop()

    with pytest.raises(Stop):
        spinslide.stop_results(spinslide.UniformDisk(), 0.5, np.linspace(0.1, 2, 5000), 1.0,
                               progress=stop)


def test_terminal_motion_and_the_flow():
    disk = spinslide.UniformDisk()
    state = spinslide.terminal_motion(disk, 0.5)
    assert state.regime == spinslide.TerminalRegime.sliding_and_spinning
    assert state.ratio == pytest.approx(spinslide.terminal_ratio(), rel=1e-15)
    assert spinslide.terminal_motion(disk, 0.2).regime == spinslide.TerminalRegime.pure_sliding
    assert spinslide.terminal_motion(disk, 0.9).regime == spinslide.TerminalRegime.pure_spinning
    lower, upper = spinslide.terminal_window(disk)
    assert (lower, upper) == pytest.approx((0.25, 2 / 3), rel=1e-15)
    zeros = spinslide.ratio_flow_zeros(disk, 0.5)
    assert len(zeros) == 1 and zeros[0].attracting
    assert zeros[0].ratio == pytest.approx(state.ratio, rel=1e-15)
    # The flow f = eps - gamma F/T vanishes there, checked with the profile's values.
    f, t = disk.force_torque(zeros[0].ratio)
    assert abs(zeros[0].ratio - 0.5 * f / t) < 1e-15
    names = {r.name for r in spinslide.TerminalRegime.__members__.values()}
    assert names == {"pure_sliding", "sliding_and_spinning", "pure_spinning"}
    assert spinslide.terminal_motion(disk, 0.5, initial_ratio=0.0).regime == \
        spinslide.TerminalRegime.pure_spinning


def test_stop_results_of_a_python_pressure_on_worker_threads():
    """A RadialProfile calls Python from stop_results' worker threads: the
    same stops as simulate_throw, and what the pressure raises arrives as a
    ValueError (not a crash, not a hang)."""
    p = spinslide.RadialProfile(lambda r: (1 - r) * (1 + r))
    v0 = np.array([0.3, 1.5])
    batch = spinslide.stop_results(p, 0.4, v0, 1.0, threads=2)
    for i, v in enumerate(v0):
        assert batch.time[i] == spinslide.simulate_throw(p, 0.4, v, 1.0).time
    calls = [0]

    def fails_later(r):
        calls[0] += 1
        if calls[0] > 20000:
            raise RuntimeError("the pressure failed")
        return 1.0

    q = spinslide.RadialProfile(fails_later)
    with pytest.raises(ValueError, match="the pressure failed"):
        spinslide.stop_results(q, 0.4, v0, 1.0, threads=2)
