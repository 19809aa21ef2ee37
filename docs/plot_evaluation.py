"""Plot of docs/evaluation.md: ns per vertex (points + exact normals, one core) of every
evaluation method against the surface degree, from evaluation_benchmark's --json output.

Usage: python3 docs/plot_evaluation.py RESULTS.json docs/evaluation_ns_per_vertex.png
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# the single-surface models of the study and their (bi-)degree
DEGREES = {"Torus": 2, "Bicubic 8x8 spans": 3, "Sup.5x5": 5, "Sup.10x10": 10, "Sup.15x15": 15}


def main(results_path, image_path):
    with open(results_path) as f:
        results = json.load(f)
    rows = [r for r in results["table5"] if r["model"] in DEGREES]
    # the largest grid measured per model (1M vertices in a full run)
    largest = {}
    for r in rows:
        largest[r["model"]] = max(largest.get(r["model"], 0), r["vertices"])
    series = {}
    for r in rows:
        if r["vertices"] != largest[r["model"]]:
            continue
        ns = r["exact normals seconds"] * 1e9 / r["vertices"]
        series.setdefault(r["method"], []).append((DEGREES[r["model"]], ns))
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for method, points in sorted(series.items()):
        points.sort()
        style = "--" if method.startswith("OCCT") else "-"
        ax.plot([p[0] for p in points], [p[1] for p in points], style, marker="o", label=method)
    ax.set_yscale("log")
    ax.set_xlabel("bi-degree of the surface")
    ax.set_ylabel("ns per vertex, points + exact normals (log)")
    counts = sorted(set(largest.values()))
    ax.set_title("NURBS grid evaluation, one core, %s vertices per model" %
                 ", ".join("{:,}".format(c) for c in counts))
    ax.set_xticks(sorted(set(DEGREES.values())))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(image_path, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
