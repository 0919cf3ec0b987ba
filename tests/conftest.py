"""Test-suite configuration.

The pyfuzzylite cross-checks (``tests/fll``) need pyfuzzylite, which pins numpy < 2 and is GPL,
so they run in their own virtual environment (``.ci/run`` step 2: ``pytest -m fll tests/fll``).
Where pyfuzzylite is not installed they are not collected at all (rather than reported skipped).
"""

import importlib.util

collect_ignore = [] if importlib.util.find_spec("fuzzylite") else ["fll"]
