"""The summary's candidates for refinement, chosen per chunk: the same choice, in the same
order, as offering the dictionary every local maximum and keeping the best few (the plain
rule, written here on its own), on noisy chunks with ties and on chunks of one or two."""

import numpy as np
import pytest

from polygon_method.linkage import summary


def _plain(keep, c, index):
    """Every interior local maximum and both ends offered, the best few kept."""
    n = len(c)
    peaks = [
        k
        for k in range(1, n - 1)
        if c[k] >= c[k - 1] and c[k] >= c[k + 1] and (c[k] > c[k - 1] or c[k] > c[k + 1])
    ]
    for k in [*peaks, 0, n - 1]:
        keep[int(index[k])] = float(c[k])
    if len(keep) > summary._CANDIDATES:
        top = sorted(keep.items(), key=lambda kv: -kv[1])[: summary._CANDIDATES]
        keep.clear()
        keep.update(top)


@pytest.mark.parametrize("seed", range(40))
def test_chunks_keep_the_plain_rules_choice_in_its_order(seed):
    rng = np.random.default_rng(seed)
    a, b, start = {}, {}, 0
    chunks = 0
    for _ in range(int(rng.integers(1, 6))):
        n = int(rng.integers(1, 400))
        if seed % 3 == 0:  # rounded to a few levels: ties everywhere
            c = np.round(rng.normal(size=n), 1)
        elif seed % 3 == 1:  # a smooth curve with rounding noise
            c = np.sin(np.linspace(0, 6, n)) + rng.normal(scale=1e-12, size=n)
        else:
            c = rng.normal(size=n)
        index = np.arange(start, start + n)
        start += n
        summary._keep_best(a, c, index)
        _plain(b, c, index)
        chunks += 1
        assert list(a.items()) == list(b.items())
    assert chunks >= 1
