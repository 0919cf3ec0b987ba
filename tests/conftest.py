"""Test-suite configuration.

The pyfuzzylite cross-checks (``tests/fll``) need pyfuzzylite, which pins numpy < 2 and is GPL,
so they run in their own virtual environment (``.ci/run`` step 2: ``pytest -m fll tests/fll``).
Where pyfuzzylite is not installed they are not collected at all (rather than reported skipped).
"""

import importlib.util
import os

from hypothesis import settings

collect_ignore = [] if importlib.util.find_spec("fuzzylite") else ["fll"]

# Property tests: no per-example deadline (the CI machine is shared and its timing varies), and in CI
# (CI=true) a derandomized search, so a run is reproducible; locally the search stays random.
settings.register_profile("default", deadline=None)
settings.register_profile("ci", deadline=None, derandomize=True)
settings.load_profile("ci" if os.environ.get("CI") else "default")
