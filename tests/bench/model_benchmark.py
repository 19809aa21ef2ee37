#!/usr/bin/python3
"""Model-level benchmark: NurbsLOD (guaranteed, approximate) against OpenCASCADE's BRepMesh.

For every corpus model and relative tolerance R, with T = R * bounding-box diagonal:
  - `nurbslod tessellate --mode guaranteed|approximate --tolerance T --threads N`
  - BRepMesh_IncrementalMesh at deflection D = T, angular 0.5 rad, timed in-process by
    build/tests/bench/brepmesh_timer (parallel mode when N != 1: BRepMesh cannot be held to N)
and for every mesh: triangles, seconds (tessellation only, as each tool reports it), end-to-end
seconds (the whole process: reading the file, NurbsLOD's import and NURBS conversion, meshing,
writing the mesh), each the least of --repeat runs (default 3), then the
measured deviation from `nurbslod verify` (dev = mesh -> face, cover = face -> mesh, open edges
after welding) and, with --judge, from the independent meshjudge.py (slow: it meshes a
reference at T/10).

With --kept-deflection, BRepMesh is also compared at equal measured error: it is run again at
D = T/2, T/4, ... (--kept-halvings, default 4), every mesh verified, and each face takes its
triangles from the largest D at which that face keeps T both ways. The sum over those faces is
set beside NurbsLOD's guaranteed triangles on the same faces; faces that keep T at no D are
counted apart. (Triangles per face of one BRepMesh run; its faces share their edges'
discretisation, so this is an estimate of what BRepMesh needs, not a mesh it makes.)

Prints a table plus ratio rows (NurbsLOD / BRepMesh for triangles and seconds) and writes it as
Markdown to docs/benchmark.md and the raw numbers to docs/benchmark.json (--md/--json move them).
A step that runs past --timeout is recorded as TIMEOUT in the table, never dropped.

Usage (run with /usr/bin/python3, which has FreeCAD's and meshjudge's dependencies):
  tests/bench/model_benchmark.py [--corpus DIR] [--models a b] [--relative 1e-3 1e-4]
      [--threads N] [--judge] [--judge-relative 1e-3] [--out DIR] [--timeout S] [--repeat N]
"""
import argparse
import datetime
import json
import os
import platform
import re
import shlex
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
MODEL_EXTENSIONS = (".stp", ".step", ".iges", ".igs", ".brep", ".brp")
METHODS = ("nurbslod-guaranteed", "nurbslod-approximate", "brepmesh")
# With --compact: guaranteed mode with --compact beside the others.
COMPACT_METHODS = ("nurbslod-guaranteed", "nurbslod-compact", "nurbslod-approximate", "brepmesh")


def ours(methods):
    """The methods that are NurbsLOD's, compared with BRepMesh in the ratio rows."""
    return [m for m in methods if m != "brepmesh"]
# The independent judge, in ../shared/tools beside the checkout.
JUDGE = os.path.join(os.path.dirname(REPO), "shared", "tools", "meshjudge.py")


def portable(value, places):
    """value (nested dicts, lists, strings) with each folder in `places` (path -> name) written
    as its name, so that the committed report names no folder of the machine it ran on."""
    if isinstance(value, dict):
        return {k: portable(v, places) for k, v in value.items()}
    if isinstance(value, list):
        return [portable(v, places) for v in value]
    if isinstance(value, str):
        for path, name in places:
            value = re.sub(re.escape(path.rstrip("/")) + r"(?=/|\s|$)", name, value)
        return value
    return value


def last_json(text):
    for line in reversed(text.strip().splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                return json.loads(line)
            except ValueError:
                continue
    return None


def run(cmd, timeout):
    """(returncode | 'TIMEOUT', stdout, stderr, wall seconds)."""
    start = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr, time.perf_counter() - start
    except subprocess.TimeoutExpired:
        return "TIMEOUT", "", "", time.perf_counter() - start


def tessellate(args, model, method, tol, mesh):
    """One method's mesh; its seconds and end-to-end seconds the least of --repeat runs (the
    runs that other processes slow down say nothing of the tool)."""
    if method == "brepmesh":
        cmd = [args.timer, model, repr(tol), mesh, str(args.threads), "0.5"]
    else:
        mode = "guaranteed" if method == "nurbslod-compact" else method.split("-")[1]
        cmd = [args.nurbslod, "tessellate", model, "-o", mesh, "--tolerance", repr(tol),
               "--mode", mode, "--threads", str(args.threads)]
        if method == "nurbslod-compact":
            cmd.append("--compact")
    result = {"cmd": " ".join(shlex.quote(c) for c in cmd)}
    for _ in range(max(1, args.repeat)):
        rc, out, err, wall = run(cmd, args.timeout)
        result["rc"] = rc
        data = last_json(out) if rc != "TIMEOUT" else None
        if data is None:
            result["error"] = "TIMEOUT" if rc == "TIMEOUT" else (err.strip()[-300:] or "no JSON")
            return result
        seconds = data.get("seconds")
        if "seconds" in result and seconds is not None and result["seconds"] is not None:
            seconds = min(seconds, result["seconds"])
        result.update({"triangles": data.get("triangles"), "seconds": seconds,
                       "wall_seconds": min(wall, result.get("wall_seconds", wall)),
                       "faces": data.get("faces"), "faces_failed": data.get("faces_failed", [])})
    return result


def measure(cmd, timeout):
    rc, out, err, wall = run(cmd, timeout)
    if rc == "TIMEOUT":
        return {"status": "TIMEOUT", "wall_seconds": wall}
    data = last_json(out)
    if data is None or rc not in (0, 1):
        return {"status": "ERROR", "rc": rc, "error": (err.strip() or out.strip())[-300:],
                "wall_seconds": wall}
    data["status"] = "PASS" if rc == 0 else "FAIL"
    data["wall_seconds"] = wall
    return data


def verify(args, model, mesh, tol):
    return measure([args.nurbslod, "verify", model, mesh, "--tolerance", repr(tol),
                    "--threads", "0"], args.timeout)


def judge(args, model, mesh, tol, json_path):
    """meshjudge prints a text line; its numbers come from its --json file."""
    if os.path.exists(json_path):
        os.remove(json_path)
    cmd = [sys.executable, JUDGE, model, mesh, "--tol", repr(tol), "--json", json_path]
    rc, out, err, wall = run(cmd, args.judge_timeout)
    if rc == "TIMEOUT":
        return {"status": "TIMEOUT", "wall_seconds": wall}
    if rc not in (0, 1) or not os.path.exists(json_path):
        return {"status": "ERROR", "rc": rc, "error": (err.strip() or out.strip())[-300:],
                "wall_seconds": wall}
    with open(json_path) as fh:
        full = json.load(fh)
    data = {"status": "PASS" if rc == 0 else "FAIL", "wall_seconds": wall}
    data.update({k: full.get(k) for k in ("max_dev", "max_cover", "open_edges",
                                           "nonmanifold_edges", "faces_over_tol",
                                           "faces_missing", "triangles", "judge_seconds")})
    per_face = full.get("per_face", {})
    data["worst_faces"] = sorted(
        ({"face": int(f), "dev": v["dev"], "cover": v["cover"]} for f, v in per_face.items()
         if max(v["dev"], v["cover"]) > tol), key=lambda x: -max(x["dev"], x["cover"]))[:5]
    return data


def per_face(args, model, mesh, tol, json_path):
    """{face: (triangles, dev, cover)} from `nurbslod verify --json`, or None."""
    if os.path.exists(json_path):
        os.remove(json_path)
    rc, _, _, _ = run([args.nurbslod, "verify", model, mesh, "--tolerance", repr(tol),
                       "--threads", "0", "--json", json_path], args.timeout)
    if rc == "TIMEOUT" or not os.path.exists(json_path):
        return None
    with open(json_path) as fh:
        data = json.load(fh)
    return {f["face"]: (f["triangles"], f["dev"], f["cover"])
            for f in data.get("per_face", []) if f.get("measured", True)}


def kept_deflection(args, model, tol, workdir, stem, ours_mesh):
    """BRepMesh at equal measured error, per face (see the module's text)."""
    ours = per_face(args, model, ours_mesh, tol, os.path.join(workdir, stem + "_ours_faces.json"))
    if ours is None:
        return {"error": "verify of NurbsLOD's mesh failed"}
    kept = {}  # face -> (halvings, triangles)
    runs = []
    whole = None  # the first D at which every face keeps T
    for k in range(args.kept_halvings + 1):
        d = tol / 2 ** k
        mesh = os.path.join(workdir, "%s_brepmesh_D%d.obj" % (stem, k))
        rc, out, _, _ = run([args.timer, model, repr(d), mesh, str(args.threads), "0.5"],
                            args.timeout)
        data = last_json(out) if rc != "TIMEOUT" else None
        faces = per_face(args, model, mesh, tol, mesh + ".faces.json") if data else None
        if faces is None:
            runs.append({"deflection": d, "error": "TIMEOUT" if rc == "TIMEOUT" else "failed"})
            continue
        good = {f for f, (_, dev, cover) in faces.items() if dev <= tol and cover <= tol}
        runs.append({"deflection": d, "triangles": data.get("triangles"),
                     "faces_kept": len(good)})
        if whole is None and good >= set(ours):
            whole = {"deflection": d, "triangles": data.get("triangles")}
        for f in good:
            kept.setdefault(f, (k, faces[f][0]))
    kept_faces = sorted(kept)
    never = sorted(set(ours) - set(kept))
    result = {
        "faces": len(ours), "faces_kept": len(kept_faces), "faces_never_kept": never,
        "brepmesh_triangles": sum(kept[f][1] for f in kept_faces),
        "ours_triangles": sum(ours[f][0] for f in kept_faces if f in ours),
        "ours_triangles_never_kept": sum(ours[f][0] for f in never),
        "halvings_histogram": [sum(1 for f in kept_faces if kept[f][0] == k)
                               for k in range(args.kept_halvings + 1)],
        "whole_model": whole, "runs": runs}
    return result


def diagonal(args, model):
    """Bounding-box diagonal from FreeCAD (the same one nurbslod --relative uses)."""
    code = ("import sys; sys.path.append('/usr/lib/freecad-python3/lib'); import FreeCAD, Part; "
            "s = Part.Shape(); s.read(sys.argv[1]); print(s.BoundBox.DiagonalLength)")
    rc, out, err, _ = run([sys.executable, "-c", code, model], 120)
    try:
        return float(out.strip().splitlines()[-1])
    except (ValueError, IndexError, AttributeError):
        return None


def ratio(a, b):
    return a / b if a is not None and b not in (None, 0) else None


def fmt(x, spec="%.3g"):
    if x is None:
        return "—"
    if isinstance(x, str):
        return x
    return spec % x


def over(m, key, tol):
    if m is None:
        return "—"
    if m.get("status") in ("TIMEOUT", "ERROR"):
        return m["status"]
    return fmt(m.get(key) / tol if m.get(key) is not None else None, "%.3f")


def build_rows(results, with_judge):
    header = ["model", "R", "method", "triangles", "seconds", "end-to-end s", "max_dev/T",
              "max_cover/T",
              "open edges", "verify"]
    if with_judge:
        header += ["judge dev/T", "judge cover/T", "judge open", "judge"]
    rows = []
    for r in results:
        tol = r["tolerance"]
        for method in METHODS:
            m = r["methods"][method]
            t = m["tessellate"]
            v = m.get("verify")
            row = [r["model"], "%g" % r["relative"], method,
                   fmt(t.get("triangles"), "%d") if "error" not in t else t["error"][:40],
                   fmt(t.get("seconds"), "%.3f"), fmt(t.get("wall_seconds"), "%.2f"),
                   over(v, "max_dev", tol), over(v, "max_cover", tol),
                   fmt(v.get("open_edges"), "%d") if v and "open_edges" in v else "—",
                   v["status"] if v else "—"]
            if with_judge:
                j = m.get("judge")
                row += [over(j, "max_dev", tol) if j else "not run",
                        over(j, "max_cover", tol) if j else "not run",
                        fmt(j.get("open_edges"), "%d") if j and "open_edges" in j else "—",
                        j["status"] if j else "not run"]
            rows.append(row)
        b = r["methods"]["brepmesh"]["tessellate"]
        for method in ours(METHODS):
            t = r["methods"][method]["tessellate"]
            row = [r["model"], "%g" % r["relative"], method.replace("nurbslod-", "ratio ") +
                   "/brepmesh", fmt(ratio(t.get("triangles"), b.get("triangles")), "%.2fx"),
                   fmt(ratio(t.get("seconds"), b.get("seconds")), "%.2fx"),
                   fmt(ratio(t.get("wall_seconds"), b.get("wall_seconds")), "%.2fx"),
                   "", "", "", ""]
            if with_judge:
                row += ["", "", "", ""]
            rows.append(row)
    return header, rows


def text_table(header, rows):
    widths = [max(len(str(x)) for x in col) for col in zip(header, *rows)]
    line = lambda cells: "  ".join(str(c).ljust(w) for c, w in zip(cells, widths))  # noqa: E731
    return "\n".join([line(header), line(["-" * w for w in widths])] + [line(r) for r in rows])


def md_table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def kept_line(k):
    if "error" in k:
        return k["error"]
    return ("%d of %d faces keep T at some D; on them BRepMesh %d, NurbsLOD %d triangles (%s); "
            "never kept: %d faces (NurbsLOD %d triangles); whole model keeps T at %s"
            % (k["faces_kept"], k["faces"], k["brepmesh_triangles"], k["ours_triangles"],
               ratio_text(k["ours_triangles"], k["brepmesh_triangles"]),
               len(k["faces_never_kept"]), k["ours_triangles_never_kept"],
               "D = %.4g (%d triangles)" % (k["whole_model"]["deflection"],
                                            k["whole_model"]["triangles"])
               if k["whole_model"] else "no D tried"))


def ratio_text(a, b):
    q = ratio(a, b)
    return "%.2fx" % q if q else "-"


def kept_rows(results):
    header = ["model", "R", "faces kept / all", "faces at D = T, T/2, T/4, ...",
              "BRepMesh triangles", "NurbsLOD triangles", "ratio", "faces never kept",
              "NurbsLOD triangles there", "whole model keeps T at D/T (triangles)"]
    rows = []
    for r in results:
        k = r.get("kept")
        if not k or "error" in k:
            continue
        w = k["whole_model"]
        rows.append([r["model"], "%g" % r["relative"], "%d / %d" % (k["faces_kept"], k["faces"]),
                     " / ".join(str(n) for n in k["halvings_histogram"]),
                     str(k["brepmesh_triangles"]), str(k["ours_triangles"]),
                     ratio_text(k["ours_triangles"], k["brepmesh_triangles"]),
                     ", ".join(str(f) for f in k["faces_never_kept"][:8]) +
                     (" (%d)" % len(k["faces_never_kept"]) if len(k["faces_never_kept"]) > 8
                      else "") or "none",
                     str(k["ours_triangles_never_kept"]),
                     "%.4g (%d)" % (w["deflection"] / r["tolerance"], w["triangles"]) if w
                     else "none up to 1/%d" % 2 ** max(0, len(k["runs"]) - 1)])
    return header, rows


def summary_ratios(results):
    """Geometric means over models of the ratios, per R."""
    import math
    out = {}
    for r in results:
        b = r["methods"]["brepmesh"]["tessellate"]
        for method in ours(METHODS):
            t = r["methods"][method]["tessellate"]
            for key in ("triangles", "seconds", "wall_seconds"):
                q = ratio(t.get(key), b.get(key))
                if q:
                    out.setdefault((r["relative"], method, key), []).append(q)
    return {k: math.exp(sum(math.log(x) for x in v) / len(v)) for k, v in out.items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--corpus", default=os.path.join(os.path.dirname(REPO), "shared", "corpus"))
    ap.add_argument("--models", nargs="+", help="model file names or stems (default: all)")
    ap.add_argument("--relative", nargs="+", type=float, default=[1e-3, 1e-4])
    ap.add_argument("--threads", type=int, default=1,
                    help="NurbsLOD --threads; BRepMesh runs parallel when != 1 (default 1)")
    ap.add_argument("--judge", action="store_true", help="also run meshjudge.py (slow)")
    ap.add_argument("--compact", action="store_true",
                    help="also run guaranteed mode with --compact (nurbslod-compact)")
    ap.add_argument("--judge-relative", nargs="+", type=float,
                    help="run meshjudge only at these R (default: every R)")
    ap.add_argument("--out", help="keep the meshes here (default: a temporary folder)")
    ap.add_argument("--timeout", type=float, default=300, help="per tessellate/verify (s)")
    ap.add_argument("--repeat", type=int, default=3,
                    help="tessellate each mesh this many times and keep the least seconds "
                    "(default 3)")
    ap.add_argument("--judge-timeout", type=float, default=300, help="per meshjudge run (s)")
    ap.add_argument("--kept-deflection", action="store_true",
                    help="also compare with BRepMesh at equal measured error (slow)")
    ap.add_argument("--kept-halvings", type=int, default=4,
                    help="BRepMesh deflections tried for --kept-deflection: T / 2^k, k <= this")
    ap.add_argument("--build", default=os.path.join(REPO, "build"))
    ap.add_argument("--md", default=os.path.join(REPO, "docs", "benchmark.md"))
    ap.add_argument("--json", default=os.path.join(REPO, "docs", "benchmark.json"))
    args = ap.parse_args()
    if args.compact:
        global METHODS
        METHODS = COMPACT_METHODS

    if not os.path.isdir(args.corpus):
        print("model_benchmark: corpus %s not found; skipping" % args.corpus)
        return 0
    args.nurbslod = os.path.join(args.build, "App", "nurbslod")
    args.timer = os.path.join(args.build, "tests", "bench", "brepmesh_timer")
    for exe in (args.nurbslod, args.timer):
        if not os.access(exe, os.X_OK):
            print("model_benchmark: %s not built (ninja -C %s nurbslod brepmesh_timer)"
                  % (exe, args.build), file=sys.stderr)
            return 2
    models = sorted(f for f in os.listdir(args.corpus) if f.lower().endswith(MODEL_EXTENSIONS))
    if args.models:
        want = set(args.models)
        models = [m for m in models if m in want or os.path.splitext(m)[0] in want]
    if not models:
        print("model_benchmark: no models selected in %s; skipping" % args.corpus)
        return 0
    workdir = args.out or tempfile.mkdtemp(prefix="nurbslod_bench_")
    os.makedirs(workdir, exist_ok=True)
    judge_rel = args.judge_relative if args.judge_relative else args.relative

    results = []
    started = time.perf_counter()
    for model in models:
        path = os.path.join(args.corpus, model)
        diag = diagonal(args, path)
        for rel in args.relative:
            stem = "%s_R%g" % (os.path.splitext(model)[0], rel)
            entry = {"model": model, "relative": rel, "diagonal": diag, "methods": {}}
            if diag is None:  # FreeCAD could not read it: nurbslod's own JSON, tolerance / R
                rc, out, _, _ = run([args.nurbslod, "tessellate", path, "-o",
                                     os.path.join(workdir, stem + "_probe.obj"),
                                     "--relative", repr(rel)], args.timeout)
                probe = last_json(out) if rc != "TIMEOUT" else None
                if not probe or not probe.get("tolerance"):
                    print("model_benchmark: cannot size %s; skipped" % model, file=sys.stderr)
                    continue
                diag = probe["tolerance"] / rel
                entry["diagonal"] = diag
            tol = rel * diag
            entry["tolerance"] = tol
            for method in METHODS:
                mesh = os.path.join(workdir, "%s_%s.obj" % (stem, method))
                m = {"mesh": mesh, "tessellate": tessellate(args, path, method, tol, mesh)}
                if "error" not in m["tessellate"]:
                    m["verify"] = verify(args, path, mesh, tol)
                    if args.judge and any(abs(rel - j) <= 1e-12 for j in judge_rel):
                        m["judge"] = judge(args, path, mesh, tol, mesh + ".judge.json")
                entry["methods"][method] = m
                t, v = m["tessellate"], m.get("verify", {})
                print("[%6.0fs] %-28s R=%g %-21s tris %-8s %ss  verify %s dev/T %s cover/T %s%s"
                      % (time.perf_counter() - started, model, rel, method,
                         t.get("triangles", t.get("error")), fmt(t.get("seconds"), "%.3f"),
                         v.get("status"), over(v, "max_dev", tol), over(v, "max_cover", tol),
                         "  judge %s dev/T %s cover/T %s" % (
                             m["judge"]["status"], over(m["judge"], "max_dev", tol),
                             over(m["judge"], "max_cover", tol)) if "judge" in m else ""),
                      flush=True)
            if args.kept_deflection and "error" not in entry["methods"][METHODS[0]]["tessellate"]:
                entry["kept"] = kept_deflection(args, path, tol, workdir, stem,
                                                entry["methods"][METHODS[0]]["mesh"])
                print("[%6.0fs] %-28s R=%g brepmesh at equal error: %s"
                      % (time.perf_counter() - started, model, rel, kept_line(entry["kept"])),
                      flush=True)
            results.append(entry)
    total = time.perf_counter() - started

    header, rows = build_rows(results, args.judge)
    print()
    print(text_table(header, rows))
    means = summary_ratios(results)
    mean_lines = ["R=%g  %s/brepmesh  %s: %.2fx" % (rel, method.replace("nurbslod-", ""), key, q)
                  for (rel, method, key), q in sorted(means.items())]
    print("\nGeometric means over models:\n" + "\n".join(mean_lines))

    # longest first: the build folder lies inside the checkout
    places = sorted([(os.path.abspath(args.build), "build"), (os.path.abspath(args.corpus), "corpus"),
                     (os.path.abspath(workdir), "OUT"), (REPO, ".")], key=lambda p: -len(p[0]))
    places += [(p, name) for p, name in [(args.build, "build"), (args.corpus, "corpus"),
                                         (workdir, "OUT")] if not os.path.isabs(p)]
    command = portable(" ".join(shlex.quote(a) for a in ["python3"] + sys.argv), places)
    results = portable(results, places)
    now = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    notes = []
    for r in results:
        for method in METHODS:
            m = r["methods"][method]
            for tool in ("verify", "judge"):
                d = m.get(tool)
                if d and d.get("status") in ("FAIL", "TIMEOUT", "ERROR"):
                    detail = ""
                    if d.get("faces_failed"):
                        detail = "; faces " + ", ".join(
                            "%d (dev %.3g, cover %.3g%s)" % (
                                f["face"], f.get("dev", float("nan")), f.get("cover", float("nan")),
                                ", " + f["problem"] if f.get("problem") else "")
                            for f in d["faces_failed"][:5])
                    elif d.get("worst_faces"):
                        detail = "; faces " + ", ".join(
                            "%d (dev %.3g, cover %.3g)" % (f["face"], f["dev"], f["cover"])
                            for f in d["worst_faces"])
                    if d.get("faces_missing"):
                        detail += "; missing faces %s" % d["faces_missing"][:10]
                    notes.append("- %s R=%g %s: %s %s (T = %.4g)%s" % (
                        r["model"], r["relative"], method, tool, d["status"], r["tolerance"],
                        detail))
            if m["tessellate"].get("faces_failed"):
                notes.append("- %s R=%g %s: tessellate reported faces_failed %s" % (
                    r["model"], r["relative"], method, m["tessellate"]["faces_failed"][:10]))
    md = ["# NurbsLOD model benchmark", "",
          "- date: %s" % now,
          "- machine: %d cores (nproc), %s" % (os.cpu_count() or 0, cpu_model()),
          "- command: `%s`" % command,
          "- threads: NurbsLOD `--threads %d`; BRepMesh_IncrementalMesh %s, deflection D = T, "
          "angular 0.5 rad, timed in-process (tests/bench/brepmesh_timer)" % (
              args.threads, "parallel" if args.threads != 1 else "sequential"),
          "- T = R x bounding-box diagonal. seconds = tessellation only (as each tool reports it); "
          "end-to-end s = the whole process (file read, import and NURBS conversion, meshing, "
          "mesh written); each the least of %d runs. " % max(1, args.repeat) +
          "max_dev/T: mesh -> exact face, max_cover/T: exact face -> mesh, from `nurbslod verify`"
          " (values > 1 exceed the tolerance); open edges after welding vertices."
          + (" judge columns: meshjudge.py (at R in %s)." % ", ".join("%g" % j for j in judge_rel)
             if args.judge else " meshjudge was not run (--judge)."),
          "- whole run: %.0f s" % total, "",
          md_table(header, rows), "",
          "Geometric means of the ratios over models:", ""]
    md += ["- " + line for line in mean_lines]
    kept_header, kept = kept_rows(results)
    if kept:
        md += ["", "## BRepMesh at equal measured error", "",
               "BRepMesh again at D = T/2^k, k = 0..%d; each face's triangles from the largest D "
               "at which it keeps T both ways (`nurbslod verify`), beside NurbsLOD's guaranteed "
               "triangles on the same faces. Faces that keep T at no D are listed apart. An "
               "estimate: BRepMesh discretises each edge once for both faces, so no single run "
               "has these per-face counts." % args.kept_halvings, "",
               md_table(kept_header, kept)]
        print()
        print(text_table(kept_header, kept))
    if notes:
        md += ["", "Failures and timeouts:", ""] + notes
    os.makedirs(os.path.dirname(args.md), exist_ok=True)
    with open(args.md, "w") as fh:
        fh.write("\n".join(md) + "\n")
    with open(args.json, "w") as fh:
        json.dump({"date": now, "nproc": os.cpu_count(), "cpu": cpu_model(), "command": command,
                   "threads": args.threads, "seconds": total, "results": results,
                   "ratio_geomeans": {"R=%g %s/brepmesh %s" % k: v for k, v in means.items()}},
                  fh, indent=1)
    print("\nwrote %s and %s (meshes in %s, OUT in the report)" % (args.md, args.json, workdir))
    if notes:
        print("\n".join(notes))
    return 0


if __name__ == "__main__":
    sys.exit(main())
