import sys
from pathlib import Path

# tests/reference.py (the high-precision mpmath reference) is imported as `reference`
_TESTS = str(Path(__file__).resolve().parent)
if _TESTS not in sys.path:
    sys.path.insert(0, _TESTS)
# benchmarks/methods.py (the other ways of solving, for comparison) is imported as `methods`
_BENCH = str(Path(__file__).resolve().parent.parent / "benchmarks")
if _BENCH not in sys.path:
    sys.path.insert(0, _BENCH)
