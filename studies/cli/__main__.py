"""``python -m studies.cli``: the ``racket-impact`` command line (BLAS on one thread unless
the environment says otherwise, as :mod:`studies.entry`).
"""

import sys

from common.blas import one_blas_thread_unless_set

one_blas_thread_unless_set()  # before numpy loads

from studies.cli import main  # noqa: E402

sys.exit(main())
