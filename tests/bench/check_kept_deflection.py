#!/usr/bin/python3
"""Runs model_benchmark.py --kept-deflection on the bolt at relative 1e-3 with one halving and
checks what it reports of BRepMesh at equal measured error: every face accounted for, the
per-face sums consistent with the main table, the table in the Markdown. Exit 77 (skipped) when
the corpus is absent. Usage: check_kept_deflection.py BUILD_DIR"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(HERE))), "shared", "corpus")
MODEL = "bug3883_xr2-ct-214_bolt.stp"


def main():
    if not os.path.isfile(os.path.join(CORPUS, MODEL)):
        print("check_kept_deflection: %s absent; skipped" % MODEL)
        return 77
    with tempfile.TemporaryDirectory(prefix="nurbslod-kept-") as out:
        md, report = os.path.join(out, "bench.md"), os.path.join(out, "bench.json")
        run = subprocess.run(
            [sys.executable, os.path.join(HERE, "model_benchmark.py"), "--corpus", CORPUS,
             "--models", MODEL, "--relative", "1e-3", "--repeat", "1", "--kept-deflection",
             "--kept-halvings", "1", "--build", sys.argv[1], "--out", out, "--md", md,
             "--json", report], stdin=subprocess.DEVNULL, capture_output=True, text=True,
            timeout=600)
        assert run.returncode == 0, run.stdout + run.stderr
        with open(report) as fh:
            entry = json.load(fh)["results"][0]
        kept = entry["kept"]
        assert "error" not in kept, kept
        assert kept["faces"] == 7, kept
        assert len(kept["runs"]) == 2 and all("error" not in r for r in kept["runs"]), kept
        assert sum(kept["halvings_histogram"]) == kept["faces_kept"], kept
        assert kept["faces_kept"] + len(kept["faces_never_kept"]) == kept["faces"], kept
        # the bolt's BRepMesh mesh keeps T on every face at D = T: its whole mesh, both ways
        assert kept["faces_kept"] == 7 and kept["whole_model"]["deflection"] == entry["tolerance"]
        methods = entry["methods"]
        assert kept["brepmesh_triangles"] == methods["brepmesh"]["tessellate"]["triangles"]
        assert kept["ours_triangles"] == methods["nurbslod-guaranteed"]["tessellate"]["triangles"]
        with open(md) as fh:
            text = fh.read()
        assert "## BRepMesh at equal measured error" in text, text
    print("check_kept_deflection: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
