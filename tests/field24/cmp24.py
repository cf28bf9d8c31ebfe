"""Field round 24: the referee24.py lines where the engine's eps and the audit's differ by more than 2e-5 (the tool: tests/fieldkit/cmp.py, which says how it works).
usage: python cmp24.py referee*.log"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import cmp  # noqa: E402

cmp.main(sys.argv[1:], tag="PROBE24")
