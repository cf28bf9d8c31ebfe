#!/bin/sh
# Field round 29: copy the engines' own example decks into decks/X* (not committed: copied at run time), with one of
# this round's mechanisms put in (a step-named include, nsq after a run, pre no after growth, type/fraction after a run,
# quoted includes).
D=$(dirname "$0")/decks; . "$(dirname "$0")/../fieldkit/xdecks.sh"   # mk, lig, LX, LG
mk X01_pour_include_step $LX/pour/in.pour; sed -i '52s/.*/include k$(step).in\nrun 25000/' $D/X01_pour_include_step/in.pour
printf 'pair_style gran/hooke/history 4000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *\n' > $D/X01_pour_include_step/k25000.in
printf 'pair_style gran/hooke/history 8000.0 NULL 50.0 NULL 0.5 0\npair_coeff * *\n' > $D/X01_pour_include_step/k0.in
mk X02_pour_include_plain $LX/pour/in.pour; sed -i '52s/.*/include "k25000.in"\nrun 25000/' $D/X02_pour_include_plain/in.pour
cp $D/X01_pour_include_step/k25000.in $D/X02_pour_include_plain/
mk X03_pour_nsq_after $LX/pour/in.pour; sed -i '52s/.*/neighbor 0.2 nsq\nrun 25000/' $D/X03_pour_nsq_after/in.pour
mk X04_pour_pre_no_grow $LX/pour/in.pour; sed -i '52s/.*/set type 1 diameter 1.6\nrun 25000 pre no/' $D/X04_pour_pre_no_grow/in.pour
mk X05_box_fraction $LX/granregion/in.granregion.box; sed -i '52s/.*/set type 2 type\/fraction 1 0.5 77\nrun 5000/' $D/X05_box_fraction/in.granregion.box
mk X06_box_fraction_budget0 $LX/granregion/in.granregion.box; sed -i '52s/.*/set type 2 type\/fraction 1 0.5 77\nrun 5000/' $D/X06_box_fraction_budget0/in.granregion.box
echo "--run-budget 0" > $D/X06_box_fraction_budget0/ARGS
