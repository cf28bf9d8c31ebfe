#!/bin/sh
# Field round 47a: the minimal reproducers (the writer's own text): base.in (a LIGGGHTS hertz pair, e 0.5, 4 mm
# spheres head-on at 1 m/s) plus the lines below, each in min/<ID>/DEM/in.deck (the CFDEM layout: the deck in a
# folder named DEM that names itself as ../DEM).
cd "$(dirname "$0")"
REF='variable P47 equal vx[2]-vx[1]
print "PUB47 eps ${P47}"'
mk() {  # ID, extra lines
  rm -rf "$1"; mkdir -p "$1/DEM/post"; printf '*\n!.gitignore\n' > "$1/DEM/post/.gitignore"
  { cat base.in; printf '%s\n' "$2"; } > "$1/DEM/in.deck"
  echo "DEM/in.deck" > "$1/DECK"; echo > "$1/LIGGGHTS"; echo "1 2" > "$1/G"; printf '%s\n' "$REF" > "$1/REF"
}
mk M01_couple_cfd_thermo_var 'fix cfd all couple/cfd couple_every 100 mpi
fix cfd2 all couple/cfd/force/implicit
variable dragX equal f_cfd2[1]
thermo_style custom step atoms v_dragX
run 5000'
mk M02_couple_cfd_reduce_dragforce 'fix cfd all couple/cfd couple_every 100 mpi
fix cfd2 all couple/cfd/force/implicit
compute explDrag all reduce sum f_dragforce[1]
thermo_style custom step atoms c_explDrag
run 5000'
mk M03_couple_cfd_control 'fix cfd all couple/cfd couple_every 100 mpi
fix cfd2 all couple/cfd/force/implicit
run 5000'
mk M04_thermo_log_dotdot 'thermo_log ../DEM/post/thermo.txt
run 5000'
mk M05_thermo_log_plain_control 'thermo_log post/thermo.txt
run 5000'
mk M06_thermo_log_dotdot_file_there 'thermo_log ../DEM/post/thermo.txt
run 5000'
echo "0 old thermo" > M06_thermo_log_dotdot_file_there/DEM/post/thermo.txt
mk M07_restart_dotdot_control 'write_restart ../DEM/post/x.restart
run 5000'
mk M08_thermo_log_empty_dir 'thermo_log post/thermo.txt
run 5000'
rm -f M08_thermo_log_empty_dir/DEM/post/.gitignore
mk M09_thermo_log_dotdot_parent_file 'thermo_log ../out/thermo.txt
run 5000'
mkdir -p M09_thermo_log_dotdot_parent_file/out; echo "x" > M09_thermo_log_dotdot_parent_file/out/readme.txt
# M10: a restart written by another deck (in.init: the base pair, 10 steps, write_restart; run by LIGGGHTS here), read by
# in.run, which gives the materials, pair_style and pair_coeff again (the CFDEM init/run split)
rm -rf M10_restart_from_init_deck; mkdir -p M10_restart_from_init_deck/DEM/post
{ cat base.in; printf 'run 10\nwrite_restart post/pair.restart\n'; } > M10_restart_from_init_deck/DEM/in.init
(cd M10_restart_from_init_deck/DEM && liggghts -in in.init -log none > /dev/null 2>&1; rm in.init)
cat > M10_restart_from_init_deck/DEM/in.run <<'EOR'
atom_style      granular
atom_modify     map array
communicate     single vel yes
newton          off
read_restart    post/pair.restart
neigh_modify    delay 0
fix             m1 all property/global youngsModulus peratomtype 5.e6
fix             m2 all property/global poissonsRatio peratomtype 0.45
fix             m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix             m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style      gran model hertz tangential history
pair_coeff      * *
timestep        1e-6
fix             integr all nve/sphere
run             5000
EOR
echo "DEM/in.run" > M10_restart_from_init_deck/DECK; echo > M10_restart_from_init_deck/LIGGGHTS; echo "1 2" > M10_restart_from_init_deck/G
printf '%s\n' "$REF" > M10_restart_from_init_deck/REF
