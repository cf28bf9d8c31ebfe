#!/bin/sh
# Field round 42: the referee (round 37's live37.py, 1 process) then the kit's audit (QUICK, one core), one after the other.
cd "$(dirname "$0")/../.."
python tests/field37/live37.py tests/field42/decks/* > tests/field42/live1.log 2>&1
QUICK=1 ROUND=42 sh tests/fieldkit/audit.sh tests/field42/decks/* > tests/field42/batch1.log 2>&1
# the second set (C10 C11 made again with their groups; F17 F18 as region walls; K, G16-G21, W13), after the first
S2="tests/field42/decks/C10_write_data_read_data tests/field42/decks/C11_write_data_nocoeff_pc5 tests/field42/decks/F17_wall_region_harmonic_mid tests/field42/decks/F18_wall_region_lj93_start tests/field42/decks/K* tests/field42/decks/G1[6-9]* tests/field42/decks/G2* tests/field42/decks/W13*"
python tests/field37/live37.py $S2 > tests/field42/live2.log 2>&1
QUICK=1 ROUND=42 sh tests/fieldkit/audit.sh $S2 > tests/field42/batch2.log 2>&1
# the third set, after the second
S3="tests/field42/decks/N2[345]* tests/field42/decks/G22* tests/field42/decks/C1[2-5]*"
python tests/field37/live37.py $S3 > tests/field42/live3.log 2>&1
QUICK=1 ROUND=42 sh tests/fieldkit/audit.sh $S3 > tests/field42/batch3.log 2>&1
# the fourth set, after the third
S4="tests/field42/decks/N2[6-9]* tests/field42/decks/G23*"
python tests/field37/live37.py $S4 > tests/field42/live4.log 2>&1
QUICK=1 ROUND=42 sh tests/fieldkit/audit.sh $S4 > tests/field42/batch4.log 2>&1
# the fifth set, after the fourth
S5="tests/field42/decks/R09* tests/field42/decks/R1[0-4]* tests/field42/decks/W14* tests/field42/decks/G24*"
python tests/field37/live37.py $S5 > tests/field42/live5.log 2>&1
QUICK=1 ROUND=42 sh tests/fieldkit/audit.sh $S5 > tests/field42/batch5.log 2>&1
# the sixth set
S6="tests/field42/decks/R1[5-7]* tests/field42/decks/E19*"
python tests/field37/live37.py $S6 > tests/field42/live6.log 2>&1
QUICK=1 ROUND=42 sh tests/fieldkit/audit.sh $S6 > tests/field42/batch6.log 2>&1
# the seventh set
S7="tests/field42/decks/H0*"
python tests/field37/live37.py $S7 > tests/field42/live7.log 2>&1
QUICK=1 ROUND=42 sh tests/fieldkit/audit.sh $S7 > tests/field42/batch7.log 2>&1
