"""``python -m restitution.cli``: the ``restitution`` command."""

import sys

from . import main

if __name__ == "__main__":   # imported (a package walk, the docs), it runs nothing
    sys.exit(main())
