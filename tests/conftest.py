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

import pytest  # noqa: E402


@pytest.fixture(autouse=True)
def _mpmath_precision_kept():
    """Each test finds mpmath at the precision the reference sets (50 digits) and leaves it
    there: a test that works at 30 digits and forgets to restore them must not lower the
    precision of the reference solves in the tests after it."""
    import mpmath

    saved = mpmath.mp.dps
    yield
    mpmath.mp.dps = saved
