# The engines' own example decks copied into a round's decks/ as deck folders (copied at run time, not committed);
# sourced by each round's xdecksNN.sh after it sets D (its decks/ folder), which then puts its mechanisms in by sed.
# mk NAME FILE: a LAMMPS example deck FILE into D/NAME (DECK, G 1); lig TUTORIAL ...: every deck of each LIGGGHTS
# tutorial folder into D/X_lig_TUTORIAL_DECK (less its 'in.'), the folder whole, with the LIGGGHTS marker.
: "${D:?set D to the round's decks folder}"
LX=/usr/share/lammps/examples; LG=/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public
mk() { mkdir -p $D/$1; cp $2 $D/$1/; basename $2 > $D/$1/DECK; echo 1 > $D/$1/G; }
lig() {
  for t in "$@"; do
    for f in $LG/$t/in.*; do n=X_lig_${t}_$(basename $f | sed 's/^in\.//'); mkdir -p $D/$n; cp -r $LG/$t/. $D/$n/; basename $f > $D/$n/DECK; echo 1 > $D/$n/G; touch $D/$n/LIGGGHTS; done
  done
}
