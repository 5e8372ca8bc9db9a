"""``python -m studies.cli``: the ``racket-impact`` command line, run as the console command
runs it (:func:`studies.entry.main`: the garbage collector frozen at exit, a Ctrl-C at the
start one line and status 130; BLAS on one thread unless the environment says otherwise, set
by :mod:`studies.cli` itself as Python locates this module, before numpy loads).
"""

import sys

from studies.entry import main

sys.exit(main())
