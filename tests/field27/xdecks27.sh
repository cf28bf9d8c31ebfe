#!/bin/sh
# Field round 27: copy the engines' own example decks into decks/X* (not committed: copied at run time), some with one
# of this round's mechanisms put in (a run made as run N every M, pre no after a restyle, clear first).
D=$(dirname "$0")/decks; . "$(dirname "$0")/../fieldkit/xdecks.sh"   # mk, lig, LX, LG
mk X01_pour $LX/pour/in.pour
mk X02_pour_every1 $LX/pour/in.pour; sed -i '0,/^run\t\t25000/s//run 25000 every 5000 "print part"/' $D/X02_pour_every1/in.pour
mk X03_pour_every2_restyle $LX/pour/in.pour; sed -i '$s/.*/run 25000 every 5000 "pair_style gran\/hooke\/history 4000.0 NULL 50.0 NULL 0.5 0" "pair_coeff * *"/' $D/X03_pour_every2_restyle/in.pour
mk X04_pour_clear $LX/pour/in.pour; sed -i '1i clear' $D/X04_pour_clear/in.pour
mk X05_pour_preno_restyle $LX/pour/in.pour; sed -i '$s/.*/pair_style gran\/hooke\/history 4000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *\nrun 25000 pre no/' $D/X05_pour_preno_restyle/in.pour
mk X06_drum $LX/granular/in.pour.drum
mk X07_flatwall $LX/granular/in.pour.flatwall
mk X08_granregion_box $LX/granregion/in.granregion.box
mk X09_funnel $LX/granregion/in.granregion.funnel
mk X10_pour2d $LX/pour/in.pour.2d
mk X11_pour2d_molecule $LX/pour/in.pour.2d.molecule; cp $LX/pour/molecule.vshape $D/X11_pour2d_molecule/
mk X12_flatwall_every $LX/granular/in.pour.flatwall; sed -i '$s/^run *\([0-9]*\)/run \1 every 1000 "print part"/' $D/X12_flatwall_every/in.pour.flatwall
mk X13_box_lostwarn $LX/granregion/in.granregion.box; sed -i '1i thermo_modify lost warn' $D/X13_box_lostwarn/in.granregion.box
lig chute_wear cohesion contactModels conveyor heatTransfer_1 hysteresis insert_stream meshGran movingMeshGran packing
