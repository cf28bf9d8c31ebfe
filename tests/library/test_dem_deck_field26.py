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
