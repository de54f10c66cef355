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


#: Chromium's switches for a headless run with no network and nothing started beside the page
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def _chromium():
    """The system's Chromium (``$CHROMIUM``, Debian's /usr/bin/chromium, or on the path)."""
    import os
    import shutil

    for path in (
        os.environ.get("CHROMIUM"),
        "/usr/bin/chromium",
        shutil.which("chromium"),
        shutil.which("chromium-browser"),
    ):
        if path and os.path.exists(path):
            return path
    return None


@pytest.fixture(scope="module")
def browser():
    """Headless Chromium driven by Playwright, one per test module; where Playwright or the
    browser is missing, or it will not start, the tests that ask for it skip saying which
    (``.ci/run`` installs both where it can)."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        pytest.skip(
            "playwright is not installed (pip install playwright): the page's "
            "browser tests cannot run"
        )
    exe = _chromium()
    if exe is None:
        pytest.skip(
            "no Chromium found (/usr/bin/chromium; apt-get install chromium): the "
            "page's browser tests cannot run"
        )
    with sync_playwright() as p:
        try:
            b = p.chromium.launch(executable_path=exe, args=CHROMIUM_ARGS)
        except Exception as exc:  # a browser that will not start is a skip with its reason
            pytest.skip(f"Chromium at {exe} does not start: {str(exc).splitlines()[0]}")
        yield b
        b.close()
