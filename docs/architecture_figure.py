"""Draw docs/images/architecture.svg: the layers of the package, as the import-linter
contract in pyproject.toml states them (read from it, so the figure stays true), each
module a box with its line count.

    python docs/architecture_figure.py
"""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "docs" / "images" / "architecture.svg"

WORDS = {  # what each layer is for (the contract names the folders)
    0: "command line: parses, reads files, prints, writes",
    1: "the page and the animations: a whole cycle",
    2: "views: checking answers, drawings and plots, variants",
    3: "the solution in words: report, step table, forces, centres",
    4: "a cycle's shape; each polygon and its scale",
    5: "the motion records: one solve, a sweep",
    6: "plan, motion, branch, bounds, centres; forces",
    7: "one module per construction kind",
    8: "the scene: records and the reader",
    9: "errors, units, how numbers are written",
}


def _lines(module: str) -> int:
    rel = Path(*module.split("."))
    f = ROOT / rel.with_suffix(".py")
    if f.exists():
        return len(f.read_text().splitlines())
    return sum(len(p.read_text().splitlines()) for p in (ROOT / rel).glob("*.py"))


def main():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyBboxPatch

    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]
    layers = cfg["contracts"][0]["layers"]
    rows = [[m.strip() for m in layer.split("|")] for layer in layers]
    width, row_h = 15.0, 0.82
    fig = Figure(figsize=(width / 2.54 * 1.25, (len(rows) * row_h + 1.2) / 2.54 * 1.25))
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, width)
    ax.set_ylim(0, len(rows) * row_h + 1.2)
    ax.axis("off")
    ax.text(
        0.2,
        len(rows) * row_h + 0.75,
        "polygon_method: imports go down only (checked by lint-imports)",
        fontsize=8,
        weight="bold",
        va="center",
    )
    for i, mods in enumerate(rows):
        y = (len(rows) - 1 - i) * row_h + 0.35
        box_w = (9.6 - 0.15 * (len(mods) - 1)) / len(mods)
        for k, m in enumerate(mods):
            x = 0.2 + k * (box_w + 0.15)
            pkg = (ROOT / Path(*m.split("."))).is_dir()
            ax.add_patch(
                FancyBboxPatch(
                    (x, y),
                    box_w,
                    row_h - 0.2,
                    boxstyle="round,pad=0.02,rounding_size=0.08",
                    fc="#dde6f2" if not pkg else "#f4e3b5",
                    ec="#23395d",
                    lw=0.6,
                )
            )
            name = m.split(".", 1)[1] + ("/" if pkg else "")
            ax.text(
                x + box_w / 2,
                y + (row_h - 0.2) / 2,
                f"{name}  {_lines(m)}",
                ha="center",
                va="center",
                fontsize=5.6,
            )
        ax.text(
            10.0,
            y + (row_h - 0.2) / 2,
            WORDS.get(i, ""),
            va="center",
            fontsize=5.6,
            color="#444444",
        )
    ax.annotate(
        "",
        xy=(14.7, 0.35),
        xytext=(14.7, len(rows) * row_h + 0.1),
        arrowprops={"arrowstyle": "->", "lw": 0.8, "color": "#23395d"},
    )
    OUT.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(OUT, format="svg", metadata={"Date": None})
    fig.savefig(OUT.with_suffix(".png"), format="png", dpi=150)
    print(OUT)


if __name__ == "__main__":
    main()
