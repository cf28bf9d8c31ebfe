"""Field round 26's classes. T: under ``pair_style hybrid`` with one sub-style alone, LAMMPS 22 Jul 2025
does not keep ``pair_coeff i j none`` for two types whose own pairs are not none: the spheres
collide under the sub-style's law (T07, T17, T21, T25, T27: 0.414918 head-on), where the audit said
there was no contact; a ``none`` on a type's pair with itself is kept (T18). Such a deck is now
refused in one line; a later pair_coeff that gives the pair back to the sub-style is read (T14: the
none was read, the kn 5000 line after it not). Each claim is measured here in LAMMPS itself."""

import pytest

from deck_cli import HEAD_ON, lammps_separation_speed, needs_lammps, run, audit

LAW = "granular hooke {kn} 300 damping mass_velocity tangential linear_nohistory 1 0.3"


def _deck(lines: str) -> str:
    return HEAD_ON.replace("pair_style granular\n{line}\n", "pair_style hybrid granular\n" + lines) + "run 30000\n"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("none, kept", [("pair_coeff 1 2 none", False), ("pair_coeff 1 1 none\npair_coeff 1 2 none", True)],
                         ids=["1 2 alone", "with 1 1"])
def test_lammps_keeps_a_none_of_two_types_only_with_one_of_their_own_pairs(tmp_path, none, kept):
    """The measurement the refusal rests on: 1 2 none alone, the spheres bounce off each other
    (a separation speed above 0.4); with 1 1 none too, they pass through (no contact: -1)."""
    speed = lammps_separation_speed(_deck(f"pair_coeff * * {LAW.format(kn=1000)}\n{none}\n"), tmp_path)
    assert (speed == pytest.approx(-1.0, abs=1e-9)) if kept else speed > 0.4, speed


@needs_lammps
@pytest.mark.dem
def test_a_none_lammps_does_not_keep_is_refused_in_one_line(tmp_path):
    (tmp_path / "in.deck").write_text(_deck(f"pair_coeff * * {LAW.format(kn=1000)}\npair_coeff 1 2 none\n"))
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "line 17 (pair_coeff 1 2 none): types 1 2: none under pair_style hybrid with one sub-style" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_pair_given_back_to_the_sub_style_after_none_has_its_new_law(tmp_path):
    """T14: * * kn 1000, 1 2 none, 1 2 kn 3000: LAMMPS' 1 2 is kn 3000's (16 000 steps a contact)."""
    deck = _deck(f"pair_coeff * * {LAW.format(kn=1000)}\npair_coeff 1 2 none\npair_coeff 1 2 {LAW.format(kn=3000)}\n")
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    row = next(r for r in got["pairs"] if r["types"] == [1, 2])
    assert abs(row["eps"][0] - lammps_separation_speed(deck, tmp_path)) < 5e-5, row["eps"]


#: N15: a sphere made 0.5 m wide in a 4 cm periodic box, LAMMPS told to go on past lost atoms
LOSING = """units si
atom_style sphere 1
boundary p p f
comm_modify vel yes
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 2 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
fix grav all gravity 9.81 vector 0 0 -1
fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL
fix integ all nve/sphere
timestep 1e-5
create_atoms 1 single 0.02 0.02 0.01
create_atoms 2 single 0.01 0.01 0.01
set type 1 diameter 0.004 density 2500
set type 2 diameter 0.006 density 2500
thermo_modify lost {lost}
set atom 2 diameter 0.5
run 10
"""


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("lost", ["ignore", "warn"])
def test_a_run_that_may_lose_atoms_unseen_says_so(tmp_path, lost):
    """N15: LAMMPS loses the type-1 sphere in the deck's one run and goes on (measured: it holds the
    0.25 m sphere alone at the end); the rows stand, the note names the line and what is not seen."""
    from deck_cli import lammps_held_at_end
    (tmp_path / "in.deck").write_text(LOSING.format(lost=lost))
    assert set(lammps_held_at_end(tmp_path / "in.deck")) == {2}
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert f"line 17 (thermo_modify lost {lost}): LAMMPS drops an atom it loses in a run and goes on" in err, err


@needs_lammps
@pytest.mark.dem
def test_lost_error_needs_no_such_note(tmp_path):
    (tmp_path / "in.deck").write_text(LOSING.format(lost="error").replace("set atom 2 diameter 0.5\n", ""))
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert "drops an atom it loses" not in err, err


@needs_lammps
@pytest.mark.dem
def test_one_pairs_small_cutoff_leaves_it_to_the_radii(tmp_path):
    """CU01: a cutoff of 1 mm on the 1 2 pair alone (contact distance 10 mm), the others without: LAMMPS'
    lists take the pair by its radii, the largest cutoff setting their reach, and it meets at first
    touch; the audit gave no row. Now its row is the law's, LAMMPS' own run within 5e-5 (16 000 steps
    a contact)."""
    law = "hooke 3000 300 damping mass_velocity tangential linear_nohistory 1 0.3"
    deck = HEAD_ON.format(line=f"pair_coeff * * {law}\npair_coeff 1 2 {law} cutoff 0.001") + "run 30000\n"
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    row = next(r for r in got["pairs"] if r["types"] == [1, 2])
    assert abs(row["eps"][0] - lammps_separation_speed(deck, tmp_path)) < 5e-5, row["eps"]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("after_a_run", [False, True], ids=["first line", "after a run"])
def test_a_pour_after_clear_is_read_as_without_it(tmp_path, after_a_run):
    """CL01, CL22: a pour after ``clear`` into a type that has a sphere already was read as the hand
    reader's, its 7800 kg/m3 spheres lost to the atoms held at the run (two poured spheres: LAMMPS
    0.445815, not printed). A clear
    on the first line changes nothing in LAMMPS, and one after a run starts the same simulation
    afresh: the rows are those of the deck without it."""
    from deck_cli import lammps_pour
    law = "pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
    deck = lammps_pour(law, ntypes=2, sphere=(2, 0.006, 2500.0)).replace(
        "fix p all pour 400 1 123 region ins diam one 0.01 dens 2500 2500",
        "fix p all pour 3 2 4767 region ins diam one 0.003 dens 7800 7800") + "run 2000\n"
    before = (deck.replace("fix p all pour", "# no pour: fix p all pour") + "clear\n") if after_a_run else "clear\n"
    rows = {}
    for name, text in (("plain", deck), ("cleared", before + deck)):
        (tmp_path / f"in.{name}").write_text(text)
        got, _ = audit(tmp_path / f"in.{name}", "--g", "1")
        rows[name] = sorted((tuple(r["types"]), round(r["eps"][0], 9)) for r in got["stages"][-1]["pairs"])
    assert rows["cleared"] == rows["plain"] and ((2, 2), pytest.approx(0.445804, abs=2e-6)) in rows["plain"], rows


@needs_lammps
def test_a_folder_that_changes_while_copied_is_refused_in_one_line(tmp_path, monkeypatch):
    """P02: files removed from the folder a shell cd .. has the audit copy, while it copies: a
    Python traceback (shutil.Error from copytree). Now one line, exit status 2."""
    import shutil

    from restitution.dem.deck import scratch

    def vanishing(src, dst, **kwargs):
        raise shutil.Error([(str(src) + "/kn.in", str(dst) + "/kn.in", "[Errno 2] No such file or directory")])
    monkeypatch.setattr(scratch.shutil, "copytree", vanishing)
    (tmp_path / "in.deck").write_text(HEAD_ON.format(line="pair_coeff * * " + LAW.format(kn=1000).split(None, 1)[1]))
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "changed or could not be read while the audit copied it" in err and "No such file" in err, err


@needs_lammps
@pytest.mark.dem
def test_every_cutoff_small_with_a_skin_that_reaches_the_contact_is_answered(tmp_path):
    """Field round 27, CU03: every cutoff 1 mm, contact distance 10 mm, neighbor skin 10 mm: LAMMPS'
    lists reach 11 mm and the pair meets at first touch; the audit left it out with a false word.
    Its row is now LAMMPS' own run's within 5e-5."""
    law = "hooke 3000 300 damping mass_velocity tangential linear_nohistory 1 0.3 cutoff 0.001"
    deck = HEAD_ON.format(line=f"pair_coeff * * {law}\nneighbor 0.01 bin") + "run 30000\n"
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    row = next(r for r in got["pairs"] if r["types"] == [1, 2])
    assert abs(row["eps"][0] - lammps_separation_speed(deck, tmp_path)) < 5e-5, row["eps"]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between", ["group a id 1\ndelete_atoms group a", "set atom 1 type 2"],
                         ids=["delete by ID", "retype"])
def test_a_type_emptied_between_runs_has_no_pairs_after(tmp_path, between):
    """Field round 27, G01, G17: a type whose atoms a command between runs removes (a delete_atoms of a
    group by ID, a set that retypes them) kept its pairs and wall rows in the later stage, where LAMMPS
    holds none of it (measured here)."""
    from deck_cli import lammps_held_at_end
    deck = (LOSING.format(lost="error").replace("thermo_modify lost error\nset atom 2 diameter 0.5\nrun 10\n", "")
            + f"run 100\n{between}\nrun 100\n")
    (tmp_path / "in.deck").write_text(deck)
    assert set(lammps_held_at_end(tmp_path / "in.deck")) == {2}
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    last = got["stages"][-1]
    assert {tuple(r["types"]) for r in last["pairs"]} <= {(2, 2)} and all(w["types"] == [2] for w in last["walls"]), last
