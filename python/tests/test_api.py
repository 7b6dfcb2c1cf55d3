#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""How the package behaves as numpy code: shapes, dtypes, scalars, errors, the
GIL and reference counts."""

import gc
import resource
import sys
import threading
import time

import numpy as np
import pytest

import spinslide

VALUE_FUNCTIONS = [spinslide.force, spinslide.torque, spinslide.force_derivative,
                   spinslide.torque_derivative]


@pytest.mark.parametrize("f", VALUE_FUNCTIONS)
def test_shapes_and_dtypes(f):
    x = np.geomspace(1e-3, 1e3, 12).reshape(3, 4)
    y = f(x)
    assert y.shape == (3, 4) and y.dtype == np.float64
    assert np.array_equal(f(x.T), y.T)  # a non-contiguous view
    y32 = f(x.astype(np.float32))
    assert y32.dtype == np.float32 and y32.shape == (3, 4)
    assert np.allclose(y32, y, rtol=1e-6)
    assert f([1, 2, 3]).dtype == np.float64  # integers promote to float64
    assert f(np.empty((0, 2))).shape == (0, 2)


@pytest.mark.parametrize("f", VALUE_FUNCTIONS)
def test_scalars_in_give_scalars_out(f):
    assert isinstance(f(0.5), np.float64)
    assert isinstance(f(np.float64(0.5)), np.float64)
    assert isinstance(f(np.float32(0.5)), np.float32)
    assert isinstance(f(np.array(0.5)), np.float64)
    assert f(2) == f(2.0)


def test_force_torque_gives_a_pair_of_the_input_shape():
    f, t = spinslide.force_torque([[0.1, 1.0], [2.0, np.inf]])
    assert f.shape == t.shape == (2, 2)
    assert f[1, 1] == 1.0 and t[1, 1] == 0.0
    f, t = spinslide.force_torque(np.float32(0.5))
    assert isinstance(f, np.float32) and isinstance(t, np.float32)


def test_profile_methods_keep_float32_and_shape():
    h = spinslide.Hertz()
    x = np.linspace(0, 5, 6, dtype=np.float32).reshape(2, 3)
    f, t = h.force_torque(x)
    assert f.dtype == np.float32 and f.shape == (2, 3)
    assert isinstance(h.torque(0.5), np.float64)


@pytest.mark.parametrize("call, argument", [
    (lambda: spinslide.force(-1.0), "eps"),
    (lambda: spinslide.torque([0.5, np.nan]), "eps"),
    (lambda: spinslide.force_torque(np.array([1.0, -0.5], dtype=np.float32)), "eps"),
    (lambda: spinslide.Hertz().force(-2.0), "eps"),
    (lambda: spinslide.Annulus(1.0), "inner_ratio"),
    (lambda: spinslide.Annulus(-0.1), "inner_ratio"),
    (lambda: spinslide.Ring(0.0), "radius"),
    (lambda: spinslide.Ring(1.5), "radius"),
    (lambda: spinslide.WeightedSum([(-1.0, spinslide.Ring())]), "weight"),
    (lambda: spinslide.WeightedSum([(0.0, spinslide.Ring())]), "weight"),
    (lambda: spinslide.WeightedSum([]), "empty"),
    (lambda: spinslide.RadialProfile(lambda r: -1.0), "pressure"),
    (lambda: spinslide.RadialProfile(lambda r: 1.0 / 0.0), "raised"),
    (lambda: spinslide.terminal_motion(spinslide.Hertz(), -1.0), "inertia_ratio"),
    (lambda: spinslide.terminal_motion(spinslide.Hertz(), 0.5, -1.0), "initial_ratio"),
    (lambda: spinslide.simulate_throw(spinslide.UniformDisk(), 0.5, -1.0, 1.0), "v0"),
    (lambda: spinslide.simulate_throw(spinslide.UniformDisk(), 0.0, 1.0, 1.0), "inertia_ratio"),
    (lambda: spinslide.stop_results(spinslide.UniformDisk(), 0.5, [1.0, np.nan], 1.0), "v0"),
    (lambda: spinslide.simulate_throw_si(spinslide.UniformDisk(), radius=-1.0,
                                         friction_coefficient=0.3, gravity=9.81,
                                         inertia_ratio=0.5, v0=1.0, omega0=1.0), "radius"),
    (lambda: spinslide.ratio_from_force(spinslide.UniformDisk(), 1.5), "F"),
    (lambda: spinslide.project_to_limit_set(spinslide.Hertz(), 0.5, 0.5, 0.0), "torque_weight"),
    (lambda: spinslide.project_to_limit_set(spinslide.Hertz(), -0.5, 0.5, 1.0), "force"),
    (lambda: spinslide.trajectory(spinslide.Hertz(), 0.4, 1.0, 1.0, [1.0, 0.5]), "time"),
])
def test_bad_arguments_raise_value_error_naming_them(call, argument):
    with pytest.raises(ValueError) as e:
        call()
    assert argument in str(e.value)


def test_non_numbers_raise_type_error():
    with pytest.raises(TypeError):
        spinslide.force("half")
    with pytest.raises(TypeError):
        spinslide.Hertz().force(["a", "b"])


def test_a_profile_cannot_be_built_from_the_base_class():
    with pytest.raises(TypeError):
        spinslide.Profile()
    assert isinstance(spinslide.Hertz(), spinslide.Profile)
    assert repr(spinslide.WeightedSum([(0.5, spinslide.Hertz()), (0.5, spinslide.Ring(0.5))])) == \
        "WeightedSum([(0.5, Hertz()), (0.5, Ring(0.5))])"


def _stamps_inside(work, seconds=0.8):
    """How often a Python thread woke (every millisecond) while this thread ran
    `work` again and again for `seconds`: where the GIL is released in work,
    about once per millisecond; where it is held, not at all during a call
    (at most once between two calls, when this thread takes the GIL back)."""
    window = []
    stamps = []
    stop = threading.Event()

    def watch():
        while not stop.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.001)

    watcher = threading.Thread(target=watch)
    watcher.start()
    time.sleep(0.01)
    window.append(time.perf_counter())
    calls = 0
    while calls < 3 or time.perf_counter() - window[0] < seconds:
        work()
        calls += 1
    window.append(time.perf_counter())
    stop.set()
    watcher.join()
    # Margins of 20 ms: the switch interval is 5 ms.
    inside = [t for t in stamps if window[0] + 0.02 < t < window[1] - 0.02]
    return len(inside), window[1] - window[0], calls


def test_the_gil_is_released_over_arrays():
    x = np.geomspace(1e-3, 1e3, 2_000_000)
    h = spinslide.Hertz()
    starts = np.linspace(0.1, 3, 2000)  # about 25 ms a call: far fewer calls than wakes
    for name, work in [("force_torque", lambda: spinslide.force_torque(x)),
                       ("Hertz().force", lambda: h.force(x)),
                       ("stop_results", lambda: spinslide.stop_results(
                           spinslide.UniformDisk(), 0.5, starts, 1.0, threads=1))]:
        count, seconds, calls = _stamps_inside(work)
        print(f"{name}: {calls} calls in {seconds:.2f} s, the other thread woke {count} times")
        # Released: about 1000 per second; held: at most one per call.
        assert count >= 100 and count > 5 * calls


def _max_rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def test_no_reference_or_memory_leak_over_a_million_calls():
    x = np.float64(0.5)
    a = np.linspace(0.1, 2.0, 8)
    h = spinslide.Hertz()
    before = (sys.getrefcount(x), sys.getrefcount(a), sys.getrefcount(h))
    for _ in range(3):  # warm up caches
        spinslide.force(x)
    gc.collect()
    rss = _max_rss_mb()
    for _ in range(1_000_000):
        spinslide.force(x)
    for _ in range(100_000):
        spinslide.force_torque(a)
        h.force(a)
        spinslide.project_to_limit_set(h, a, a, 1.0)
    gc.collect()
    grown = _max_rss_mb() - rss
    after = (sys.getrefcount(x), sys.getrefcount(a), sys.getrefcount(h))
    print(f"max RSS grew by {grown:.1f} MB over 1.3e6 calls")
    assert after == before
    assert grown < 8


def test_every_public_name_has_a_docstring_and_a_stub():
    import ast
    from pathlib import Path

    stub = Path(spinslide.__file__).with_name("__init__.pyi")
    tree = ast.parse(stub.read_text())
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = set(spinslide.__all__)
    assert public <= stubbed, public - stubbed
    assert stubbed - {"_Float"} <= public | {"Profile"}, stubbed - public
    for name in public:
        doc = getattr(spinslide, name).__doc__
        assert doc and len(doc) > 20, name
    assert "ε" in spinslide.force.__doc__ and "ulp" in spinslide.force.__doc__
    assert (stub.with_name("py.typed")).exists()
