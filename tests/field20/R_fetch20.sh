#!/bin/sh
# Field round 20: build the public decks R01-R04 from their repositories (their text is not committed).
# usage (from the worktree): sh tests/field20/R_fetch20.sh MIRRORS   where MIRRORS/<owner>+<name>/repo is a git directory
# of each repository (a bare clone); the commits are pinned below. Edits (runs shortened, template placeholders filled,
# particle counts cut) are made by sed and listed in each deck's first comment lines.
M=${1:?mirror directory}
D=tests/field20/decks
g() { git --git-dir="$M/$1/repo" show "$2:$3"; }
# R01: simongravelle/lammps-input-files inputs/pouring-granular/input.lammps @ 3e31ef4c101d8c54dcd2095bab7e2237df23dcae
d=$D/R01_gravelle_pouring_loop; mkdir -p $d; echo "0.1 1" > $d/G
{ echo "# R01 simongravelle/lammps-input-files inputs/pouring-granular/input.lammps @3e31ef4c; edits: loop 10000 -> 3, final run 2000000 -> 2000, dump removed: 4 pours (default d 1, dens 1) redefined each pass, wall/gran/region hooke/history on the box"
  g simongravelle+lammps-input-files 3e31ef4c101d8c54dcd2095bab7e2237df23dcae inputs/pouring-granular/input.lammps \
  | sed -e 's/loop 10000/loop 3/' -e 's/^run 2000000.*/run 2000/' -e 's/^dump /#dump /'; } > $d/in.deck
# R02: Linussgi/liggghts-dem-study study-templates/resodyn.sim + particles.sim + cylinder.stl @ 1f8bbfee3c11480459e255318178cfde6b7de0dc
d=$D/R02_linussgi_resodyn_mixer; mkdir -p $d/post; touch $d/LIGGGHTS; echo "0.1 1" > $d/G
C=1f8bbfee3c11480459e255318178cfde6b7de0dc
{ echo "# R02 Linussgi/liggghts-dem-study study-templates/resodyn.sim @1f8bbfee; edits: placeholders num_particles 300, amp 0.00255, fric_pp 0.5; runs 2 s, 10 s, 1 s -> 0.01 s, 0.005 s, 0.005 s; dumps removed: 10 templates of type 1, sjkr cohesion with energy density 0, cdt rolling, mesh wiggled"
  g Linussgi+liggghts-dem-study $C study-templates/resodyn.sim | sed -e 's/{{ num_particles }}/300/' -e 's/{{ amp }}/0.00255/' \
   -e 's#equal 2/${timestep}#equal 0.01/${timestep}#' -e 's#equal 10/${timestep}#equal 0.005/${timestep}#' -e 's#equal 1/${timestep}#equal 0.005/${timestep}#' \
   -e 's/^dump /#dump /' -e 's/^variable insert_every equal 0.1/variable insert_every equal 0.001/'; } > $d/in.deck
g Linussgi+liggghts-dem-study $C study-templates/particles.sim | sed -e 's/{{ fric_pp }}/0.5/' > $d/particles.sim
g Linussgi+liggghts-dem-study $C study-templates/cylinder.stl > $d/cylinder.stl
# R03, R04: uob-positron-imaging-centre/DigitalTwins @ b2a50e0 (GranuDrum MCC input, GranuHeap template)
C=$(git --git-dir="$M/uob-positron-imaging-centre+DigitalTwins/repo" rev-parse HEAD)
d=$D/R03_uob_granudrum_mcc; mkdir -p $d/mesh $d/simulation_inputs; touch $d/LIGGGHTS; echo "0.1 1" > $d/G
{ echo "# R03 uob-positron-imaging-centre/DigitalTwins GranuDrum/access_calibration/simulation_inputs/granudrum_mcc_000000.sim @$C; edits: N 29954 -> 300, a run 3000 appended (the script's driver runs it): 10 templates of type 1 by number, sjkr energy density 0, rotating meshes, a log line to a subfolder"
  g uob-positron-imaging-centre+DigitalTwins $C GranuDrum/access_calibration/simulation_inputs/granudrum_mcc_000000.sim | sed -e 's/^variable N equal 29954.0/variable N equal 300/'; echo "run 3000"; } > $d/in.deck
for f in inface_mm.stl rotating_drum_mm.stl rotating_drum_side_mm.stl; do g uob-positron-imaging-centre+DigitalTwins $C GranuDrum/access_calibration/mesh/$f > $d/mesh/$f; done
d=$D/R04_uob_granuheap; mkdir -p $d/mesh; touch $d/LIGGGHTS; echo "0.1 1" > $d/G
{ echo "# R04 uob-positron-imaging-centre/DigitalTwins GranuHeap/minimal/granuheap_template.sim @$C; edits: N 29954 -> 300, a run 3000 appended: insert/stream of 10 radii by number, curvature_tolerant bottom mesh, sjkr energy density 0"
  g uob-positron-imaging-centre+DigitalTwins $C GranuHeap/minimal/granuheap_template.sim | sed -e 's/^variable N              equal 29954/variable N equal 300/'; echo "run 3000"; } > $d/in.deck
for f in aor_bottom.stl inlet.stl wall.stl; do g uob-positron-imaging-centre+DigitalTwins $C GranuHeap/minimal/mesh/$f > $d/mesh/$f; done
echo done
