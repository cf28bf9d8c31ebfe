"""A deck that reads the environment (``variable NAME getenv VAR``, as job-array decks choose their
parameters) is interpreted by its engine in the user's environment, as the engine run by hand
would see it, and the audit names each variable read with its value. Field round 8: the engine's
pass ran in an emptied environment, so such a deck got the eps of the parameter file chosen by an
empty value (0.5 where LAMMPS with CASE=stiff gives 0.9), exit 0."""

import pytest

from deck_cli import LIGGGHTS_BOX, agrees_with_lammps, audit, lammps_spheres, needs_lammps, needs_liggghts

LINE = "pair_coeff * * hooke 1000.0 {e} damping coeff_restitution tangential linear_nohistory 0 0"


def _lammps_deck(tmp_path):
    (tmp_path / "params_.in").write_text(LINE.format(e=0.5) + "\n")
    (tmp_path / "params_stiff.in").write_text(LINE.format(e=0.9) + "\n")
    (tmp_path / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + "variable case getenv CASE\n"
                                      "include params_${case}.in\ntimestep 1e-6\nrun 10\n")
    return tmp_path / "in.deck"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("case, e", [("stiff", 0.9), (None, 0.5)])
def test_lammps_reads_the_users_environment_and_the_audit_names_it(tmp_path, monkeypatch, case, e):
    if case is None:
        monkeypatch.delenv("CASE", raising=False)
    else:
        monkeypatch.setenv("CASE", case)
    got, err = audit(_lammps_deck(tmp_path), "--g", "1")
    assert [r["typed_e"] for r in got["pairs"]] == [e]
    agrees_with_lammps(got["pairs"], {1: (0.002, 2500.0)}, LINE.format(e=e), 1)
    (note,) = [n for n in got["notes"] if "CASE" in n]
    assert ("'stiff'" if case else "unset or empty") in note


@needs_liggghts
@pytest.mark.dem
def test_liggghts_reads_the_users_environment(tmp_path, monkeypatch):
    monkeypatch.setenv("CASE", "stiff")
    for name, e in (("mat_.in", 0.5), ("mat_stiff.in", 0.9)):
        (tmp_path / name).write_text(f"fix m3 all property/global coefficientRestitution peratomtypepair 1 {e}\n")
    (tmp_path / "in.deck").write_text(LIGGGHTS_BOX.replace("create_box 2", "create_box 1") + """\
fix m1 all property/global youngsModulus peratomtype 5e7
fix m2 all property/global poissonsRatio peratomtype 0.3
variable case getenv CASE
include mat_${case}.in
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001
""")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [r["typed_e"] for r in got["pairs"]] == [0.9]
    assert any("CASE" in n and "'stiff'" in n for n in got["notes"])
