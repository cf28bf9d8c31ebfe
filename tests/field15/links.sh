#!/bin/sh
# Field round 15: make (or with "rm" remove) the links the x decks need; they are not committed.
D=$(dirname "$0")/decks
if [ "$1" = rm ]; then
  rm -f $D/x01*/root $D/x01*/tmpl $D/x02*/self $D/x02*/dangling $D/x03*/out.restart $D/x03*/out.data $D/x04*/in.link $D/x05*/zero.lmp $D/x08*/rnd.data $D/x10*/mol.fifo $D/x06*/pipe.lmp $D/x07*/big.lmp /tmp/f15big.lmp
  exit 0
fi
ln -sfn / $D/x01_symlink_to_root_beside/root; ln -sfn /tmp $D/x01_symlink_to_root_beside/tmpl
ln -sfn . $D/x02_symlink_loop_beside/self; ln -sfn /nonexistent/f15 $D/x02_symlink_loop_beside/dangling
ln -sfn /tmp/f15canary_out.restart $D/x03_link_named_as_output/out.restart; ln -sfn /tmp/f15canary_out.data $D/x03_link_named_as_output/out.data
d4=$D/x04_deck_is_symlink; mkdir -p $d4/sub; mv -f $d4/in.deck $d4/sub/in.deck 2>/dev/null; mv -f $d4/inc.lmp $d4/sub/inc.lmp 2>/dev/null
ln -sfn sub/in.deck $d4/in.link; echo in.link > $d4/DECK
ln -sfn /dev/zero $D/x05_include_link_to_devzero/zero.lmp
mkfifo $D/x06_include_fifo/pipe.lmp 2>/dev/null
truncate -s 3G /tmp/f15big.lmp; ln -sfn /tmp/f15big.lmp $D/x07_include_link_to_big_file/big.lmp
ln -sfn /dev/urandom $D/x08_read_data_link_to_urandom/rnd.data
mkfifo $D/x10_molecule_fifo/mol.fifo 2>/dev/null
