#!/bin/sh
# Field round 28: copy the engines' own example decks into decks/X* (not committed: copied at run time), with one of
# this round's mechanisms put in (pre no after a size change, a skin set after a run, a step variable read after an
# every run, type/fraction after a run).
D=$(dirname "$0")/decks; . "$(dirname "$0")/../fieldkit/xdecks.sh"   # mk, lig, LX, LG
mk X01_pour $LX/pour/in.pour
mk X02_pour_pre_no_grow $LX/pour/in.pour; sed -i '52s/.*/set type 1 diameter 1.6\nrun 25000 pre no/' $D/X02_pour_pre_no_grow/in.pour
mk X03_pour_skin_after $LX/pour/in.pour; sed -i '52s/.*/neighbor 0.02 bin\nrun 25000/' $D/X03_pour_skin_after/in.pour
mk X04_pour_step_var $LX/pour/in.pour; sed -i '48s/.*/run 25000 every 5000 "variable s equal $(step)"\nif "${s} == 25000" then "pair_style gran\/hooke\/history 4000.0 NULL 50.0 NULL 0.5 0" "pair_coeff * *"/' $D/X04_pour_step_var/in.pour
mk X05_flatwall_step_var $LX/granular/in.pour.flatwall; sed -i '65s/.*/run 5000 every 1000 "variable s equal $(step)"\nif "${s} == 5000" then "neighbor 0.001 bin"\nrun 1000/' $D/X05_flatwall_step_var/in.pour.flatwall
mk X06_box_type_fraction $LX/granregion/in.granregion.box; sed -i '52s/.*/set type 2 type\/fraction 1 0.5 77\nrun 5000/' $D/X06_box_type_fraction/in.granregion.box
mk X07_box_pre_no_grow $LX/granregion/in.granregion.box; sed -i '52s/.*/set type 2 diameter 1.5\nrun 5000 pre no/' $D/X07_box_pre_no_grow/in.granregion.box
lig packing
