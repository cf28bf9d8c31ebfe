#!/bin/sh
# Field round 15: audit the x decks (links, a pipe, /dev/zero) with the links made by links.sh, under a 3 GB
# address-space limit, a 400 MB file-size limit and a time limit, so a deck that makes the audit read without end
# cannot take the machine's memory. usage (from the worktree): sh tests/field15/run_x_decks.sh
. tests/field15/env.sh
sh tests/field15/links.sh
for d in x01_symlink_to_root_beside x02_symlink_loop_beside x03_link_named_as_output x04_deck_is_symlink \
         x05_include_link_to_devzero x06_include_fifo x07_include_link_to_big_file x08_read_data_link_to_urandom x09_include_a_directory x10_molecule_fifo; do
  ( ulimit -v 3000000; ulimit -f 400000; timeout 90 nice -n 10 sh tests/field15/audit.sh tests/field15/decks/$d ); echo "$d: timeout/audit rc $?"
  ls /tmp/f15canary* 2>/dev/null
done
sh tests/field15/links.sh rm
