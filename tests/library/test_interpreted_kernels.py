"""Small requests in a process that has not started numba run the kernels as plain Python
(restitution.fast.jit.call_kernel): the same numbers, bit for bit, as the compiled kernels,
and a warm-cache one-point call that never imports numba."""

from __future__ import annotations

import hashlib
import io
import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from restitution.core.errors import ParameterError
from restitution.fast.ladder import Ladder

# Run in a fresh interpreter: this test process has numba started by other tests.
SAME_BITS = textwrap.dedent("""
    import sys
    import numpy as np
    from restitution.fast.integrator import INTERPRETED_MAX_POINTS, collide_fast
    from restitution.fast.panels import chebyshev_panels_eval
    from restitution.core.exponents import as_exponents
    from restitution.fast import integrator, jit

    jit.PLAIN_BUDGET = float("inf")   # every small request below in plain Python, however long
    integrator.INTERPRETED_MAX_POINTS = float("inf")   # the creeping returns too
    om = np.geomspace(1e-4, 1e6, INTERPRETED_MAX_POINTS)
    pairs = [("3/2", "1"), ("3/2", "1/2"), ("5/2", "1"), ("1", "3/2"), ("2", "3/4")]
    plain = {}
    for a, g in pairs:
        ex = as_exponents(a, g)
        for end in ("force", "overlap"):
            plain[a, g, end] = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, om, 1e-12, end)
    rng = np.random.default_rng(1)
    coef, visc, elas = rng.normal(size=(7, 11)) * 0.1, np.array([0.2, 1.0, 0.1, 0.0, 0.0]), np.array([0.6, 1.2, 0.3, 0.0, 0.0])
    wide = np.geomspace(1e-9, 1e9, 1500)
    plain_panels = chebyshev_panels_eval(wide, -2.0, 0.5, coef, visc, elas)
    assert "numba" not in sys.modules, "a small request started numba"

    integrator.INTERPRETED_MAX_POINTS = INTERPRETED_MAX_POINTS
    for (a, g, end), got in plain.items():   # now compiled: enough points to pass the limit
        ex = as_exponents(a, g)
        many = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, np.tile(om, 20), 1e-12, end)[: om.size]
        assert "numba" in sys.modules
        assert np.array_equal(got, many, equal_nan=True), (a, g, end, got[:, 0], many[:, 0])
    compiled_panels = chebyshev_panels_eval(np.tile(wide, 2), -2.0, 0.5, coef, visc, elas)[: wide.size]
    assert np.array_equal(plain_panels, compiled_panels)
    print("same bits")
""")


@pytest.mark.slow
def test_plain_python_kernels_give_the_compiled_numbers_bit_for_bit():
    pytest.importorskip("numba")
    proc = subprocess.run([sys.executable, "-c", SAME_BITS], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert proc.stdout.strip() == "same bits"


@pytest.mark.slow
def test_a_warm_one_point_call_starts_no_compiler(tmp_path):
    """After a request that builds the master curve, a one-point call loads it (its checks passed
    once and are marked) and answers from it without importing numba."""
    pytest.importorskip("numba")
    env = {"RESTITUTION_CACHE": str(tmp_path)}
    code = ("import numpy as np\nfrom restitution import epsilon\n"
            "print(epsilon(alpha='3/2', gamma='1', omega=np.geomspace(1e-3, 1e3, 100000)).method)")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600,
                          env={**__import__("os").environ, **env})
    assert proc.stdout.strip() == "master", proc.stderr
    probe = ("import sys\nfrom restitution.cli import main\n"
             "assert main(['eps', '--alpha', '3/2', '--gamma', '1', '--omega', '0.1']) == 0\n"
             "print('numba' in sys.modules)")
    for _ in range(2):   # the first load checks and marks, the second trusts the mark
        proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=600,
                              env={**__import__("os").environ, **env})
        assert proc.returncode == 0, proc.stderr
        assert "method master" in proc.stdout
    assert proc.stdout.strip().splitlines()[-1] == "False"
    assert list(tmp_path.glob("master-*.json.checked"))


def test_an_entry_changed_after_its_checks_were_marked_is_checked_again(tmp_path):
    """The mark covers the content it was made for: a coefficient shifted and sealed again after
    the mark was written is checked, refused without building and rebuilt with it."""
    omega = np.geomspace(0.05, 20.0, 7)
    Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO()).evaluate(omega, tol=None, method="master")
    Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO()).evaluate(omega, tol=None, method="master",
                                                                               build=False)
    (path,) = tmp_path.glob("master-*.json")
    assert path.with_name(path.name + ".checked").exists()
    stored = json.loads(path.read_text())
    m = stored["content"].get("master", stored["content"])
    m["coef"][10][0] += 0.01
    text = json.dumps(stored["content"], sort_keys=True, separators=(",", ":"))
    stored["sha256"] = hashlib.sha256(text.encode()).hexdigest()
    path.write_text(json.dumps(stored))
    err = io.StringIO()
    with pytest.raises(ParameterError, match="method"):
        Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=err).evaluate(omega, tol=None, method="master",
                                                                         build=False)
    assert "does not pass its checks" in err.getvalue()


def test_where_plain_python_raises_the_compiled_kernel_answers(monkeypatch):
    """Plain Python raises OverflowError where compiled code carries on with inf: the compiled
    kernel runs instead, and no numpy warning reaches the user."""
    from restitution.fast import jit

    monkeypatch.setattr(jit, "HAVE_NUMBA", True)
    monkeypatch.delitem(sys.modules, "numba", raising=False)
    monkeypatch.setattr(jit, "_SPENT", {"plain": 0.0})   # what earlier tests in this process spent
    ran = []

    def kernel(x):
        plain = getattr(jit._MODE, "plain", False)
        ran.append(plain)
        if plain:
            np.float64(1e300) ** 2      # would warn outside errstate
            raise OverflowError("math range error")
        return 2 * x

    assert jit.call_kernel(1, 8, kernel, 21) == 42 and ran == [True, False]
    ran.clear()
    assert jit.call_kernel(9, 8, kernel, 21) == 42 and ran == [False]   # over the limit: compiled at once


MANY_SMALL = textwrap.dedent("""
    import sys
    import numpy as np
    from restitution.fast import jit
    from restitution.fast.collision_kernels import collide_many
    from restitution.fast.integrator import collide_fast

    jit.PLAIN_BUDGET, jit.COMPILE_BUDGET = 0.1, 0.3
    assert not jit._compiled_on_disk(collide_many), "an empty NUMBA_CACHE_DIR holds a kernel"
    om = np.array([0.3])
    first = collide_fast(3, 2, 2, om, 1e-12, "force")
    assert "numba" not in sys.modules, "one small request started numba"
    calls = 1
    while "numba" not in sys.modules and calls < 1000:
        collide_fast(3, 2, 2, om, 1e-12, "force")
        calls += 1
    assert "numba" in sys.modules, "a thousand small requests never started numba"
    assert jit._SPENT["plain"] >= jit.COMPILE_BUDGET, "nothing compiled on disk: compiling's budget applies"
    assert np.array_equal(first, collide_fast(3, 2, 2, om, 1e-12, "force"))
    assert jit._compiled_on_disk(collide_many)
    print(calls)
""")


@pytest.mark.slow
def test_many_small_requests_start_numba_once_plain_python_took_its_start(tmp_path):
    """A loop of one-point requests runs plain Python only until that has cost about numba's start
    (jit.PLAIN_BUDGET, or COMPILE_BUDGET with no kernel compiled on disk, as here), then compiled,
    with the same numbers."""
    pytest.importorskip("numba")
    env = {**__import__("os").environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    proc = subprocess.run([sys.executable, "-c", MANY_SMALL], capture_output=True, text=True, timeout=600, env=env)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert 2 <= int(proc.stdout.strip()) < 1000


def test_a_creeping_return_counts_as_many_points():
    """The overlap rule's creeping return at small Omega takes seconds in plain Python (the uniform
    build's three law checks at 1e-3..4e-3 took 1.6 s for alpha = 5/2, gamma = 1, against 0.5 s for
    numba's start): it counts by its estimated cost, so such requests are compiled at once."""
    from restitution.fast.integrator import INTERPRETED_MAX_POINTS, _plain_work
    law_check = np.array([1e-3, 2e-3, 4e-3])
    assert _plain_work(law_check, 1e-14, True, 5, 2) > INTERPRETED_MAX_POINTS
    assert _plain_work(np.array([1e-3]), 1e-10, True, 5, 2) <= INTERPRETED_MAX_POINTS   # 0.1-0.2 s plain
    assert _plain_work(np.array([1e-4]), 1e-10, True, 3, 2) > INTERPRETED_MAX_POINTS
    assert _plain_work(np.array([1e-4]), 1e-10, False, 2, 3) > INTERPRETED_MAX_POINTS   # alpha < gamma creeps too
    assert _plain_work(law_check, 1e-14, False, 3, 2) == 3                             # the force rule: points


# numba's start leaves objects that live until exit; the collector walking them at exit cost a
# third of a one-call process. Registered first, the check runs last at exit (atexit is LIFO).
COLLECTOR = textwrap.dedent("""
    import atexit, gc
    atexit.register(lambda: print("frozen at exit:", gc.get_freeze_count() > 0, flush=True))
    from restitution.fast.jit import njit

    @njit
    def twice(x):
        return 2.0 * x

    assert gc.isenabled() and twice(1.5) == 3.0
    assert gc.isenabled(), "numba's start left the collector off"
    assert gc.get_freeze_count() == 0, "frozen before exit"

    @njit
    def thrice(x):
        return 3.0 * x

    gc.disable()
    assert thrice(1.0) == 3.0 and not gc.isenabled(), "a caller's disabled collector was turned on"
    gc.enable()
""")


def test_numba_start_gives_the_collector_back_and_the_heap_is_frozen_at_exit():
    pytest.importorskip("numba")
    proc = subprocess.run([sys.executable, "-c", COLLECTOR], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert proc.stdout.strip() == "frozen at exit: True", proc.stdout


# numba's first compile or cache load imports numba.np.arraymath, whose BLAS probe imported
# scipy.linalg (a quarter of a second of CPU) to pick an inner product no kernel here uses.
NO_BLAS_PROBE = textwrap.dedent("""
    import sys
    import numpy as np
    from restitution.fast.integrator import collide_fast

    res = collide_fast(2, 3, 1, np.geomspace(11.0, 113.0, 45), 1e-12, "overlap")   # compiled: 45 points
    assert "numba" in sys.modules and np.all(np.isfinite(res[:, 0]))
    assert "scipy.linalg" not in sys.modules, "numba's start imported scipy.linalg"
    import numba.np.arraymath as arraymath, numba.np.linalg as linalg
    assert arraymath.ensure_blas is linalg.ensure_blas, "numba's own probe was not given back"
    print("no scipy.linalg")
""")


def test_numba_start_does_not_import_scipy_linalg():
    pytest.importorskip("numba")
    proc = subprocess.run([sys.executable, "-c", NO_BLAS_PROBE], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert proc.stdout.strip() == "no scipy.linalg"


# The plain kernels' budget counts CPU, not the wall clock: on a loaded machine waiting for a core
# made numba start for work that had cost far less than its start.
WAITING = textwrap.dedent("""
    import sys, time
    from restitution.fast import jit

    @jit.njit
    def waits(seconds):
        time.sleep(seconds)   # plain Python only: the wall clock runs, the CPU does not
        return seconds

    assert jit.call_kernel(1, 8, waits, 0.3) == 0.3 and "numba" not in sys.modules
    print(round(jit._SPENT["plain"], 2))
""")


def test_the_plain_budget_counts_cpu_not_waiting():
    pytest.importorskip("numba")
    proc = subprocess.run([sys.executable, "-c", WAITING], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert float(proc.stdout) < 0.1, proc.stdout
