"""``python -m fuzzynav`` is the same as the ``fuzzynav`` command."""

import sys

from fuzzynav.cli import main

sys.exit(main())
