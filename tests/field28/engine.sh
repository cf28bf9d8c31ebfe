#!/bin/sh
# Field round 28: run a deck folder to its end in its own engine (the tool: tests/fieldkit/engine.sh; ENGINE.txt beside the deck).
ROUND=28 exec sh "$(dirname "$0")/../fieldkit/engine.sh" "$@"
