#!/bin/bash
# Runs `nurbslod verify` and tools/meshjudge.py side by side on FreeCAD's own BRepMesh
# tessellation of each model, and prints both summaries, their run times and a per-face
# comparison (faces whose verdicts differ, or whose numbers differ by more than tol/10).
#
# Usage: compare_with_meshjudge.sh BUILD_DIR OUT_DIR MODEL RELATIVE [MODEL RELATIVE ...]
#   RELATIVE: the deflection and the tolerance, as a fraction of the model's bounding-box
#   diagonal (both tools get the same absolute tolerance).
# Exit code 1 when a face's PASS/FAIL differs between the two.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1 out=$2
shift 2
mkdir -p "$out"
judge=${MESHJUDGE:-$here/../../../shared/tools/meshjudge.py}
status=0
while [ $# -ge 2 ]; do
    model=$1 relative=$2
    shift 2
    name=$(basename "$model")
    name=${name%.*}
    diagonal=$(/usr/bin/python3 -c "
import sys; sys.path.append('/usr/lib/freecad-python3/lib'); import FreeCAD, Part
s = Part.Shape(); s.read('$model'); print(repr(s.BoundBox.DiagonalLength))" 2>/dev/null | tail -1)
    tolerance=$(python3 -c "print(repr($relative * $diagonal))")
    echo "== $name: tolerance $tolerance (relative $relative of diagonal $diagonal)"
    /usr/bin/python3 "$here/brepmesh_obj.py" "$model" "$tolerance" "$out/$name.obj" >/dev/null
    # wall and CPU (user + system) seconds of each whole process, reading the model included
    start=$(date +%s.%N)
    /usr/bin/time -f "%U %S" -o "$out/$name.judge.cpu" /usr/bin/python3 "$judge" "$model" \
        "$out/$name.obj" --tol "$tolerance" --json "$out/$name.judge.json" | tail -1 || true
    middle=$(date +%s.%N)
    /usr/bin/time -f "%U %S" -o "$out/$name.verify.cpu" "$build/App/nurbslod" verify "$model" \
        "$out/$name.obj" --tolerance "$tolerance" --json "$out/$name.verify.json" |
        tail -2 | head -1 || true
    end=$(date +%s.%N)
    python3 - "$out/$name.judge.json" "$out/$name.verify.json" "$start" "$middle" "$end" \
        "$(cat "$out/$name.judge.cpu")" "$(cat "$out/$name.verify.cpu")" <<'PY' || status=1
import json, sys
judge, verify = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
start, middle, end = map(float, sys.argv[3:6])
judge_cpu, verify_cpu = (sum(map(float, t.split()[-2:])) for t in sys.argv[6:8])
tol = judge["tol"]
faces = {f["face"]: f for f in verify["per_face"]}
disagree = 0
for key, j in sorted(judge["per_face"].items(), key=lambda kv: int(kv[0])):
    v = faces.get(int(key))
    judge_pass = j["dev"] <= tol and j["cover"] <= tol
    verify_pass = bool(v and v["measured"] and v["dev"] <= tol and v["cover"] <= tol)
    disagree += judge_pass != verify_pass
    if judge_pass != verify_pass or abs(j["dev"] - v["dev"]) > tol / 10 or abs(j["cover"] - v["cover"]) > tol / 10:
        print("  Face%-5s judge dev %-10.4g cover %-10.4g | verify dev %-10.4g cover %-10.4g  %s" % (
            key, j["dev"], j["cover"], v["dev"], v["cover"],
            "VERDICTS DIFFER" if judge_pass != verify_pass else "numbers differ"))
print("  faces measured by both %d, verdicts differ on %d\n"
      "  judge  %.2f s wall, %.2f s CPU, its own timer %.2f s\n"
      "  verify %.2f s wall, %.2f s CPU, its own timer %.2f s" % (
          len(judge["per_face"]), disagree, middle - start, judge_cpu, judge["judge_seconds"],
          end - middle, verify_cpu, verify["seconds"]))
sys.exit(1 if disagree else 0)
PY
done
exit $status
