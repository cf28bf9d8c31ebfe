"""Field round 47's silently wrong classes, on bonded atoms (LAMMPS measured, the audit's rows printed
with no word on the code before):

- special_bonds' 1-3 and 1-4 weights: two spheres joined through a third are 1-3 neighbours, and
  under ``special_bonds lj 1 0 1`` LAMMPS leaves them out of its lists (they pass through each
  other: Y21 -1, Y22 likewise for 1-4), under 0.5 it halves their force (Y27 0.542539); the audit
  looked at the 1-2 weight only and printed the contact's 0.4149;
- a bond style with a force (harmonic) pulls on a sphere of the pair during its contact (Y08
  0.291769 where the audit printed 0.4149).

The audit cannot tell which atoms are bonded, so every pair is named, not audited; a bond_style zero
with weights 1 1 1 changes nothing and the pair is audited (the control, as LAMMPS measures it).

Also two wrong notes: each of several fix gravity on a sphere sized alone, and a deck moved only by
fix brownian refused as one that no fix moves."""

import pytest

from deck_cli import lammps_separation_speed, needs_lammps, run

CHAIN = """units si
atom_style hybrid sphere 1 bond
atom_modify map array sort 0 0
comm_modify vel yes
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05
create_box 2 box bond/types 1 extra/bond/per/atom 2 extra/special/per/atom 4
create_atoms 1 single -0.0051 0 0
create_atoms 2 single 0.0051 0 0
create_atoms 1 single {third} 0
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.01 density 2500
velocity all set 0 0 0
set atom 1 vx 0.5
set atom 2 vx -0.5
fix integrate all nve/sphere
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
timestep 1e-7
{bond}
{bonds}
special_bonds lj {weights}
run 80000
"""
#: the pair as 1-3 neighbours through a third sphere far off to the side, bonds of no force
THROUGH = dict(third="0 0.03", bond="bond_style zero\nbond_coeff 1",
               bonds="create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 2")
#: a third sphere ahead of sphere 2 along x, bonded to it and pulling on it
PULLED = dict(third="0.03 0", bond="bond_style harmonic\nbond_coeff 1 5 0.0249", bonds="create_bonds single/bond 1 2 3",
              weights="1 1 1")


def audited_row(tmp_path, deck: str):
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 0, err
    rows = [line for line in out.split("types 1 2")[1:2] for line in line.splitlines() if line.startswith("  g 1 ")]
    return (float(rows[0].split()[3]) if rows else None), err


@needs_lammps
@pytest.mark.dem
def test_the_control_bonds_of_no_force_at_weight_1_are_audited(tmp_path):
    deck = CHAIN.format(**THROUGH, weights="1 1 1")
    eps, err = audited_row(tmp_path, deck)
    measured = lammps_separation_speed(deck, tmp_path)
    assert eps is not None and abs(eps - measured) < 1e-4, (eps, measured, err)   # 0.005249, 0.005242


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("weights, said", [("1 0 1", "1-3 get no contact"), ("1 0.5 1", "1-3 get their contact "
                                                                                         "scaled by 0.5")])
def test_neighbours_1_3_at_a_weight_below_1_are_not_audited(tmp_path, weights, said):
    deck = CHAIN.format(**THROUGH, weights=weights)
    eps, err = audited_row(tmp_path, deck)
    assert eps is None and f"types 1 2: bonded atoms' neighbours {said}" in err, err
    control = lammps_separation_speed(CHAIN.format(**THROUGH, weights="1 1 1"), tmp_path)
    assert abs(lammps_separation_speed(deck, tmp_path) - control) > 1e-3     # the engine's pair is not the law's


@needs_lammps
@pytest.mark.dem
def test_a_bond_with_a_force_on_a_sphere_of_the_pair_is_named(tmp_path):
    deck = CHAIN.format(**PULLED)
    eps, err = audited_row(tmp_path, deck)
    assert eps is None and "types 1 2: bond_style harmonic pulls on bonded atoms during a contact" in err, err
    control = CHAIN.format(**{**PULLED, "bond": "bond_style zero\nbond_coeff 1"})
    # measured: 0.008160 with the bond's pull, 0.005242 without it (the law's 0.005249 at dt -> 0)
    assert abs(lammps_separation_speed(deck, tmp_path) - lammps_separation_speed(control, tmp_path)) > 1e-3
    assert audited_row(tmp_path, control)[0] is not None


@needs_lammps
@pytest.mark.dem
def test_several_gravities_on_a_sphere_are_sized_together(tmp_path):
    """G07: two fixes of 250 down on a floor drop; each fix's note took its own 250 alone (0.316664
    at g 1) where LAMMPS measured 0.260657 under their 500 (one fix of 500: 0.261239 at dt -> 0)."""
    base = """units si
atom_style sphere 1
boundary p p f
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 1 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
{gravity}
fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL
fix integ all nve/sphere
timestep 1e-6
create_atoms 1 single 0.02 0.02 0.0021
set atom 1 diameter 0.004 density 2500
"""
    notes = []
    for gravity in ("fix grav all gravity 250 vector 0 0 -1\nfix grav2 all gravity 250 vector 0 0 -1",
                    "fix grav all gravity 500 vector 0 0 -1"):
        (tmp_path / "in.deck").write_text(base.format(gravity=gravity))
        status, out, err = run(tmp_path / "in.deck", "--g", "1")
        assert status == 0, err
        notes.append([line.split("measures: ")[1].split(";")[0] for line in err.splitlines()
                      if "fix gravity (grav)" in line])
    assert notes[0] == notes[1] and "0.261239 at g = 1" in notes[1][0], notes


@needs_lammps
@pytest.mark.dem
def test_a_pair_moved_by_fix_brownian_is_named_not_refused(tmp_path):
    """F36: fix brownian as the only mover; the audit refused the deck, quoting a LAMMPS warning
    ("No fixes with time integration") LAMMPS does not print; its steps are overdamped and random."""
    deck = CHAIN.format(**THROUGH, weights="1 1 1").replace("fix integrate all nve/sphere",
                                                          "fix integrate all brownian 1e-20 4767 gamma_t 1e-3")
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 0 and "types 1 2: fix integrate (brownian) moves type 1 by overdamped random steps" in err, err
    assert "not understood" not in err, err
