"""The deck's folder copied into the scratch directory (issue 52, field round 14, D6): a deck saved in
the temporary directory itself, whose copy copied the scratch into itself until "File name too long",
and a named pipe or socket beside a deck, which copytree cannot copy, each gave a traceback."""

import os
import socket

import pytest

from restitution.dem.deck.scratch import scratch_copy


def _marker(k, run):
    return run + "\n"


def test_a_scratch_directory_inside_the_decks_folder_is_not_copied_into_itself(tmp_path):
    (tmp_path / "in.deck").write_text("atom_style sphere\nrun 10\n")
    (tmp_path / "data.txt").write_text("1 2 3\n")
    where = tmp_path / "restitution-deck-scratch"
    where.mkdir()
    scratch = scratch_copy(tmp_path / "in.deck", where, _marker)
    copied = sorted(p.name for p in scratch.deck.parent.iterdir())
    assert "data.txt" in copied and "in.deck" in copied and where.name not in copied


@pytest.mark.parametrize("kind", ["fifo", "socket"])
def test_a_pipe_or_socket_beside_the_deck_is_left_out_of_the_copy(tmp_path, kind):
    folder, where = tmp_path / "deck", tmp_path / "scratch"
    folder.mkdir()
    where.mkdir()
    (folder / "in.deck").write_text("atom_style sphere\nrun 10\n")
    if kind == "fifo":
        os.mkfifo(folder / "pipe")
    else:
        sock = socket.socket(socket.AF_UNIX)
        sock.bind(str(folder / "sock"))
    try:
        scratch = scratch_copy(folder / "in.deck", where, _marker)
    finally:
        if kind == "socket":
            sock.close()
    assert sorted(p.name for p in scratch.deck.parent.iterdir() if not p.name.startswith(".")) == ["in.deck"]


def test_a_link_to_a_device_is_left_out_and_the_scan_of_named_files_reads_no_device(tmp_path):
    """Field round 15, x05-x07: an include of a link to /dev/zero ran out of memory in the scan of the
    files a deck names (and the engine would read it without end), one of a named pipe hung. Such a
    link is not copied; the scan reads regular files of bounded size only."""
    folder, where = tmp_path / "deck", tmp_path / "scratch"
    folder.mkdir()
    where.mkdir()
    (folder / "in.deck").write_text("atom_style sphere\ninclude zero.lmp\ninclude pipe.lmp\nrun 10\n")
    (folder / "zero.lmp").symlink_to("/dev/zero")
    os.mkfifo(folder / "pipe.lmp")
    (folder / "dangling.lmp").symlink_to(tmp_path / "nowhere")
    scratch = scratch_copy(folder / "in.deck", where, _marker)
    copied = sorted(p.name for p in scratch.deck.parent.iterdir() if not p.name.startswith("."))
    assert copied == ["dangling.lmp", "in.deck"] and scratch.left_out == {"zero.lmp", "pipe.lmp"}
