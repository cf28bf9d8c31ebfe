#!/bin/sh
# Field round 22: run a deck folder to its end in its own engine (the tool: tests/fieldkit/engine.sh; ENGINE.txt beside the deck).
ROUND=22 exec sh "$(dirname "$0")/../fieldkit/engine.sh" "$@"
