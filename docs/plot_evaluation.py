"""Plot of docs/evaluation.md: ns per vertex (points + exact normals, one core) of every
evaluation method against the surface degree, from evaluation_benchmark's --json output.

Usage: python3 docs/plot_evaluation.py RESULTS.json docs/evaluation_ns_per_vertex.png
       python3 docs/plot_evaluation.py --tables RESULTS.json   (the report's Markdown tables)
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




def markdown_tables(results_path):
    """Markdown tables of docs/evaluation.md from the same JSON (python3 plot_evaluation.py
    --tables RESULTS.json)."""
    with open(results_path) as f:
        results = json.load(f)
    rows = results["table5"]
    by = {}
    for r in rows:
        by.setdefault((r["model"], r["vertices"]), {})[r["method"]] = r
    keys = list(dict.fromkeys((r["model"], r["vertices"]) for r in rows))
    smallest = {}
    for model, n in keys:
        smallest[model] = min(smallest.get(model, n), n)

    def cell(model, n, method, mode, scale):
        r = by[(model, n)].get(method)
        if r is None:
            return "-"
        value = r[mode + " seconds"]
        return ("%.3f" % (value * 1e3)) if scale == "ms" else ("%.1f" % (value * 1e9 / n))

    columns = [
        ("optimized direct, exact", "optimized direct (coherent)", "exact normals"),
        ("optimized direct, points", "optimized direct (coherent)", "points"),
        ("optimized direct, approx.", "optimized direct (coherent)", "approx. normals"),
        ("two-stage CdB, exact", "two-stage Cox-de Boor", "exact normals"),
        ("de Casteljau, exact", "de Casteljau", "exact normals"),
        ("mod. de Casteljau, exact", "modified de Casteljau", "exact normals"),
        ("Horner, exact", "Horner power basis", "exact normals"),
        ("Horner, approx.", "Horner power basis", "approx. normals"),
        ("grid AVX2, exact", "grid evaluator AVX2", "exact normals"),
        ("grid AVX2, points", "grid evaluator AVX2", "points"),
        ("grid AVX2, approx.", "grid evaluator AVX2", "approx. normals"),
        ("OCCT D1, exact", "OCCT Geom_BSplineSurface D0/D1", "exact normals"),
        ("OCCT cache, exact", "OCCT GeomAdaptor (BSplSLib cache)", "exact normals"),
    ]
    for title, scale, pick in (
        ("milliseconds, the paper's vertex counts", "ms", lambda m, n: n == smallest[m]),
        ("ns per vertex, 1M vertices", "ns", lambda m, n: n >= 999000),
        ("ns per vertex, the paper's vertex counts", "ns", lambda m, n: n == smallest[m]),
    ):
        print("\n%s\n" % title)
        print("| model | vertices | " + " | ".join(c[0] for c in columns) + " |")
        print("|---|---:|" + "---:|" * len(columns))
        for model, n in keys:
            if not pick(model, n):
                continue
            print("| %s | %d | " % (model, n) +
                  " | ".join(cell(model, n, c[1], c[2], scale) for c in columns) + " |")
    print("\nthreaded (wall time), ns per vertex, exact normals\n")
    for model, n in keys:
        for method, r in by[(model, n)].items():
            if "threads" in method:
                print("| %s | %d | %s | %.1f | %.1f |" % (
                    model, n, method, r["points seconds"] * 1e9 / n,
                    r["exact normals seconds"] * 1e9 / n))
    print("\nscattered\n")
    for r in results.get("scattered", []):
        n = r["vertices"]
        print("| %s | %d | %.1f | %.1f | %.1f | %.1fx |" % (
            r["model"], n, r["bsplinesurface_seconds"] * 1e9 / n,
            r["point_set_evaluator_seconds"] * 1e9 / n, r["occt_adaptor_seconds"] * 1e9 / n,
            r["bsplinesurface_seconds"] / r["point_set_evaluator_seconds"]))


if __name__ == "__main__":
    if sys.argv[1] == "--tables":
        markdown_tables(sys.argv[2])
    else:
        main(sys.argv[1], sys.argv[2])
