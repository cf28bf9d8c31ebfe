#!/bin/sh
# Field round 16: run round 13's referee over deck folders that have a spec.json, one at a time, niced
for d in "$@"; do
  [ -f "$d/spec.json" ] || continue
  echo "### $d"; nice -n 10 python tests/field13/referee13.py "$d" 2>&1 | tail -12
done
