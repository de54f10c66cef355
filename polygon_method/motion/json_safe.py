"""What a solution's JSON may hold: bounds too large to be of use written as None (with how
many and why), and never a NaN or an inf (JSON holds neither): each written as None, with a
warning naming where.

>>> finite_only({"v": 1.5, "w": float("inf"), "warnings": []})
{'v': 1.5, 'w': None, 'warnings': ['1 number(s) overflowed or are undefined, written as null: w']}
"""

from __future__ import annotations

from ..solver.errorbound import NO_BOUND, USELESS

__all__ = ["useful_bounds", "finite_only"]


def useful_bounds(d: dict) -> dict:
    """The JSON's ``error_bounds`` with each bound of :data:`USELESS` or more (no useful
    bound: it may be as large as the largest value of its kind) written as None, and
    ``no_useful_bound`` giving their count and the reason."""
    count = [0]

    def clean(x):
        if isinstance(x, dict):
            return {k: clean(v) for k, v in x.items()}
        if x < USELESS:
            return float(x)
        count[0] += 1
        return None

    out = {"relative_to": d["relative_to"]}
    out.update(clean({k: v for k, v in d.items() if k != "relative_to"}))
    if count[0]:
        out["no_useful_bound"] = {"count": count[0] - (out["worst"] is None), "reason": NO_BOUND}
    return out


def finite_only(d: dict) -> dict:
    """``d`` with every number JSON cannot hold (an overflow to inf, an undefined value)
    written as None, and a warning saying so: the JSON never holds NaN or inf."""
    bad = []

    def clean(x, where):
        if isinstance(x, float):
            if x - x == 0.0:  # finite
                return x
            bad.append(where)
            return None
        if isinstance(x, dict):
            return {k: clean(v, f"{where}.{k}" if where else str(k)) for k, v in x.items()}
        if isinstance(x, (list, tuple)):
            return [clean(v, where) for v in x]
        return x

    out = clean(d, "")
    if bad:
        out["warnings"].append(
            f"{len(bad)} number(s) overflowed or are undefined, written "
            f"as null: {', '.join(dict.fromkeys(bad[:5]))}" + (" ..." if len(bad) > 5 else "")
        )
    return out
