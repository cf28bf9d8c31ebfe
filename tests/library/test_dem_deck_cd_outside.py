"""A deck that changes its directory out of its folder (``shell cd /tmp``, ``shell cd ..``) and then
writes a file (field round 9, c42): LAMMPS run by hand writes it there. The audit's engine ran in a
view where nothing outside the scratch was writable, stopped on "Read-only file system" and the
audit refused the deck with "LAMMPS stops here", which the user's LAMMPS never says. The view's
own folders outside the copy are now a private, in-memory stand-in: the write lands there and is
dropped with it, the deck goes on, and nothing is written on the machine outside the scratch."""

import uuid

import pytest

from deck_cli import agrees_with_lammps, audit, lammps_spheres, needs_lammps
from restitution.dem.dialect.sandbox import available as confining

HOOKE = "pair_coeff * * hooke 2000 0.05 damping velocity tangential linear_nohistory 0 0"


@needs_lammps
@pytest.mark.dem
@pytest.mark.skipif(not confining(), reason="the engine's own shell commands run only where the pass is confined")
@pytest.mark.parametrize("cd", ["shell cd /tmp", "shell cd ..\nshell cd .."])
def test_a_file_written_after_a_cd_out_of_the_folder_lets_the_deck_go_on(tmp_path, cd):
    """Before: exit 2, "LAMMPS stops here: Cannot open data file ...: Read-only file system"."""
    name = f"escape_{uuid.uuid4().hex}"
    folder = tmp_path / "case"
    folder.mkdir()
    (folder / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + HOOKE + f"\n{cd}\nshell mkdir {name}_dir\n"
                                    f"write_data {name}.data\nwrite_restart {name}.restart\ntimestep 1e-6\nrun 10\n")
    got, err = audit(folder / "in.deck", "--g", "1")
    agrees_with_lammps(got["pairs"], {1: (0.002, 2500.0)}, HOOKE, 1)
    import glob
    import tempfile
    # nothing beside the deck, above it or in the machine's temporary folder
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["case", "in.deck"]
    assert not glob.glob(f"{tempfile.gettempdir()}/{name}*") and not glob.glob(f"/tmp/{name}*")


@needs_lammps
@pytest.mark.dem
@pytest.mark.skipif(not confining(), reason="the engine's own shell commands run only where the pass is confined")
def test_a_write_the_confinement_stops_is_not_put_in_lammps_mouth(tmp_path):
    """A write into a system folder (which the view binds read-only): refused in one line that
    says the audit's confinement stopped it (before: "LAMMPS stops here: ... Read-only file system")."""
    (tmp_path / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + HOOKE + "\nshell cd /usr\n"
                                      "write_data escape.data\ntimestep 1e-6\nrun 10\n")
    from deck_cli import run
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "stops here" not in err and "may write only in its copy" in err and "write_data escape.data" in err
