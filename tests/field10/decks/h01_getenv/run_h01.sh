#!/bin/sh
# h01 reads F10_KN from the environment: run it with the value the referee assumes
F10_KN=3000 exec "$(dirname "$0")/../../run.sh" "$(dirname "$0")"
