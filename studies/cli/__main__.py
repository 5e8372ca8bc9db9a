"""``python -m studies.cli``: the ``racket-impact`` command line."""

import sys

from studies.cli import main

sys.exit(main())
