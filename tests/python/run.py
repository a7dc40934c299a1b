"""Runs the Python package's tests (ctest entry `python`): exits 77 (ctest: not run) when NumPy is
missing for this interpreter, else the unittest result."""

import sys
import unittest
from pathlib import Path

try:
    import numpy  # noqa: F401
except ImportError:
    print(f"not run: NumPy is missing for {sys.executable} (Debian: python3-numpy; tools/install-deps.sh)")
    sys.exit(77)

here = Path(__file__).resolve().parent
sys.path.insert(0, str(here))
suite = unittest.defaultTestLoader.discover(str(here), pattern="test_*.py", top_level_dir=str(here))
result = unittest.TextTestRunner(verbosity=2).run(suite)
sys.exit(0 if result.wasSuccessful() else 1)
