import sys
from pathlib import Path

# tests/reference.py (the high-precision mpmath reference) is imported as `reference`
_TESTS = str(Path(__file__).resolve().parent)
if _TESTS not in sys.path:
    sys.path.insert(0, _TESTS)
