"""``python -m studies.cli``: the ``racket-impact`` command line, run as the console command
runs it (:func:`studies.entry.main`: BLAS on one thread unless the environment says otherwise,
the garbage collector frozen at exit, a Ctrl-C at the start one line and status 130).
"""

import sys

from studies.entry import main

sys.exit(main())
