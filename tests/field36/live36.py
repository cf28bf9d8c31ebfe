"""Field round 36 referee: the deck run AS WRITTEN on 1 process and on several (tests/fieldkit/live_np.py says how).
usage: python live36.py DECKDIR ...      prints NAME | np=1 LIVE36 eps ... | np=2 LIVE36 eps ..."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import live_np  # noqa: E402

if __name__ == "__main__":
    live_np.main(sys.argv[1:], round=36, var="L36", tag="LIVE36")
