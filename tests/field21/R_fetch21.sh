#!/bin/sh
# Field round 21: build the public deck(s) R* from their repositories (their text is not committed).
# usage (from the worktree): sh tests/field21/R_fetch21.sh MIRRORS   where MIRRORS/<owner>+<name>/repo is a git directory
# of each repository (a bare clone); the commits are pinned below. Edits are made by sed and listed in each deck's first comment.
M=${1:?mirror directory}
D=tests/field21/decks
g() { git --git-dir="$M/$1/repo" show "$2:$3"; }
# R01: ykevin09/examples_LIGGGHTS 0-element/1-undrained_simple_shear/0-25_25_25_dmax_vs_dmin_3/0-iso_comp.lmp @ f1dc1423b97def51d0b6f104ff3698091fbdbb34
C=f1dc1423b97def51d0b6f104ff3698091fbdbb34; P=0-element/1-undrained_simple_shear/0-25_25_25_dmax_vs_dmin_3
d=$D/R01_ykevin_iso_comp_run_every_if_quit; mkdir -p $d/input/data $d/input/mesh; touch $d/LIGGGHTS; echo "0.1 1" > $d/G; echo in.deck > $d/DECK
{ echo "# R01 ykevin09/examples_LIGGGHTS $P/0-iso_comp.lmp @f1dc142; edits: totalStep 2e8 -> 2000, hstep 10000 -> 500, rstep -> 1000: 15625 Ottawa sand spheres (2 types), hertz e 0.8 with limitForce, six moving mesh plates, run N every M \"if '\${eBvol} < 1.2' then 'write_restart ...' 'quit'\""
  g ykevin09+examples_LIGGGHTS $C $P/0-iso_comp.lmp | sed -e 's/^variable        totalStep equal 2e8/variable        totalStep equal 2000/' \
    -e 's/^variable        hstep equal 10000/variable        hstep equal 500/' -e 's/^variable        rstep equal v_hstep\*10/variable        rstep equal 1000/'; } > $d/in.deck
g ykevin09+examples_LIGGGHTS $C $P/input/data/Ottawa-F65.spl > $d/input/data/Ottawa-F65.spl
g ykevin09+examples_LIGGGHTS $C $P/input/mesh/plane.stl > $d/input/mesh/plane.stl

# R02: R01's deck with the void-ratio threshold 1.2 -> 100 (true at once) and a next stage appended (e 0.5, run 1000), as a
# modeller chaining stages writes it: LIGGGHTS quits in the run every's if after its first part; the appended stage never runs
d=$D/R02_ykevin_iso_comp_threshold_met_next_stage; mkdir -p $d/input/data $d/input/mesh; touch $d/LIGGGHTS; echo "0.1 1" > $d/G; echo in.deck > $d/DECK
{ echo "# R02 ykevin09/examples_LIGGGHTS $P/0-iso_comp.lmp @f1dc142; edits as R01, and threshold '< 1.2' -> '< 100', a stage appended: e 0.5 and run 1000"
  g ykevin09+examples_LIGGGHTS $C $P/0-iso_comp.lmp | sed -e 's/^variable        totalStep equal 2e8/variable        totalStep equal 2000/' \
    -e 's/^variable        hstep equal 10000/variable        hstep equal 500/' -e 's/^variable        rstep equal v_hstep\*10/variable        rstep equal 1000/' \
    -e "s/if '\${eBvol} < 1.2'/if '\${eBvol} < 100'/"
  echo "fix             m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5"; echo "run             1000"; } > $d/in.deck
g ykevin09+examples_LIGGGHTS $C $P/input/data/Ottawa-F65.spl > $d/input/data/Ottawa-F65.spl
g ykevin09+examples_LIGGGHTS $C $P/input/mesh/plane.stl > $d/input/mesh/plane.stl
echo done R02
# R03, R04: DiscreteLogarithm/capillary-LAMMPS-LIGGGHTS examples/freecool/freecool.gran.si.lammps @ a6e98666135d912c3219803bd904dba3b7d9fc3b
# (its -var values vfraction 0.3 and seed 12345 given as variable lines in front; run 100000000 -> 1000).
# R03 keeps the deck's fix addcapillaryforce (this LAMMPS has no such fix: the engine stops there); R04 comments it out.
C=a6e98666135d912c3219803bd904dba3b7d9fc3b; F=examples/freecool/freecool.gran.si.lammps
d=$D/R03_discretelog_freecool_capillary_fix; mkdir -p $d; echo "0.01 0.1" > $d/G; echo in.deck > $d/DECK
{ echo "# R03 DiscreteLogarithm/capillary-LAMMPS-LIGGGHTS $F @${C%%????????????????????????????????}; edits: -var vfraction 0.3 seed 12345 as variable lines, run 1e8 -> 1000; 27 spheres of 1 mm, mass 1 kg, gran/hertz/history gamma 0, a custom capillary fix"
  echo "variable vfraction equal 0.3"; echo "variable seed equal 12345"
  g DiscreteLogarithm+capillary-LAMMPS-LIGGGHTS $C $F | sed -e 's/^run\t\t100000000/run 1000/'; } > $d/in.deck
d=$D/R04_discretelog_freecool_no_capillary; mkdir -p $d; echo "0.01 0.1" > $d/G; echo in.deck > $d/DECK
{ echo "# R04 as R03 with the fix addcapillaryforce line commented out: elastic hertz (gamma_n 0): eps 1"
  echo "variable vfraction equal 0.3"; echo "variable seed equal 12345"
  g DiscreteLogarithm+capillary-LAMMPS-LIGGGHTS $C $F | sed -e 's/^run\t\t100000000/run 1000/' -e 's/^fix             5 all addcapillaryforce/#fix 5 all addcapillaryforce/'; } > $d/in.deck
echo done R03 R04
